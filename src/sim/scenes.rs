//! Procedural scenes. Every size and count is drawn from ranges with the
//! seeded RNG, so each room instance differs. Coordinates: metres, z up,
//! floor at z = 0.

use super::geometry::{cuboid, Shape};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;

pub(crate) fn u(r: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    r.random_range(lo..hi)
}

const WALL: f64 = 0.2;

/// Floor, ceiling and four walls around the interior [x0, x0+l] x [y0, y0+w].
pub fn room_shell(x0: f64, y0: f64, l: f64, w: f64, h: f64) -> Vec<Shape> {
    vec![
        cuboid(
            [x0 - WALL, y0 - WALL, -WALL],
            [l + 2.0 * WALL, w + 2.0 * WALL, WALL],
        ),
        cuboid(
            [x0 - WALL, y0 - WALL, h],
            [l + 2.0 * WALL, w + 2.0 * WALL, WALL],
        ),
        cuboid([x0 - WALL, y0 - WALL, 0.0], [WALL, w + 2.0 * WALL, h]),
        cuboid([x0 + l, y0 - WALL, 0.0], [WALL, w + 2.0 * WALL, h]),
        cuboid([x0, y0 - WALL, 0.0], [l, WALL, h]),
        cuboid([x0, y0 + w, 0.0], [l, WALL, h]),
    ]
}

/// A frame for placing furniture: local x, y (metres) turned by `yaw`
/// about (x, y). Parts are boxes given by local centre, footprint, bottom
/// height and height.
#[derive(Clone, Copy)]
pub(crate) struct Frame {
    pub(crate) x: f64,
    pub(crate) y: f64,
    pub(crate) yaw: f64,
}

impl Frame {
    pub(crate) fn at(x: f64, y: f64, yaw: f64) -> Frame {
        Frame { x, y, yaw }
    }
    /// A local point in room coordinates.
    pub(crate) fn point(&self, local: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.yaw.sin_cos();
        [
            self.x + c * local[0] - s * local[1],
            self.y + s * local[0] + c * local[1],
        ]
    }
    pub(crate) fn part(
        &self,
        out: &mut Vec<Shape>,
        centre: [f64; 2],
        size: [f64; 2],
        z0: f64,
        h: f64,
    ) {
        let [x, y] = self.point(centre);
        out.push(Shape::OrientedBox {
            centre: [x, y, z0 + h / 2.0],
            half: [size[0] / 2.0, size[1] / 2.0, h / 2.0],
            yaw: self.yaw,
        });
    }
}

/// An office chair centred at (x, y) facing `yaw`: five-star base, column,
/// seat and back.
pub(crate) fn chair(out: &mut Vec<Shape>, x: f64, y: f64, yaw: f64) {
    let f = Frame::at(x, y, yaw);
    f.part(out, [0.0, 0.0], [0.6, 0.06], 0.05, 0.05);
    f.part(out, [0.0, 0.0], [0.06, 0.6], 0.05, 0.05);
    f.part(out, [0.0, 0.0], [0.06, 0.06], 0.1, 0.35);
    f.part(out, [0.0, 0.0], [0.48, 0.46], 0.42, 0.07);
    f.part(out, [-0.22, 0.0], [0.05, 0.44], 0.55, 0.5);
}

/// A table or desk in a frame: top and two side panels (or legs).
pub(crate) fn table(out: &mut Vec<Shape>, f: &Frame, centre: [f64; 2], size: [f64; 2], h: f64) {
    f.part(out, centre, size, h - 0.03, 0.03);
    for side in [-1.0, 1.0] {
        let x = centre[0] + side * (size[0] / 2.0 - 0.03);
        f.part(out, [x, centre[1]], [0.05, size[1] * 0.9], 0.0, h - 0.03);
    }
}

