//! Laboratories: bench runs with a sink, fume hoods, island benches with
//! their reagent shelves and lab stools.

use super::{between, stock, walls, Side, SWING};
use crate::sim::geometry::{cuboid, Shape};
use crate::sim::scenes::u;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// How deep a fume hood is (m), from the wall.
const HOOD_DEPTH: f64 = 0.9;

/// A laboratory: benches with a top at about 0.9 m along the side walls
/// from the door's swing on, a sink in the x = w one; fume hoods on the
/// x = 0 wall at the back with islands (or peninsulas from the window
/// wall) along the room, or on the window wall with islands (or
/// peninsulas from the x = 0 wall) across it; tall chemical cabinets on
/// the corridor wall at the x = w end and in some an emergency shower at
/// the other.
pub(super) fn laboratory(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, back, front] = walls(w, d);
    let top = u(r, 0.88, 0.92);
    let bd = u(r, 0.7, 0.8);
    let y0 = SWING + u(r, 0.1, 0.4);
    // Tall cabinets (chemicals, flammables) on the corridor wall.
    let mut a = w - 0.05;
    for _ in 0..r.random_range(1..=2) {
        let cl = u(r, 0.9, 1.2);
        a -= cl;
        s.push(front.block(a, cl, 0.0, u(r, 0.5, 0.6), 0.0, u(r, 1.95, 2.1)));
        a -= 0.02;
    }
    // An emergency shower with an eyewash by the door.
    if r.random::<f64>() < 0.6 {
        let a = u(r, 0.3, 0.5);
        for (radius, z0, z1) in [(0.025, 0.0, 2.2), (0.15, 2.15, 2.22), (0.14, 0.95, 1.05)] {
            s.push(front.cylinder(a, 0.3, radius, z0, z1));
        }
    }
    // The bench with the sink on the x = w wall, from the swing's edge to
    // the window wall.
    let sink_at = between(r, y0 + 0.5, d - 0.6);
    lab_bench(s, r, &right, (y0, d - y0), bd, top, (false, sink_at));
    sink(s, r, &right, sink_at, top);
    if r.random::<f64>() < 0.6 {
        // Along the room: hoods on the x = 0 wall from the window wall
        // forward, a bench from the swing's edge up to them.
        let hoods = 1
            + (d >= 6.5 && r.random::<f64>() < 0.5) as usize
            + (d >= 7.5 && r.random::<f64>() < 0.3) as usize;
        let mut a = d;
        for _ in 0..hoods {
            let hw = u(r, 1.2, 1.8);
            a -= hw;
            fume_hood(s, r, &left, a, hw, h);
        }
        if a - 0.05 - y0 >= 0.8 {
            lab_bench(s, r, &left, (y0, a - 0.05 - y0), bd, top, (true, -1.0));
        }
        // Islands, or peninsulas from the window wall, with aisles of 1.2
        // m or more between them and the wall benches.
        let (xa, xb) = (HOOD_DEPTH, w - bd);
        let middle = xb - xa;
        let id = u(r, 1.2, 1.6).min(middle - 2.4);
        let k = (((middle - 1.2) / (id + 1.2)).floor() as usize).max(1);
        let aisle = (middle - k as f64 * id) / (k as f64 + 1.0);
        let peninsula = r.random::<f64>() < 0.5;
        let back_bench = !peninsula && r.random::<f64>() < 0.6;
        let ya = u(r, 1.6, 2.0);
        let yb = if peninsula {
            d
        } else {
            d - if back_bench { bd } else { 0.0 } - u(r, 1.2, 1.4)
        };
        if back_bench {
            lab_bench(
                s,
                r,
                &back,
                (xa + 0.05, middle - 0.1),
                bd,
                top,
                (true, -1.0),
            );
        }
        for i in 0..k {
            let x = xa + aisle * (i + 1) as f64 + id * i as f64;
            island(s, r, [x, ya], [id, yb - ya], true, top);
        }
    } else {
        // Across the room: hoods on the window wall from near the x = 0
        // corner, a bench along the rest of it.
        let end = w - bd - 0.05;
        let mut a = u(r, 0.05, 0.3);
        let hoods = 1
            + (end - a >= 3.6 + 0.8 && r.random::<f64>() < 0.5) as usize
            + (end - a >= 5.4 + 0.8 && r.random::<f64>() < 0.3) as usize;
        for _ in 0..hoods {
            let hw = u(r, 1.2, 1.8);
            fume_hood(s, r, &back, a, hw, h);
            a += hw + 0.02;
        }
        if end - a >= 0.8 {
            lab_bench(
                s,
                r,
                &back,
                (a + 0.03, end - a - 0.03),
                bd,
                top,
                (true, -1.0),
            );
        }
        // Peninsulas from the x = 0 wall, or in a wide room islands with
        // a bench along that wall.
        let free = w >= 7.0 && r.random::<f64>() < 0.5;
        let xa = if free {
            lab_bench(
                s,
                r,
                &left,
                (y0, d - HOOD_DEPTH - 0.05 - y0),
                bd,
                top,
                (true, -1.0),
            );
            bd + u(r, 1.2, 1.4)
        } else {
            0.0
        };
        let xb = w - bd - u(r, 1.2, 1.5);
        let ya = u(r, 1.6, 2.0);
        let yb = d - HOOD_DEPTH - 1.2;
        let id = u(r, 1.2, 1.6).min(yb - ya);
        let k = (((yb - ya + 1.2) / (id + 1.2)).floor() as usize).max(1);
        let gap = if k > 1 {
            (yb - ya - k as f64 * id) / (k as f64 - 1.0)
        } else {
            0.0
        };
        for i in 0..k {
            let y = ya + i as f64 * (id + gap);
            island(s, r, [xa, y], [xb - xa, id], false, top);
        }
    }
}

