//! Research-institute floors, a scene family written for issue 18's
//! twenty-sixth round by another hand, after the recommended room setting
//! existed and while that round's two descriptor parts were built (the
//! hand knew nothing of them), so that none of them was shaped on it; the
//! round's plan named its kinds: the layout of [`super::office_floor`] (a corridor between two rows
//! of rooms, one ceiling) as a floor of an institute's laboratory
//! building, its rooms furnished as real ones are.
//!
//! The corridor has linear ceiling lights down its middle and along its
//! walls notice boards, fire extinguisher cabinets, gas-cylinder cages,
//! banks of lockers, a bench or a few chairs, bins and now and then a
//! copier; its middle is left clear. Laboratories are wet labs: bench
//! runs with a top at about 0.9 m along the side walls (one with a sink,
//! a swan-neck tap and a drying rack above it), double-sided island
//! benches or peninsulas with a service spine and in most a reagent
//! shelf on posts above them, set along the room or across it, fume hoods
//! (2.3-2.5 m high, 0.9 m deep, an exhaust duct to the ceiling) against a
//! side wall or the window wall, lab stools at the benches, tall
//! chemical cabinets on the corridor wall and in some an emergency shower
//! with an eyewash by the door. Workshops have heavy workbenches (tops at
//! about 0.9 m, a vise, a lower shelf, tool boards on the wall above some)
//! along the window wall and a side wall, roller tool cabinets between
//! them or tall tool cabinets, steel shelving of stock along the other
//! side wall, and machines standing free of the walls in one or two rows
//! with a metre or more round them, as many as the rows hold of a shop's
//! two lathes and two milling machines, a drill press, a band saw, a
//! pedestal grinder and an assembly table; a trolley is parked by the
//! corridor wall. Server rooms have one or more rows of
//! 19-inch racks (0.6 m wide, 1.0-1.2 m deep, 2.0-2.2 m high) with aisles
//! between them, running away from the corridor or along it, one or two
//! cooling units (about 1.9 m) on the window wall, in half of them a
//! ladder cable tray hung over each row, gas-suppression cylinders in a
//! corner, in some an electrical panel on a side wall, and in most a small
//! desk with a monitor and a chair by the corridor wall. Seminar rooms
//! have tables (tops at 0.72-0.75 m, on four legs or panel ends) with
//! stacking or swivel chairs in rows, in a U or pushed together into one
//! or two blocks, facing a whiteboard on the front wall (the window wall
//! or a side wall), a lectern or a teacher's desk with its chair before
//! it, in most a projector screen (in about half a ceiling projector
//! too), and in some a side table or a pinboard. Doors are ordinary doors in the corridor wall
//! (the leaf itself not modelled, as on the hotel and home floors), shut
//! in most server rooms and in some of the other rooms, standing where
//! the room leaves a door's swing clear. Gaps left in a row are store
//! rooms (never scanned) with shelving, behind a mostly shut door.
//!
//! What it leaves out: the floor has no offices, kitchens, restrooms or
//! stairs, though a real institute floor has them; every room opens onto
//! the corridor through its own door and is as deep as its row (6-8 m).
//! Nothing is modelled above the ceiling or under a floor: no exposed
//! ducts, pipes or cable ladders under a lab's ceiling but the fume hoods'
//! exhausts, no raised floor or hot-aisle containment in the server rooms.
//! Glass is left out (fume-hood sashes but their bottom rail, the mesh of
//! the gas cages, glazed cabinet doors), as are windows, people, cables on
//! the floor and small things (glassware, tools and stock are boxes of
//! their size, machines boxy shapes of their parts). A floor has one
//! workshop, one server room and one seminar room, and laboratories in the
//! rest of its rows.

use super::geometry::{cuboid, Shape};
use super::hotel::{dining_chair, door_in_clear_span};
use super::office_floor::FloorPlan;
use super::plans::place;
use super::scenes::{chair, table, u, Frame};
use rand::seq::SliceRandom;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// The kinds of place on an institute floor, its ground-truth labels.
pub const INSTITUTE_KINDS: [&str; 5] = [
    "corridor",
    "laboratory",
    "workshop",
    "server_room",
    "seminar_room",
];

/// The institute floor: a workshop and a seminar room on one side, a
/// server room and a laboratory on the other, laboratories filling both
/// rows.
pub const INSTITUTE: FloorPlan = FloorPlan {
    kinds: INSTITUTE_KINDS,
    width: room_width,
    // Laboratory modules, from the corridor to the window wall.
    row_depth: (6.0, 8.0),
    // Trolleys and gas cylinders are wheeled along it past what stands
    // at its walls.
    corridor_width: (2.0, 2.8),
    // A laboratory building's clear height under its services.
    ceiling: (2.9, 3.3),
    north: ["workshop", "seminar_room"],
    south: ["server_room", "laboratory"],
    filler: "laboratory",
    open: &[],
    furnish,
    fittings: corridor_fittings,
    door,
    glazed: &[],
};

