//! Seminar rooms: a whiteboard, a lectern or a teacher's desk, and
//! tables with chairs in rows, a U or blocks.

use super::{between, SWING};
use crate::sim::geometry::{cuboid, Shape};
use crate::sim::hotel::dining_chair;
use crate::sim::scenes::{chair, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// How a seminar room's tables are set out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Seating {
    /// In rows facing the front.
    Rows,
    /// In a U open to the front, chairs round its outside.
    U,
    /// Pushed together into one or two blocks, chairs all round.
    Block,
}

/// What every table and chair of a seminar room shares.
struct Set {
    /// Table length and depth (m).
    size: [f64; 2],
    /// Top height (m).
    top: f64,
    /// Four legs, or panel ends.
    legs: bool,
    /// Swivel chairs, or stacking chairs.
    swivel: bool,
}

/// A seminar room: laid out with its front on the window wall (y = d),
/// or in two rooms of five on the x = w side wall (built in a frame
/// turned a quarter and mirrored into place); a whiteboard on the front
/// wall, in most a projector screen beside it or pulled down before it
/// (with a projector under the ceiling in four of five), a lectern or a
/// teacher's desk with its chair before the board; tables with chairs in
/// rows, a U or blocks, keeping 1.25 m clear along the frame's x = 0 side
/// (the door's way in: an aisle along the side wall from the corridor,
/// or the strip along the corridor wall when turned) and 0.5 m at the
/// others; in some a side table or a pinboard on the side wall opposite.
/// Returns how the tables are set out.
pub(super) fn seminar_room(
    w: f64,
    d: f64,
    h: f64,
    r: &mut ChaCha8Rng,
    s: &mut Vec<Shape>,
) -> Seating {
    let turned = r.random::<f64>() < 0.4;
    let (lw, ld) = if turned { (d, w) } else { (w, d) };
    let mut t = Vec::new();
    let set = Set {
        size: [u(r, 1.2, 1.6), u(r, 0.5, 0.7)],
        top: u(r, 0.72, 0.75),
        legs: r.random::<bool>(),
        swivel: r.random::<f64>() < 0.35,
    };
    let front = u(r, 1.8, 2.3);
    // The whiteboard and its pen tray.
    let bw = u(r, 2.4, 4.0).min(lw - 1.6);
    let bx = between(r, 0.8, lw - 0.8 - bw);
    t.push(cuboid([bx, ld - 0.03, 0.9], [bw, 0.03, 1.2]));
    t.push(cuboid([bx, ld - 0.09, 0.86], [bw, 0.06, 0.03]));
    if r.random::<f64>() < 0.65 {
        let sw = u(r, 1.8, 2.4);
        let stop = (h - 0.45).min(2.7);
        let (sx, off) = if bx - 0.3 >= sw + 0.3 {
            (between(r, 0.3, bx - 0.3 - sw), 0.05)
        } else if lw - bx - bw - 0.3 >= sw + 0.3 {
            (between(r, bx + bw + 0.3, lw - 0.3 - sw), 0.05)
        } else {
            ((bx + bw / 2.0 - sw / 2.0).clamp(0.3, lw - 0.3 - sw), 0.12)
        };
        let sh = (sw * 0.7).min(stop - 0.6);
        t.push(cuboid([sx, ld - off - 0.01, stop - sh], [sw, 0.01, sh]));
        t.push(cuboid(
            [sx - 0.05, ld - off - 0.08, stop],
            [sw + 0.1, 0.1, 0.1],
        ));
        if r.random::<f64>() < 0.8 {
            let p = [sx + sw / 2.0, (ld - u(r, 3.0, 4.5)).max(1.5)];
            t.push(Shape::Cylinder {
                centre: p,
                radius: 0.02,
                z0: h - 0.45,
                z1: h,
            });
            t.push(cuboid(
                [p[0] - 0.17, p[1] - 0.15, h - 0.6],
                [0.34, 0.3, 0.15],
            ));
        }
    }
    // The lecturer's place before the board, to one side.
    let lx = lw
        * if r.random::<bool>() {
            u(r, 0.2, 0.35)
        } else {
            u(r, 0.65, 0.8)
        };
    if r.random::<f64>() < 0.45 {
        let ly = ld - u(r, 0.9, 1.2);
        t.push(cuboid(
            [lx - 0.28, ly - 0.22, 0.0],
            [0.55, 0.45, u(r, 1.05, 1.2)],
        ));
    } else {
        let dl = u(r, 1.2, 1.6);
        let dy = ld - u(r, 1.0, 1.15);
        let x0 = (lx - dl / 2.0).clamp(0.3, lw - 0.3 - dl);
        desk_table(&mut t, [x0, dy - 0.325], [dl, 0.65], 0.74, true);
        t.push(cuboid(
            [x0 + dl / 2.0 - 0.25, dy - 0.1, 0.74],
            [0.5, 0.05, 0.35],
        ));
        let cx = x0 + dl / 2.0 + u(r, -0.2, 0.2);
        seat(&mut t, r, true, [cx, dy + 0.325 + 0.25], -FRAC_PI_2);
    }
    // Where tables and chairs may stand.
    let xl = SWING + 0.25;
    let my = 0.5;
    let side_table = r.random::<f64>() < 0.35;
    let xr = lw - if side_table { 1.4 } else { u(r, 0.5, 0.8) };
    let y_front = ld - front;
    if side_table {
        let sl = u(r, 1.2, 1.8);
        let sy = between(r, my + 0.3, y_front - sl);
        desk_table(&mut t, [lw - 0.5, sy], [0.5, sl], set.top, set.legs);
        if r.random::<f64>() < 0.6 {
            t.push(cuboid(
                [lw - 0.4, sy + 0.2, set.top],
                [0.3, 0.3, u(r, 0.3, 0.45)],
            ));
        }
    } else if r.random::<f64>() < 0.4 {
        let pl = u(r, 1.0, 2.0);
        let py = between(r, my + 0.5, y_front - pl);
        t.push(cuboid([lw - 0.02, py, 1.0], [0.02, pl, u(r, 0.8, 1.0)]));
    }
    let zone = ([xl, my], [xr, y_front]);
    let roll = r.random::<f64>();
    let seating = if roll < 0.3 && u_shape(&mut t, r, zone, &set) {
        Seating::U
    } else if (0.3..0.55).contains(&roll) && block(&mut t, r, zone, &set) {
        Seating::Block
    } else {
        rows(&mut t, r, zone, &set);
        Seating::Rows
    };
    if turned {
        s.extend(t.iter().map(transpose));
    } else {
        s.extend(t);
    }
    seating
}

