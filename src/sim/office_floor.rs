//! A scene family written for issue 18's evaluation while the new
//! descriptors were being built (by another hand; none was tuned on it):
//! office floors. [`super::school`] was written after they were committed,
//! [`super::hospital`] later by another hand. Each floor is a
//! central corridor with a row of rooms on each side, doors open or shut
//! into it, all under one ceiling; the rooms are private offices, meeting
//! rooms, open-plan areas and restrooms (and storage closets, never
//! scanned, where a row has a gap left). A scan sees through open doors
//! into the rooms next to it, as on a real floor.
//!
//! Several floors are built per seed, each with its own sizes, as if each
//! came from another building; the scans of a kind are spread over rooms
//! of different floors, a few scans per room, at free spots anywhere in it.

use super::geometry::{cuboid, Shape};
use super::plans::place;
use super::scenes::{bookcase, chair, free_position, table, u, Frame, Room};
use super::{Scene, Shot, SimParams};
use crate::sim::SensorPose;
use rand::seq::SliceRandom;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The kinds of place on an office floor, its ground-truth labels.
pub const OFFICE_FLOOR_KINDS: [&str; 5] = [
    "corridor",
    "private_office",
    "meeting_room",
    "open_plan",
    "restroom",
];

/// What makes a kind of floor: its kinds, their sizes, which rooms every
/// floor has, and how rooms and the corridor are furnished. The office
/// floor is [`OFFICE`]; [`super::school`], [`super::hospital`],
/// [`super::hotel`] and [`super::mall`] have others.
pub struct FloorPlan {
    /// The scanned kinds, the corridor first.
    pub kinds: [&'static str; 5],
    /// Width along the corridor of a room of a kind (m), lowest and highest.
    pub width: fn(&str) -> (f64, f64),
    /// Depth of a row of rooms, away from the corridor (m).
    pub row_depth: (f64, f64),
    /// Corridor width (m).
    pub corridor_width: (f64, f64),
    /// Floor to ceiling (m).
    pub ceiling: (f64, f64),
    /// The rooms every floor has on the north and the south side.
    pub north: [&'static str; 2],
    /// As `north`, the other side.
    pub south: [&'static str; 2],
    /// The kind that fills a row (gaps narrower than it: storage closets).
    pub filler: &'static str,
    /// Kinds open to the corridor through a wide opening, not a door.
    pub open: &'static [&'static str],
    /// Furniture of a room of a kind, interior [0, w] x [0, d], the
    /// corridor wall at y = 0.
    pub furnish: fn(&str, [f64; 3], &mut ChaCha8Rng, &mut Vec<Shape>),
    /// Fittings of a corridor `length` long and `width` wide, `height` high.
    pub fittings: fn(f64, f64, f64, &mut ChaCha8Rng, &mut Vec<Shape>),
    /// Where a room's door goes in its corridor wall: see [`DoorAt`].
    pub door: DoorAt,
    /// Kinds whose corridor wall is a glazed shopfront: a low base,
    /// mullions and a fascia, the glass itself not modelled (a lidar sees
    /// mostly through it), the door or opening left clear under the
    /// fascia.
    pub glazed: &'static [&'static str],
}

/// Where the door of a room goes, from the room's kind, its width, the
/// door's width, whether the plan opens the room to the corridor, and the
/// room's furniture (interior [0, w] x [0, d], the corridor wall at
/// y = 0): the door's start along the wall from the room's start, or None
/// for a shut door (a plain wall).
pub type DoorAt = fn(&str, f64, f64, bool, &[Shape], &mut ChaCha8Rng) -> Option<f64>;

/// The office floor's doors, and the school's and the hospital's: shut in
/// one room of four (never in an open room), else anywhere along the wall
/// 0.1 m from its ends, whatever stands behind it.
pub fn door_anywhere(
    _kind: &str,
    width: f64,
    door: f64,
    open: bool,
    _furniture: &[Shape],
    r: &mut ChaCha8Rng,
) -> Option<f64> {
    if !open && r.random::<f64>() < 0.25 {
        return None;
    }
    Some(u(r, 0.1, (width - door - 0.1).max(0.11)))
}

/// The office floor.
pub const OFFICE: FloorPlan = FloorPlan {
    kinds: OFFICE_FLOOR_KINDS,
    width: room_width,
    row_depth: ROW_DEPTH,
    corridor_width: CORRIDOR_WIDTH,
    ceiling: CEILING,
    north: ["open_plan", "meeting_room"],
    south: ["restroom", "meeting_room"],
    filler: "private_office",
    open: &["open_plan"],
    furnish,
    fittings: corridor_fittings,
    door: door_anywhere,
    glazed: &[],
};

/// Width along the corridor of a room of an office-floor kind (m), lowest
/// and highest.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "private_office" => (2.8, 4.0),
        "meeting_room" => (4.0, 7.0),
        "open_plan" => (9.0, 16.0),
        "restroom" => (2.6, 3.6),
        _ /* storage */ => (0.5, 2.8),
    }
}

