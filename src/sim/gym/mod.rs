//! Sports-centre floors: the fitness floor of a leisure or university
//! sports centre, a scene family written by a helper for issue 18's
//! twenty-seventh round, who chose the building and its kinds: the layout
//! of [`super::office_floor`] (a corridor between two rows of rooms, one
//! ceiling), its rooms furnished as real ones are.
//!
//! Why this building: a fitness floor is a public building a mobile
//! robot maps and cleans (floor scrubbers and security robots run in
//! sports centres), none of the other families is one, and in larger
//! centres the floor really is a corridor with rooms off it: a cardio
//! room, a weights room, two or more group-exercise studios and the two
//! changing rooms, behind ordinary doors. The four kinds are the rooms
//! such a floor has most of; the corridor is the fifth. Each is
//! furnished from what such rooms in real centres hold, with their usual
//! sizes and spacings (clearances behind treadmills, aisles between
//! racks, lockers and benches) and their usual variation: which
//! machines make up the rows and how many, which way they face, whether
//! the racks or the dumbbells take the window wall, what a studio
//! stores, whether it is a cycling studio, how a changing room's
//! lockers, benches and showers are arranged.
//!
//! The corridor has ceiling lights down its middle and along its walls
//! notice boards and timetable screens, fire extinguishers, drinking
//! fountains or water coolers, benches, a vending machine now and then,
//! bins and a first-aid or defibrillator cabinet; its middle is left
//! clear. Cardio rooms have rows of machines of one model a row,
//! treadmills (a deck at 0.2-0.3 m, a console at 1.25-1.45 m),
//! cross-trainers, upright and recumbent bikes, stair climbers and
//! rowers, 0.45-0.7 m apart side by side, facing the window wall or a
//! side wall with aisles of 0.9-1.8 m behind each row (most behind
//! treadmills), televisions hung before the front row or on the wall they
//! face, a wipes-and-sanitiser stand by the door and in some a water
//! cooler. Weights rooms have power racks (four uprights 2.2-2.4 m high,
//! a pull-up bar, most with a barbell on its hooks and some with plates
//! on it, safety arms, some on a lifting platform) with plate trees
//! between them along one wall, a two-tier dumbbell rack along another
//! with benches before it, selectorised machines (a weight-stack tower,
//! a seat and pads: presses, pulldowns, leg presses) side by side along
//! the third, and in the middle of some a free-standing cable crossover
//! or more benches. Studios are group-exercise studios: a mostly open
//! floor facing a front wall (the x = 0 wall or the window wall) with in
//! most an instructor's platform, a sound cabinet and speakers high on
//! the wall; along a side wall storage of stacked steps, mat rolls in a
//! basket, exercise balls, a pump-set rack or small dumbbells; in some a
//! barre along a wall; and one studio in four is a cycling studio of
//! spin bikes in staggered rows facing the instructor's bike on its
//! platform, with pedestal fans. Changing rooms have banks of lockers
//! (1.8-2.0 m) along the side walls, benches before them, in wide rooms
//! an island of back-to-back lockers or a bench down the middle, where
//! the second side wall has no lockers a vanity counter with hair
//! dryers, and at the back a shower area behind a tiled partition
//! 2.1-2.4 m high with an opening, with cubicles or open shower heads,
//! in some with toilet cubicles. Doors are
//! ordinary doors in the corridor wall (the leaf not modelled), shut in
//! most changing rooms (they close on their own) and in some of the
//! others, standing where the room leaves a door's swing clear. Gaps
//! left in a row are equipment stores (never scanned): shelving, and
//! stacked mats or open racks, behind a mostly shut door.
//!
//! What it leaves out: the floor has no reception, café, sports hall,
//! swimming pool, offices or stairs, though a real centre has them; the
//! cardio and weights rooms are separate rooms, not one open gym hall,
//! and every room opens onto the corridor through its own single door
//! (no double doors, no glazed walls onto the corridor, no modesty screen
//! inside a changing room's door). Mirrors, glass and windows are left
//! out (a lidar sees a mirror as more room; here a mirrored wall is a
//! plain wall), as are people, cables, rubber flooring, ceiling fans,
//! ducts and everything above the ceiling; machines are boxes of their
//! parts (no curved frames, belts, flywheels or pulleys as such, a
//! barbell is a square bar), dumbbells and plates are boxes of their
//! size. Also left out: functional-training rigs, punching bags,
//! kettlebells, medicine balls and plyometric boxes in the weights room,
//! machines along its corridor wall or in free rows in its middle,
//! saunas off the changing rooms, and the spin bikes' flywheel covers,
//! studio mirrors and sound desks beyond one cabinet. A floor has one cardio room, one weights room and two changing
//! rooms (men's and women's, furnished alike), and studios in the rest of
//! its rows.

mod cardio_room;
mod changing_room;
mod corridor;
mod studio;
mod weight_room;

use super::geometry::{cuboid, Shape};
use super::hotel::door_unless_shut;
use super::institute::{between, walls};
use super::office_floor::{mirrored_in_one_of_two, FloorPlan};
use super::scenes::u;
use cardio_room::cardio_room;
use changing_room::changing_room;
use corridor::corridor_fittings;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use studio::studio;
use weight_room::weight_room;