/// `s` mirrored in the line x = y.
fn transpose(s: &Shape) -> Shape {
    match *s {
        Shape::Cuboid { min, max } => Shape::Cuboid {
            min: [min[1], min[0], min[2]],
            max: [max[1], max[0], max[2]],
        },
        Shape::OrientedBox { centre, half, yaw } => Shape::OrientedBox {
            centre: [centre[1], centre[0], centre[2]],
            half,
            yaw: FRAC_PI_2 - yaw,
        },
        Shape::Cylinder {
            centre,
            radius,
            z0,
            z1,
        } => Shape::Cylinder {
            centre: [centre[1], centre[0]],
            radius,
            z0,
            z1,
        },
        Shape::Sphere { centre, radius } => Shape::Sphere {
            centre: [centre[1], centre[0], centre[2]],
            radius,
        },
    }
}

/// A table over `[x0, x0 + sx] x [y0, y0 + sy]`, its top at `h`: on four
/// legs, or (`legs` false) on a panel at each end of its long side.
fn desk_table(s: &mut Vec<Shape>, [x0, y0]: [f64; 2], [sx, sy]: [f64; 2], h: f64, legs: bool) {
    s.push(cuboid([x0, y0, h - 0.03], [sx, sy, 0.03]));
    if legs {
        for x in [x0 + 0.03, x0 + sx - 0.07] {
            for y in [y0 + 0.03, y0 + sy - 0.07] {
                s.push(cuboid([x, y, 0.0], [0.04, 0.04, h - 0.03]));
            }
        }
    } else if sx >= sy {
        for x in [x0 + 0.03, x0 + sx - 0.07] {
            s.push(cuboid([x, y0 + 0.05, 0.0], [0.04, sy - 0.1, h - 0.03]));
        }
    } else {
        for y in [y0 + 0.03, y0 + sy - 0.07] {
            s.push(cuboid([x0 + 0.05, y, 0.0], [sx - 0.1, 0.04, h - 0.03]));
        }
    }
}

/// A chair at `c` facing `yaw`: a swivel chair turned a little, or a
/// stacking chair.
fn seat(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, swivel: bool, c: [f64; 2], yaw: f64) {
    if swivel {
        chair(s, c[0], c[1], yaw + u(r, -0.35, 0.35));
    } else {
        let turn = u(r, -0.1, 0.1);
        dining_chair(s, r, &Frame::at(c[0], c[1], yaw + turn));
    }
}

