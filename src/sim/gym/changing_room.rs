//! Changing rooms: banks of lockers, benches, a vanity with hair dryers
//! and a shower area behind a partition, in some with toilets.

use super::{between, walls, SWING};
use crate::sim::geometry::Shape;
use crate::sim::institute::Side;
use crate::sim::scenes::u;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// A changing room: at the back a shower area behind a tiled partition
/// 2.1-2.4 m high with an opening, cubicles (three rooms of five) or
/// open shower heads along the window wall, in two rooms of five the
/// cubicles at one end toilets; lockers along the x = 0 wall from the
/// door's swing to the partition's passage, along the x = w wall too or
/// a vanity counter with hair dryers there; benches before the lockers
/// (one down the middle where two would not leave an aisle), and in wide
/// rooms most often an island of back-to-back lockers down the middle
/// with a bench in each aisle; a bin by the corridor wall.
pub(super) fn changing_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, back, front] = walls(w, d);
    let y0 = SWING + u(r, 0.1, 0.4);
    let sd = showers(s, r, &back, w, h);
    let end = d - sd - u(r, 0.9, 1.2);
    let ld = u(r, 0.45, 0.55);
    let lh = u(r, 1.8, 2.0);
    lockers(s, r, &left, (y0, end), ld, lh);
    let right_lockers = r.random::<f64>() < 0.6;
    if right_lockers {
        lockers(s, r, &right, (y0, end), ld, lh);
    } else {
        vanity(s, r, &right, (y0, end));
    }
    let inner = (ld, w - if right_lockers { ld } else { 0.6 });
    let (bd, bh) = (u(r, 0.35, 0.4), u(r, 0.42, 0.46));
    let (ya, yb) = (y0 + u(r, 0.2, 0.5), end - u(r, 0.2, 0.5));
    let island = w >= 6.5 && r.random::<f64>() < 0.7;
    if island {
        let xc = (inner.0 + inner.1) / 2.0;
        let (ia, ib) = (y0 + u(r, 0.3, 0.6), end - u(r, 0.3, 0.6));
        for o in [xc - ld, xc] {
            lockers_out(s, r, &left, (ia, ib), (o, ld), lh);
        }
        for x in [(inner.0 + xc - ld) / 2.0, (xc + ld + inner.1) / 2.0] {
            bench(s, &left, (ya, yb), x - bd / 2.0, [bd, bh]);
        }
    } else if right_lockers && inner.1 - inner.0 >= 2.0 * (0.95 + bd) + 1.0 {
        for x in [inner.0 + u(r, 0.9, 1.0), inner.1 - u(r, 0.9, 1.0) - bd] {
            bench(s, &left, (ya, yb), x, [bd, bh]);
        }
    } else {
        let x = (inner.0 + inner.1) / 2.0 - bd / 2.0 + u(r, -0.2, 0.2);
        bench(s, &left, (ya, yb), x, [bd, bh]);
    }
    s.push(front.cylinder(
        w - u(r, 0.3, 0.5),
        0.25,
        u(r, 0.2, 0.25),
        0.0,
        u(r, 0.6, 0.8),
    ));
}

/// Banks of lockers along `side` from `a0` to `a1`, `depth` deep and
/// `tall` high, banks of three to five columns of 0.3-0.4 m, now and
/// then a gap between two banks.
fn lockers(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a0, a1): (f64, f64),
    depth: f64,
    tall: f64,
) {
    lockers_out(s, r, side, (a0, a1), (0.0, depth), tall);
}

/// As [`lockers`], from `o` out from the wall.
fn lockers_out(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a0, a1): (f64, f64),
    (o, depth): (f64, f64),
    tall: f64,
) {
    let col = u(r, 0.3, 0.4);
    let mut a = a0;
    while a + 3.0 * col <= a1 {
        let n = r.random_range(3..=5).min(((a1 - a) / col).floor() as usize);
        let len = n as f64 * col;
        s.push(side.block(a, len, o, depth, 0.0, tall));
        a += len
            + if r.random::<f64>() < 0.2 {
                u(r, 0.3, 0.8)
            } else {
                0.0
            };
    }
}

/// A bench along y over `(a0, a1)` (given along the x = 0 wall `side`)
/// from `x` across, `[bd, bh]` deep and high: a slatted top on two or
/// three legs.
fn bench(s: &mut Vec<Shape>, side: &Side, (a0, a1): (f64, f64), x: f64, [bd, bh]: [f64; 2]) {
    let len = a1 - a0;
    if len < 0.8 {
        return;
    }
    s.push(side.block(a0, len, x, bd, bh - 0.05, 0.05));
    let legs = if len > 2.5 { 3 } else { 2 };
    for i in 0..legs {
        let a = a0 + 0.1 + (len - 0.26) * i as f64 / (legs - 1) as f64;
        s.push(side.block(a, 0.06, x + 0.04, bd - 0.08, 0.0, bh - 0.05));
    }
}

/// A vanity counter at 0.82-0.88 m along `side`, 1.5-3.0 m long within
/// `(a0, a1)`, its basins set into it (not modelled) and an apron, two
/// to four hair dryers on the wall beside it.
fn vanity(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, (a0, a1): (f64, f64)) {
    let vl = u(r, 1.5, 3.0).min(a1 - a0 - 0.8).max(0.8);
    let a = a0 + between(r, 0.0, a1 - a0 - vl - 0.8);
    let top = u(r, 0.82, 0.88);
    s.push(side.block(a, vl, 0.0, 0.55, top - 0.05, 0.05));
    s.push(side.block(a, vl, 0.5, 0.05, top - 0.25, 0.2));
    let n = r.random_range(2..=4);
    for i in 0..n {
        let p = a + vl + 0.15 + i as f64 * 0.3;
        if p + 0.15 <= a1 {
            s.push(side.block(p, 0.12, 0.0, 0.1, u(r, 1.3, 1.45), 0.25));
        }
    }
}