/// A lab bench run along `side` over `(a, len)` along it, `depth` out:
/// base cabinets under a top at `top`, instruments on it (none within
/// 0.5 m of `sink` along it), and where `above.0` wall cabinets or open
/// shelves of bottles over it in most.
fn lab_bench(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a, len): (f64, f64),
    depth: f64,
    top: f64,
    (above, sink): (bool, f64),
) {
    s.push(side.block(a, len, 0.0, depth - 0.03, 0.0, top - 0.04));
    s.push(side.block(a, len, 0.0, depth, top - 0.04, 0.04));
    let mut p = a + u(r, 0.05, 0.5);
    while p + 0.3 < a + len {
        let il = u(r, 0.25, 0.6).min(a + len - p);
        if r.random::<f64>() < 0.5 && (p + il < sink - 0.5 || p > sink + 0.5) {
            let o = u(r, 0.05, 0.15);
            let deep = u(r, 0.25, 0.45).min(depth - 0.05 - o);
            s.push(side.block(p, il, o, deep, top, u(r, 0.15, 0.55)));
        }
        p += il + u(r, 0.3, 1.0);
    }
    let roll = r.random::<f64>();
    if !above || roll >= 0.75 {
        return;
    }
    let z = u(r, 1.45, 1.55);
    if roll < 0.35 {
        s.push(side.block(a, len, 0.0, 0.35, z, u(r, 2.05, 2.2) - z));
    } else {
        for level in [z, z + u(r, 0.38, 0.45)] {
            s.push(side.block(a, len, 0.0, 0.28, level, 0.02));
            stock(s, r, side, a, len, (0.0, 0.28), level + 0.02, 0.3);
        }
    }
}

/// A sink in a bench along `side`, `a` along it: a swan-neck tap and its
/// spout over the basin (the basin itself, in the top, not modelled), in
/// most a drying rack of glassware on the wall above.
fn sink(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, a: f64, top: f64) {
    s.push(side.cylinder(a, 0.08, 0.02, top, top + 0.38));
    s.push(side.block(a - 0.02, 0.04, 0.08, 0.22, top + 0.33, 0.04));
    if r.random::<f64>() < 0.7 {
        s.push(side.block(a - 0.35, 0.7, 0.0, 0.03, top + 0.5, 0.7));
        s.push(side.block(a - 0.3, 0.6, 0.03, u(r, 0.08, 0.14), top + 0.55, 0.55));
    }
}

/// A fume hood `len` wide against `side` at `a` along it: a ventilated
/// cabinet under the work surface at 0.9 m, side posts, the baffle at
/// the back and the upper body over the sash to 2.3-2.5 m, the sash's
/// bottom rail where it is left (its glass left out), an exhaust duct up
/// to the ceiling `h`.
fn fume_hood(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, a: f64, len: f64, h: f64) {
    let top = u(r, 2.3, 2.5);
    let dp = HOOD_DEPTH;
    s.push(side.block(a, len, 0.0, dp - 0.05, 0.0, 0.86));
    s.push(side.block(a, len, 0.0, dp, 0.86, 0.04));
    for a0 in [a, a + len - 0.1] {
        s.push(side.block(a0, 0.1, 0.0, dp, 0.9, top - 0.9));
    }
    s.push(side.block(a + 0.1, len - 0.2, 0.0, 0.12, 0.9, top - 0.9));
    let upper = u(r, 1.8, 1.95);
    s.push(side.block(a + 0.1, len - 0.2, 0.0, dp, upper, top - upper));
    let sash = 0.9 + u(r, 0.25, 0.6);
    s.push(side.block(a + 0.1, len - 0.2, dp - 0.08, 0.05, sash, 0.05));
    // Apparatus in the hood.
    if r.random::<f64>() < 0.7 {
        let il = u(r, 0.2, 0.5).min(len - 0.4);
        let at = between(r, a + 0.15, a + len - 0.15 - il);
        s.push(side.block(at, il, 0.2, u(r, 0.2, 0.4), 0.9, u(r, 0.1, 0.5)));
    }
    s.push(side.cylinder(a + len / 2.0, 0.35, u(r, 0.1, 0.15), top, h));
}