/// Chairs along a table's side from `a` to `b` (along x, or along y when
/// `along_y`), `at` across, facing `yaw`: one per 0.6 m, a few missing.
#[allow(clippy::too_many_arguments)]
fn chairs(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    set: &Set,
    (a, b): (f64, f64),
    at: f64,
    along_y: bool,
    yaw: f64,
) {
    let n = ((b - a) / 0.6).floor().max(1.0) as usize;
    for i in 0..n {
        if r.random::<f64>() < 0.88 {
            let p = a + (i as f64 + 0.5) * (b - a) / n as f64 + u(r, -0.05, 0.05);
            let c = if along_y { [at, p] } else { [p, at] };
            seat(s, r, set.swivel, c, yaw);
        }
    }
}

/// Rows of tables in `zone` (lowest and highest corner), the first at
/// its front edge, chairs behind each facing the front, in one block or
/// two either side of an aisle, as many rows as leave the chairs in the
/// zone.
fn rows(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    ([xl, my], [xr, yf]): ([f64; 2], [f64; 2]),
    set: &Set,
) {
    let [tl, td] = set.size;
    let avail = xr - xl;
    let (blocks, aisle) = if avail >= 4.0 * tl + 0.9 && r.random::<f64>() < 0.8 {
        (2, u(r, 0.9, 1.2))
    } else {
        (1, 0.0)
    };
    let n = ((avail - aisle) / (blocks as f64 * tl)).floor().max(1.0) as usize;
    let span = (blocks * n) as f64 * tl + aisle;
    let x0 = xl + (avail - span) / 2.0;
    let mut y = yf;
    while y - td - 0.7 >= my {
        for b in 0..blocks {
            for k in 0..n {
                let x = x0 + b as f64 * (n as f64 * tl + aisle) + k as f64 * tl;
                desk_table(s, [x + 0.01, y - td], [tl - 0.02, td], set.top, set.legs);
                let cy = y - td - u(r, 0.3, 0.4);
                chairs(s, r, set, (x, x + tl), cy, false, FRAC_PI_2);
            }
        }
        y -= td + u(r, 0.7, 0.85);
    }
}

/// Tables in a U open to the front within `zone`, chairs round its
/// outside; false (nothing placed) where the zone is too small for a U
/// with 1.2 m inside it.
fn u_shape(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    ([xl, my], [xr, yf]): ([f64; 2], [f64; 2]),
    set: &Set,
) -> bool {
    let [tl, td] = set.size;
    let (ux0, ux1) = (xl + 0.7, xr - 0.7);
    let (uy0, uy1) = (my + 0.7, yf);
    if ux1 - ux0 - 2.0 * td < 1.2 || uy1 - uy0 - td < 1.2 {
        return false;
    }
    let n = ((ux1 - ux0) / tl).floor().max(1.0);
    let bl = (ux1 - ux0) / n;
    for k in 0..n as usize {
        let x = ux0 + k as f64 * bl;
        desk_table(s, [x + 0.01, uy0], [bl - 0.02, td], set.top, set.legs);
        let cy = uy0 - u(r, 0.3, 0.4);
        chairs(s, r, set, (x, x + bl), cy, false, FRAC_PI_2);
    }
    let al = uy1 - uy0 - td;
    let n = (al / tl).floor().max(1.0);
    let bl = al / n;
    for (x, cx, yaw) in [(ux0, ux0 - 0.35, 0.0), (ux1 - td, ux1 + 0.35, PI)] {
        for k in 0..n as usize {
            let y = uy0 + td + k as f64 * bl;
            desk_table(s, [x, y + 0.01], [td, bl - 0.02], set.top, set.legs);
            chairs(s, r, set, (y, y + bl), cx, true, yaw);
        }
    }
    true
}

