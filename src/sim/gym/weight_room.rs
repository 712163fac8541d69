//! Weights rooms: power racks with plate trees, a dumbbell rack with
//! benches, selectorised machines and in some a cable crossover.

use super::{between, walls, SWING};
use crate::sim::geometry::Shape;
use crate::sim::institute::Side;
use crate::sim::scenes::u;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// A weights room: selectorised machines side by side along the x = 0
/// wall from the door's swing on up to 0.9 m before what stands along
/// the window wall; power racks along the window wall and the dumbbell
/// rack with its benches along the x = w wall, or the other way round,
/// the window-wall run ending a metre before what stands along the
/// x = w wall. In the middle
/// where it is large enough a free-standing cable crossover (two in
/// five) or one or two more benches; a bin by the door.
pub(super) fn weight_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, back, front] = walls(w, d);
    let y0 = SWING + u(r, 0.2, 0.5);
    let dumbbells_back = r.random::<bool>();
    let (rw, rd) = (u(r, 1.2, 1.4), u(r, 1.2, 1.5));
    let platform = r.random::<f64>() < 0.35;
    let rack_reach = 0.08 + rd + if platform { 0.9 } else { 0.0 };
    let (dd, bl) = (u(r, 0.6, 0.75), u(r, 1.2, 1.35));
    let bench_at = dd + u(r, 0.8, 1.0);
    let dumbbell_reach = bench_at + bl;
    let (back_reach, right_reach) = if dumbbells_back {
        (dumbbell_reach, rack_reach)
    } else {
        (rack_reach, dumbbell_reach)
    };
    let ml = machines(s, r, &left, (y0, d - back_reach - 0.9), h);
    let run = (0.1, w - right_reach - 1.0);
    if dumbbells_back {
        dumbbell_station(s, r, &back, run, [dd, bench_at, bl]);
        power_racks(s, r, &right, (y0, d - 0.1), [rw, rd], platform);
    } else {
        power_racks(s, r, &back, run, [rw, rd], platform);
        dumbbell_station(s, r, &right, (y0, d - 0.1), [dd, bench_at, bl]);
    }
    // The middle.
    let (x0, x1) = (ml + 1.0, run.1);
    let (ya, yb) = (y0 + 0.3, d - back_reach - 1.0);
    let roll = r.random::<f64>();
    if roll < 0.4 && yb - ya >= 3.8 && x1 - x0 >= 1.2 {
        let len = u(r, 3.0, 3.6).min(yb - ya - 0.2);
        let a = between(r, ya, yb - len);
        let xc = (x0 + x1) / 2.0;
        crossover(s, r, &left, (a, len), xc);
    } else if roll < 0.7 && x1 - x0 >= 1.0 && yb - ya >= 1.6 {
        for i in 0..r.random_range(1..=2) {
            let xc = x0 + (x1 - x0) * (i as f64 + 1.0) / 3.0;
            let yc = between(r, ya + 0.7, yb - 0.7);
            bench(s, r, &front, xc, yc - bl / 2.0, bl);
        }
    }
    s.push(front.block(w - 0.5, 0.38, 0.0, 0.38, 0.0, u(r, 0.6, 0.8)));
}

/// Selectorised machines along `side` from `a0` to `a1`, backs to the
/// wall, 0.6-0.9 m apart: seated presses, pulldowns and leg presses.
/// Returns how far out the deepest reaches.
fn machines(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a0, a1): (f64, f64),
    h: f64,
) -> f64 {
    let mut a = a0 + u(r, 0.0, 0.2);
    let (mut reach, mut tries): (f64, usize) = (0.0, 0);
    loop {
        let kind = r.random_range(0..3);
        let (mw, md) = match kind {
            0 => (u(r, 1.0, 1.4), u(r, 1.2, 1.5)),
            1 => (u(r, 1.2, 1.5), u(r, 1.3, 1.7)),
            _ => (u(r, 1.0, 1.3), u(r, 1.9, 2.2)),
        };
        if a + mw > a1 {
            // Another model may fit what is left.
            tries += 1;
            if tries > 3 {
                break;
            }
            continue;
        }
        machine(s, r, side, (a, mw), md, kind, h);
        reach = reach.max(md);
        a += mw + u(r, 0.6, 0.9);
    }
    reach
}