/// The shower area along the back wall `side` of a room `w` wide: a
/// tiled partition 2.1-2.4 m high with an opening 1.0-1.2 m wide, and
/// behind it cubicles (partitions raised 0.15 m, a shower head each,
/// some at one end toilets with a pan and a cistern) or open shower
/// heads with their mixers. Returns how deep the area is, partition
/// included.
fn showers(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, w: f64, h: f64) -> f64 {
    let cd = u(r, 1.0, 1.2);
    let sd = cd + u(r, 0.7, 0.9) + 0.1;
    let ph = u(r, 2.1, 2.4).min(h - 0.5);
    let open = u(r, 1.0, 1.2);
    let at = between(r, 0.3, w - open - 0.3);
    s.push(side.block(0.0, at, sd - 0.1, 0.1, 0.0, ph));
    s.push(side.block(at + open, w - at - open, sd - 0.1, 0.1, 0.0, ph));
    let cw = u(r, 0.9, 1.0);
    let n = ((w - 0.1) / cw).floor() as usize;
    let head = u(r, 2.0, 2.1).min(ph - 0.1);
    if r.random::<f64>() < 0.6 {
        let wcs = if r.random::<f64>() < 0.4 {
            r.random_range(2..=3).min(n - 1)
        } else {
            0
        };
        for i in 0..n {
            let x = w - (i + 1) as f64 * cw;
            s.push(side.block(x, 0.03, 0.0, cd, 0.15, u(r, 1.8, 1.85)));
            let c = x + cw / 2.0;
            if i < wcs {
                s.push(side.block(c - 0.18, 0.36, 0.0, 0.62, 0.0, 0.42));
                s.push(side.block(c - 0.2, 0.4, 0.0, 0.16, 0.42, 0.4));
            } else {
                s.push(side.block(c - 0.08, 0.16, 0.0, 0.12, head, 0.05));
                s.push(side.block(c - 0.1, 0.2, 0.0, 0.08, 1.05, 0.15));
            }
        }
    } else {
        let k = ((w - 0.4) / u(r, 0.9, 1.1)).floor().max(1.0) as usize;
        for i in 0..k {
            let c = 0.2 + (w - 0.4) * (i as f64 + 0.5) / k as f64;
            s.push(side.block(c - 0.08, 0.16, 0.0, 0.12, head, 0.05));
            s.push(side.block(c - 0.1, 0.2, 0.0, 0.08, 1.05, 0.15));
        }
    }
    sd
}

#[cfg(test)]
mod tests {
    use crate::sim::gym::tests::{extents, room};

    #[test]
    fn a_changing_room_has_lockers_benches_and_showers_behind_a_partition() {
        let mut r = crate::rng::rng(8);
        let (mut islands, mut vanities, mut toilets, mut cubicles) = (0, 0, 0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("changing_room", &mut r);
            let e = extents(&s);
            let size =
                |e: &([f64; 2], [f64; 2], f64, f64)| [e.1[0] - e.0[0], e.1[1] - e.0[1], e.3 - e.2];
            // Banks of lockers: 0.45-0.55 m deep, 1.8-2.0 m high.
            let banks: Vec<_> = e
                .iter()
                .filter(|e| {
                    let [a, b, z] = size(e);
                    e.2 == 0.0
                        && (1.8..=2.0).contains(&z)
                        && (0.45..=0.55).contains(&a.min(b))
                        && a.max(b) >= 0.9
                })
                .collect();
            assert!(!banks.is_empty(), "{w:.2} x {d:.2}: no lockers");
            // Benches' tops at 0.42-0.46 m.
            let benches = e
                .iter()
                .filter(|e| (0.42..=0.46).contains(&e.3) && (size(e)[2] - 0.05).abs() < 1e-9)
                .count();
            assert!(benches >= 1, "{w:.2} x {d:.2}: no bench");
            // The partition: 0.1 m thick, 2.1-2.4 m high, along x.
            let partition = e
                .iter()
                .filter(|e| {
                    e.2 == 0.0
                        && (size(e)[1] - 0.1).abs() < 1e-9
                        && (2.1..=2.4).contains(&size(e)[2])
                })
                .count();
            assert_eq!(partition, 2, "{w:.2} x {d:.2}");
            // Shower heads: 0.05 m high at 2.0-2.1 m.
            let heads = e
                .iter()
                .filter(|e| (2.0..=2.1).contains(&e.2) && (size(e)[2] - 0.05).abs() < 1e-9)
                .count();
            assert!(heads >= 2, "{w:.2} x {d:.2}: {heads} shower heads");
            islands += banks.iter().any(|b| b.0[0] > 0.4 && b.1[0] < w - 0.4) as usize;
            vanities += e
                .iter()
                .any(|e| (0.77..=0.83).contains(&e.2) && (size(e)[2] - 0.05).abs() < 1e-9)
                as usize;
            toilets += e.iter().any(|e| e.2 == 0.0 && (e.3 - 0.42).abs() < 1e-9) as usize;
            cubicles += e
                .iter()
                .any(|e| (e.2 - 0.15).abs() < 1e-9 && size(e)[2] >= 1.8)
                as usize;
        }
        assert!(
            islands >= 40 && vanities >= 80 && toilets >= 40 && cubicles >= 130,
            "{islands} {vanities} {toilets} {cubicles}"
        );
    }
}