/// Tables pushed together into one block (or two side by side) in
/// `zone`, two tables deep, chairs along both long sides and at the
/// ends; false (nothing placed) where the zone holds no block of two
/// tables by two.
fn block(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    ([xl, my], [xr, yf]): ([f64; 2], [f64; 2]),
    set: &Set,
) -> bool {
    let [tl, td] = set.size;
    let (zx0, zx1) = (xl + 0.75, xr - 0.75);
    let (zy0, zy1) = (my + 0.75, yf - 0.5);
    if zy1 - zy0 < 2.0 * td || zx1 - zx0 < 2.0 * tl {
        return false;
    }
    let nb = if zx1 - zx0 >= 4.0 * tl + 1.5 && r.random::<f64>() < 0.5 {
        2
    } else {
        1
    };
    let m = ((zx1 - zx0 - (nb - 1) as f64 * 1.5) / (nb as f64 * tl))
        .floor()
        .min(4.0) as usize;
    let bx = m as f64 * tl;
    let span = nb as f64 * bx + (nb - 1) as f64 * 1.5;
    let x0 = (zx0 + zx1) / 2.0 - span / 2.0;
    let yc = between(r, zy0 + td, zy1 - td);
    for b in 0..nb {
        let bx0 = x0 + b as f64 * (bx + 1.5);
        for k in 0..m {
            for y in [yc - td, yc] {
                desk_table(
                    s,
                    [bx0 + k as f64 * tl + 0.01, y],
                    [tl - 0.02, td],
                    set.top,
                    set.legs,
                );
            }
        }
        let cy = yc - td - u(r, 0.3, 0.4);
        chairs(s, r, set, (bx0, bx0 + bx), cy, false, FRAC_PI_2);
        let cy = yc + td + u(r, 0.3, 0.4);
        chairs(s, r, set, (bx0, bx0 + bx), cy, false, -FRAC_PI_2);
        for (cx, yaw) in [(bx0 - 0.35, 0.0), (bx0 + bx + 0.35, PI)] {
            if r.random::<f64>() < 0.8 {
                seat(s, r, set.swivel, [cx, yc], yaw);
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::institute::tests::{draw, size};
    use crate::sim::office_floor::boxes;

    #[test]
    fn a_seminar_room_has_tables_and_chairs_a_whiteboard_and_a_lectern_or_desk() {
        let mut r = crate::rng::rng(8);
        let (mut seen, mut screens, mut turned) = ([0; 3], 0, 0);
        for _ in 0..300 {
            let [w, d, h] = draw("seminar_room", &mut r);
            let mut s = Vec::new();
            let seating = seminar_room(w, d, h, &mut r, &mut s);
            seen[seating as usize] += 1;
            let b = boxes(&s);
            // Tables standing free (not the side table at a wall): tops
            // 0.03 m thick at 0.72-0.75 m, 0.5 m deep or more.
            let tables = b
                .iter()
                .filter(|b| {
                    (0.72..=0.75).contains(&b.1[2])
                        && (size(b)[2] - 0.03).abs() < 1e-9
                        && size(b)[0].min(size(b)[1]) >= 0.5 - 1e-9
                        && b.0[0] > 1e-9
                        && b.1[0] < w - 1e-9
                        && b.1[1] < d - 1e-9
                })
                .count();
            // Chairs: their seats at 0.41-0.42 m.
            let chairs = s
                .iter()
                .filter(|s| {
                    matches!(s, Shape::OrientedBox { centre, half, .. }
                        if half[0] >= 0.2 && half[1] >= 0.2 && half[2] < 0.05
                            && (0.4..0.43).contains(&(centre[2] - half[2])))
                })
                .count();
            assert!(
                tables >= 4 && chairs >= tables,
                "{w:.2} x {d:.2} {seating:?}: {tables} tables, {chairs} chairs"
            );
            // The whiteboard: 0.03 m thick, 0.9-2.1 m, on a wall but the
            // corridor's.
            let board = b.iter().find(|b| {
                b.0[2] == 0.9 && (b.1[2] - 2.1).abs() < 1e-9 && size(b)[0].min(size(b)[1]) < 0.031
            });
            let board = board.unwrap_or_else(|| panic!("{w:.2} x {d:.2}: no whiteboard"));
            let on_wall = board.0[0].abs() < 1e-9
                || (board.1[0] - w).abs() < 1e-9
                || (board.1[1] - d).abs() < 1e-9;
            assert!(on_wall, "{board:?}");
            turned += ((board.1[1] - d).abs() > 1e-9) as usize;
            let lectern = b.iter().any(|b| {
                b.0[2] == 0.0
                    && (1.05..=1.2).contains(&b.1[2])
                    && (size(b)[0] * size(b)[1] - 0.55 * 0.45).abs() < 1e-9
            });
            let desk = b
                .iter()
                .any(|b| (b.0[2] - 0.74).abs() < 1e-9 && (size(b)[2] - 0.35).abs() < 1e-9);
            assert!(lectern || desk, "no lectern or teacher's desk");
            screens += b
                .iter()
                .any(|b| size(b)[0].min(size(b)[1]) < 0.011 && b.0[2] > 0.5)
                as usize;
        }
        assert!(seen.iter().all(|&n| n >= 40), "rows, U, blocks: {seen:?}");
        assert!(
            screens >= 150 && (90..=150).contains(&turned),
            "{screens} screens, {turned} turned"
        );
    }
}