/// A selectorised machine `mw` wide along `side` at `a`, `md` deep: a
/// weight-stack tower against the wall, a base frame, and a seated press
/// (back pad, seat, press arms), a pulldown (a tall tower, a beam out
/// over the seat, a bar, knee pads) or a leg press (a sled, a reclined
/// seat and back, a foot plate).
fn machine(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a, mw): (f64, f64),
    md: f64,
    kind: usize,
    h: f64,
) {
    let c = a + mw / 2.0;
    let tower = if kind == 1 {
        u(r, 2.1, 2.3)
    } else {
        u(r, 1.8, 2.1)
    }
    .min(h - 0.5);
    s.push(side.block(c - 0.3, 0.6, 0.05, 0.35, 0.0, tower));
    s.push(side.block(a + 0.05, mw - 0.1, 0.05, md - 0.1, 0.0, 0.08));
    match kind {
        0 => {
            s.push(side.block(c - 0.22, 0.44, 0.45, 0.1, 0.55, 0.7));
            s.push(side.block(c - 0.2, 0.4, 0.55, 0.4, 0.42, 0.1));
            for x in [a + 0.1, a + mw - 0.16] {
                s.push(side.block(x, 0.06, 0.5, md - 0.6, u(r, 1.0, 1.2), 0.06));
            }
        }
        1 => {
            s.push(side.block(c - 0.05, 0.1, 0.05, md - 0.3, tower - 0.1, 0.1));
            s.push(side.block(c - 0.2, 0.4, md - 0.75, 0.4, 0.45, 0.1));
            s.push(side.block(c - 0.2, 0.4, md - 0.45, 0.15, 0.62, 0.12));
            s.push(side.block(a + 0.05, mw - 0.1, md - 0.8, 0.04, u(r, 1.6, 1.9), 0.04));
        }
        _ => {
            s.push(side.block(c - 0.35, 0.7, 0.4, md - 0.45, 0.08, 0.3));
            s.push(side.block(c - 0.25, 0.5, md - 0.95, 0.5, 0.38, 0.12));
            s.push(side.block(c - 0.25, 0.5, md - 0.3, 0.12, 0.5, 0.6));
            s.push(side.block(c - 0.35, 0.7, 0.45, 0.08, 0.4, 0.6));
        }
    }
}

/// Power racks along `side` from `a0` to `a1`, `[rw, rd]` each, 0.08 m
/// off the wall, a plate tree between two racks or the racks 1.1-1.4 m
/// apart, on lifting platforms where `platform`; at least one rack.
fn power_racks(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a0, a1): (f64, f64),
    [rw, rd]: [f64; 2],
    platform: bool,
) {
    let mut a = a0 + between(r, 0.4, 0.6);
    let mut first = true;
    while first || a + rw + 0.4 <= a1 {
        power_rack(s, r, side, a, [rw, rd], platform);
        first = false;
        let tree = r.random::<f64>() < 0.5;
        let gap = if tree { u(r, 1.8, 2.1) } else { u(r, 1.1, 1.4) };
        if tree && a + rw + gap + rw + 0.4 <= a1 {
            plate_tree(s, r, side, a + rw + gap / 2.0);
        }
        a += rw + gap;
    }
}

