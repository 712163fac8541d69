//! Workshops: workbenches, tool cabinets, steel shelving, a trolley and
//! the machines standing free in the middle.

use super::{between, stock, walls, Side, SWING};
use crate::sim::geometry::{cuboid, Shape};
use crate::sim::scenes::u;
use rand::seq::SliceRandom;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// A workshop: workbenches along the window wall, more of them (or tall
/// tool cabinets) along the x = 0 wall from the door's swing on, steel
/// shelving of stock along the x = w wall, machines in one or two rows
/// in the middle with a metre or more round them, a trolley by the
/// corridor wall at the x = 0 end and a tall tool cabinet or a hand
/// basin at the other. Returns each machine's footprint (lowest and
/// highest corner) and height.
pub(super) fn workshop(
    w: f64,
    d: f64,
    h: f64,
    r: &mut ChaCha8Rng,
    s: &mut Vec<Shape>,
) -> Vec<([f64; 2], [f64; 2], f64)> {
    let [left, right, back, front] = walls(w, d);
    let top = u(r, 0.88, 0.95);
    let wd = u(r, 0.7, 0.85);
    let sd = u(r, 0.5, 0.6);
    let y0 = SWING + u(r, 0.1, 0.4);
    shelving(s, r, &right, (y0, d - y0), sd, h);
    bench_run(s, r, &back, (0.05, w - sd - 0.15), wd, top);
    let reach = if r.random::<f64>() < 0.7 {
        bench_run(s, r, &left, (y0, d - wd - 0.05 - y0), wd, top);
        wd
    } else {
        let mut a = y0;
        for _ in 0..r.random_range(1..=3) {
            let cl = u(r, 0.9, 1.0);
            if a + cl > d - wd - 0.05 {
                break;
            }
            s.push(left.block(a, cl, 0.0, 0.5, 0.0, u(r, 1.9, 2.0)));
            a += cl + 0.02;
        }
        // A rack of long stock or a tool board on the wall beyond them.
        if d - wd - 0.1 - a >= 0.8 {
            s.push(left.block(a + 0.05, d - wd - 0.15 - a, 0.0, 0.03, 1.0, 1.0));
        }
        0.5
    };
    // The trolley, and a tall tool cabinet or a hand basin.
    let (tl, tw) = (u(r, 0.8, 1.0), u(r, 0.5, 0.6));
    let (ta, ttop) = (u(r, 0.1, 0.4), u(r, 0.85, 0.95));
    trolley(s, r, &front, ta, [tl, tw], ttop);
    if r.random::<f64>() < 0.5 {
        s.push(front.block(w - 1.05, 1.0, 0.0, 0.5, 0.0, u(r, 1.9, 2.0)));
    } else {
        s.push(front.block(w - 0.7, 0.5, 0.0, 0.4, 0.75, 0.15));
        s.push(front.cylinder(w - 0.45, 0.05, 0.02, 0.9, 1.15));
    }
    // The machines.
    let xa = reach + u(r, 1.0, 1.3);
    let xb = w - sd - u(r, 1.0, 1.3);
    let ya = SWING + u(r, 0.6, 0.9);
    let yb = d - wd - u(r, 1.0, 1.3);
    let mut rows = vec![ya + 0.7];
    let second = ya + 0.7 + 1.4 + u(r, 1.2, 1.5);
    if second + 0.7 <= yb {
        rows.push(second);
    }
    // The shop's machines, taken in a random order: up to two lathes and
    // two milling machines, a drill press, a band saw, a pedestal
    // grinder, an assembly table; each row takes the next that fits.
    let mut stock: Vec<(usize, [f64; 2])> = [0, 0, 1, 1, 2, 3, 4, 5]
        .into_iter()
        .map(|kind| (kind, machine_size(kind, r)))
        .collect();
    stock.shuffle(r);
    let mut placed = Vec::new();
    for yc in rows {
        let mut x = xa;
        while let Some(k) = stock.iter().position(|m| x + m.1[0] <= xb) {
            let (kind, size) = stock.remove(k);
            let m = Machine {
                at: [x, yc - size[1] / 2.0],
                size,
                turned: r.random::<bool>(),
            };
            let height = match kind {
                0 => lathe(s, r, &m),
                1 => milling_machine(s, r, &m),
                2 => drill_press(s, r, &m),
                3 => band_saw(s, r, &m),
                4 => grinder(s, &m),
                _ => assembly_table(s, r, &m),
            };
            placed.push((m.at, [m.at[0] + size[0], m.at[1] + size[1]], height));
            x += size[0] + u(r, 0.9, 1.3);
        }
    }
    placed
}

