//! School floors, a scene family written for issue 18 after its new
//! descriptors had been committed, so that none of them was shaped on it:
//! the layout of [`super::office_floor`] (a corridor between two rows of
//! rooms, one ceiling) with a school's rooms. Classrooms of rows of pupil
//! desks facing a board, a library of shelving stacks and reading tables,
//! a cafeteria of long tables with benches and a serving counter, open to
//! the corridor, a staff room with sofas, a kitchenette and pigeonholes,
//! and corridors lined with lockers.

use super::geometry::{cuboid, Shape};
use super::office_floor::{door_anywhere, FloorPlan};
use super::scenes::{chair, table, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The kinds of place on a school floor, its ground-truth labels.
pub const SCHOOL_KINDS: [&str; 5] = [
    "corridor",
    "classroom",
    "library",
    "cafeteria",
    "staff_room",
];

/// The school floor.
pub const SCHOOL: FloorPlan = FloorPlan {
    kinds: SCHOOL_KINDS,
    width: room_width,
    row_depth: (6.5, 8.5),
    corridor_width: (2.4, 3.2),
    ceiling: (2.9, 3.3),
    north: ["library", "classroom"],
    south: ["cafeteria", "staff_room"],
    filler: "classroom",
    open: &["cafeteria"],
    furnish,
    fittings: lockers,
    door: door_anywhere,
    glazed: &[],
};

/// Width along the corridor of a room of a school kind (m), lowest and
/// highest.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "classroom" => (7.0, 9.5),
        "library" => (10.0, 16.0),
        "cafeteria" => (12.0, 18.0),
        "staff_room" => (4.0, 6.0),
        _ /* storage */ => (0.5, 7.0),
    }
}

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// corridor wall at y = 0.
fn furnish(kind: &str, [w, d, _h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    match kind {
        "classroom" => {
            // A board on the wall at x = w, the teacher's desk before it,
            // rows of two-pupil desks facing it.
            s.push(cuboid([w - 0.03, d * 0.25, 0.9], [0.03, d * 0.5, 1.2]));
            let teacher = Frame::at(w - 1.3, d * u(r, 0.3, 0.7), FRAC_PI_2);
            table(s, &teacher, [0.0, 0.0], [1.4, 0.7], 0.74);
            let mut x = w - 2.8;
            while x > 1.0 {
                let mut y = 0.9;
                while y + 1.3 < d - 0.5 {
                    if r.random::<f64>() < 0.9 {
                        let f = Frame::at(x, y + 0.6, FRAC_PI_2);
                        table(s, &f, [0.0, 0.0], [1.2, 0.5], 0.7);
                        // Behind the desk, facing the board (+x).
                        for dy in [-0.3, 0.3] {
                            let [cx, cy] = f.point([dy, 0.55]);
                            chair(s, cx, cy, u(r, -0.4, 0.4));
                        }
                    }
                    y += 1.6;
                }
                x -= u(r, 1.3, 1.5);
            }
        }
        "library" => {
            // Double-sided shelving stacks across the room, reading tables
            // in the space left.
            let stacks_end = w * u(r, 0.5, 0.65);
            let mut x = 0.8;
            while x < stacks_end {
                let len = d - 2.4;
                let h = u(r, 1.8, 2.2);
                s.push(cuboid([x, 1.2, 0.0], [0.6, len, 0.05]));
                for level in 0..5 {
                    let z = 0.1 + level as f64 * (h - 0.1) / 5.0;
                    s.push(cuboid([x, 1.2, z], [0.6, len, 0.02]));
                    // Books on both faces, in runs with gaps.
                    let mut y = 1.25;
                    while y < 1.2 + len - 0.2 {
                        let run = u(r, 0.2, 0.6);
                        if r.random::<f64>() < 0.8 {
                            let depth = u(r, 0.15, 0.27);
                            s.push(cuboid([x + 0.3 - depth, y, z + 0.02], [2.0 * depth, run, u(r, 0.18, 0.3)]));
                        }
                        y += run + u(r, 0.0, 0.15);
                    }
                }
                s.push(cuboid([x + 0.29, 1.2, 0.0], [0.02, len, h]));
                x += u(r, 1.7, 2.0);
            }
            let mut x = stacks_end + 1.2;
            while x + 1.8 < w - 0.5 {
                let f = Frame::at(x + 0.9, d * u(r, 0.4, 0.6), u(r, -0.1, 0.1));
                table(s, &f, [0.0, 0.0], [1.8, 0.9], 0.74);
                for side in [-1.0, 1.0] {
                    if r.random::<f64>() < 0.8 {
                        let [cx, cy] = f.point([u(r, -0.5, 0.5), side * 0.75]);
                        chair(s, cx, cy, u(r, 0.0, TAU));
                    }
                }
                x += 3.0;
            }
        }
        "cafeteria" => {
            // A serving counter along the far wall, long tables with
            // benches in rows.
            s.push(cuboid([1.0, d - 0.8, 0.0], [(w - 2.0).min(6.0), 0.8, 0.95]));
            s.push(cuboid([1.0, d - 0.6, 1.4], [(w - 2.0).min(6.0), 0.05, 0.5]));
            let mut x = 1.2;
            while x + 3.0 < w - 0.8 {
                let mut y = 1.6;
                while y + 1.8 < d - 1.8 {
                    let len = u(r, 2.4, 3.0);
                    s.push(cuboid([x, y + 0.45, 0.72], [len, 0.8, 0.04]));
                    s.push(cuboid([x + 0.1, y + 0.8, 0.0], [0.06, 0.1, 0.72]));
                    s.push(cuboid([x + len - 0.16, y + 0.8, 0.0], [0.06, 0.1, 0.72]));
                    for by in [y, y + 1.45] {
                        s.push(cuboid([x, by, 0.42], [len, 0.3, 0.04]));
                    }
                    y += 2.6;
                }
                x += u(r, 3.4, 3.8);
            }
        }
        "staff_room" => {
            // Pigeonholes and a kitchenette on the side walls, a sofa and a
            // low table, a round table with chairs.
            s.push(cuboid([0.0, 1.0, 0.0], [0.4, 1.6, 1.8]));
            s.push(cuboid([w - 0.6, 1.0, 0.0], [0.6, (d - 2.0).min(2.4), 0.9]));
            s.push(cuboid([w - 0.35, 1.0, 1.45], [0.35, (d - 2.0).min(2.4), 0.7]));
            let sofa = Frame::at(w * 0.4, d - 0.5, PI);
            sofa.part(s, [0.0, 0.0], [2.0, 0.85], 0.0, 0.45);
            sofa.part(s, [0.0, -0.35], [2.0, 0.2], 0.45, 0.4);
            s.push(cuboid([w * 0.4 - 0.5, d - 1.7, 0.0], [1.0, 0.5, 0.4]));
            let round = [w * u(r, 0.4, 0.6), d * 0.4];
            s.push(Shape::Cylinder {
                centre: round,
                radius: 0.5,
                z0: 0.72,
                z1: 0.75,
            });
            s.push(Shape::Cylinder {
                centre: round,
                radius: 0.06,
                z0: 0.0,
                z1: 0.72,
            });
            for _ in 0..r.random_range(2..=4) {
                let a = u(r, 0.0, TAU);
                chair(s, round[0] + 0.85 * a.cos(), round[1] + 0.85 * a.sin(), a + PI);
            }
        }
        _ /* storage */ => {
            let mut y = 0.6;
            while y < d - 0.5 {
                s.push(cuboid([0.0, y, 0.0], [(w - 0.1).min(0.5), 0.45, u(r, 1.6, 2.2)]));
                y += 0.5;
            }
        }
    }
}

/// Corridor fittings: banks of lockers along one wall (the other keeps
/// its doors in view), with gaps at random, and a notice board now and
/// then.
fn lockers(length: f64, width: f64, _height: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let side = if r.random::<bool>() {
        0.0
    } else {
        width - 0.45
    };
    let mut x = u(r, 0.5, 2.0);
    while x < length - 1.5 {
        let bank = u(r, 2.0, 5.0).min(length - 0.5 - x);
        s.push(cuboid([x, side, 0.0], [bank, 0.45, u(r, 1.8, 1.9)]));
        x += bank + u(r, 1.0, 4.0);
        if r.random::<f64>() < 0.3 {
            let board = if side == 0.0 { 0.0 } else { width - 0.03 };
            s.push(cuboid([x - 0.9, board, 1.1], [0.8, 0.03, 0.7]));
        }
    }
}