/// A double-sided island bench over `[x0, x0 + sx] x [y0, y0 + sy]`,
/// long along y (`along_y`) or x: base cabinets under a top at `top`, a
/// service spine (sockets, gas and water taps) down its middle, in most
/// a reagent shelf of one or two levels on posts over the spine with
/// bottles on it, instruments on both faces, and up to two lab stools
/// at each face.
fn island(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    [x0, y0]: [f64; 2],
    [sx, sy]: [f64; 2],
    along_y: bool,
    top: f64,
) {
    s.push(cuboid([x0, y0, 0.0], [sx, sy, top - 0.04]));
    s.push(cuboid([x0, y0, top - 0.04], [sx, sy, 0.04]));
    let (len, wid) = if along_y { (sy, sx) } else { (sx, sy) };
    // A box `l0..l0 + ll` along the island and `c0..c0 + cw` across it
    // from its middle line, and a point.
    let part = |l0: f64, ll: f64, c0: f64, cw: f64, z: f64, hz: f64| {
        if along_y {
            cuboid([x0 + wid / 2.0 + c0, y0 + l0, z], [cw, ll, hz])
        } else {
            cuboid([x0 + l0, y0 + wid / 2.0 + c0, z], [ll, cw, hz])
        }
    };
    let point = |l: f64, c: f64| {
        if along_y {
            [x0 + wid / 2.0 + c, y0 + l]
        } else {
            [x0 + l, y0 + wid / 2.0 + c]
        }
    };
    let spine = u(r, 0.3, 0.5);
    s.push(part(0.05, len - 0.1, -0.06, 0.12, top, spine));
    if r.random::<f64>() < 0.7 {
        let z1 = u(r, 1.45, 1.6);
        let levels = if r.random::<bool>() {
            vec![z1, z1 + u(r, 0.38, 0.45)]
        } else {
            vec![z1]
        };
        let zt = levels[levels.len() - 1] + 0.02;
        let n = ((len - 0.2) / 1.5).ceil().max(1.0) as usize;
        for i in 0..=n {
            s.push(Shape::Cylinder {
                centre: point(0.1 + (len - 0.2) * i as f64 / n as f64, 0.0),
                radius: 0.025,
                z0: top + spine,
                z1: zt,
            });
        }
        for &z in &levels {
            s.push(part(0.05, len - 0.1, -0.15, 0.3, z, 0.02));
            let mut l = 0.1;
            while l < len - 0.2 {
                let run = u(r, 0.1, 0.4).min(len - 0.1 - l);
                if r.random::<f64>() < 0.7 {
                    let cw = u(r, 0.08, 0.26);
                    s.push(part(
                        l,
                        run,
                        u(r, -0.14, 0.14 - cw),
                        cw,
                        z + 0.02,
                        u(r, 0.1, 0.3),
                    ));
                }
                l += run + u(r, 0.05, 0.3);
            }
        }
    }
    let face = wid / 2.0 - 0.06;
    for sign in [-1.0, 1.0] {
        let mut l = u(r, 0.1, 0.6);
        while l + 0.3 < len {
            let il = u(r, 0.25, 0.6).min(len - 0.05 - l);
            if r.random::<f64>() < 0.45 {
                let cw = u(r, 0.25, 0.45).min(face - 0.1);
                let c0 = if sign < 0.0 {
                    -wid / 2.0 + 0.05
                } else {
                    wid / 2.0 - 0.05 - cw
                };
                s.push(part(l, il, c0, cw, top, u(r, 0.15, 0.55)));
            }
            l += il + u(r, 0.3, 1.0);
        }
        for _ in 0..r.random_range(0..=2) {
            let l = between(r, 0.4, len - 0.4);
            stool(s, point(l, sign * (wid / 2.0 + 0.25)), u(r, 0.6, 0.72));
        }
    }
}