/// A power rack at `a` along `side`: four uprights 2.2-2.4 m high, a top
/// frame with a pull-up bar at the front, floor rails, safety arms, in
/// most a barbell on its hooks (in some loaded with plates), on a
/// lifting platform reaching 0.9 m before it where `platform`.
fn power_rack(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    a: f64,
    [rw, rd]: [f64; 2],
    platform: bool,
) {
    let (o0, p) = (0.08, 0.075);
    let top = u(r, 2.2, 2.4);
    if platform {
        s.push(side.block(a - 0.3, rw + 0.6, o0, rd + 0.9, 0.0, 0.05));
    }
    for x in [a, a + rw - p] {
        for o in [o0, o0 + rd - p] {
            s.push(side.block(x, p, o, p, 0.0, top));
        }
        s.push(side.block(x, p, o0, rd, 0.0, 0.05));
        s.push(side.block(x, p, o0, rd, top - p, p));
        s.push(side.block(x, 0.05, o0, rd, u(r, 0.6, 1.0), 0.05));
    }
    for o in [o0, o0 + rd - p] {
        s.push(side.block(a, rw, o, p, top - p, p));
    }
    if r.random::<f64>() < 0.7 {
        let bz = u(r, 1.2, 1.5);
        let ob = o0 + rd - 0.2;
        let c = a + rw / 2.0;
        s.push(side.block(c - 1.1, 2.2, ob, 0.03, bz, 0.03));
        if r.random::<f64>() < 0.4 {
            let t = u(r, 0.05, 0.15);
            for x in [c - 0.95, c + 0.95 - t] {
                s.push(side.block(x, t, ob - 0.21, 0.45, bz - 0.21, 0.45));
            }
        }
    }
}

/// A plate tree at `a` along `side`, 0.4 m out: a base, a post and
/// plates hung on its horns on both sides.
fn plate_tree(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, a: f64) {
    let o = 0.4;
    s.push(side.block(a - 0.25, 0.5, o - 0.25, 0.5, 0.0, 0.05));
    s.push(side.cylinder(a, o, 0.03, 0.05, u(r, 1.2, 1.4)));
    for hz in [0.35, 0.7, 1.05] {
        for sign in [-1.0, 1.0] {
            if r.random::<f64>() < 0.7 {
                let t = u(r, 0.04, 0.18);
                let x = if sign < 0.0 { a - 0.03 - t } else { a + 0.03 };
                let size = u(r, 0.3, 0.45);
                s.push(side.block(
                    x,
                    t,
                    o - size / 2.0,
                    size,
                    (hz - size / 2.0).max(0.06),
                    size,
                ));
            }
        }
    }
}

/// A dumbbell rack along `side` over `(a0, a1)` (`[dd, at, bl]`: its
/// depth, where the benches before it start and their length): two
/// tiers of dumbbells growing along it, 2.0-3.6 m long, centred in the
/// run, and one to three benches before it.
fn dumbbell_station(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a0, a1): (f64, f64),
    [dd, at, bl]: [f64; 3],
) {
    let dl = u(r, 2.0, 3.6).min(a1 - a0 - 0.2).max(1.2);
    let a = a0 + between(r, 0.1, a1 - a0 - dl - 0.1);
    for e in [a, a + dl - 0.05] {
        s.push(side.block(e, 0.05, 0.0, dd, 0.0, 0.85));
    }
    for (o, z) in [(0.05, 0.75), (dd / 2.0, 0.35)] {
        s.push(side.block(a, dl, o, dd / 2.0 - 0.05, z, 0.04));
        let mut p = a + 0.07;
        let mut k: f64 = 0.0;
        while p + 0.2 < a + dl - 0.05 {
            let pl = (0.2 + k * 0.01).min(0.34);
            if r.random::<f64>() < 0.9 {
                s.push(side.block(
                    p,
                    pl,
                    o + 0.02,
                    dd / 2.0 - 0.09,
                    z + 0.04,
                    (0.1 + k * 0.008).min(0.24),
                ));
            }
            p += pl + 0.04;
            k += 1.0;
        }
    }
    let n = ((dl / 1.1).floor() as usize).clamp(1, 3);
    for i in 0..n {
        let c = a + dl * (i as f64 + 0.5) / n as f64;
        bench(s, r, side, c, at, bl);
    }
}

/// A bench `bl` long across `side` at `c` along it, from `o0` out: a
/// pad 0.3 m wide with its top at 0.43-0.47 m on two legs, in half the
/// benches the back raised upright at its wall end.
fn bench(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, c: f64, o0: f64, bl: f64) {
    let top = u(r, 0.43, 0.47);
    for o in [o0 + 0.05, o0 + bl - 0.13] {
        s.push(side.block(c - 0.25, 0.5, o, 0.08, 0.0, top - 0.07));
    }
    if r.random::<bool>() {
        s.push(side.block(c - 0.15, 0.3, o0, bl, top - 0.07, 0.07));
    } else {
        s.push(side.block(c - 0.15, 0.3, o0 + bl - 0.5, 0.5, top - 0.07, 0.07));
        s.push(side.block(c - 0.15, 0.3, o0 + 0.1, 0.12, top - 0.07, 0.7));
    }
}

