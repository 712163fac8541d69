//! Group-exercise studios: an open floor facing a front wall, an
//! instructor's platform, sound, storage of steps, mats and balls, a
//! barre; or a cycling studio of spin bikes in rows.

use super::{walls, SWING};
use crate::sim::geometry::Shape;
use crate::sim::institute::Side;
use crate::sim::scenes::{u, Frame};
use rand::seq::SliceRandom;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// A studio facing the x = 0 wall (three of five) or the window wall:
/// speakers high on the front wall, a sound cabinet in its corner away
/// from the corridor (the x = 0 end of the window wall), in most an
/// instructor's platform in its middle. One in four is a cycling studio
/// of spin bikes in staggered rows facing the instructor's bike on the
/// platform, with pedestal fans; the others keep their floor open, store
/// steps, mats, balls and weights along the x = w wall from the door's
/// swing on and in half a barre along the remaining wall.
pub(super) fn studio(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, back, _] = walls(w, d);
    let y0 = SWING + u(r, 0.2, 0.5);
    let on_left = r.random::<f64>() < 0.6;
    // The front wall, its usable stretch along it, and how deep the
    // room is from it.
    let (fw, (a0, a1), deep) = if on_left {
        (&left, (y0, d), w)
    } else {
        (&back, (0.0, w), d - y0)
    };
    let cycling = r.random::<f64>() < 0.25;
    for a in [a0 + 0.3, a1 - 0.6] {
        let zs = u(r, 2.1, (h - 0.75).min(2.5));
        s.push(fw.block(a, 0.3, 0.0, 0.25, zs, 0.45));
    }
    // The sound cabinet at the window end of the x = 0 wall or the
    // x = 0 end of the window wall.
    let cab = u(r, 0.5, 0.6);
    let cab_at = if on_left { a1 - 0.1 - cab } else { 0.1 };
    s.push(fw.block(cab_at, cab, 0.0, 0.5, 0.0, u(r, 1.0, 1.2)));
    let mid = (a0 + a1) / 2.0;
    let (pl, pd, ph) = (
        u(r, 1.8, 2.4).min(a1 - a0 - 2.0 * (cab + 0.3)),
        u(r, 1.2, 1.6),
        u(r, 0.2, 0.3),
    );
    let platform = cycling || r.random::<f64>() < 0.6;
    if platform {
        s.push(fw.block(mid - pl / 2.0, pl, 0.0, pd, 0.0, ph));
    }
    // Facing the front wall.
    let yaw = if on_left { PI } else { FRAC_PI_2 };
    let to_room = |o: f64, a: f64| fw.point(a, o);
    if cycling {
        let [x, y] = to_room(pd / 2.0, mid);
        spin_bike(s, r, &Frame::at(x, y, yaw + PI), ph);
        let (pitch, row) = (u(r, 1.0, 1.2), u(r, 1.4, 1.7));
        let (l0, l1) = (a0 + 0.5, a1 - 0.5);
        let mut o = pd + u(r, 0.9, 1.3) + 0.6;
        let mut k = 0;
        while o + 0.6 < deep - 0.5 {
            let shift = if k % 2 == 1 { pitch / 2.0 } else { 0.0 };
            let mut a = l0 + 0.3 + shift;
            while a + 0.3 <= l1 {
                let [x, y] = to_room(o, a);
                spin_bike(s, r, &Frame::at(x, y, yaw), 0.0);
                a += pitch;
            }
            o += row;
            k += 1;
        }
        for a in [a0 + 0.4, a1 - 1.0] {
            if r.random::<f64>() < 0.7 {
                let [x, y] = to_room(pd + 0.4, a + 0.3);
                pedestal_fan(s, r, [x, y]);
            }
        }
        return;
    }
    // Storage along the x = w wall, clear of the platform's corner.
    let end = if on_left { d - 0.1 } else { d - 0.6 };
    storage(s, r, &right, (y0, end), h);
    if r.random::<bool>() {
        let (side, from, to) = if on_left {
            (&back, 0.3, w - 1.2)
        } else {
            (&left, y0, d - 0.7)
        };
        barre(s, r, side, (from, to));
    }
}