/// Depth of a row of rooms, away from the corridor (m).
pub const ROW_DEPTH: (f64, f64) = (4.5, 6.5);
/// Corridor width (m).
pub const CORRIDOR_WIDTH: (f64, f64) = (1.8, 2.4);
/// Floor to ceiling (m).
pub const CEILING: (f64, f64) = (2.6, 3.0);
const WALL: f64 = 0.12;

/// One room of a floor: its kind and interior, in floor coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct FloorRoom {
    /// One of the plan's kinds, or `storage`.
    pub kind: &'static str,
    /// Lowest x and y of the interior (m).
    pub min: [f64; 2],
    /// Highest x and y of the interior (m).
    pub max: [f64; 2],
    /// Furniture in floor coordinates (scans keep clear of it).
    furniture: Vec<Shape>,
}

/// A floor: its rooms (the corridor first) and everything a sensor can hit.
pub struct Floor {
    /// The corridor, then the rooms of both rows.
    pub rooms: Vec<FloorRoom>,
    /// Walls, floor, ceiling and furniture.
    pub shapes: Vec<Shape>,
    /// Floor to ceiling (m).
    pub height: f64,
}

/// The kinds of one row, in order along the corridor: the kinds every
/// floor has, then one to three fillers, shuffled.
fn row_kinds(
    first: &[&'static str],
    filler: &'static str,
    r: &mut ChaCha8Rng,
) -> Vec<&'static str> {
    let mut kinds = first.to_vec();
    let offices = r.random_range(1..=3);
    kinds.extend(std::iter::repeat_n(filler, offices));
    kinds.shuffle(r);
    kinds
}