/// A cable crossover standing free, along y over `(a, len)` at `xc`
/// across (given along the x = 0 wall `side`): two towers 2.2-2.4 m
/// high joined by a top beam and a floor rail, the handles hanging.
fn crossover(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, (a, len): (f64, f64), xc: f64) {
    let top = u(r, 2.2, 2.4);
    let o = xc - 0.25;
    for t in [a, a + len - 0.5] {
        s.push(side.block(t, 0.5, o, 0.5, 0.0, top));
        s.push(side.block(t + 0.2, 0.1, o + 0.2, 0.1, u(r, 1.0, 1.6), 0.15));
    }
    s.push(side.block(a, len, o + 0.2, 0.1, top - 0.1, 0.1));
    s.push(side.block(a, len, o + 0.2, 0.1, 0.0, 0.06));
}

#[cfg(test)]
mod tests {
    use crate::sim::gym::tests::{extents, room};

    #[test]
    fn a_weights_room_has_power_racks_a_dumbbell_rack_benches_and_machines() {
        let mut r = crate::rng::rng(7);
        let (mut barbells, mut crossovers, mut platforms) = (0, 0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("weight_room", &mut r);
            let e = extents(&s);
            let size =
                |e: &([f64; 2], [f64; 2], f64, f64)| [e.1[0] - e.0[0], e.1[1] - e.0[1], e.3 - e.2];
            // Uprights: 0.075 m square, 2.2-2.4 m high; four a rack.
            let uprights = e
                .iter()
                .filter(|e| {
                    let [a, b, z] = size(e);
                    e.2 == 0.0
                        && (a - 0.075).abs() < 1e-9
                        && (b - 0.075).abs() < 1e-9
                        && (2.2..=2.4).contains(&z)
                })
                .count();
            assert!(
                uprights >= 4 && uprights % 4 == 0,
                "{w:.2} x {d:.2}: {uprights} uprights"
            );
            // Bench pads: 0.3 m wide, 0.07 m thick, tops at 0.43-0.47 m.
            let benches = e
                .iter()
                .filter(|e| (0.43..=0.47).contains(&e.3) && (size(e)[2] - 0.07).abs() < 1e-9)
                .count();
            assert!(benches >= 1, "{w:.2} x {d:.2}: no bench");
            // Dumbbell tiers at 0.35 and 0.75 m.
            let tiers = e
                .iter()
                .filter(|e| (e.2 == 0.35 || e.2 == 0.75) && (size(e)[2] - 0.04).abs() < 1e-9)
                .count();
            assert_eq!(tiers, 2, "{w:.2} x {d:.2}");
            // Weight-stack towers: 0.6 x 0.35 m, 1.8-2.3 m high.
            let towers = e
                .iter()
                .filter(|e| {
                    let [a, b, z] = size(e);
                    e.2 == 0.0
                        && (a.max(b) - 0.6).abs() < 1e-9
                        && (b.min(a) - 0.35).abs() < 1e-9
                        && z >= 1.8
                })
                .count();
            assert!(towers >= 1, "{w:.2} x {d:.2}: {towers} machines");
            barbells += e
                .iter()
                .any(|e| (size(e)[0].max(size(e)[1]) - 2.2).abs() < 1e-9)
                as usize;
            crossovers += e.iter().any(|e| {
                let [a, b, z] = size(e);
                e.2 == 0.0 && (a - 0.5).abs() < 1e-9 && (b - 0.5).abs() < 1e-9 && z >= 2.2
            }) as usize;
            platforms += e
                .iter()
                .any(|e| e.2 == 0.0 && e.3 == 0.05 && size(e)[0] * size(e)[1] >= 2.5)
                as usize;
        }
        assert!(
            barbells >= 150 && crossovers >= 25 && platforms >= 60,
            "{barbells} {crossovers} {platforms}"
        );
    }
}