/// Storage along `side` from `a0` to `a1`: stacks of steps, a basket of
/// rolled mats, exercise balls, a pump-set rack, a rack of small
/// dumbbells and mats hung on the wall, in a random order, each in most
/// studios, as far as the wall holds them.
fn storage(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, (a0, a1): (f64, f64), h: f64) {
    let mut items = [0, 1, 2, 3, 4, 5];
    items.shuffle(r);
    let mut a = a0 + u(r, 0.0, 0.4);
    for item in items {
        if r.random::<f64>() < 0.25 {
            continue;
        }
        let used = match item {
            0 => {
                // Steps stacked on the floor, two to four stacks.
                let n = r.random_range(2..=4);
                let (sl, sd) = (u(r, 0.85, 1.05), u(r, 0.35, 0.4));
                if a + n as f64 * (sd + 0.05) > a1 {
                    continue;
                }
                for i in 0..n {
                    let at = a + i as f64 * (sd + 0.05);
                    let stack = r.random_range(3..=10) as f64 * u(r, 0.1, 0.12);
                    s.push(side.block(at, sd, 0.02, sl, 0.0, stack));
                }
                n as f64 * (sd + 0.05)
            }
            1 => {
                // Rolled mats standing in a basket.
                let (bl, bd) = (u(r, 0.5, 0.7), u(r, 0.4, 0.5));
                if a + bl > a1 {
                    continue;
                }
                s.push(side.block(a, bl, 0.02, bd, 0.0, 0.35));
                for _ in 0..r.random_range(4..=12) {
                    let c = [u(r, a + 0.08, a + bl - 0.08), u(r, 0.1, bd - 0.06)];
                    s.push(side.cylinder(c[0], c[1], u(r, 0.06, 0.08), 0.02, u(r, 0.6, 0.68)));
                }
                bl
            }
            2 => {
                // Exercise balls against the wall.
                let n = r.random_range(2..=6);
                let rad = u(r, 0.27, 0.33);
                if a + n as f64 * 2.0 * rad > a1 {
                    continue;
                }
                for i in 0..n {
                    let c = side.point(a + rad + i as f64 * 2.0 * rad, rad + 0.02);
                    s.push(Shape::Sphere {
                        centre: [c[0], c[1], rad],
                        radius: rad,
                    });
                }
                n as f64 * 2.0 * rad
            }
            3 | 4 => {
                // A rack of pump sets (bars above, plates below) or of
                // small dumbbells: end frames, two or three shelves.
                let (rl, rd) = (u(r, 1.0, 1.4), u(r, 0.4, 0.5));
                if a + rl > a1 {
                    continue;
                }
                let levels = [0.05, 0.45, 0.85];
                for e in [a, a + rl - 0.04] {
                    s.push(side.block(e, 0.04, 0.02, rd, 0.0, 1.05));
                }
                for z in levels {
                    s.push(side.block(a, rl, 0.02, rd, z, 0.02));
                    let mut p = a + 0.06;
                    while p + 0.15 < a + rl - 0.04 {
                        let (pl, ph) = if item == 3 {
                            (u(r, 0.05, 0.15), u(r, 0.2, 0.3))
                        } else {
                            (u(r, 0.18, 0.25), u(r, 0.08, 0.12))
                        };
                        if r.random::<f64>() < 0.8 {
                            s.push(side.block(p, pl, 0.05, rd - 0.06, z + 0.02, ph));
                        }
                        p += pl + u(r, 0.03, 0.1);
                    }
                }
                rl
            }
            _ => {
                // Mats hung on the wall.
                let n = r.random_range(3..=8);
                let len = n as f64 * 0.62;
                if a + len > a1 {
                    continue;
                }
                let z0 = u(r, 0.2, 0.4);
                s.push(side.block(
                    a,
                    len,
                    0.0,
                    u(r, 0.05, 0.12),
                    z0,
                    u(r, 1.2, 1.7).min(h - 1.0),
                ));
                len
            }
        };
        a += used + u(r, 0.2, 0.6);
    }
}

/// A barre along `side` from `a0` to `a1`: a rail at 0.95-1.05 m, in
/// half a second at 0.75-0.85 m, 0.15-0.2 m out from the wall on
/// brackets every 1.5 m or less.
fn barre(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, side: &Side, (a0, a1): (f64, f64)) {
    let len = a1 - a0;
    if len < 1.5 {
        return;
    }
    let o = u(r, 0.15, 0.2);
    let top = u(r, 0.95, 1.05);
    let low = r.random::<bool>().then(|| u(r, 0.75, 0.85));
    s.push(side.block(a0, len, o, 0.04, top, 0.04));
    if let Some(z) = low {
        s.push(side.block(a0, len, o, 0.04, z, 0.04));
    }
    let n = (len / 1.5).ceil() as usize;
    for i in 0..=n {
        let a = a0 + (len - 0.04) * i as f64 / n as f64;
        let z = low.unwrap_or(top);
        s.push(side.block(a, 0.04, 0.0, o + 0.04, z, top + 0.04 - z));
    }
}