/// Room widths for `kinds`, then private offices (and a closet for the
/// last gap) until the row is `length` long.
fn fill_row(
    plan: &FloorPlan,
    kinds: &[&'static str],
    widths: &[f64],
    length: f64,
    r: &mut ChaCha8Rng,
) -> Vec<(&'static str, f64)> {
    let mut row: Vec<_> = kinds.iter().copied().zip(widths.iter().copied()).collect();
    let (lo, hi) = (plan.width)(plan.filler);
    // Each room after the first stands behind a partition wall.
    let mut left = length - widths.iter().sum::<f64>() - WALL * (widths.len() as f64 - 1.0);
    while left > WALL + 0.5 {
        let room = left - WALL;
        let w = if room <= hi {
            room
        } else {
            u(r, lo, hi).min(room - 0.5)
        };
        row.push((if w >= lo { plan.filler } else { "storage" }, w));
        left -= w + WALL;
    }
    row
}

/// Build one floor of `plan`.
pub fn floor(plan: &FloorPlan, r: &mut ChaCha8Rng) -> Floor {
    let h = u(r, plan.ceiling.0, plan.ceiling.1);
    let cw = u(r, plan.corridor_width.0, plan.corridor_width.1);
    let (d0, d1) = plan.row_depth;
    let depth = [u(r, d0, d1), u(r, d0, d1)];
    let north = row_kinds(&plan.north, plan.filler, r);
    let south = row_kinds(&plan.south, plan.filler, r);
    let draw = |kinds: &[&str], r: &mut ChaCha8Rng| -> Vec<f64> {
        kinds
            .iter()
            .map(|k| {
                let (lo, hi) = (plan.width)(k);
                u(r, lo, hi)
            })
            .collect()
    };
    let (wn, ws) = (draw(&north, r), draw(&south, r));
    let span = |w: &[f64]| w.iter().sum::<f64>() + WALL * (w.len() as f64 - 1.0);
    let length = span(&wn).max(span(&ws));
    let rows = [
        fill_row(plan, &north, &wn, length, r),
        fill_row(plan, &south, &ws, length, r),
    ];
    let mut shapes = vec![
        // Floor and ceiling over the whole floor, outer walls round it.
        cuboid(
            [-WALL, -depth[1] - 2.0 * WALL, -0.2],
            [
                length + 2.0 * WALL,
                depth[0] + depth[1] + cw + 4.0 * WALL,
                0.2,
            ],
        ),
        cuboid(
            [-WALL, -depth[1] - 2.0 * WALL, h],
            [
                length + 2.0 * WALL,
                depth[0] + depth[1] + cw + 4.0 * WALL,
                0.2,
            ],
        ),
        cuboid(
            [-WALL, -depth[1] - 2.0 * WALL, 0.0],
            [WALL, depth[0] + depth[1] + cw + 4.0 * WALL, h],
        ),
        cuboid(
            [length, -depth[1] - 2.0 * WALL, 0.0],
            [WALL, depth[0] + depth[1] + cw + 4.0 * WALL, h],
        ),
        cuboid(
            [-WALL, -depth[1] - 2.0 * WALL, 0.0],
            [length + 2.0 * WALL, WALL, h],
        ),
        cuboid(
            [-WALL, cw + depth[0] + WALL, 0.0],
            [length + 2.0 * WALL, WALL, h],
        ),
    ];
    let mut rooms = vec![FloorRoom {
        kind: "corridor",
        min: [0.0, 0.0],
        max: [length, cw],
        furniture: vec![],
    }];
    for (side, row) in rows.iter().enumerate() {
        // North rooms: y from cw + WALL, away from the corridor; south
        // rooms mirrored, y from -WALL down.
        let (flip, y0) = if side == 0 {
            (false, cw + WALL)
        } else {
            (true, -WALL)
        };
        let d = depth[side];
        let mut x = 0.0;
        for &(kind, w) in row {
            let mut local = Vec::new();
            (plan.furnish)(kind, [w, d, h], r, &mut local);
            let furniture: Vec<Shape> = local
                .iter()
                .map(|s| place(s, [false, flip], [x, y0]))
                .collect();
            let wall_y = if flip { -WALL } else { cw };
            let open = plan.open.contains(&kind);
            let door = door_width(kind, open, w, r);
            let at = (plan.door)(kind, w, door, open, &local, r);
            let gap = at.map(|a| (x + a, door));
            if plan.glazed.contains(&kind) {
                shapes.extend(shopfront(x, w, wall_y, h, gap));
            } else {
                shapes.extend(corridor_wall(open, x, w, wall_y, h, gap));
            }
            if x + w < length - 1e-9 {
                let yy = if flip { -WALL - d } else { cw + WALL };
                shapes.push(cuboid([x + w, yy, 0.0], [WALL, d, h]));
            }
            let (ylo, yhi) = if flip { (y0 - d, y0) } else { (y0, y0 + d) };
            shapes.extend(furniture.iter().copied());
            rooms.push(FloorRoom {
                kind,
                min: [x, ylo],
                max: [x + w, yhi],
                furniture,
            });
            x += w + WALL;
        }
    }
    let mut corridor = Vec::new();
    (plan.fittings)(length, cw, h, r, &mut corridor);
    shapes.extend(corridor.iter().copied());
    rooms[0].furniture = corridor;
    Floor {
        rooms,
        shapes,
        height: h,
    }
}

/// The width of a room's door: a wide opening into an `open` room, a
/// narrower door into a closet, else 0.9 m.
fn door_width(kind: &str, open: bool, width: f64, r: &mut ChaCha8Rng) -> f64 {
    match kind {
        _ if open => u(r, 2.4, 3.5),
        "storage" => 0.8f64.min(width - 0.2),
        _ => 0.9,
    }
}

/// The wall between a room and the corridor, from `x` along `width`, its
/// corridor face at `y`: a plain wall, or with a gap (its start and width)
/// for a door (an `open` room's wide opening) with a lintel above it.
fn corridor_wall(
    open: bool,
    x: f64,
    width: f64,
    y: f64,
    h: f64,
    gap: Option<(f64, f64)>,
) -> Vec<Shape> {
    let Some((d0, door)) = gap else {
        return vec![cuboid([x, y, 0.0], [width, WALL, h])];
    };
    let top = if open { h - 0.3 } else { 2.1 };
    vec![
        cuboid([x, y, 0.0], [d0 - x, WALL, h]),
        cuboid(
            [d0 + door, y, 0.0],
            [(x + width - d0 - door).max(0.0), WALL, h],
        ),
        cuboid([d0, y, top], [door, WALL, h - top]),
    ]
}

/// A glazed shopfront from `x` along `width`, its corridor face at `y`:
/// a base 0.3 m high, a mullion at the ends of each glazed stretch and
/// every 1.5 m or less along it, a fascia over the whole front from 3 m
/// (0.6 m under a lower ceiling) up, and the entrance (`gap`, its start
/// and width) open under the fascia. The glass panes are left out.
fn shopfront(x: f64, width: f64, y: f64, h: f64, gap: Option<(f64, f64)>) -> Vec<Shape> {
    let fascia = (h - 0.6).clamp(2.1, 3.0);
    let mut s = vec![cuboid([x, y, fascia], [width, WALL, h - fascia])];
    let stretches = match gap {
        Some((d0, door)) => vec![(x, d0), (d0 + door, x + width)],
        None => vec![(x, x + width)],
    };
    for (a, b) in stretches {
        if b - a < 0.06 {
            continue;
        }
        s.push(cuboid([a, y, 0.0], [b - a, WALL, 0.3]));
        let n = ((b - a) / 1.5).ceil().max(1.0) as usize;
        for i in 0..=n {
            let m = (a + (b - a) * i as f64 / n as f64 - 0.03).clamp(a, b - 0.06);
            s.push(cuboid([m, y, 0.3], [0.06, WALL, fascia - 0.3]));
        }
    }
    s
}

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// corridor wall at y = 0.
fn furnish(kind: &str, [w, d, _h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    match kind {
        "private_office" => {
            // A desk against the far wall or a side wall, its chair, a
            // bookcase and a visitor's chair.
            let f = if r.random::<bool>() {
                Frame::at(w / 2.0, d - 0.4, 0.0)
            } else {
                Frame::at(0.4, d * u(r, 0.5, 0.7), FRAC_PI_2)
            };
            table(s, &f, [0.0, 0.0], [u(r, 1.4, 1.8), 0.75], 0.73);
            let [cx, cy] = f.point([u(r, -0.3, 0.3), -u(r, 0.7, 0.9)]);
            chair(s, cx, cy, u(r, 0.0, TAU));
            let shelf = Frame::at(w, u(r, 1.0, 1.5), FRAC_PI_2);
            let tall = u(r, 1.8, 2.1);
            bookcase(s, r, &shelf, 0.0, (d - 2.6).clamp(0.8, 2.0), tall);
            if r.random::<f64>() < 0.6 {
                chair(s, w * u(r, 0.3, 0.7), d * u(r, 0.3, 0.5), u(r, 0.0, TAU));
            }
        }
        "meeting_room" => {
            // A table along the room's longer side with chairs round it, a
            // screen on an end wall, a sideboard.
            let along_x = w >= d;
            let (long, short) = if along_x { (w, d) } else { (d, w) };
            let f = Frame::at(w / 2.0, d / 2.0, if along_x { 0.0 } else { FRAC_PI_2 });
            let (tl, tw) = ((long - 2.2).clamp(1.6, 4.5), (short - 2.4).clamp(0.9, 1.4));
            table(s, &f, [0.0, 0.0], [tl, tw], 0.74);
            for side in [-1.0, 1.0] {
                let mut x = -tl / 2.0 + 0.4;
                while x < tl / 2.0 - 0.3 {
                    if r.random::<f64>() < 0.85 {
                        let [cx, cy] = f.point([x + u(r, -0.1, 0.1), side * (tw / 2.0 + u(r, 0.25, 0.5))]);
                        chair(s, cx, cy, f.yaw + side * FRAC_PI_2 + u(r, -0.5, 0.5));
                    }
                    x += 0.75;
                }
            }
            let screen = f.point([long / 2.0 - 0.05, 0.0]);
            s.push(Shape::OrientedBox {
                centre: [screen[0], screen[1], 1.45],
                half: [0.03, u(r, 0.6, 0.9), 0.45],
                yaw: f.yaw,
            });
            if r.random::<f64>() < 0.7 {
                let [sx, sy] = f.point([-long / 2.0 + 0.25, 0.0]);
                s.push(Shape::OrientedBox {
                    centre: [sx, sy, 0.45],
                    half: [0.23, 0.8, 0.45],
                    yaw: f.yaw,
                });
            }
        }
        "open_plan" => {
            // Pods of four desks round a cross of low screens, in a grid;
            // cabinets along the side walls, a few plants.
            let mut x = 1.6;
            while x + 1.5 < w - 1.0 {
                let mut y = 1.8;
                while y + 1.5 < d - 0.6 {
                    let f = Frame::at(x + 1.4, y + 0.75, u(r, -0.05, 0.05));
                    f.part(s, [0.0, 0.0], [2.8, 0.03], 0.73, 0.4);
                    f.part(s, [0.0, 0.0], [0.03, 1.5], 0.73, 0.4);
                    for (dx, dy) in [(-0.7, -0.38), (0.7, -0.38), (-0.7, 0.38), (0.7, 0.38)] {
                        if r.random::<f64>() < 0.85 {
                            table(s, &f, [dx, dy], [1.38, 0.72], 0.73);
                            let [cx, cy] = f.point([dx + u(r, -0.2, 0.2), dy * 2.6]);
                            chair(s, cx, cy, u(r, 0.0, TAU));
                        }
                    }
                    y += 3.6;
                }
                x += 3.8;
            }
            for _ in 0..r.random_range(1..=3) {
                let (px, py) = (u(r, 0.5, w - 0.5), d - 0.45);
                s.push(Shape::Cylinder {
                    centre: [px, py],
                    radius: 0.22,
                    z0: 0.0,
                    z1: 0.45,
                });
                s.push(Shape::Sphere {
                    centre: [px, py, u(r, 0.9, 1.3)],
                    radius: u(r, 0.3, 0.5),
                });
            }
            let side = Frame::at(0.0, 0.0, FRAC_PI_2);
            let mut y = 1.0;
            while y + 1.0 < d {
                if r.random::<f64>() < 0.7 {
                    side.part(s, [y + 0.45, -0.25], [0.9, 0.45], 0.0, u(r, 1.0, 1.3));
                }
                y += 1.0;
            }
        }
        "restroom" => {
            // Stalls of raised partitions along the far wall, basins on a
            // counter with a mirror along a side wall.
            let stalls = (((w - 0.2) / 0.9).floor() as usize).max(1);
            let y0 = d - 1.5;
            s.push(cuboid([0.0, y0, 0.15], [w, 0.04, 1.85]));
            for i in 1..stalls {
                s.push(cuboid([i as f64 * 0.9, y0, 0.15], [0.04, 1.5, 1.85]));
            }
            for i in 0..stalls {
                s.push(cuboid([i as f64 * 0.9 + 0.27, d - 0.7, 0.0], [0.36, 0.6, 0.42]));
            }
            let len = (y0 - 1.4).max(0.8);
            s.push(cuboid([0.0, 1.1, 0.82], [0.55, len, 0.05]));
            s.push(cuboid([0.0, 1.1, 1.2], [0.02, len, 0.8]));
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

/// A room's furniture `t`, laid out from its x = 0 wall (the room `w`
/// wide), into `s`, mirrored about the room's middle in one room of two
/// (one draw of `r`), so that layouts face either way along the corridor.
pub(super) fn mirrored_in_one_of_two(t: &[Shape], w: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mirror = r.random::<bool>();
    s.extend(
        t.iter()
            .map(|p| place(p, [mirror, false], [if mirror { w } else { 0.0 }, 0.0])),
    );
}

/// Corridor fittings: pilasters and notice boards on both walls, a bench
/// or a printer now and then.
fn corridor_fittings(length: f64, cw: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mut x = u(r, 1.0, 4.0);
    while x < length - 1.0 {
        let y = if r.random::<bool>() { 0.0 } else { cw - 0.1 };
        s.push(cuboid([x, y, 0.0], [0.3, 0.1, h]));
        if r.random::<f64>() < 0.4 {
            let board = if y == 0.0 { 0.0 } else { cw - 0.03 };
            s.push(cuboid([x + 0.6, board, 1.0], [u(r, 0.6, 1.2), 0.03, 0.8]));
        }
        x += u(r, 3.0, 6.0);
    }
    if r.random::<f64>() < 0.5 {
        s.push(cuboid([length * u(r, 0.2, 0.8), 0.0, 0.0], [1.2, 0.6, 1.0]));
    }
}

/// The scans of a simulation of floors of `plan`: `params.scans` per
/// kind, in groups of `params.scans_per_room` per room, the rooms of a
/// kind taken in turn from floors built one after another (one corridor
/// and at least one room of every kind per floor) until every kind has
/// enough.
pub(super) fn scans(
    plan: &FloorPlan,
    params: &SimParams,
    r: &mut ChaCha8Rng,
) -> (Vec<Scene>, Vec<Shot>) {
    let rooms_per_kind = params.scans.div_ceil(params.scans_per_room);
    let floors: Vec<Floor> = (0..rooms_per_kind).map(|_| floor(plan, r)).collect();
    let mut shots = Vec::new();
    let mut room_id = 0;
    for kind in plan.kinds {
        // Round-robin over floors, so consecutive rooms of a kind come from
        // different floors.
        let mut of_kind: Vec<(usize, usize)> = Vec::new();
        let per_floor: Vec<Vec<usize>> = floors
            .iter()
            .map(|f| {
                (0..f.rooms.len())
                    .filter(|&k| f.rooms[k].kind == kind)
                    .collect()
            })
            .collect();
        let most = per_floor.iter().map(Vec::len).max().unwrap_or(0);
        for j in 0..most {
            for (fi, list) in per_floor.iter().enumerate() {
                if let Some(&k) = list.get(j) {
                    of_kind.push((fi, k));
                }
            }
        }
        let mut left = params.scans;
        for &(fi, k) in of_kind.iter().take(rooms_per_kind) {
            let take = left.min(params.scans_per_room);
            let room = &floors[fi].rooms[k];
            for _ in 0..take {
                let [x, y] = free_spot(room, r);
                let z = params.sensor_height.unwrap_or_else(|| u(r, 1.0, 1.3));
                shots.push(Shot {
                    scene: fi,
                    room: room_id,
                    pose: SensorPose::level([x, y, z], r.random_range(0.0..TAU)),
                    label: kind.to_string(),
                });
            }
            room_id += 1;
            left -= take;
        }
    }
    let scenes = floors
        .into_iter()
        .map(|f| Scene {
            shapes: f.shapes,
            ground: None,
        })
        .collect();
    (scenes, shots)
}

/// A free spot anywhere in a room: 0.5 m from its walls, 0.4 m from its
/// furniture where it can be.
fn free_spot(room: &FloorRoom, r: &mut ChaCha8Rng) -> [f64; 2] {
    let local = Room {
        shapes: room
            .furniture
            .iter()
            .map(|s| place(s, [false, false], [-room.min[0], -room.min[1]]))
            .collect(),
        size: [room.max[0] - room.min[0], room.max[1] - room.min[1]],
        furniture: room.furniture.len(),
    };
    let [x, y] = free_position(&local, r, 0.5);
    [x + room.min[0], y + room.min[1]]
}

/// A room of `kind` of a size drawn from `plan`'s ranges, furnished as
/// the plan furnishes it (the floor families' fixture tests).
#[cfg(test)]
pub(super) fn furnished_room(
    plan: &FloorPlan,
    kind: &str,
    r: &mut ChaCha8Rng,
) -> ([f64; 3], Vec<Shape>) {
    let (wl, wh) = (plan.width)(kind);
    let size = [
        u(r, wl, wh),
        u(r, plan.row_depth.0, plan.row_depth.1),
        u(r, plan.ceiling.0, plan.ceiling.1),
    ];
    let mut s = Vec::new();
    (plan.furnish)(kind, size, r, &mut s);
    (size, s)
}

/// Whether a scan can stand in a room `w` by `d` with furniture `s`:
/// a spot 0.5 m from the walls and 0.4 m from the furniture (the floor
/// families' fixture tests).
#[cfg(test)]
pub(super) fn has_free_spot(w: f64, d: f64, s: &[Shape]) -> bool {
    let n = 40;
    (0..=n).any(|i| {
        (0..=n).any(|j| {
            let x = 0.5 + (w - 1.0) * i as f64 / n as f64;
            let y = 0.5 + (d - 1.0) * j as f64 / n as f64;
            s.iter().all(|p| p.horizontal_distance(x, y) > 0.4)
        })
    })
}

/// Check that every room of `kinds` of `plan` (300 a kind) has
/// furniture, all of it inside the room, on the floor and under the
/// ceiling, and that above where the floor tests look for the walls
/// (0.15 m under the ceiling, with 0.1 m to spare) only cylinders of
/// `slim` m radius or less reach (the floor families' fixture tests).
#[cfg(test)]
pub(super) fn assert_furniture_inside(
    plan: &FloorPlan,
    kinds: &[&str],
    slim: f64,
    r: &mut ChaCha8Rng,
) {
    use super::hotel::extent;
    for kind in kinds {
        for _ in 0..300 {
            let ([w, d, h], s) = furnished_room(plan, kind, r);
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
                if z1 > h - 0.25 {
                    assert!(
                        matches!(shape, Shape::Cylinder { radius, .. } if *radius <= slim),
                        "{kind}: {shape:?} under a ceiling at {h}"
                    );
                }
            }
        }
    }
}

/// Check that every room of `kinds` of `plan` (300 a kind) leaves a free
/// spot for a scan ([`has_free_spot`]; the floor families' fixture
/// tests).
#[cfg(test)]
pub(super) fn assert_free_spots(plan: &FloorPlan, kinds: &[&str], r: &mut ChaCha8Rng) {
    for kind in kinds {
        for _ in 0..300 {
            let ([w, d, _], s) = furnished_room(plan, kind, r);
            assert!(has_free_spot(w, d, &s), "{kind} {w:.2} x {d:.2}");
        }
    }
}

/// Check that `plan` puts an open 0.9 m door of each of `kinds` 0.1 m
/// or more from the room's ends, and that nothing stands within `swing`
/// m of it inside the room (300 rooms a kind; the floor families' fixture
/// tests).
#[cfg(test)]
pub(super) fn assert_doors_swing_clear(
    plan: &FloorPlan,
    kinds: &[&str],
    swing: f64,
    r: &mut ChaCha8Rng,
) {
    use super::hotel::{extent, overlap};
    for kind in kinds {
        for _ in 0..300 {
            let ([w, ..], s) = furnished_room(plan, kind, r);
            let x = (plan.door)(kind, w, 0.9, true, &s, r).expect("open");
            assert!(
                x >= 0.1 - 1e-9 && x + 0.9 <= w - 0.1 + 1e-9,
                "{kind}: {x} in {w}"
            );
            let clear = ([x, 0.0], [x + 0.9, swing]);
            for shape in &s {
                let (a, b, _, _) = extent(shape);
                assert!(
                    !overlap((a, b), clear),
                    "{kind} {w}: door at {x}: {shape:?}"
                );
            }
        }
    }
}

/// The axis-aligned boxes of `s`: lowest and highest corners.
#[cfg(test)]
pub(super) fn boxes(s: &[Shape]) -> Vec<([f64; 3], [f64; 3])> {
    s.iter()
        .filter_map(|s| match *s {
            Shape::Cuboid { min, max } => Some((min, max)),
            _ => None,
        })
        .collect()
}
