//! Cardio rooms: rows of treadmills, cross-trainers, bikes, stair
//! climbers and rowers, televisions, a wipes stand.

use super::{between, walls, SWING};
use crate::sim::geometry::Shape;
use crate::sim::scenes::{u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// The cardio machines, each a row's model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Machine {
    Treadmill,
    CrossTrainer,
    UprightBike,
    RecumbentBike,
    StairClimber,
    Rower,
}

impl Machine {
    /// A machine drawn as gyms stock them: treadmills most, then
    /// cross-trainers and bikes, a few stair climbers and rowers.
    fn draw(r: &mut ChaCha8Rng) -> Machine {
        let x = r.random::<f64>();
        match x {
            _ if x < 0.36 => Machine::Treadmill,
            _ if x < 0.58 => Machine::CrossTrainer,
            _ if x < 0.74 => Machine::UprightBike,
            _ if x < 0.84 => Machine::RecumbentBike,
            _ if x < 0.91 => Machine::StairClimber,
            _ => Machine::Rower,
        }
    }

    /// Length (the way the user faces) and width of a model.
    fn size(self, r: &mut ChaCha8Rng) -> [f64; 2] {
        match self {
            Machine::Treadmill => [u(r, 1.9, 2.2), u(r, 0.8, 0.95)],
            Machine::CrossTrainer => [u(r, 1.8, 2.1), u(r, 0.65, 0.8)],
            Machine::UprightBike => [u(r, 1.0, 1.25), u(r, 0.55, 0.65)],
            Machine::RecumbentBike => [u(r, 1.55, 1.8), u(r, 0.6, 0.7)],
            Machine::StairClimber => [u(r, 1.3, 1.6), u(r, 0.8, 1.0)],
            Machine::Rower => [u(r, 2.3, 2.5), u(r, 0.5, 0.6)],
        }
    }

    /// The clear aisle behind a row of it (m): room to step off a
    /// running belt behind treadmills.
    fn aisle(self, r: &mut ChaCha8Rng) -> f64 {
        match self {
            Machine::Treadmill => u(r, 1.3, 1.8),
            _ => u(r, 0.9, 1.3),
        }
    }
}

/// A cardio room: rows of machines facing the window wall (rows along
/// x) or the x = 0 wall (rows along y), the first row 0.6-1.0 m from
/// it, the last clear of the door's swing; televisions hung from the
/// ceiling before the front row or on the faced wall; a wipes and
/// sanitiser stand by the corridor wall at the x = w end, in some a
/// water cooler on a side wall.
pub(super) fn cardio_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, _, back, front] = walls(w, d);
    let y0 = SWING + u(r, 0.2, 0.5);
    let facing_window = r.random::<f64>() < 0.65;
    // Rows run along `lat` (lowest, highest) across the room, from the
    // faced wall back over `depth` m; a point `t` back from the faced
    // wall and `l` along the row.
    let side_margin = u(r, 0.5, 0.8);
    let (lat, depth) = if facing_window {
        ((side_margin, w - side_margin), d - y0)
    } else {
        ((y0, d - side_margin), w - side_margin)
    };
    let to_room = |t: f64, l: f64| if facing_window { [l, d - t] } else { [t, l] };
    let yaw = if facing_window { FRAC_PI_2 } else { PI };
    let mut t = u(r, 0.6, 1.0);
    let (mut rows, mut tries) = (0, 0);
    loop {
        let kind = Machine::draw(r);
        let [len, wid] = kind.size(r);
        if t + len > depth {
            // Another model may fit what is left (the first row always
            // finds one).
            tries += 1;
            if rows > 0 && tries > 4 {
                break;
            }
            continue;
        }
        let gap = u(r, 0.45, 0.7);
        let n = (((lat.1 - lat.0 + gap) / (wid + gap)).floor() as usize).max(1);
        let span = n as f64 * wid + (n - 1) as f64 * gap;
        let l0 = lat.0 + between(r, 0.0, lat.1 - lat.0 - span);
        for i in 0..n {
            if n > 3 && r.random::<f64>() < 0.05 {
                continue;
            }
            let [x, y] = to_room(t + len / 2.0, l0 + wid / 2.0 + i as f64 * (wid + gap));
            machine(s, r, kind, &Frame::at(x, y, yaw), [len, wid]);
        }
        rows += 1;
        t += len + kind.aisle(r);
    }
    // Televisions before the front row.
    let tvs = r.random_range(1..=3);
    let faced = if facing_window { &back } else { &left };
    let along = if facing_window { w } else { d - y0 };
    let from = if facing_window { 0.0 } else { y0 };
    for i in 0..tvs {
        let tl = u(r, 1.0, 1.3);
        let a = from + along * (i as f64 + 0.5) / tvs as f64 - tl / 2.0;
        let z = u(r, 2.0, (h - 0.95).min(2.3));
        if facing_window {
            // Hung from the ceiling on a rod, the windows behind them.
            let o = u(r, 0.3, 0.45);
            s.push(faced.block(a, tl, o, 0.08, z, 0.7));
            s.push(faced.cylinder(a + tl / 2.0, o + 0.04, 0.03, z + 0.7, h));
        } else {
            s.push(faced.block(a, tl, 0.0, 0.1, z, 0.7));
        }
    }
    // The wipes and sanitiser stand and its bin.
    let p = front.point(w - u(r, 0.3, 0.5), 0.25);
    s.push(Shape::Cylinder {
        centre: p,
        radius: 0.03,
        z0: 0.0,
        z1: 1.05,
    });
    s.push(front.block(w - 0.55, 0.25, 0.15, 0.18, 1.05, 0.3));
    s.push(front.block(w - 0.95, 0.35, 0.0, 0.35, 0.0, u(r, 0.6, 0.8)));
    // A water cooler by the corridor wall at the other end.
    if r.random::<f64>() < 0.4 {
        let a = u(r, 0.2, 0.5);
        s.push(front.block(a, 0.32, 0.0, 0.32, 0.0, u(r, 0.95, 1.05)));
        s.push(front.cylinder(a + 0.16, 0.16, 0.13, 1.05, u(r, 1.4, 1.55)));
    }
}