/// The kinds of place on a sports-centre floor, its ground-truth labels.
pub const GYM_KINDS: [&str; 5] = [
    "corridor",
    "cardio_room",
    "weight_room",
    "studio",
    "changing_room",
];

/// The sports-centre floor: a cardio room and a changing room on one
/// side, a weights room and a changing room on the other, studios
/// filling both rows.
pub const GYM: FloorPlan = FloorPlan {
    kinds: GYM_KINDS,
    width: room_width,
    // Deep rooms: a studio or a gym room is about square.
    row_depth: (7.0, 9.5),
    // Groups walk along it to and from the studios between classes.
    corridor_width: (2.0, 2.8),
    // Sports rooms are higher than offices (a raised arm, a jump).
    ceiling: (3.0, 3.6),
    north: ["cardio_room", "changing_room"],
    south: ["weight_room", "changing_room"],
    filler: "studio",
    open: &[],
    furnish,
    fittings: corridor_fittings,
    door,
    glazed: &[],
};

/// Width along the corridor of a room of a sports-centre kind (m),
/// lowest and highest.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "cardio_room" => (8.0, 14.0),
        "weight_room" => (8.0, 14.0),
        "studio" => (7.0, 12.0),
        "changing_room" => (4.5, 8.0),
        _ /* equipment store */ => (0.5, 7.0),
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
        "cardio_room" => cardio_room(w, d, h, r, &mut t),
        "weight_room" => weight_room(w, d, h, r, &mut t),
        "studio" => studio(w, d, h, r, &mut t),
        "changing_room" => changing_room(w, d, h, r, &mut t),
        _ => equipment_store(w, d, h, r, &mut t),
    }
    mirrored_in_one_of_two(&t, w, r, s);
}

/// Where a room's door goes: shut in seven changing rooms of ten (their
/// doors close on their own), two studios of five (a class on), one
/// cardio room of five, a quarter of the weights rooms and most stores;
/// else where the corridor wall is clear of furniture for a door's
/// swing ([`SWING`]) into the room.
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
        "changing_room" => 0.7,
        "studio" => 0.4,
        "cardio_room" => 0.2,
        "weight_room" => 0.25,
        _ => 0.85,
    };
    door_unless_shut(shut, width, door, SWING, furniture, r)
}

// --- Equipment stores ---

/// An equipment store (a gap left in a row, never scanned): steel
/// shelving of boxes along a side wall past the door's swing, stacks of
/// mats or open racks along the other where it is wide enough.
fn equipment_store(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let [left, right, ..] = walls(w, d);
    let depth = (w / 2.0 - 0.1).clamp(0.1, 0.6);
    let sh = u(r, 1.8, 2.2).min(h - 0.4);
    let y0 = SWING - 0.2;
    for level in 0..5 {
        let z = 0.1 + level as f64 * (sh - 0.15) / 4.0;
        s.push(left.block(y0, d - y0 - 0.1, 0.0, depth, z, 0.02));
        if r.random::<f64>() < 0.75 {
            let run = u(r, 0.4, d - y0 - 0.3);
            let a = between(r, y0 + 0.05, d - 0.15 - run);
            s.push(left.block(a, run, 0.0, depth, z + 0.02, u(r, 0.15, 0.35)));
        }
    }
    if w >= 2.0 * depth + 1.4 {
        let mut a = y0;
        while a + 1.0 < d - 0.1 {
            let (ml, md) = (u(r, 0.9, 1.2), u(r, 0.5, 0.6).min(w - depth - 1.0));
            if r.random::<bool>() {
                s.push(right.block(a, ml.min(d - 0.1 - a), 0.0, md, 0.0, u(r, 0.2, 1.2)));
            } else {
                s.push(cuboid([w - md, a, 0.0], [md, 0.04, 1.0]));
                s.push(cuboid([w - md, a, 0.96], [md, ml.min(d - 0.1 - a), 0.04]));
            }
            a += ml + u(r, 0.2, 0.6);
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::sim::hotel::extent;
    use crate::sim::office_floor::{
        assert_doors_swing_clear, assert_free_spots, assert_furniture_inside, furnished_room,
    };

    /// A room of `kind` of a size drawn from the plan's ranges.
    pub(in crate::sim::gym) fn room(kind: &str, r: &mut ChaCha8Rng) -> ([f64; 3], Vec<Shape>) {
        furnished_room(&GYM, kind, r)
    }

    /// Lowest and highest corner and height of each shape.
    pub(in crate::sim::gym) fn extents(s: &[Shape]) -> Vec<([f64; 2], [f64; 2], f64, f64)> {
        s.iter().map(extent).collect()
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        let mut kinds = GYM_KINDS[1..].to_vec();
        kinds.push("storage");
        // Above the ceiling's margin only slim rods reach: the
        // televisions' drop rods.
        assert_furniture_inside(&GYM, &kinds, 0.05, &mut r);
    }

    #[test]
    fn doors_keep_their_swing_clear_and_some_are_shut() {
        let mut r = crate::rng::rng(3);
        assert_doors_swing_clear(&GYM, &GYM_KINDS[1..], SWING, &mut r);
        for (kind, lo, hi) in [
            ("changing_room", 630, 770),
            ("studio", 330, 470),
            ("weight_room", 180, 320),
            ("cardio_room", 140, 260),
            ("storage", 780, 920),
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
        assert_free_spots(&GYM, &GYM_KINDS[1..], &mut r);
    }
}