/// Workbenches along `side` over `(a, len)`, `depth` out: benches of 1.5
/// to 2.5 m, a roller tool cabinet between some.
fn bench_run(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a, len): (f64, f64),
    depth: f64,
    top: f64,
) {
    let end = a + len;
    let mut p = a;
    while end - p >= 0.6 {
        if r.random::<f64>() < 0.2 && end - p >= 0.8 {
            let cl = u(r, 0.6, 0.8);
            s.push(side.block(p, cl, 0.0, 0.5, 0.0, u(r, 0.85, 1.05)));
            p += cl + 0.05;
            continue;
        }
        let bl = u(r, 1.5, 2.5).min(end - p);
        workbench(s, r, side, p, bl, depth, top);
        p += bl + u(r, 0.0, 0.2);
    }
}

/// A heavy workbench along `side` from `a`, `len` long and `depth` out: a
/// thick top at `top` on four steel legs, a lower shelf, in some a drawer
/// unit under the top and a vise on its front edge, things on it, and in
/// most a tool board on the wall above.
fn workbench(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    a: f64,
    len: f64,
    depth: f64,
    top: f64,
) {
    s.push(side.block(a, len, 0.0, depth, top - 0.05, 0.05));
    for la in [a + 0.03, a + len - 0.09] {
        for lo in [0.03, depth - 0.09] {
            s.push(side.block(la, 0.06, lo, 0.06, 0.0, top - 0.05));
        }
    }
    s.push(side.block(a + 0.03, len - 0.06, 0.03, depth - 0.06, 0.15, 0.03));
    if len >= 1.0 && r.random::<f64>() < 0.5 {
        s.push(side.block(a + len - 0.6, 0.5, 0.05, depth - 0.1, top - 0.55, 0.5));
    }
    if len >= 0.8 && r.random::<f64>() < 0.6 {
        let va = u(r, a + 0.15, a + len - 0.35);
        s.push(side.block(va, 0.2, depth - 0.15, 0.25, top, 0.15));
    }
    for _ in 0..r.random_range(0..=2) {
        let bl = u(r, 0.25, 0.5).min(len - 0.1);
        let ba = between(r, a + 0.05, a + len - 0.05 - bl);
        s.push(side.block(ba, bl, 0.05, u(r, 0.2, 0.35), top, u(r, 0.1, 0.3)));
    }
    if len >= 1.0 && r.random::<f64>() < 0.6 {
        let bl = u(r, 1.0, 2.0).min(len - 0.2);
        let z = top + u(r, 0.2, 0.3);
        let bh = u(r, 0.7, 0.9);
        s.push(side.block(a + 0.1, bl, 0.0, 0.03, z, bh));
        let mut p = a + 0.15;
        while p + 0.1 < a + bl {
            let tl = u(r, 0.05, 0.3).min(a + 0.05 + bl - p);
            if r.random::<f64>() < 0.7 {
                let tz = z + u(r, 0.05, bh - 0.4);
                s.push(side.block(p, tl, 0.03, u(r, 0.03, 0.08), tz, u(r, 0.1, 0.35)));
            }
            p += tl + u(r, 0.05, 0.2);
        }
    }
}

