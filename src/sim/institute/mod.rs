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

mod corridor;
mod laboratory;
mod seminar_room;
mod server_room;
mod workshop;

use super::geometry::{cuboid, Shape};
use super::hotel::door_unless_shut;
use super::office_floor::{mirrored_in_one_of_two, FloorPlan};
use super::scenes::u;
use corridor::corridor_fittings;
use laboratory::laboratory;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use seminar_room::seminar_room;
use server_room::server_room;
use workshop::workshop;

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
    mirrored_in_one_of_two(&t, w, r, s);
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
    door_unless_shut(shut, width, door, SWING, furniture, r)
}

/// A draw from `lo..hi`, or `lo` where that leaves nothing to draw from.
pub(in crate::sim) fn between(r: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
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
pub(in crate::sim) struct Side {
    wall: Wall,
    w: f64,
    d: f64,
}

impl Side {
    /// The room's point `a` along the wall and `o` out from it.
    pub(in crate::sim) fn point(&self, a: f64, o: f64) -> [f64; 2] {
        match self.wall {
            Wall::Left => [o, a],
            Wall::Right => [self.w - o, a],
            Wall::Back => [a, self.d - o],
            Wall::Front => [a, o],
        }
    }

    /// A box from `a` to `a + len` along the wall, `o` to `o + depth`
    /// out from it, `z` to `z + height` up.
    pub(in crate::sim) fn block(
        &self,
        a: f64,
        len: f64,
        o: f64,
        depth: f64,
        z: f64,
        height: f64,
    ) -> Shape {
        let [p, q] = [self.point(a, o), self.point(a + len, o + depth)];
        cuboid(
            [p[0].min(q[0]), p[1].min(q[1]), z],
            [(q[0] - p[0]).abs(), (q[1] - p[1]).abs(), height],
        )
    }

    /// An upright cylinder at `a` along the wall, `o` out from it.
    pub(in crate::sim) fn cylinder(&self, a: f64, o: f64, radius: f64, z0: f64, z1: f64) -> Shape {
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
pub(in crate::sim) fn walls(w: f64, d: f64) -> [Side; 4] {
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

// --- Store rooms ---

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::office_floor::{
        assert_doors_swing_clear, assert_free_spots, assert_furniture_inside, furnished_room,
    };

    /// A room of `kind` of a size drawn from the plan's ranges.
    pub(super) fn room(kind: &str, r: &mut ChaCha8Rng) -> ([f64; 3], Vec<Shape>) {
        furnished_room(&INSTITUTE, kind, r)
    }

    /// A room size drawn from the plan's ranges, for the kinds whose
    /// layout functions are called directly (unmirrored).
    pub(super) fn draw(kind: &str, r: &mut ChaCha8Rng) -> [f64; 3] {
        let (lo, hi) = room_width(kind);
        [
            u(r, lo, hi),
            u(r, INSTITUTE.row_depth.0, INSTITUTE.row_depth.1),
            u(r, INSTITUTE.ceiling.0, INSTITUTE.ceiling.1),
        ]
    }

    /// The summed length of the boxes `thick` m thick whose tops lie in
    /// `tops` (bench and workbench runs).
    pub(super) fn top_run(
        b: &[([f64; 3], [f64; 3])],
        tops: std::ops::RangeInclusive<f64>,
        thick: f64,
    ) -> f64 {
        b.iter()
            .filter(|b| tops.contains(&b.1[2]) && (size(b)[2] - thick).abs() < 1e-9)
            .map(|b| size(b)[0].max(size(b)[1]))
            .sum()
    }

    pub(super) fn size(b: &([f64; 3], [f64; 3])) -> [f64; 3] {
        [b.1[0] - b.0[0], b.1[1] - b.0[1], b.1[2] - b.0[2]]
    }

    /// The horizontal distance between two footprints (0 where they
    /// touch or overlap).
    pub(super) fn gap(a: ([f64; 2], [f64; 2]), b: ([f64; 2], [f64; 2])) -> f64 {
        let dx = (a.0[0] - b.1[0]).max(b.0[0] - a.1[0]).max(0.0);
        let dy = (a.0[1] - b.1[1]).max(b.0[1] - a.1[1]).max(0.0);
        dx.hypot(dy)
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        let mut kinds = INSTITUTE_KINDS[1..].to_vec();
        kinds.push("storage");
        // Above the ceiling's margin only slim ducts and rods reach:
        // fume-hood exhausts, a projector's rod, a tray's hangers.
        assert_furniture_inside(&INSTITUTE, &kinds, 0.15, &mut r);
    }

    #[test]
    fn doors_keep_their_swing_clear_and_some_are_shut() {
        let mut r = crate::rng::rng(3);
        assert_doors_swing_clear(&INSTITUTE, &INSTITUTE_KINDS[1..], SWING, &mut r);
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

    #[test]
    fn every_room_leaves_a_free_spot_for_a_scan() {
        let mut r = crate::rng::rng(4);
        assert_free_spots(&INSTITUTE, &INSTITUTE_KINDS[1..], &mut r);
    }
}