/// A lab stool at `c`: a five-star base (a disc), a gas-lift column, a
/// foot ring and a round seat at `seat`.
fn stool(s: &mut Vec<Shape>, c: [f64; 2], seat: f64) {
    for (radius, z0, z1) in [
        (0.22, 0.03, 0.08),
        (0.03, 0.08, seat - 0.05),
        (0.2, 0.34, 0.36),
        (0.17, seat - 0.05, seat),
    ] {
        s.push(Shape::Cylinder {
            centre: c,
            radius,
            z0,
            z1,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::institute::tests::{gap, room, size, top_run};
    use crate::sim::office_floor::boxes;

    #[test]
    fn a_laboratory_has_benches_islands_with_aisles_fume_hoods_a_sink_and_tall_cabinets() {
        let mut r = crate::rng::rng(5);
        let (mut side_hoods, mut back_hoods, mut stools, mut shelves, mut showers) =
            (0, 0, 0, 0, 0);
        for _ in 0..300 {
            let ([w, d, h], s) = room("laboratory", &mut r);
            let b = boxes(&s);
            // Tops 0.04 m thick at 0.88-0.92 m: 4 m of them at least.
            let run = top_run(&b, 0.88..=0.92, 0.04);
            assert!(run >= 4.0, "{w:.2} x {d:.2}: {run} m of bench");
            // A fume hood's upper body: 0.9 m deep against a side wall or
            // the window wall, from 1.8-1.95 m to 2.3-2.5 m; an exhaust
            // duct from it to the ceiling.
            let upper = |b: &&([f64; 3], [f64; 3])| {
                (2.3..=2.5).contains(&b.1[2]) && (1.8..=1.95).contains(&b.0[2])
            };
            let on_side = b.iter().filter(upper).any(|b| {
                (size(b)[0] - 0.9).abs() < 1e-9
                    && (b.0[0].abs() < 1e-9 || (b.1[0] - w).abs() < 1e-9)
            });
            let on_back = b
                .iter()
                .filter(upper)
                .any(|b| (size(b)[1] - 0.9).abs() < 1e-9 && (b.1[1] - d).abs() < 1e-9);
            assert!(on_side || on_back, "{w:.2} x {d:.2}: no fume hood");
            side_hoods += on_side as usize;
            back_hoods += on_back as usize;
            let duct = s.iter().any(|s| {
                matches!(s, Shape::Cylinder { radius, z0, z1, .. }
                    if *radius >= 0.1 && (2.3..=2.5).contains(z0) && *z1 == h)
            });
            assert!(duct, "no exhaust duct");
            // A swan-neck tap, tall cabinets on the corridor wall.
            let tap = s.iter().any(|s| {
                matches!(s, Shape::Cylinder { radius, z0, z1, .. }
                    if *radius == 0.02 && (z1 - z0 - 0.38).abs() < 1e-9)
            });
            assert!(tap, "no sink");
            let cabinet = b.iter().any(|b| {
                b.0[2] == 0.0
                    && b.0[1].abs() < 1e-9
                    && (1.95..=2.1).contains(&b.1[2])
                    && (0.5..=0.6).contains(&size(b)[1])
            });
            assert!(cabinet, "no tall cabinet");
            // Islands: base cabinets 1.2-1.6 m deep, every other bench or
            // hood base 1.2 m away at least.
            let base = |b: &&([f64; 3], [f64; 3])| {
                b.0[2] == 0.0 && (0.8..=0.9).contains(&b.1[2]) && size(b)[0] * size(b)[1] >= 0.3
            };
            let bases: Vec<_> = b.iter().filter(base).collect();
            let islands: Vec<_> = bases
                .iter()
                .filter(|b| (1.2 - 1e-9..=1.6).contains(&size(b)[0].min(size(b)[1])))
                .collect();
            assert!(!islands.is_empty(), "{w:.2} x {d:.2}: no island");
            for i in &islands {
                for o in &bases {
                    if std::ptr::eq(**i, *o) {
                        continue;
                    }
                    let g = gap(
                        ([i.0[0], i.0[1]], [i.1[0], i.1[1]]),
                        ([o.0[0], o.0[1]], [o.1[0], o.1[1]]),
                    );
                    assert!(g >= 1.2 - 1e-9, "{w:.2} x {d:.2}: an aisle of {g}");
                }
            }
            stools += s
                .iter()
                .any(|s| matches!(s, Shape::Cylinder { radius, .. } if *radius == 0.17))
                as usize;
            shelves += s
                .iter()
                .any(|s| matches!(s, Shape::Cylinder { radius, .. } if *radius == 0.025))
                as usize;
            showers += s
                .iter()
                .any(|s| matches!(s, Shape::Cylinder { radius, z1, .. } if *radius == 0.15 && *z1 == 2.22))
                as usize;
        }
        assert!(
            side_hoods >= 120 && back_hoods >= 80,
            "{side_hoods} on a side wall, {back_hoods} on the window wall"
        );
        assert!(
            stools >= 200 && shelves >= 150 && showers >= 120,
            "{stools} {shelves} {showers}"
        );
    }
}