/// Steel shelving units along `side` over `(a, len)`, `depth` out: units
/// of 0.9 to 1.2 m, four or five shelves to 1.8-2.2 m on corner posts,
/// stock on them (boxes, bins, bar and sheet material).
fn shelving(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    (a, len): (f64, f64),
    depth: f64,
    h: f64,
) {
    let sh = u(r, 1.8, 2.2).min(h - 0.4);
    let levels = r.random_range(4..=5);
    let gap = (sh - 0.12) / (levels - 1) as f64;
    let mut p = a;
    while a + len - p >= 0.9 {
        let ul = u(r, 0.9, 1.2).min(a + len - p);
        for pa in [p, p + ul - 0.04] {
            for po in [0.0, depth - 0.04] {
                s.push(side.block(pa, 0.04, po, 0.04, 0.0, sh));
            }
        }
        for i in 0..levels {
            let z = 0.1 + i as f64 * gap;
            s.push(side.block(p, ul, 0.0, depth, z, 0.02));
            let tall = if i + 1 < levels { gap - 0.06 } else { 0.35 };
            stock(s, r, side, p, ul, (0.0, depth), z + 0.02, tall);
        }
        p += ul + 0.02;
    }
}

/// A workshop trolley against `side` at `a` along it, `size` (along, out)
/// with shelves at 0.15 and 0.5 m and at `top`, four posts and a push
/// handle.
fn trolley(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    a: f64,
    [len, depth]: [f64; 2],
    top: f64,
) {
    let o = 0.05;
    for pa in [a, a + len - 0.03] {
        for po in [o, o + depth - 0.03] {
            s.push(side.block(pa, 0.03, po, 0.03, 0.0, top));
        }
    }
    for z in [0.15, 0.5, top - 0.03] {
        s.push(side.block(a, len, o, depth, z, 0.03));
    }
    s.push(side.block(a + len - 0.03, 0.03, o, depth, top, 0.15));
    if r.random::<f64>() < 0.7 {
        s.push(side.block(
            a + 0.1,
            u(r, 0.2, 0.5),
            o + 0.05,
            u(r, 0.2, 0.4),
            top,
            u(r, 0.1, 0.3),
        ));
    }
}

/// A machine's footprint and how it faces.
struct Machine {
    /// The footprint's lowest corner (m).
    at: [f64; 2],
    /// Its length along x and depth along y (m).
    size: [f64; 2],
    /// Whether its front (the operator's side) faces -y, not +y.
    turned: bool,
}

impl Machine {
    /// A part `x0..x0 + sx` along the machine, `y0..y0 + sy` from its
    /// back towards its front, `z0..z0 + sz` up.
    fn part(&self, x0: f64, y0: f64, sx: f64, sy: f64, z0: f64, sz: f64) -> Shape {
        let y = if self.turned {
            self.size[1] - y0 - sy
        } else {
            y0
        };
        cuboid([self.at[0] + x0, self.at[1] + y, z0], [sx, sy, sz])
    }

    /// An upright cylinder at `x` along the machine, `y` from its back.
    fn post(&self, x: f64, y: f64, radius: f64, z0: f64, z1: f64) -> Shape {
        let y = if self.turned { self.size[1] - y } else { y };
        Shape::Cylinder {
            centre: [self.at[0] + x, self.at[1] + y],
            radius,
            z0,
            z1,
        }
    }
}

/// The footprint (length, depth) of a machine of `kind`: a lathe, a
/// milling machine, a drill press, a band saw, a pedestal grinder or an
/// assembly table.
fn machine_size(kind: usize, r: &mut ChaCha8Rng) -> [f64; 2] {
    match kind {
        0 => [u(r, 1.5, 2.4), u(r, 0.65, 0.8)],
        1 => [u(r, 1.2, 1.6), u(r, 1.1, 1.4)],
        2 => [u(r, 0.5, 0.6), u(r, 0.6, 0.75)],
        3 => [u(r, 0.6, 0.85), u(r, 0.55, 0.7)],
        4 => [u(r, 0.5, 0.6), u(r, 0.35, 0.45)],
        _ => [u(r, 1.2, 2.0), u(r, 0.8, 1.0)],
    }
}