/// A spin bike centred on `f`, the rider facing local +x, standing at
/// `z` (the instructor's on the platform): feet, a frame, a flywheel
/// under a guard, a seat post and saddle at 0.95-1.1 m, a handlebar at
/// 1.0-1.15 m.
pub(super) fn spin_bike(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame, z: f64) {
    let len = u(r, 1.1, 1.25);
    let (fr, bk) = (len / 2.0, -len / 2.0);
    let seat = u(r, 0.95, 1.1);
    let bar = u(r, 1.0, 1.15);
    for x in [bk + 0.05, fr - 0.05] {
        f.part(s, [x, 0.0], [0.08, 0.52], z, 0.06);
    }
    f.part(s, [0.0, 0.0], [len - 0.3, 0.08], z + 0.06, 0.35);
    f.part(s, [fr - 0.3, 0.0], [0.5, 0.08], z + 0.1, 0.48);
    f.part(s, [bk + 0.35, 0.0], [0.05, 0.05], z + 0.4, seat - 0.4);
    f.part(s, [bk + 0.35, 0.0], [0.26, 0.16], z + seat, 0.07);
    f.part(s, [fr - 0.35, 0.0], [0.05, 0.05], z + 0.55, bar - 0.55);
    f.part(s, [fr - 0.28, 0.0], [0.25, 0.45], z + bar, 0.04);
}

/// A pedestal fan at `c`: a round base, a pole and the head.
fn pedestal_fan(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, c: [f64; 2]) {
    let top = u(r, 1.2, 1.5);
    for (radius, z0, z1) in [(0.25, 0.0, 0.05), (0.02, 0.05, top), (0.25, top, top + 0.2)] {
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
    use crate::sim::geometry::Shape;
    use crate::sim::gym::tests::{extents, room};

    #[test]
    fn a_studio_is_open_faces_a_platform_and_stores_its_kit_or_holds_spin_bikes() {
        let mut r = crate::rng::rng(6);
        let (mut cycling, mut platforms, mut balls, mut barres, mut open) = (0, 0, 0, 0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("studio", &mut r);
            let e = extents(&s);
            // Speakers: 0.45 m high from 2.1 m up.
            let speakers = e
                .iter()
                .filter(|e| e.2 >= 2.1 && (e.3 - e.2 - 0.45).abs() < 1e-9)
                .count();
            assert_eq!(speakers, 2, "{w:.2} x {d:.2}");
            // Saddles: 0.26 x 0.16 m, 0.07 m thick.
            let saddles = e
                .iter()
                .filter(|e| (e.3 - e.2 - 0.07).abs() < 1e-9 && e.2 >= 0.9)
                .count();
            if saddles > 0 {
                cycling += 1;
                assert!(saddles >= 6, "{w:.2} x {d:.2}: {saddles} spin bikes");
            } else {
                // Most of the floor open: what stands on it covers under
                // a quarter of it.
                let covered: f64 = e
                    .iter()
                    .filter(|e| e.2 < 0.5)
                    .map(|e| (e.1[0] - e.0[0]) * (e.1[1] - e.0[1]))
                    .sum();
                open += (covered < 0.25 * w * d) as usize;
            }
            platforms += e.iter().any(|e| {
                e.2 == 0.0
                    && (0.2..=0.3).contains(&e.3)
                    && (e.1[0] - e.0[0]) * (e.1[1] - e.0[1]) >= 1.2
            }) as usize;
            balls += s.iter().any(|s| matches!(s, Shape::Sphere { .. })) as usize;
            barres += e.iter().any(|e| {
                (0.95..=1.05).contains(&e.2)
                    && (e.1[0] - e.0[0]).max(e.1[1] - e.0[1]) >= 1.5
                    && (e.3 - e.2 - 0.04).abs() < 1e-9
            }) as usize;
        }
        assert!((45..=110).contains(&cycling), "{cycling} cycling studios");
        assert!(open + cycling >= 290, "{open} open");
        assert!(
            platforms >= 180 && balls >= 80 && barres >= 60,
            "{platforms} {balls} {barres}"
        );
    }
}