/// A cardio machine of `kind`, `[len, wid]`, centred on `f`, the user
/// facing local +x.
pub(super) fn machine(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    kind: Machine,
    f: &Frame,
    [len, wid]: [f64; 2],
) {
    let (fr, bk) = (len / 2.0, -len / 2.0);
    match kind {
        Machine::Treadmill => {
            let deck = u(r, 0.2, 0.3);
            let console = u(r, 1.25, 1.45);
            f.part(s, [-0.2, 0.0], [len - 0.4, wid], 0.0, deck);
            f.part(s, [fr - 0.2, 0.0], [0.4, wid], 0.0, u(r, 0.35, 0.45));
            for side in [-1.0, 1.0] {
                let c = side * (wid / 2.0 - 0.05);
                f.part(s, [fr - 0.25, c], [0.08, 0.08], 0.4, console - 0.4);
                f.part(s, [fr - 0.6, c], [0.5, 0.04], u(r, 0.95, 1.05), 0.04);
            }
            f.part(s, [fr - 0.3, 0.0], [0.3, wid * 0.9], console, 0.25);
        }
        Machine::CrossTrainer => {
            let console = u(r, 1.35, 1.5);
            f.part(s, [0.0, 0.0], [len, 0.25], 0.0, 0.15);
            f.part(s, [bk + 0.3, 0.0], [0.55, 0.4], 0.0, u(r, 0.7, 0.8));
            for side in [-1.0, 1.0] {
                let p = u(r, -0.3, 0.2);
                f.part(s, [p, side * 0.13], [0.4, 0.15], 0.25, 0.06);
                f.part(
                    s,
                    [fr - 0.5 + u(r, -0.1, 0.1), side * (wid / 2.0 - 0.08)],
                    [0.05, 0.05],
                    0.9,
                    0.8,
                );
            }
            f.part(s, [fr - 0.4, 0.0], [0.1, 0.12], 0.15, console - 0.15);
            f.part(s, [fr - 0.4, 0.0], [0.2, 0.35], console, 0.25);
        }
        Machine::UprightBike => {
            let seat = u(r, 0.95, 1.05);
            for x in [bk + 0.05, fr - 0.05] {
                f.part(s, [x, 0.0], [0.1, wid], 0.0, 0.08);
            }
            f.part(s, [0.05, 0.0], [0.7, 0.2], 0.08, 0.62);
            f.part(s, [bk + 0.3, 0.0], [0.06, 0.06], 0.5, seat - 0.5);
            f.part(s, [bk + 0.3, 0.0], [0.28, 0.24], seat, 0.08);
            f.part(s, [fr - 0.2, 0.0], [0.08, 0.08], 0.7, 0.55);
            f.part(s, [fr - 0.3, 0.0], [0.1, 0.5], 1.1, 0.04);
            f.part(s, [fr - 0.18, 0.0], [0.2, 0.35], 1.25, 0.2);
        }
        Machine::RecumbentBike => {
            f.part(s, [0.0, 0.0], [len, 0.25], 0.0, 0.12);
            f.part(s, [bk + 0.45, 0.0], [0.45, 0.5], 0.45, 0.1);
            f.part(s, [bk + 0.15, 0.0], [0.1, 0.5], 0.55, u(r, 0.45, 0.55));
            for side in [-1.0, 1.0] {
                f.part(
                    s,
                    [bk + 0.45, side * (wid / 2.0 - 0.02)],
                    [0.3, 0.04],
                    0.6,
                    0.04,
                );
            }
            f.part(s, [fr - 0.3, 0.0], [0.5, 0.25], 0.05, 0.6);
            f.part(s, [fr - 0.5, 0.0], [0.08, 0.08], 0.65, 0.4);
            f.part(s, [fr - 0.5, 0.0], [0.2, 0.35], 1.05, 0.2);
        }
        Machine::StairClimber => {
            let top = u(r, 1.45, 1.6);
            f.part(s, [0.0, 0.0], [len, wid], 0.0, 0.25);
            f.part(s, [fr - 0.4, 0.0], [0.7, wid - 0.15], 0.25, u(r, 0.9, 1.1));
            for side in [-1.0, 1.0] {
                let c = side * (wid / 2.0 - 0.04);
                f.part(s, [fr - 0.15, c], [0.06, 0.06], 0.25, top - 0.25);
                f.part(s, [fr - 0.5, c], [0.7, 0.04], 1.1, 0.04);
            }
            f.part(s, [fr - 0.2, 0.0], [0.25, wid * 0.8], top, 0.25);
        }
        Machine::Rower => {
            f.part(s, [fr - 0.25, 0.0], [0.5, wid], 0.0, u(r, 0.55, 0.65));
            f.part(s, [-0.25, 0.0], [len - 0.5, 0.12], 0.25, 0.08);
            f.part(s, [bk + 0.05, 0.0], [0.1, wid - 0.05], 0.0, 0.25);
            f.part(s, [u(r, -0.6, 0.1), 0.0], [0.3, 0.3], 0.33, 0.08);
            f.part(s, [fr - 0.45, 0.0], [0.04, 0.04], 0.55, 0.4);
            f.part(s, [fr - 0.45, 0.0], [0.05, 0.25], 0.95, 0.2);
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::sim::gym::tests::{extents, room};

    #[test]
    fn a_cardio_room_has_rows_of_machines_with_consoles_and_televisions() {
        let mut r = crate::rng::rng(5);
        let (mut treadmills, mut bikes, mut two_rows) = (0, 0, 0);
        for _ in 0..300 {
            let ([w, d, h], s) = room("cardio_room", &mut r);
            let e = extents(&s);
            // Consoles (a rower's monitor) at 0.95-1.6 m, 0.05-0.3 m
            // deep: a row of three at least in every room.
            let consoles_at: Vec<[f64; 2]> = e
                .iter()
                .filter(|e| {
                    let [a, b] = [e.1[0] - e.0[0], e.1[1] - e.0[1]];
                    (0.95..=1.6).contains(&e.2)
                        && (e.3 - e.2 - 0.2).abs() < 0.051
                        && a.min(b) <= 0.31
                        && a.max(b) >= 0.24
                })
                .map(|e| [(e.0[0] + e.1[0]) / 2.0, (e.0[1] + e.1[1]) / 2.0])
                .collect();
            let consoles = consoles_at.len();
            assert!(consoles >= 3, "{w:.2} x {d:.2}: {consoles} consoles");
            // A treadmill's deck: 1.5 m long or more, 0.2-0.3 m high.
            treadmills += e.iter().any(|e| {
                let [a, b] = [e.1[0] - e.0[0], e.1[1] - e.0[1]];
                e.2 == 0.0 && (0.2..=0.3).contains(&e.3) && a.max(b) >= 1.45 && a.min(b) >= 0.75
            }) as usize;
            // An upright bike's seat at 0.95-1.05 m.
            bikes += e
                .iter()
                .any(|e| (0.95..=1.05).contains(&e.2) && (e.3 - e.2 - 0.08).abs() < 1e-9)
                as usize;
            // Machines in rows: consoles at two places or more both
            // along the rows and across them.
            let distinct = |k: usize| {
                let mut c: Vec<f64> = consoles_at.iter().map(|p| p[k]).collect();
                c.sort_by(f64::total_cmp);
                c.dedup_by(|a, b| (*a - *b).abs() < 0.3);
                c.len()
            };
            two_rows += (distinct(0).min(distinct(1)) >= 2) as usize;
            // A television: 1.0-1.3 m wide, 0.7 m high, from 2.0 m up.
            let tv = e.iter().any(|e| {
                let [a, b] = [e.1[0] - e.0[0], e.1[1] - e.0[1]];
                (e.3 - e.2 - 0.7).abs() < 1e-9 && a.max(b) >= 1.0 && e.2 >= 2.0 && e.3 < h
            });
            assert!(tv, "{w:.2} x {d:.2}: no television");
        }
        assert!(
            treadmills >= 200 && bikes >= 100 && two_rows >= 150,
            "{treadmills} {bikes} {two_rows}"
        );
    }
}