/// Width along the corridor of a room of an institute kind (m), lowest
/// and highest: a laboratory is two or three planning modules.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "laboratory" => (5.6, 8.4),
        "workshop" => (6.5, 11.0),
        "server_room" => (4.0, 7.5),
        "seminar_room" => (6.0, 10.0),
        _ /* store room */ => (0.5, 5.6),
    }
}

/// How far into a room (m) a door's swing reaches, kept clear of
/// furniture where the door stands.
const SWING: f64 = 1.0;

/// How deep a fume hood is (m), from the wall.
const HOOD_DEPTH: f64 = 0.9;

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// corridor wall at y = 0, `h` high. Every room is laid out from its
/// x = 0 wall, then mirrored in about one of two.
fn furnish(kind: &str, [w, d, h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mut t = Vec::new();
    match kind {
        "laboratory" => laboratory(w, d, h, r, &mut t),
        "workshop" => {
            workshop(w, d, h, r, &mut t);
        }
        "server_room" => server_room(w, d, h, r, &mut t),
        "seminar_room" => {
            seminar_room(w, d, h, r, &mut t);
        }
        _ => store_room(w, d, h, r, &mut t),
    }
    let mirror = r.random::<bool>();
    s.extend(
        t.iter()
            .map(|p| place(p, [mirror, false], [if mirror { w } else { 0.0 }, 0.0])),
    );
}

/// Where a room's door goes: shut in four server rooms of five (kept
/// shut for the cooling and the gas suppression), two laboratories of
/// five, about a third of the workshops and seminar rooms and most store
/// rooms; else where the corridor wall is clear of furniture for a door's
/// swing ([`SWING`]) into the room, anywhere along it if nowhere is
/// (which the layouts below never leave).
fn door(
    kind: &str,
    width: f64,
    door: f64,
    open: bool,
    furniture: &[Shape],
    r: &mut ChaCha8Rng,
) -> Option<f64> {
    let shut = match kind {
        _ if open => 0.0,
        "server_room" => 0.8,
        "laboratory" => 0.4,
        "workshop" => 0.3,
        "seminar_room" => 0.35,
        _ => 0.8,
    };
    if r.random::<f64>() < shut {
        return None;
    }
    door_in_clear_span(width, door, SWING, furniture, r)
}

/// A draw from `lo..hi`, or `lo` where that leaves nothing to draw from.
fn between(r: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    if hi > lo {
        u(r, lo, hi)
    } else {
        lo
    }
}

/// A wall of a room [0, w] x [0, d]: x = 0, x = w, the window wall at
/// y = d, the corridor wall at y = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Wall {
    Left,
    Right,
    Back,
    Front,
}

/// What stands against a wall, given by how far along the wall (from
/// its end at x = 0 or y = 0) and how far out from it.
#[derive(Clone, Copy, Debug)]
struct Side {
    wall: Wall,
    w: f64,
    d: f64,
}

impl Side {
    /// The room's point `a` along the wall and `o` out from it.
    fn point(&self, a: f64, o: f64) -> [f64; 2] {
        match self.wall {
            Wall::Left => [o, a],
            Wall::Right => [self.w - o, a],
            Wall::Back => [a, self.d - o],
            Wall::Front => [a, o],
        }
    }

    /// A box from `a` to `a + len` along the wall, `o` to `o + depth`
    /// out from it, `z` to `z + height` up.
    fn block(&self, a: f64, len: f64, o: f64, depth: f64, z: f64, height: f64) -> Shape {
        let [p, q] = [self.point(a, o), self.point(a + len, o + depth)];
        cuboid(
            [p[0].min(q[0]), p[1].min(q[1]), z],
            [(q[0] - p[0]).abs(), (q[1] - p[1]).abs(), height],
        )
    }

    /// An upright cylinder at `a` along the wall, `o` out from it.
    fn cylinder(&self, a: f64, o: f64, radius: f64, z0: f64, z1: f64) -> Shape {
        Shape::Cylinder {
            centre: self.point(a, o),
            radius,
            z0,
            z1,
        }
    }
}

/// The four walls of a room `w` by `d`: x = 0, x = w, the window wall,
/// the corridor wall.
fn walls(w: f64, d: f64) -> [Side; 4] {
    [Wall::Left, Wall::Right, Wall::Back, Wall::Front].map(|wall| Side { wall, w, d })
}