/// A bookcase against a wall: carcass, `levels` shelves and books of
/// uneven depth and height on each shelf (a filled case is not a flat
/// face). Local x along the wall, y out of the wall.
pub(crate) fn bookcase(
    out: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    f: &Frame,
    x0: f64,
    len: f64,
    h: f64,
) {
    let depth = 0.32;
    let levels = ((h / 0.34).floor() as usize).max(2);
    f.part(out, [x0 + len / 2.0, 0.01], [len, 0.02], 0.0, h);
    for side in [0.01, len - 0.01] {
        f.part(out, [x0 + side, depth / 2.0], [0.02, depth], 0.0, h);
    }
    for i in 0..levels {
        let z = h * i as f64 / levels as f64;
        f.part(out, [x0 + len / 2.0, depth / 2.0], [len, depth], z, 0.02);
        // Runs of books, with gaps.
        let mut x = x0 + 0.03;
        while x < x0 + len - 0.1 {
            let run = u(r, 0.1, 0.4).min(x0 + len - 0.03 - x);
            if r.random::<f64>() < 0.8 {
                let d = u(r, 0.15, 0.29);
                let bh = u(r, 0.17, 0.3).min(h / levels as f64 - 0.04);
                f.part(out, [x + run / 2.0, 0.02 + d / 2.0], [run, d], z + 0.02, bh);
            }
            x += run + u(r, 0.0, 0.1);
        }
    }
}

/// A generated room: its shapes and interior size. `shapes[..furniture]`
/// stand on the floor (the sensor keeps clear of them); the rest are
/// overhead services and the shell.
pub struct Room {
    /// Everything the sensor can hit: furniture first, then the shell.
    pub shapes: Vec<Shape>,
    /// Interior length and width (m); the floor spans [0, size] in x and y.
    pub size: [f64; 2],
    /// How many of `shapes` are furniture standing on the floor.
    pub furniture: usize,
}

/// The indoor kinds (KyushuIndoor's categories).
pub const INDOOR_KINDS: [&str; 5] = ["office", "kitchen", "lab", "study_room", "corridor"];

/// Interior length, width and height of a room of a kind, drawn from the
/// ranges its use gives it (see [`indoor_room`]).
pub fn room_size(kind: &str, r: &mut ChaCha8Rng) -> [f64; 3] {
    let (l, w, h) = match kind {
        "office" => ((6.0, 10.0), (5.0, 8.0), (2.6, 2.8)),
        "kitchen" => ((3.0, 5.0), (2.4, 3.6), (2.4, 2.7)),
        "lab" => ((10.0, 16.0), (7.0, 10.0), (3.0, 3.6)),
        "study_room" => ((5.0, 8.0), (4.0, 6.0), (2.5, 2.8)),
        _ /* corridor */ => ((20.0, 50.0), (1.8, 2.8), (2.5, 3.0)),
    };
    [u(r, l.0, l.1), u(r, w.0, w.1), u(r, h.0, h.1)]
}

/// A room built to `plan` as rooms of one kind in one building are: each
/// side within +-10 % of the plan's (the height within +-3 %).
pub fn room_from_plan(plan: [f64; 3], r: &mut ChaCha8Rng) -> [f64; 3] {
    [
        plan[0] * u(r, 0.9, 1.1),
        plan[1] * u(r, 0.9, 1.1),
        plan[2] * u(r, 0.97, 1.03),
    ]
}

