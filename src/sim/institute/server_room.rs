//! Server rooms: rows of racks, cooling units, cable trays, gas
//! suppression and a desk.

use super::{between, walls};
use crate::sim::geometry::{cuboid, Shape};
use crate::sim::scenes::{chair, table, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// A server room: one or two cooling units on the window wall, rows of
/// racks between them and the corridor wall, running away from the
/// corridor (every room narrower than 6 m, most others) or along it,
/// with aisles of 1.0-1.2 m between rows and 0.8-1.0 m at the walls; in
/// half the rooms a cable tray hung over each row; a desk with a monitor
/// and a chair by the corridor wall at the x = 0 end in most, gas
/// suppression cylinders at the other; in some an electrical panel on
/// the x = w wall.
pub(super) fn server_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, back, front] = walls(w, d);
    let rd = u(r, 1.0, 1.2);
    let rh = u(r, 2.0, 2.2);
    let cd = u(r, 0.8, 0.9);
    let units = if w >= 5.5 && r.random::<f64>() < 0.6 {
        2
    } else {
        1
    };
    let seg = w / units as f64;
    for i in 0..units {
        let cl = u(r, 1.2, 2.0).min(seg - 0.4);
        let a = i as f64 * seg + between(r, 0.2, seg - 0.2 - cl);
        s.push(back.block(a, cl, 0.0, cd, 0.0, u(r, 1.85, 1.98)));
        // Its display and grille on the front.
        s.push(back.block(a + 0.1, 0.3, cd, 0.02, 1.4, 0.2));
    }
    let desk = r.random::<f64>() < 0.75;
    if desk {
        let dl = u(r, 1.0, 1.2);
        let yc = 0.1 + dl / 2.0;
        table(
            s,
            &Frame::at(0.35, yc, FRAC_PI_2),
            [0.0, 0.0],
            [dl, 0.7],
            0.73,
        );
        s.push(left.block(yc - 0.06, 0.12, 0.1, 0.15, 0.73, 0.1));
        s.push(left.block(yc - 0.27, 0.54, 0.15, 0.04, 0.83, 0.33));
        chair(
            s,
            0.7 + u(r, 0.25, 0.35),
            yc + u(r, -0.15, 0.15),
            PI + u(r, -0.4, 0.4),
        );
    }
    for i in 0..r.random_range(1..=2) {
        let c = w - 0.3 - i as f64 * 0.45;
        s.push(front.cylinder(c, 0.3, u(r, 0.15, 0.2), 0.0, u(r, 1.3, 1.7)));
    }
    let y_from = if desk { u(r, 1.5, 1.8) } else { u(r, 1.2, 1.5) };
    let y_to = d - cd - u(r, 1.0, 1.3);
    if r.random::<f64>() < 0.5 {
        let pl = u(r, 0.8, 1.2);
        let pa = between(r, y_from, y_to - pl);
        s.push(right.block(pa, pl, 0.0, 0.25, u(r, 0.4, 0.5), u(r, 1.5, 1.7)));
    }
    let tray = r.random::<f64>() < 0.5;
    let tz = (rh + u(r, 0.25, 0.4)).min(h - 0.4);
    let wall = u(r, 0.8, 1.0);
    let aisle = u(r, 1.0, 1.2);
    if w < 6.0 || r.random::<f64>() < 0.6 {
        let n = (((w - 2.0 * wall + aisle) / (rd + aisle)).floor() as usize).max(1);
        let span = n as f64 * rd + (n - 1) as f64 * aisle;
        let x0 = (w - span) / 2.0;
        let count = ((y_to - y_from) / 0.6).floor() as usize;
        let ya = y_to - count as f64 * 0.6;
        for i in 0..n {
            let x = x0 + i as f64 * (rd + aisle);
            rack_row(s, r, [x, ya], count, true, [rd, rh]);
            if tray {
                cable_tray(s, r, (x + rd / 2.0, ya), count as f64 * 0.6, true, (tz, h));
            }
        }
    } else {
        let n = (((y_to - y_from + aisle) / (rd + aisle)).floor() as usize).max(1);
        let count = ((w - 2.0 * wall) / 0.6).floor() as usize;
        let x0 = (w - count as f64 * 0.6) / 2.0;
        for i in 0..n {
            let y = y_from + i as f64 * (rd + aisle);
            rack_row(s, r, [x0, y], count, false, [rd, rh]);
            if tray {
                cable_tray(s, r, (y + rd / 2.0, x0), count as f64 * 0.6, false, (tz, h));
            }
        }
    }
}

/// A row of `n` racks from `at`, along y (`along_y`) or x, each 0.6 m
/// wide, `depth` deep and `height` high; in a long row a rack left out
/// now and then.
fn rack_row(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    at: [f64; 2],
    n: usize,
    along_y: bool,
    [depth, height]: [f64; 2],
) {
    for i in 0..n {
        if n >= 5 && i > 0 && i + 1 < n && r.random::<f64>() < 0.08 {
            continue;
        }
        let p = i as f64 * 0.6;
        s.push(if along_y {
            cuboid([at[0], at[1] + p, 0.0], [depth, 0.6, height])
        } else {
            cuboid([at[0] + p, at[1], 0.0], [0.6, depth, height])
        });
    }
}