/// A lathe: two cabinet stands, a chip tray between them, the bed, the
/// headstock at one end, the carriage and the tailstock on the bed, a
/// splash guard behind. Returns its height.
fn lathe(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    let hh = u(r, 1.2, 1.45);
    s.push(m.part(0.0, 0.05, 0.5, fy - 0.15, 0.0, 0.8));
    s.push(m.part(fx - 0.45, 0.05, 0.45, fy - 0.15, 0.0, 0.8));
    s.push(m.part(0.5, 0.05, fx - 0.95, fy - 0.15, 0.7, 0.05));
    s.push(m.part(0.3, 0.15, fx - 0.4, 0.35, 0.8, 0.25));
    s.push(m.part(0.0, 0.05, 0.6, fy - 0.15, 0.8, hh - 0.8));
    let cx = between(r, 0.65, fx - 0.8);
    s.push(m.part(cx, 0.1, 0.3, fy - 0.1, 0.85, 0.35));
    s.push(m.part(fx - 0.5, 0.2, 0.3, 0.3, 1.05, 0.2));
    s.push(m.part(0.0, 0.0, fx, 0.04, 0.8, hh - 0.85));
    hh
}

/// A knee-type milling machine: its base, the column at the back, the
/// knee, the table across the machine's length, the ram and head over
/// it, the spindle, the knee's crank. Returns its height.
fn milling_machine(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    let mh = u(r, 1.75, 1.95);
    let c = fx / 2.0;
    s.push(m.part(c - 0.35, 0.0, 0.7, fy - 0.1, 0.0, 0.25));
    s.push(m.part(c - 0.3, 0.0, 0.6, 0.55, 0.25, mh - 0.25));
    s.push(m.part(c - 0.25, 0.55, 0.5, fy - 0.9, 0.25, 0.6));
    s.push(m.part(0.0, fy - 0.75, fx, 0.35, 0.85, 0.1));
    s.push(m.part(c - 0.22, 0.2, 0.44, fy - 0.55, 1.45, mh - 1.5));
    s.push(m.post(c, fy - 0.6, 0.06, 1.15, 1.45));
    s.push(m.part(c - 0.1, fy - 0.35, 0.2, 0.35, 0.6, 0.2));
    mh
}

/// A floor drill press: a base plate, the column, the round table, the
/// head with the motor's belt cover on top, the spindle. Returns its
/// height.
fn drill_press(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    let dh = u(r, 1.6, 1.85);
    let c = fx / 2.0;
    s.push(m.part(0.0, 0.0, fx, 0.5, 0.0, 0.08));
    s.push(m.post(c, 0.15, 0.05, 0.08, dh - 0.1));
    let tz = u(r, 0.75, 1.0);
    s.push(m.post(c, 0.42, 0.17, tz, tz + 0.04));
    s.push(m.part(0.03, 0.03, fx - 0.06, fy - 0.03, dh - 0.45, 0.3));
    s.push(m.part(c - 0.15, 0.0, 0.3, 0.25, dh - 0.15, 0.15));
    s.push(m.post(c, 0.42, 0.03, dh - 0.6, dh - 0.45));
    dh
}

/// A vertical band saw: the cabinet of the lower wheel, the table on it,
/// the spine up one side, the upper wheel's housing, the blade guard.
/// Returns its height.
fn band_saw(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    let bh = u(r, 1.7, 1.9);
    s.push(m.part(0.0, 0.0, fx, fy, 0.0, 0.88));
    s.push(m.part(0.0, 0.0, fx, fy, 0.9, 0.04));
    s.push(m.part(0.0, 0.05, 0.15, fy - 0.1, 0.94, bh - 0.94));
    s.push(m.part(0.0, 0.1, fx, 0.3, bh - 0.55, 0.55));
    s.push(m.part(fx * 0.6, fy / 2.0 - 0.03, 0.05, 0.06, 1.1, bh - 0.55 - 1.1));
    bh
}

/// A pedestal grinder: a base disc, the pedestal, the motor with a wheel
/// and its guard at each end, 1.2 m high. Returns its height.
fn grinder(s: &mut Vec<Shape>, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    s.push(m.post(fx / 2.0, fy / 2.0, (fy / 2.0).min(0.2), 0.0, 0.04));
    s.push(m.post(fx / 2.0, fy / 2.0, 0.05, 0.04, 0.95));
    s.push(m.part(0.0, fy / 2.0 - 0.12, fx, 0.24, 0.95, 0.25));
    1.2
}