/// One room of a kind. Each kind has the floor area and furniture its use
/// gives it in a university building: a kitchenette of 7-18 m2 with
/// counters, wall cupboards and a fridge; a group study room of 20-48 m2
/// lined with bookcases round a large table; an open-plan office of
/// 30-80 m2 with desk islands behind partitions; a lab of 70-160 m2 with
/// island benches under reagent shelves, fume cupboards and ducts under a
/// high ceiling; a corridor 1.8-2.8 m wide and 20-50 m long with doors,
/// notice boards and the odd bench or vending machine. Chairs stand at any
/// angle.
pub fn indoor_room(kind: &str, size: [f64; 3], r: &mut ChaCha8Rng) -> Room {
    let mut s = Vec::new();
    let mut overhead = Vec::new();
    let [l, w, h] = size;
    let wall_x = Frame::at(0.0, 0.0, 0.0); // along y = 0, facing +y
    match kind {
        "office" => {
            // Islands of desk pairs facing each other across a partition,
            // islands along x, aisles between them.
            let desk = [1.2 + 0.2 * r.random::<f64>(), 0.7];
            let mut y = 1.2;
            while y + 1.4 < w - 1.0 {
                let mut x = 1.0;
                while x + desk[0] < l - 0.6 {
                    let f = Frame::at(x + desk[0] / 2.0, y + 0.7, 0.0);
                    f.part(&mut s, [0.0, 0.0], [desk[0], 0.03], 0.72, 0.45);
                    for side in [-1.0, 1.0] {
                        if r.random::<f64>() < 0.9 {
                            table(&mut s, &f, [0.0, side * 0.36], desk, 0.72);
                            f.part(&mut s, [u(r, -0.3, 0.3), side * 0.2], [0.55, 0.05], 0.78, 0.35);
                            let cy = side * u(r, 0.9, 1.2);
                            chair(&mut s, f.x + u(r, -0.2, 0.2), f.y + cy, u(r, 0.0, TAU));
                        }
                    }
                    x += desk[0] + 0.02;
                }
                y += 1.4 + u(r, 1.6, 2.0);
            }
            // Filing cabinets and lockers along the far wall.
            let back = Frame::at(0.0, w, std::f64::consts::PI);
            let mut x = -l + 0.3;
            while x < -1.2 {
                if r.random::<f64>() < 0.7 {
                    back.part(&mut s, [x + 0.45, 0.25], [0.9, 0.45], 0.0, u(r, 1.1, 1.9));
                }
                x += 0.95;
            }
        }
        "kitchen" => {
            let run = l - 0.8;
            wall_x.part(&mut s, [run / 2.0, 0.3], [run, 0.6], 0.0, 0.9);
            let upper = u(r, 1.45, 1.6);
            wall_x.part(&mut s, [run / 2.0, 0.18], [run, 0.35], upper, 0.7);
            wall_x.part(&mut s, [u(r, 0.4, run - 0.4), 0.25], [0.5, 0.35], 0.9, 0.3);
            wall_x.part(&mut s, [run + 0.4, 0.35], [0.7, 0.7], 0.0, u(r, 1.6, 1.9));
            if r.random::<f64>() < 0.6 {
                // The L's second leg along x = 0.
                wall_x.part(&mut s, [0.3, 0.6 + w * 0.25], [0.6, w * 0.5], 0.0, 0.9);
                wall_x.part(&mut s, [0.18, 0.6 + w * 0.25], [0.35, w * 0.5], upper, 0.7);
            }
            if w > 2.8 {
                let f = Frame::at(l * 0.55, w * 0.65, u(r, -0.2, 0.2));
                table(&mut s, &f, [0.0, 0.0], [1.0, 0.7], 0.72);
                for _ in 0..r.random_range(2..=3) {
                    let a = u(r, 0.0, TAU);
                    chair(&mut s, f.x + 0.75 * a.cos(), f.y + 0.6 * a.sin(), a + std::f64::consts::PI);
                }
            }
        }
        "lab" => {
            // Island benches with a reagent shelf on posts above.
            let mut y = 1.8;
            while y < w - 2.0 {
                let depth = u(r, 1.2, 1.6);
                s.push(cuboid([2.0, y, 0.0], [l - 4.0, depth, 0.9]));
                let z = u(r, 1.5, 1.8);
                s.push(cuboid([2.0, y + depth * 0.4, z], [l - 4.0, 0.3, 0.03]));
                let mut px = 2.0;
                while px < l - 2.0 {
                    s.push(cuboid([px, y + depth * 0.45, 0.9], [0.05, 0.05, z - 0.9]));
                    // Instruments and glassware on the bench.
                    if r.random::<f64>() < 0.6 {
                        let (a, b) = (u(r, 0.2, 0.6), u(r, 0.2, 0.5));
                        s.push(cuboid([px + 0.2, y + 0.05, 0.9], [a, b, u(r, 0.15, 0.5)]));
                    }
                    px += 1.5;
                }
                for _ in 0..2 {
                    let x = u(r, 2.5, l - 2.5);
                    s.push(Shape::Cylinder {
                        centre: [x, y - 0.35],
                        radius: 0.17,
                        z0: 0.0,
                        z1: 0.65,
                    });
                }
                y += depth + u(r, 1.6, 2.0);
            }
            // Fume cupboards on one end wall, tall cabinets on a long wall.
            let end = Frame::at(0.0, 0.0, std::f64::consts::FRAC_PI_2);
            let mut yy = 0.8;
            while yy < w - 1.8 {
                end.part(&mut s, [yy + 0.75, -0.45], [1.5, 0.9], 0.0, 2.4);
                yy += u(r, 1.7, 2.4);
            }
            let mut x = 1.2;
            while x < l - 1.5 {
                if r.random::<f64>() < 0.7 {
                    s.push(cuboid([x, 0.0, 0.0], [1.0, 0.6, u(r, 1.9, 2.4)]));
                }
                x += 1.3;
            }
            // Ducts, pipes and a cable tray under the ceiling.
            let mut yd = u(r, 0.5, 1.5);
            while yd < w - 0.5 {
                let size = if r.random::<bool>() { 0.35 } else { 0.1 };
                overhead.push(cuboid([0.0, yd, h - 0.3 - size], [l, size, size]));
                yd += u(r, 1.5, 3.0);
            }
        }
        "study_room" => {
            // Bookcases along both long walls, a whiteboard on an end wall.
            let near = Frame::at(0.0, 0.0, 0.0);
            let far = Frame::at(l, w, std::f64::consts::PI);
            for f in [near, far] {
                let mut x = 0.2;
                while x + 0.9 < l - 0.2 {
                    if r.random::<f64>() < 0.85 {
                        let height = u(r, 1.8, 2.1);
                        bookcase(&mut s, r, &f, x, 0.9, height);
                    }
                    x += 0.92;
                }
            }
            s.push(cuboid([l - 0.03, w * 0.5 - 0.9, 0.8], [0.02, 1.8, 1.2]));
            // A large table with chairs round it.
            let (tl, tw) = ((l - 2.4).min(3.2), (w - 2.4).clamp(0.9, 1.3));
            let f = Frame::at(l / 2.0, w / 2.0, u(r, -0.05, 0.05));
            table(&mut s, &f, [0.0, 0.0], [tl, tw], 0.72);
            let per_side = (tl / 0.7).floor() as usize;
            for side in [-1.0, 1.0] {
                for i in 0..per_side {
                    if r.random::<f64>() < 0.8 {
                        let x = -tl / 2.0 + 0.35 + i as f64 * 0.7 + u(r, -0.1, 0.1);
                        let y = side * (tw / 2.0 + u(r, 0.2, 0.45));
                        let yaw = side * std::f64::consts::FRAC_PI_2 + u(r, -0.6, 0.6);
                        let [cx, cy] = f.point([x, y]);
                        chair(&mut s, cx, cy, yaw);
                    }
                }
            }
        }
        _ /* corridor */ => {
            let mut x = u(r, 1.0, 3.0);
            while x < l - 1.0 {
                // Door frames and pilasters along both walls, notice boards
                // between them.
                let side = if r.random::<bool>() { 0.0 } else { w - 0.15 };
                s.push(cuboid([x, side, 0.0], [0.3, 0.15, h]));
                if r.random::<f64>() < 0.4 {
                    let board = if side == 0.0 { 0.0 } else { w - 0.03 };
                    s.push(cuboid([x + 0.8, board, 1.0], [u(r, 0.8, 1.5), 0.03, 0.9]));
                }
                x += u(r, 2.5, 5.0);
            }
            if r.random::<f64>() < 0.5 {
                s.push(cuboid([l * u(r, 0.2, 0.8), 0.0, 0.0], [1.5, 0.4, 0.45]));
            }
            if r.random::<f64>() < 0.3 {
                s.push(cuboid([l * u(r, 0.2, 0.8), w - 0.75, 0.0], [1.0, 0.75, 1.8]));
            }
        }
    }
    let furniture = s.len();
    s.extend(overhead);
    s.extend(room_shell(0.0, 0.0, l, w, h));
    Room {
        shapes: s,
        size: [l, w],
        furniture,
    }
}

/// A free sensor position inside a room: away from walls and furniture.
pub fn free_position(room: &Room, r: &mut ChaCha8Rng, margin: f64) -> [f64; 2] {
    let [l, w] = room.size;
    let mut best = [l / 2.0, w / 2.0];
    let mut best_clear = -1.0;
    for _ in 0..200 {
        let p = [
            u(r, margin, (l - margin).max(margin + 0.01)),
            u(r, margin, (w - margin).max(margin + 0.01)),
        ];
        // Clearance to the furniture.
        let clear = room.shapes[..room.furniture]
            .iter()
            .map(|s| s.horizontal_distance(p[0], p[1]))
            .fold(f64::INFINITY, f64::min);
        if clear > 0.4 {
            return p;
        }
        if clear > best_clear {
            best_clear = clear;
            best = p;
        }
    }
    best
}