/// A ladder cable tray over a row of racks: centred across the row on
/// `c`, from `from` along it, `len` long, at `z`: two side rails, the
/// cables lying in it, rods hung from the ceiling at `h`.
fn cable_tray(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    (c, from): (f64, f64),
    len: f64,
    along_y: bool,
    (z, h): (f64, f64),
) {
    let tw = u(r, 0.3, 0.5);
    let part = |a0: f64, al: f64, c0: f64, cw: f64, z0: f64, zh: f64| {
        if along_y {
            cuboid([c + c0, from + a0, z0], [cw, al, zh])
        } else {
            cuboid([from + a0, c + c0, z0], [al, cw, zh])
        }
    };
    for c0 in [-tw / 2.0, tw / 2.0 - 0.03] {
        s.push(part(0.0, len, c0, 0.03, z, 0.1));
    }
    s.push(part(
        0.0,
        len,
        -tw / 2.0 + 0.03,
        tw - 0.06,
        z,
        u(r, 0.03, 0.08),
    ));
    let k = (len / 1.5).ceil().max(1.0) as usize;
    for i in 0..=k {
        let a = 0.05 + (len - 0.1) * i as f64 / k as f64;
        for sign in [-1.0, 1.0] {
            let cc = c + sign * (tw / 2.0 - 0.015);
            s.push(Shape::Cylinder {
                centre: if along_y {
                    [cc, from + a]
                } else {
                    [from + a, cc]
                },
                radius: 0.008,
                z0: z + 0.1,
                z1: h,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::institute::tests::{gap, room, size};
    use crate::sim::office_floor::boxes;

    #[test]
    fn a_server_room_has_rows_of_racks_with_aisles_cooling_units_and_mostly_a_desk() {
        let mut r = crate::rng::rng(7);
        let (mut desks, mut trays, mut along, mut across) = (0, 0, 0, 0);
        for _ in 0..300 {
            let ([w, d, h], s) = room("server_room", &mut r);
            let b = boxes(&s);
            let racks: Vec<_> = b
                .iter()
                .filter(|b| {
                    let [x, y, z] = size(b);
                    b.0[2] == 0.0
                        && (2.0..=2.2).contains(&z)
                        && (((x - 0.6).abs() < 1e-9 && (1.0..=1.2).contains(&y))
                            || ((y - 0.6).abs() < 1e-9 && (1.0..=1.2).contains(&x)))
                })
                .collect();
            // Racks in rows: those of a row share their extent across it.
            let row_of = |b: &([f64; 3], [f64; 3])| {
                if (size(b)[1] - 0.6).abs() < 1e-9 {
                    (0, (b.0[0] * 1e6).round() as i64)
                } else {
                    (1, (b.0[1] * 1e6).round() as i64)
                }
            };
            let mut rows = std::collections::BTreeMap::new();
            for b in &racks {
                *rows.entry(row_of(b)).or_insert(0) += 1;
            }
            let longest = rows.values().copied().max().unwrap_or(0);
            assert!(longest >= 3, "{w:.2} x {d:.2}: rows {rows:?}");
            along += rows.keys().any(|k| k.0 == 0) as usize;
            across += rows.keys().any(|k| k.0 == 1) as usize;
            for a in &racks {
                // 0.8 m from the walls, aisles of 1.0 m at least between rows.
                assert!(
                    a.0[0] >= 0.8 - 1e-9 && a.1[0] <= w - 0.8 + 1e-9 && a.0[1] >= 1.2 - 1e-9,
                    "{w:.2} x {d:.2}: a rack at {a:?}"
                );
                for o in &racks {
                    if row_of(a) != row_of(o) {
                        let g = gap(
                            ([a.0[0], a.0[1]], [a.1[0], a.1[1]]),
                            ([o.0[0], o.0[1]], [o.1[0], o.1[1]]),
                        );
                        assert!(g >= 1.0 - 1e-9, "{w:.2} x {d:.2}: an aisle of {g}");
                    }
                }
            }
            // A cooling unit against the window wall, a metre from the racks.
            let crac: Vec<_> = b
                .iter()
                .filter(|b| {
                    b.0[2] == 0.0
                        && (1.85..=1.98).contains(&b.1[2])
                        && (b.1[1] - d).abs() < 1e-9
                        && (0.8..=0.9).contains(&size(b)[1])
                })
                .collect();
            assert!(!crac.is_empty(), "no cooling unit");
            let nearest = racks
                .iter()
                .map(|a| crac[0].0[1] - a.1[1])
                .fold(f64::INFINITY, f64::min);
            assert!(nearest >= 1.0 - 1e-9, "{nearest} m before the cooling unit");
            desks += s
                .iter()
                .any(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] + half[2] - 0.73).abs() < 1e-9))
                as usize;
            trays += s.iter().any(
                |s| matches!(s, Shape::Cylinder { radius, z1, .. } if *radius == 0.008 && *z1 == h),
            ) as usize;
        }
        assert!(desks >= 190 && trays >= 110, "{desks} desks, {trays} trays");
        assert!(
            along >= 150 && across >= 30,
            "{along} along, {across} across"
        );
    }
}