/// Runs of boxes (bottles, boxes of stock) on a shelf along `side` from
/// `a`, `len` long, from `o` out to `o + depth`, standing at `z`, at most
/// `tall` high.
#[allow(clippy::too_many_arguments)]
fn stock(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    side: &Side,
    a: f64,
    len: f64,
    (o, depth): (f64, f64),
    z: f64,
    tall: f64,
) {
    let mut p = a + 0.03;
    while p < a + len - 0.1 {
        let run = u(r, 0.1, 0.45).min(a + len - 0.03 - p);
        if r.random::<f64>() < 0.7 {
            let deep = between(r, 0.08, depth - 0.04);
            s.push(side.block(p, run, o + 0.02, deep, z, u(r, 0.4, 1.0) * tall));
        }
        p += run + u(r, 0.05, 0.3);
    }
}

// --- Laboratories ---

/// A laboratory: benches with a top at about 0.9 m along the side walls
/// from the door's swing on, a sink in the x = w one; fume hoods on the
/// x = 0 wall at the back with islands (or peninsulas from the window
/// wall) along the room, or on the window wall with islands (or
/// peninsulas from the x = 0 wall) across it; tall chemical cabinets on
/// the corridor wall at the x = w end and in some an emergency shower at
/// the other.
fn laboratory(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
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

// --- Workshops ---

/// A workshop: workbenches along the window wall, more of them (or tall
/// tool cabinets) along the x = 0 wall from the door's swing on, steel
/// shelving of stock along the x = w wall, machines in one or two rows
/// in the middle with a metre or more round them, a trolley by the
/// corridor wall at the x = 0 end and a tall tool cabinet or a hand
/// basin at the other. Returns each machine's footprint (lowest and
/// highest corner) and height.
fn workshop(
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

// --- Server rooms ---

/// A server room: one or two cooling units on the window wall, rows of
/// racks between them and the corridor wall, running away from the
/// corridor (every room narrower than 6 m, most others) or along it,
/// with aisles of 1.0-1.2 m between rows and 0.8-1.0 m at the walls; in
/// half the rooms a cable tray hung over each row; a desk with a monitor
/// and a chair by the corridor wall at the x = 0 end in most, gas
/// suppression cylinders at the other; in some an electrical panel on
/// the x = w wall.
fn server_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
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

// --- Seminar rooms ---

/// How a seminar room's tables are set out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Seating {
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
fn seminar_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) -> Seating {
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

// --- Store rooms and the corridor ---

/// A store room (a gap left in a row, never scanned): shelving of
/// consumables along its side walls past the door's swing.
fn store_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let depth = (w / 2.0 - 0.1).clamp(0.1, 0.6);
    let sh = u(r, 1.8, 2.2).min(h - 0.4);
    for x in [0.0, w - depth] {
        for level in 0..5 {
            let z = 0.1 + level as f64 * (sh - 0.15) / 4.0;
            s.push(cuboid([x, 0.8, z], [depth, d - 1.0, 0.02]));
            if r.random::<f64>() < 0.75 {
                let run = u(r, 0.4, d - 1.2);
                let y = u(r, 0.8, d - 0.2 - run);
                let tall = u(r, 0.15, 0.35);
                s.push(cuboid([x, y, z + 0.02], [depth, run, tall]));
            }
        }
        if w < 2.0 * depth + 0.6 {
            break;
        }
    }
}

/// The corridor's fittings, `length` by `width`, `h` high: linear
/// lights down its middle under the ceiling; along its walls notice
/// boards, fire extinguisher cabinets or extinguishers on brackets,
/// gas-cylinder cages (corner posts, a top frame and the cylinders; the
/// mesh left out), banks of lockers, a bench or two or three chairs, bins
/// and now and then a copier. Nothing stands more than 0.65 m out from a
/// wall.
fn corridor_fittings(length: f64, width: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
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
    use crate::sim::hotel::{extent, overlap};
    use crate::sim::office_floor::{boxes, furnished_room};

    /// A room of `kind` of a size drawn from the plan's ranges.
    fn room(kind: &str, r: &mut ChaCha8Rng) -> ([f64; 3], Vec<Shape>) {
        furnished_room(&INSTITUTE, kind, r)
    }

    /// A room size drawn from the plan's ranges, for the kinds whose
    /// layout functions are called directly (unmirrored).
    fn draw(kind: &str, r: &mut ChaCha8Rng) -> [f64; 3] {
        let (lo, hi) = room_width(kind);
        [
            u(r, lo, hi),
            u(r, INSTITUTE.row_depth.0, INSTITUTE.row_depth.1),
            u(r, INSTITUTE.ceiling.0, INSTITUTE.ceiling.1),
        ]
    }

    fn size(b: &([f64; 3], [f64; 3])) -> [f64; 3] {
        [b.1[0] - b.0[0], b.1[1] - b.0[1], b.1[2] - b.0[2]]
    }

    /// The horizontal distance between two footprints (0 where they
    /// touch or overlap).
    fn gap(a: ([f64; 2], [f64; 2]), b: ([f64; 2], [f64; 2])) -> f64 {
        let dx = (a.0[0] - b.1[0]).max(b.0[0] - a.1[0]).max(0.0);
        let dy = (a.0[1] - b.1[1]).max(b.0[1] - a.1[1]).max(0.0);
        dx.hypot(dy)
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        for kind in INSTITUTE_KINDS.iter().skip(1).copied().chain(["storage"]) {
            for _ in 0..300 {
                let ([w, d, h], s) = room(kind, &mut r);
                assert!(!s.is_empty(), "{kind}: empty");
                for shape in &s {
                    let (lo, hi, z0, z1) = extent(shape);
                    let inside =
                        lo[0] >= -1e-9 && lo[1] >= -1e-9 && hi[0] <= w + 1e-9 && hi[1] <= d + 1e-9;
                    assert!(inside, "{kind} {w:.2} x {d:.2}: {shape:?} outside");
                    assert!(
                        z0 >= -1e-9 && z1 <= h + 1e-9,
                        "{kind}: {shape:?} at {z0}..{z1} m under {h}"
                    );
                    // Above where the floor tests look for the walls (0.15
                    // m under the ceiling) only slim ducts and rods reach:
                    // fume-hood exhausts, a projector's rod, a tray's
                    // hangers.
                    if z1 > h - 0.25 {
                        assert!(
                            matches!(shape, Shape::Cylinder { radius, .. } if *radius <= 0.15),
                            "{kind}: {shape:?} under a ceiling at {h}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn doors_keep_their_swing_clear_and_some_are_shut() {
        let mut r = crate::rng::rng(3);
        for kind in &INSTITUTE_KINDS[1..] {
            for _ in 0..300 {
                let ([w, ..], s) = room(kind, &mut r);
                let x = (INSTITUTE.door)(kind, w, 0.9, true, &s, &mut r).expect("open");
                assert!(
                    x >= 0.1 - 1e-9 && x + 0.9 <= w - 0.1 + 1e-9,
                    "{kind}: {x} in {w}"
                );
                let swing = ([x, 0.0], [x + 0.9, SWING]);
                for shape in &s {
                    let (a, b, _, _) = extent(shape);
                    assert!(
                        !overlap((a, b), swing),
                        "{kind} {w}: door at {x}: {shape:?}"
                    );
                }
            }
        }
        for (kind, lo, hi) in [
            ("server_room", 730, 870),
            ("laboratory", 330, 470),
            ("seminar_room", 280, 420),
            ("workshop", 230, 370),
            ("storage", 730, 870),
        ] {
            let shut = (0..1000)
                .filter(|_| door(kind, 5.0, 0.9, false, &[], &mut r).is_none())
                .count();
            assert!((lo..=hi).contains(&shut), "{kind}: {shut}");
        }
    }

    /// Whether a scan can stand in a room `w` by `d` with furniture `s`:
    /// a spot 0.5 m from the walls and 0.4 m from the furniture.
    fn has_free_spot(w: f64, d: f64, s: &[Shape]) -> bool {
        let n = 40;
        (0..=n).any(|i| {
            (0..=n).any(|j| {
                let x = 0.5 + (w - 1.0) * i as f64 / n as f64;
                let y = 0.5 + (d - 1.0) * j as f64 / n as f64;
                s.iter().all(|p| p.horizontal_distance(x, y) > 0.4)
            })
        })
    }

    #[test]
    fn every_room_leaves_a_free_spot_for_a_scan() {
        let mut r = crate::rng::rng(4);
        for kind in &INSTITUTE_KINDS[1..] {
            for _ in 0..300 {
                let ([w, d, _], s) = room(kind, &mut r);
                assert!(has_free_spot(w, d, &s), "{kind} {w:.2} x {d:.2}");
            }
        }
    }

    #[test]
    fn a_laboratory_has_benches_islands_with_aisles_fume_hoods_a_sink_and_tall_cabinets() {
        let mut r = crate::rng::rng(5);
        let (mut side_hoods, mut back_hoods, mut stools, mut shelves, mut showers) =
            (0, 0, 0, 0, 0);
        for _ in 0..300 {
            let ([w, d, h], s) = room("laboratory", &mut r);
            let b = boxes(&s);
            // Tops 0.04 m thick at 0.88-0.92 m: 4 m of them at least.
            let run: f64 = b
                .iter()
                .filter(|b| (0.88..=0.92).contains(&b.1[2]) && (size(b)[2] - 0.04).abs() < 1e-9)
                .map(|b| size(b)[0].max(size(b)[1]))
                .sum();
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
            let run: f64 = b
                .iter()
                .filter(|b| (0.88..=0.95).contains(&b.1[2]) && (size(b)[2] - 0.05).abs() < 1e-9)
                .map(|b| size(b)[0].max(size(b)[1]))
                .sum();
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