/// A steel assembly table: a top at 0.85-0.95 m on four legs, a lower
/// shelf, work on it. Returns its height.
fn assembly_table(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, m: &Machine) -> f64 {
    let [fx, fy] = m.size;
    let top = u(r, 0.85, 0.95);
    s.push(m.part(0.0, 0.0, fx, fy, top - 0.03, 0.03));
    for x in [0.03, fx - 0.09] {
        for y in [0.03, fy - 0.09] {
            s.push(m.part(x, y, 0.06, 0.06, 0.0, top - 0.03));
        }
    }
    s.push(m.part(0.05, 0.05, fx - 0.1, fy - 0.1, 0.2, 0.03));
    let wl = u(r, 0.3, 0.7);
    let tall = u(r, 0.1, 0.4);
    s.push(m.part(
        between(r, 0.1, fx - 0.1 - wl),
        0.2,
        wl,
        u(r, 0.2, 0.5),
        top,
        tall,
    ));
    top + tall
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::hotel::extent;
    use crate::sim::institute::tests::{draw, gap, size, top_run};
    use crate::sim::office_floor::boxes;

    #[test]
    fn a_workshop_has_workbenches_shelving_a_trolley_and_machines_standing_free() {
        let mut r = crate::rng::rng(6);
        let (mut two, mut high, mut vises) = (0, 0, 0);
        for _ in 0..300 {
            let [w, d, h] = draw("workshop", &mut r);
            let mut s = Vec::new();
            let machines = workshop(w, d, h, &mut r, &mut s);
            let b = boxes(&s);
            // Workbench tops, 0.05 m thick at 0.88-0.95 m: 2 m at least.
            let run = top_run(&b, 0.88..=0.95, 0.05);
            assert!(run >= 2.0, "{w:.2} x {d:.2}: {run} m of workbench");
            // Steel shelving: corner posts to 1.8-2.2 m.
            let shelving = b.iter().any(|b| {
                b.0[2] == 0.0
                    && (1.8..=2.2).contains(&b.1[2])
                    && (size(b)[0] - 0.04).abs() < 1e-9
                    && (size(b)[1] - 0.04).abs() < 1e-9
            });
            assert!(shelving, "no shelving");
            // The trolley's handle: 0.15 m over its top shelf.
            let trolley = b.iter().any(|b| {
                (0.85..=0.95).contains(&b.0[2])
                    && (size(b)[2] - 0.15).abs() < 1e-9
                    && size(b)[0] < 0.05
            });
            assert!(trolley, "no trolley");
            vises += b.iter().any(|b| {
                (size(b)[2] - 0.15).abs() < 1e-9
                    && (0.88..=0.95).contains(&b.0[2])
                    && size(b)[0] > 0.1
            }) as usize;
            // Machines: one at least of 1.2-1.95 m; each a metre from the
            // walls and 0.9 m from anything not its own.
            assert!(!machines.is_empty(), "{w:.2} x {d:.2}: no machine");
            assert!(
                machines.iter().all(|m| (0.85..=1.95).contains(&m.2)),
                "{machines:?}"
            );
            high += machines.iter().any(|m| m.2 >= 1.6) as usize;
            two += (machines.len() >= 2) as usize;
            for &(lo, hi, _) in &machines {
                assert!(
                    lo[0] >= 1.0 && lo[1] >= 1.0 && hi[0] <= w - 1.0 && hi[1] <= d - 1.0,
                    "{w:.2} x {d:.2}: a machine at {lo:?}..{hi:?}"
                );
                for shape in &s {
                    let (a, b, _, _) = extent(shape);
                    let own = a[0] >= lo[0] - 1e-9
                        && a[1] >= lo[1] - 1e-9
                        && b[0] <= hi[0] + 1e-9
                        && b[1] <= hi[1] + 1e-9;
                    if !own {
                        let g = gap((lo, hi), (a, b));
                        assert!(g >= 0.9 - 1e-9, "{w:.2} x {d:.2}: {g} m to {shape:?}");
                    }
                }
            }
        }
        assert!(
            two >= 200 && high >= 200 && vises >= 200,
            "{two} with two machines, {high} with a tall one, {vises} with a vise"
        );
    }
}
