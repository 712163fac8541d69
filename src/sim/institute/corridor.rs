//! The corridor's fittings: ceiling lights down its middle and what
//! stands along its walls.

use crate::sim::geometry::{cuboid, Shape};
use crate::sim::hotel::dining_chair;
use crate::sim::scenes::{u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::FRAC_PI_2;

/// The corridor's fittings, `length` by `width`, `h` high: linear
/// lights down its middle under the ceiling; along its walls notice
/// boards, fire extinguisher cabinets or extinguishers on brackets,
/// gas-cylinder cages (corner posts, a top frame and the cylinders; the
/// mesh left out), banks of lockers, a bench or two or three chairs, bins
/// and now and then a copier. Nothing stands more than 0.65 m out from a
/// wall.
pub(super) fn corridor_fittings(
    length: f64,
    width: f64,
    h: f64,
    r: &mut ChaCha8Rng,
    s: &mut Vec<Shape>,
) {
    let mut x = u(r, 0.8, 2.5);
    while x < length - 1.6 {
        let (ll, lw) = (u(r, 1.2, 1.5), u(r, 0.15, 0.3));
        s.push(cuboid(
            [x, width / 2.0 - lw / 2.0, h - 0.07],
            [ll, lw, 0.07],
        ));
        x += ll + u(r, 2.0, 3.5);
    }
    // Against a wall: `south` (y = 0) or the other, `depth` out.
    let at = |south: bool, depth: f64| if south { 0.0 } else { width - depth };
    let mut x = u(r, 0.3, 2.0);
    while x < length - 2.0 {
        let south = r.random::<bool>();
        let roll = r.random::<f64>();
        let used = if roll < 0.2 {
            let len = u(r, 0.9, 1.8);
            s.push(cuboid(
                [x, at(south, 0.03), u(r, 0.9, 1.1)],
                [len, 0.03, u(r, 0.8, 1.1)],
            ));
            len
        } else if roll < 0.32 {
            if r.random::<bool>() {
                let (len, z0) = (u(r, 0.5, 0.7), u(r, 0.6, 0.9));
                s.push(cuboid([x, at(south, 0.2), z0], [len, 0.2, u(r, 0.8, 1.0)]));
                len
            } else {
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
                0.2
            }
        } else if roll < 0.44 {
            let (len, dep, ch) = (u(r, 0.7, 1.2), u(r, 0.4, 0.5), u(r, 1.8, 2.0));
            let y = at(south, dep);
            for px in [x, x + len - 0.04] {
                for py in [y, y + dep - 0.04] {
                    s.push(cuboid([px, py, 0.0], [0.04, 0.04, ch]));
                }
            }
            s.push(cuboid([x, y, ch - 0.03], [len, dep, 0.03]));
            s.push(cuboid([x, y, 0.0], [len, dep, 0.05]));
            let n = (((len - 0.1) / 0.25).floor() as usize).min(4);
            for i in 0..n {
                if r.random::<f64>() < 0.85 {
                    let c = [x + 0.17 + i as f64 * 0.25, y + dep / 2.0];
                    let top = u(r, 1.4, 1.65);
                    s.push(Shape::Cylinder {
                        centre: c,
                        radius: u(r, 0.1, 0.115),
                        z0: 0.05,
                        z1: top,
                    });
                    s.push(Shape::Cylinder {
                        centre: c,
                        radius: 0.04,
                        z0: top,
                        z1: top + 0.12,
                    });
                }
            }
            len
        } else if roll < 0.58 {
            let len = u(r, 0.9, 3.0).min(length - 1.0 - x);
            let dep = u(r, 0.45, 0.5);
            s.push(cuboid(
                [x, at(south, dep), 0.0],
                [len, dep, u(r, 1.8, 1.95)],
            ));
            len
        } else if roll < 0.68 {
            if r.random::<f64>() < 0.4 {
                let len = u(r, 1.2, 1.8);
                let y = at(south, 0.42);
                s.push(cuboid([x, y, 0.42], [len, 0.42, 0.04]));
                for lx in [x + 0.05, x + len - 0.1] {
                    s.push(cuboid([lx, y + 0.05, 0.0], [0.05, 0.32, 0.42]));
                }
                len
            } else {
                let n = r.random_range(2..=3);
                let (cy, yaw) = if south {
                    (0.27, FRAC_PI_2)
                } else {
                    (width - 0.27, -FRAC_PI_2)
                };
                for i in 0..n {
                    dining_chair(s, r, &Frame::at(x + 0.3 + i as f64 * 0.55, cy, yaw));
                }
                n as f64 * 0.55 + 0.05
            }
        } else if roll < 0.74 {
            let n = r.random_range(2..=3);
            let mut bx = x;
            for _ in 0..n {
                let (bw, bd) = (u(r, 0.35, 0.4), u(r, 0.35, 0.4));
                s.push(cuboid([bx, at(south, bd), 0.0], [bw, bd, u(r, 0.6, 0.85)]));
                bx += bw + 0.02;
            }
            bx - x
        } else if roll < 0.78 {
            let (len, dep) = (u(r, 0.6, 0.7), u(r, 0.55, 0.65));
            s.push(cuboid(
                [x, at(south, dep), 0.0],
                [len, dep, u(r, 0.95, 1.15)],
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
    use crate::sim::hotel::extent;
    use crate::sim::institute::tests::size;
    use crate::sim::office_floor::boxes;

    #[test]
    fn the_corridor_has_lights_down_its_middle_and_fittings_along_its_walls() {
        let (mut cages, mut lockers, mut boards) = (0, 0, 0);
        for seed in 1..=12 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (24.0, 2.0, 3.0);
            let mut s = Vec::new();
            corridor_fittings(length, cw, h, &mut r, &mut s);
            let lights = boxes(&s).iter().filter(|b| b.1[2] == h).count();
            assert!(lights >= 4, "seed {seed}: {lights} lights");
            assert!(
                s.len() >= lights + 3,
                "seed {seed}: {} fittings",
                s.len() - lights
            );
            for shape in &s {
                let (lo, hi, z0, z1) = extent(shape);
                assert!(lo[0] >= 0.0 && hi[0] <= length, "{shape:?}");
                assert!(lo[1] >= -1e-9 && hi[1] <= cw + 1e-9, "{shape:?}");
                assert!(z0 >= 0.0 && z1 <= h + 1e-9, "{shape:?}");
                if z1 < h {
                    // Along a wall, the middle left free.
                    assert!(
                        hi[1] <= 0.65 + 1e-9 || lo[1] >= cw - 0.65 - 1e-9,
                        "seed {seed}: {shape:?} in the way"
                    );
                }
            }
            cages += s.iter().any(
                |s| matches!(s, Shape::Cylinder { radius, .. } if (0.1..=0.115).contains(radius)),
            ) as usize;
            lockers += boxes(&s)
                .iter()
                .any(|b| (1.8..=1.95).contains(&b.1[2]) && (0.45..=0.5).contains(&size(b)[1]))
                as usize;
            boards += boxes(&s)
                .iter()
                .any(|b| (size(b)[1] - 0.03).abs() < 1e-9 && b.0[2] >= 0.9)
                as usize;
        }
        assert!(
            cages >= 4 && lockers >= 4 && boards >= 4,
            "{cages} {lockers} {boards}"
        );
    }
}
