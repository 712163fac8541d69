//! The corridor's fittings: ceiling lights down its middle and what
//! stands along its walls.

use crate::sim::geometry::{cuboid, Shape};
use crate::sim::scenes::u;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// The corridor's fittings, `length` by `width`, `h` high: square light
/// panels down its middle under the ceiling; along its walls notice
/// boards and timetable screens, fire extinguishers on brackets,
/// drinking fountains on the wall or floor-standing water coolers,
/// benches, now and then a vending machine, bins, a first-aid or
/// defibrillator cabinet. Nothing stands more than 0.85 m out from a
/// wall (a vending machine; everything else 0.5 m).
pub(super) fn corridor_fittings(
    length: f64,
    width: f64,
    h: f64,
    r: &mut ChaCha8Rng,
    s: &mut Vec<Shape>,
) {
    let mut x = u(r, 0.5, 2.0);
    let panel = u(r, 0.6, 0.62);
    while x < length - 1.0 {
        s.push(cuboid(
            [x, width / 2.0 - panel / 2.0, h - 0.04],
            [panel, panel, 0.04],
        ));
        x += panel + u(r, 1.8, 3.0);
    }
    // Against a wall: `south` (y = 0) or the other, `depth` out.
    let at = |south: bool, depth: f64| if south { 0.0 } else { width - depth };
    let mut x = u(r, 0.3, 2.0);
    while x < length - 2.0 {
        let south = r.random::<bool>();
        let roll = r.random::<f64>();
        let used = if roll < 0.2 {
            // A notice board, or a timetable screen.
            let (len, dep, z0, tall) = if r.random::<f64>() < 0.7 {
                (u(r, 0.9, 1.8), 0.03, u(r, 0.9, 1.1), u(r, 0.8, 1.1))
            } else {
                (u(r, 0.9, 1.25), 0.08, u(r, 1.5, 1.7), u(r, 0.55, 0.72))
            };
            s.push(cuboid([x, at(south, dep), z0], [len, dep, tall]));
            len
        } else if roll < 0.3 {
            // A fire extinguisher on its bracket, a sign above it.
            let z0 = u(r, 0.2, 0.5);
            s.push(cuboid(
                [x + 0.05, at(south, 0.05), z0 + 0.3],
                [0.1, 0.05, 0.08],
            ));
            s.push(Shape::Cylinder {
                centre: [x + 0.1, at(south, 0.16) + 0.08],
                radius: 0.08,
                z0,
                z1: z0 + 0.6,
            });
            s.push(cuboid([x, at(south, 0.01), 1.6], [0.2, 0.01, 0.2]));
            0.2
        } else if roll < 0.42 {
            if r.random::<bool>() {
                // A drinking fountain on the wall, a bottle filler above.
                let (len, dep) = (u(r, 0.45, 0.6), u(r, 0.3, 0.45));
                s.push(cuboid([x, at(south, dep), 0.75], [len, dep, 0.3]));
                s.push(cuboid(
                    [x + 0.05, at(south, 0.12), 1.05],
                    [len - 0.1, 0.12, 0.4],
                ));
                len
            } else {
                // A water cooler and its cup holder.
                let (c, dep) = (u(r, 0.3, 0.35), u(r, 0.3, 0.38));
                s.push(cuboid([x, at(south, dep), 0.0], [c, dep, u(r, 0.95, 1.05)]));
                s.push(Shape::Cylinder {
                    centre: [x + c / 2.0, at(south, dep) + dep / 2.0],
                    radius: 0.13,
                    z0: 1.05,
                    z1: 1.05 + u(r, 0.35, 0.5),
                });
                c
            }
        } else if roll < 0.58 {
            // A bench on two legs, or a row of two to four seats on a beam.
            let len = u(r, 1.2, 2.0);
            let dep = u(r, 0.38, 0.45);
            let y = at(south, dep);
            s.push(cuboid([x, y, u(r, 0.42, 0.46)], [len, dep, 0.05]));
            for lx in [x + 0.1, x + len - 0.16] {
                s.push(cuboid([lx, y + 0.05, 0.0], [0.06, dep - 0.1, 0.42]));
            }
            if r.random::<bool>() {
                s.push(cuboid([x, at(south, 0.06), 0.5], [len, 0.06, 0.4]));
            }
            len
        } else if roll < 0.64 {
            // A vending machine.
            let (len, dep) = (u(r, 0.8, 1.0), u(r, 0.75, 0.85));
            s.push(cuboid(
                [x, at(south, dep), 0.0],
                [len, dep, u(r, 1.8, 1.95)],
            ));
            len
        } else if roll < 0.74 {
            // Bins: general waste and recycling.
            let n = r.random_range(1..=3);
            let mut bx = x;
            for _ in 0..n {
                let (bw, bd) = (u(r, 0.3, 0.4), u(r, 0.3, 0.4));
                s.push(cuboid([bx, at(south, bd), 0.0], [bw, bd, u(r, 0.6, 0.9)]));
                bx += bw + 0.03;
            }
            bx - x
        } else if roll < 0.8 {
            // A first-aid or defibrillator cabinet.
            let len = u(r, 0.35, 0.45);
            s.push(cuboid(
                [x, at(south, 0.16), u(r, 1.0, 1.2)],
                [len, 0.16, u(r, 0.4, 0.5)],
            ));
            len
        } else {
            0.0
        };
        x += used + u(r, 1.2, 3.5);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::gym::tests::extents;

    #[test]
    fn the_corridor_has_lights_down_its_middle_and_fittings_along_its_walls() {
        let (mut benches, mut water, mut boards) = (0, 0, 0);
        for seed in 1..=12 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (30.0, 2.0, 3.2);
            let mut s = Vec::new();
            corridor_fittings(length, cw, h, &mut r, &mut s);
            let e = extents(&s);
            let lights = e.iter().filter(|e| e.3 == h).count();
            assert!(lights >= 8, "seed {seed}: {lights} lights");
            assert!(
                s.len() >= lights + 4,
                "seed {seed}: {} fittings",
                s.len() - lights
            );
            for (lo, hi, z0, z1) in &e {
                assert!(lo[0] >= 0.0 && hi[0] <= length, "{lo:?} {hi:?}");
                assert!(lo[1] >= -1e-9 && hi[1] <= cw + 1e-9, "{lo:?} {hi:?}");
                assert!(*z0 >= 0.0 && *z1 <= h + 1e-9);
                if *z1 < h {
                    // Along a wall, the middle left free.
                    assert!(
                        hi[1] <= 0.85 + 1e-9 || lo[1] >= cw - 0.85 - 1e-9,
                        "seed {seed}: {lo:?} {hi:?} in the way"
                    );
                }
            }
            benches += e
                .iter()
                .any(|e| (0.47..=0.51).contains(&e.3) && e.1[0] - e.0[0] >= 1.2)
                as usize;
            water += e.iter().any(|e| e.2 == 0.75 || e.2 == 1.05) as usize;
            boards += e
                .iter()
                .any(|e| e.1[1] - e.0[1] < 0.031 && e.2 >= 0.9 && e.2 < 1.2)
                as usize;
        }
        assert!(
            benches >= 4 && water >= 4 && boards >= 4,
            "{benches} {water} {boards}"
        );
    }
}
