//! Hotel floors, a scene family written for issue 18's twenty-third round
//! by another hand, after the descriptors and the recommended room
//! setting existed, so that none of them was shaped on it: the layout of
//! [`super::office_floor`] (a corridor between two rows of rooms, one
//! ceiling) with a hotel's rooms, furnished as real hotels are. Guest
//! rooms with an en-suite bathroom box by the door (full-height
//! partitions, a bath or shower, a basin and a WC), a double bed or two
//! singles with a headboard against a side wall between nightstands, a
//! dresser with a television facing the bed, a desk and chair, a
//! wardrobe, an armchair by the window, curtains and sometimes a luggage
//! rack; a breakfast room of small tables for two or four with chairs, a
//! buffet counter, a coffee station and sometimes a banquette; a lobby
//! open to the corridor with a reception desk, sofas and armchairs round
//! low tables, planters and on some floors columns; conference rooms set
//! as a boardroom or in rows of tables facing a screen, with a credenza;
//! and corridors with wall lights, exit signs, console tables and now and
//! then a housekeeping or room-service trolley. Guest-room doors close by
//! themselves and are mostly shut; a door stands where the room leaves its
//! corridor wall clear (a guest room's beside its bathroom), anywhere
//! along the wall in a room that leaves no such stretch.

use super::geometry::{cuboid, Shape};
use super::office_floor::{mirrored_in_one_of_two, FloorPlan};
use super::scenes::{chair, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The kinds of place on a hotel floor, its ground-truth labels.
pub const HOTEL_KINDS: [&str; 5] = [
    "corridor",
    "guest_room",
    "breakfast_room",
    "lobby",
    "conference_room",
];

/// The hotel floor: the public rooms on one side, meeting rooms on the
/// other, guest rooms filling both rows.
pub const HOTEL: FloorPlan = FloorPlan {
    kinds: HOTEL_KINDS,
    width: room_width,
    // A guest room's bay: bathroom and entry, the bed across the room,
    // the window bay.
    row_depth: (6.5, 9.0),
    // Wide enough for a housekeeping cart and a guest to pass.
    corridor_width: (1.8, 2.3),
    // Under a suspended ceiling over the services.
    ceiling: (2.6, 2.9),
    north: ["lobby", "breakfast_room"],
    south: ["conference_room", "conference_room"],
    filler: "guest_room",
    // The corridor to the rooms leads off the lobby.
    open: &["lobby"],
    furnish,
    fittings: corridor_fittings,
    door,
    glazed: &[],
};

/// Width along the corridor of a room of a hotel kind (m), lowest and
/// highest: a guest room is one structural bay.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "guest_room" => (3.6, 4.5),
        "breakfast_room" => (8.0, 14.0),
        "lobby" => (9.0, 15.0),
        "conference_room" => (5.0, 9.0),
        _ /* linen store */ => (0.5, 3.6),
    }
}

/// How far into a room (m) furniture stands in a doorway's way.
const DOORWAY: f64 = 1.0;

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// corridor wall at y = 0, `h` high.
fn furnish(kind: &str, [w, d, h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    match kind {
        "guest_room" => {
            guest_room(w, d, h, r, s);
        }
        "breakfast_room" => breakfast_room(w, d, r, s),
        "lobby" => lobby(w, d, h, r, s),
        "conference_room" => conference_room(w, d, r, s),
        _ => linen_store(w, d, r, s),
    }
}

/// Where a hotel room's door goes: a guest room's is shut in three of
/// five (it closes by itself; housekeeping props it open), another room's
/// in one of four, the lobby's opening never. It stands where the
/// corridor wall is clear of furniture for a metre into the room (a guest
/// room's beside its bathroom), anywhere along the wall if nowhere is.
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
        "guest_room" => 0.6,
        _ => 0.25,
    };
    door_unless_shut(shut, width, door, DOORWAY, furniture, r)
}

/// A room's door: shut with probability `shut` (one draw of `r`; no
/// doorway to scan through), else where [`door_in_clear_span`] puts it.
/// The floor families' `door` rules differ only in `shut` and `depth`.
pub(super) fn door_unless_shut(
    shut: f64,
    width: f64,
    door: f64,
    depth: f64,
    furniture: &[Shape],
    r: &mut ChaCha8Rng,
) -> Option<f64> {
    if r.random::<f64>() < shut {
        return None;
    }
    door_in_clear_span(width, door, depth, furniture, r)
}

/// Where a door `door` wide goes along a wall `width` long: uniform over
/// every place where nothing stands within `depth` of the wall, anywhere
/// along it if nowhere is. (Also the mall's shop entrances.)
pub(super) fn door_in_clear_span(
    width: f64,
    door: f64,
    depth: f64,
    furniture: &[Shape],
    r: &mut ChaCha8Rng,
) -> Option<f64> {
    let spans = clear_spans(width, depth, furniture);
    let slack = |(a, b): (f64, f64)| (b - a - door).max(0.0);
    let room: f64 = spans.iter().copied().map(slack).sum();
    if room <= 0.0 {
        return Some(u(r, 0.1, (width - door - 0.1).max(0.11)));
    }
    let mut t = r.random::<f64>() * room;
    for &span in &spans {
        if t <= slack(span) {
            return Some(span.0 + t);
        }
        t -= slack(span);
    }
    spans.last().map(|&(_, b)| b - door)
}

/// The stretches of a room's corridor wall, `width` long, 0.1 m from its
/// ends, that no furniture stands in front of within `depth` of it.
fn clear_spans(width: f64, depth: f64, furniture: &[Shape]) -> Vec<(f64, f64)> {
    let mut blocked: Vec<(f64, f64)> = furniture
        .iter()
        .map(footprint)
        .filter(|(lo, _)| lo[1] < depth)
        .map(|(lo, hi)| (lo[0] - 0.05, hi[0] + 0.05))
        .collect();
    blocked.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut spans, mut x) = (Vec::new(), 0.1);
    for (a, b) in blocked {
        if a > x {
            spans.push((x, a.min(width - 0.1)));
        }
        x = x.max(b);
    }
    spans.push((x, width - 0.1));
    spans.retain(|(a, b)| b > a);
    spans
}

/// The lowest and highest x and y of a shape's footprint.
pub(super) fn footprint(s: &Shape) -> ([f64; 2], [f64; 2]) {
    match *s {
        Shape::Cuboid { min, max } => ([min[0], min[1]], [max[0], max[1]]),
        Shape::Cylinder { centre, radius, .. } => (
            [centre[0] - radius, centre[1] - radius],
            [centre[0] + radius, centre[1] + radius],
        ),
        Shape::Sphere { centre, radius } => (
            [centre[0] - radius, centre[1] - radius],
            [centre[0] + radius, centre[1] + radius],
        ),
        Shape::OrientedBox { .. } => {
            let c = s.footprint_corners().unwrap_or_default();
            let fold = |k: usize, f: fn(f64, f64) -> f64, start: f64| {
                c.iter().map(|p| p[k]).fold(start, f)
            };
            (
                [
                    fold(0, f64::min, f64::INFINITY),
                    fold(1, f64::min, f64::INFINITY),
                ],
                [
                    fold(0, f64::max, f64::NEG_INFINITY),
                    fold(1, f64::max, f64::NEG_INFINITY),
                ],
            )
        }
    }
}

/// A shape's footprint and its lowest and highest point (the floor
/// families' fixture tests).
#[cfg(test)]
pub(super) fn extent(s: &Shape) -> ([f64; 2], [f64; 2], f64, f64) {
    let (lo, hi) = footprint(s);
    let (z0, z1) = match *s {
        Shape::Cuboid { min, max } => (min[2], max[2]),
        Shape::OrientedBox { centre, half, .. } => (centre[2] - half[2], centre[2] + half[2]),
        Shape::Cylinder { z0, z1, .. } => (z0, z1),
        Shape::Sphere { centre, radius } => (centre[2] - radius, centre[2] + radius),
    };
    (lo, hi, z0, z1)
}

/// Whether two footprints overlap by more than a rounding error.
#[cfg(test)]
pub(super) fn overlap(a: ([f64; 2], [f64; 2]), b: ([f64; 2], [f64; 2])) -> bool {
    (0..2).all(|k| a.0[k] < b.1[k] - 1e-9 && b.0[k] < a.1[k] - 1e-9)
}

/// A guest room, laid out with its bathroom on the x = 0 side, then
/// mirrored in about one room of two (each room by its own coin flip):
/// the bathroom box against the corridor
/// wall, the entry hall beside it, a wardrobe in the hall where it is
/// wide enough (else just past the bathroom), the bed's head against a
/// side wall and the dresser and desk on the other, the window bay at the
/// far wall. Returns how many of the shapes it adds, the first ones, are
/// the bathroom's.
fn guest_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) -> usize {
    let mut t = Vec::new();
    // The hall keeps at least 1.3 m for the door and a wardrobe's doors.
    let bw = u(r, 1.6, 2.4).min(w - 1.3);
    let bd = u(r, 2.0, 2.6);
    bathroom(&mut t, r, bw, bd, h);
    let bathroom_shapes = t.len();
    let hall_wardrobe = w - bw >= 2.0;
    let wl = u(r, 1.0, 1.6);
    // Along the wall opposite the bed: from where to where it is free.
    let mut wall_from = bd + 0.15;
    let head_left = if hall_wardrobe {
        wardrobe(&mut t, r, &Frame::at(w, 0.2, PI), -wl.min(bd - 0.3), h);
        r.random::<bool>()
    } else {
        // Past the bathroom on its side; the bed goes to the other wall.
        wardrobe(&mut t, r, &Frame::at(0.0, bd + 0.1, 0.0), wl, h);
        wall_from += wl;
        false
    };
    let bed_from = bd + 0.35;
    let (ext, beds) = bed_group(r, d - bed_from - 1.55);
    // The armchair's bay by the window, where the bed leaves room.
    let bay = d - bed_from - ext >= 1.55;
    let top = if bay { d - 1.45 } else { d - 0.2 };
    let yc = bed_from + ext / 2.0 + u(r, 0.0, (top - bed_from - ext).max(0.0) + 1e-9);
    let (head, opposite) = if head_left {
        (Frame::at(0.0, yc, 0.0), 1.0)
    } else {
        (Frame::at(w, yc, PI), 0.0)
    };
    bed(&mut t, r, &head, ext, beds);
    // On the other wall: the dresser with the television facing the
    // bed, the desk in the longer stretch left, a luggage rack if a
    // stretch is left.
    let wall_x = opposite * w;
    let yaw = if head_left { PI } else { 0.0 };
    let room_to = d - 0.1;
    let len = u(r, 1.2, 2.0).min(room_to - wall_from - 0.1);
    let yd = yc.clamp(wall_from + len / 2.0, room_to - len / 2.0);
    let wall = |y: f64| Frame::at(wall_x, y, yaw);
    dresser(&mut t, r, &wall(yd), len);
    let before = (wall_from, yd - len / 2.0 - 0.05);
    let after = (yd + len / 2.0 + 0.05, room_to);
    let (long, short) = if after.1 - after.0 >= before.1 - before.0 {
        (after, before)
    } else {
        (before, after)
    };
    // How far towards the window that wall's furniture reaches.
    let mut reach = yd + len / 2.0;
    let desk_len = u(r, 1.0, 1.4);
    if long.1 - long.0 >= desk_len {
        let y = (long.0 + long.1) / 2.0;
        desk(&mut t, r, &wall(y), desk_len);
        reach = reach.max(y + desk_len / 2.0 + 0.2);
        if short.1 - short.0 >= 0.75 && r.random::<f64>() < 0.5 {
            let y = (short.0 + short.1) / 2.0;
            luggage_rack(&mut t, &wall(y));
            reach = reach.max(y + 0.35);
        }
    } else {
        // No stretch for a desk: the dresser's end serves as one.
        let [cx, cy] = wall(yd + len / 2.0 - 0.35).point([0.8, 0.0]);
        chair(
            &mut t,
            cx.clamp(0.5, w - 0.5),
            cy,
            yaw + PI + u(r, -0.5, 0.5),
        );
        reach = reach.max(cy + 0.45);
    }
    if bay {
        // The window corner on the bed's side if the other wall's
        // furniture reaches the other one.
        let near_head = reach > d - 1.45 || r.random::<bool>();
        let ax = if near_head == head_left {
            u(r, 0.55, 0.8)
        } else {
            w - u(r, 0.55, 0.8)
        };
        window_chair(&mut t, r, ax, d - 0.7, ax < w / 2.0);
    }
    // Curtains drawn back to both sides of the window.
    for left in [true, false] {
        let pw = u(r, 0.3, 0.55);
        let x = if left { 0.05 } else { w - 0.05 - pw };
        t.push(cuboid([x, d - 0.16, 0.0], [pw, 0.12, h - 0.25]));
    }
    mirrored_in_one_of_two(&t, w, r, s);
    bathroom_shapes
}

/// The bathroom box in the corner at (0, 0), `bw` by `bd` outside:
/// partitions to the ceiling, a door off the hall (on its x = bw side)
/// under a lintel, a raised tiled floor (scans keep out), a bath or a
/// shower tray along the corridor wall, a WC and a vanity with a basin.
fn bathroom(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, bw: f64, bd: f64, h: f64) {
    let (iw, id) = (bw - 0.1, bd - 0.1);
    s.push(cuboid([0.0, 0.0, 0.0], [iw, id, 0.02]));
    s.push(cuboid([0.0, id, 0.0], [bw, 0.1, h]));
    let g = u(r, 0.85, id - 0.85);
    s.push(cuboid([iw, 0.0, 0.0], [0.1, g, h]));
    s.push(cuboid([iw, g + 0.75, 0.0], [0.1, id - g - 0.75, h]));
    s.push(cuboid([iw, g, 2.05], [0.1, 0.75, h - 2.05]));
    if iw >= 1.6 && r.random::<f64>() < 0.6 {
        s.push(cuboid([0.0, 0.0, 0.0], [iw.min(1.7), 0.72, 0.56]));
    } else {
        s.push(cuboid([0.0, 0.0, 0.0], [0.9, 0.9, 0.06]));
        // The shower's glass screen has a frame the sensor sees.
        s.push(cuboid([0.88, 0.0, 0.06], [0.02, 0.9, 1.9]));
    }
    let vw = u(r, 0.6, 1.0).min(iw - 0.3);
    s.push(cuboid([0.15, id - 0.5, 0.0], [vw, 0.5, 0.86]));
    let wc = (0.9 + id - 0.5) / 2.0;
    s.push(cuboid([0.0, wc - 0.19, 0.0], [0.62, 0.38, 0.42]));
    s.push(cuboid([0.0, wc - 0.22, 0.42], [0.18, 0.44, 0.4]));
}

/// A wardrobe against a wall: its frame on the wall, facing local +x,
/// running `len` along local y (negative: the other way), 0.6 m deep,
/// 2.0-2.3 m high, on a plinth.
fn wardrobe(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame, len: f64, _h: f64) {
    let top = u(r, 2.0, 2.3);
    f.part(s, [0.3, len / 2.0], [0.6, len.abs()], 0.0, top);
}

/// The bed group's extent along its wall and its beds: one double
/// between two nightstands or, in one room of three where `room` (m
/// along the wall, the window bay kept) allows, two singles with a
/// nightstand between. Returns the extent and (bed length, bed width,
/// beds).
fn bed_group(r: &mut ChaCha8Rng, room: f64) -> (f64, (f64, f64, usize)) {
    let len = u(r, 1.95, 2.1);
    let single = [0.9, 1.0][r.random_range(0..2)];
    let twin = 2.0 * single + 0.7;
    if r.random::<f64>() < 0.35 && twin <= room {
        return (twin, (len, single, 2));
    }
    let double = [1.4, 1.6, 1.8][r.random_range(0..3)];
    (double + 1.1, (len, double, 1))
}

/// The bed group on frame `f` (on the wall, local +x into the room):
/// an upholstered headboard across it, the beds with pillows and a runner
/// over the foot, nightstands with lamps.
fn bed(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    f: &Frame,
    ext: f64,
    (len, bw, beds): (f64, f64, usize),
) {
    f.part(s, [0.04, 0.0], [0.08, ext], 0.0, u(r, 1.1, 1.4));
    let base = u(r, 0.3, 0.4);
    let top = base + u(r, 0.22, 0.3);
    let centres: Vec<f64> = if beds == 1 {
        vec![0.0]
    } else {
        vec![-(bw + 0.5) / 2.0, (bw + 0.5) / 2.0]
    };
    for &y in &centres {
        let x = 0.08 + len / 2.0;
        f.part(s, [x, y], [len, bw], 0.0, base);
        f.part(s, [x, y], [len - 0.02, bw - 0.02], base, top - base);
        f.part(s, [0.08 + len * 0.8, y], [0.5, bw + 0.06], top, 0.03);
        let pillows = if beds == 1 { 2 } else { 1 };
        for i in 0..pillows {
            let py = y + (i as f64 - (pillows as f64 - 1.0) / 2.0) * bw / 2.0;
            f.part(s, [0.3, py], [0.38, bw / pillows as f64 - 0.08], top, 0.14);
        }
    }
    let (sw, sh) = (u(r, 0.4, 0.48), u(r, 0.5, 0.6));
    let stands = if beds == 1 {
        let y = bw / 2.0 + 0.04 + sw / 2.0;
        vec![-y, y]
    } else {
        vec![0.0]
    };
    for y in stands {
        f.part(s, [0.08 + 0.21, y], [0.42, sw], 0.0, sh);
        if r.random::<f64>() < 0.8 {
            let c = f.point([0.08 + 0.21, y]);
            lamp(s, c, sh, 0.45);
        }
    }
}

/// A table lamp standing at `c` on a top at `z`: a stem and a shade.
fn lamp(s: &mut Vec<Shape>, c: [f64; 2], z: f64, tall: f64) {
    s.push(Shape::Cylinder {
        centre: c,
        radius: 0.05,
        z0: z,
        z1: z + tall * 0.6,
    });
    s.push(Shape::Cylinder {
        centre: c,
        radius: 0.16,
        z0: z + tall * 0.6,
        z1: z + tall,
    });
}

/// The dresser on frame `f` (on the wall, local +x into the room), `len`
/// long: a low unit with drawers and a minibar, the television on the
/// wall above it or on a stand on top.
fn dresser(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame, len: f64) {
    let h = u(r, 0.7, 0.8);
    f.part(s, [0.25, 0.0], [0.5, len], 0.0, h);
    let tv = u(r, 0.95, 1.25).min(len);
    if r.random::<f64>() < 0.65 {
        f.part(s, [0.04, 0.0], [0.06, tv], h + 0.3, tv * 0.58);
    } else {
        f.part(s, [0.2, 0.0], [0.25, 0.3], h, 0.05);
        f.part(s, [0.2, 0.0], [0.06, tv], h + 0.1, tv * 0.58);
    }
}

/// A desk on frame `f` (on the wall, local +x into the room), `len` long,
/// a lamp on it and its chair pulled out.
fn desk(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame, len: f64) {
    f.part(s, [0.275, 0.0], [0.55, len], 0.72, 0.03);
    for side in [-1.0, 1.0] {
        f.part(
            s,
            [0.275, side * (len / 2.0 - 0.03)],
            [0.5, 0.04],
            0.0,
            0.72,
        );
    }
    if r.random::<f64>() < 0.6 {
        lamp(s, f.point([0.15, len / 2.0 - 0.2]), 0.75, 0.45);
    }
    let [cx, cy] = f.point([u(r, 0.75, 1.0), u(r, -0.2, 0.2)]);
    chair(s, cx, cy, f.yaw + PI + u(r, -0.6, 0.6));
}

/// A folding luggage rack against the wall on frame `f`: two end frames
/// and a slatted top at 0.5 m.
fn luggage_rack(s: &mut Vec<Shape>, f: &Frame) {
    for side in [-0.3, 0.3] {
        f.part(s, [0.28, side], [0.45, 0.03], 0.0, 0.5);
    }
    f.part(s, [0.28, 0.0], [0.45, 0.66], 0.48, 0.03);
}

/// A lounge armchair at (x, y) facing into the room from a window
/// corner (`left`: the x = 0 one), a side table and in some rooms a
/// floor lamp beside it.
fn window_chair(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, x: f64, y: f64, left: bool) {
    let towards = if left {
        -FRAC_PI_2 + 0.6
    } else {
        -FRAC_PI_2 - 0.6
    };
    lounge_chair(s, &Frame::at(x, y, towards + u(r, -0.3, 0.3)));
    let side = if left { x + 0.75 } else { x - 0.75 };
    round_table(s, [side, y + 0.15], 0.25, 0.55);
    if r.random::<f64>() < 0.5 {
        let lx = if left { x + 1.2 } else { x - 1.2 };
        lamp(s, [lx, y + 0.25], 0.0, 1.6);
    }
}

/// A lounge armchair centred on `f`, facing local +x: 0.78 m square,
/// seat at 0.42 m, arms at 0.6 m, back to 0.8-0.9 m.
fn lounge_chair(s: &mut Vec<Shape>, f: &Frame) {
    f.part(s, [0.05, 0.0], [0.6, 0.56], 0.1, 0.32);
    f.part(s, [-0.3, 0.0], [0.18, 0.78], 0.1, 0.75);
    for side in [-1.0, 1.0] {
        f.part(s, [0.0, side * 0.33], [0.78, 0.12], 0.1, 0.5);
    }
    for (a, b) in [(-0.33, -0.33), (-0.33, 0.33), (0.33, -0.33), (0.33, 0.33)] {
        f.part(s, [a, b], [0.04, 0.04], 0.0, 0.1);
    }
}

/// A sofa of `len` m centred on `f`, facing local +x: seat at 0.43 m,
/// arms at 0.62 m, back to 0.82 m, 0.9 m deep, on short legs.
fn sofa(s: &mut Vec<Shape>, f: &Frame, len: f64) {
    f.part(s, [0.1, 0.0], [0.7, len - 0.36], 0.1, 0.33);
    f.part(s, [-0.33, 0.0], [0.24, len], 0.1, 0.72);
    for side in [-1.0, 1.0] {
        f.part(s, [0.0, side * (len / 2.0 - 0.09)], [0.9, 0.18], 0.1, 0.52);
    }
    for (a, b) in [(-0.4, -1.0), (-0.4, 1.0), (0.4, -1.0), (0.4, 1.0)] {
        f.part(s, [a, b * (len / 2.0 - 0.05)], [0.04, 0.04], 0.0, 0.1);
    }
}

/// A dining chair centred on `f`, facing local +x: four legs, an
/// upholstered seat at 0.46 m, a back to 0.86-0.95 m.
pub(super) fn dining_chair(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame) {
    for (a, b) in [(-0.2, -0.2), (-0.2, 0.2), (0.2, -0.2), (0.2, 0.2)] {
        f.part(s, [a, b], [0.03, 0.03], 0.0, 0.41);
    }
    f.part(s, [0.0, 0.0], [0.45, 0.45], 0.41, 0.06);
    f.part(s, [-0.21, 0.0], [0.04, 0.42], 0.47, u(r, 0.39, 0.48));
}

/// A four-legged table of `size` centred on `f`, its top at 0.75 m.
pub(super) fn dining_table(s: &mut Vec<Shape>, f: &Frame, size: [f64; 2]) {
    f.part(s, [0.0, 0.0], size, 0.72, 0.03);
    let [a, b] = [size[0] / 2.0 - 0.05, size[1] / 2.0 - 0.05];
    for (x, y) in [(-a, -b), (-a, b), (a, -b), (a, b)] {
        f.part(s, [x, y], [0.04, 0.04], 0.0, 0.72);
    }
}

/// A round pedestal table of `radius` at `c`, its top at `h`.
pub(super) fn round_table(s: &mut Vec<Shape>, c: [f64; 2], radius: f64, h: f64) {
    for (radius, z0, z1) in [
        (radius.min(0.25), 0.0, 0.03),
        (0.04, 0.03, h - 0.03),
        (radius, h - 0.03, h),
    ] {
        s.push(Shape::Cylinder {
            centre: c,
            radius,
            z0,
            z1,
        });
    }
}

/// A breakfast room: a buffet counter along the far wall under a
/// sneeze-guard shelf with chafing dishes, a coffee station on a side
/// wall, small tables for two and four with chairs on a grid, and in some
/// rooms a banquette along the other side wall with tables for two.
fn breakfast_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let bl = u(r, 3.0, 6.0).min(w - 2.5);
    let bx = u(r, 1.0, w - 1.0 - bl);
    s.push(cuboid([bx, d - 0.75, 0.0], [bl, 0.75, 0.9]));
    s.push(cuboid([bx, d - 0.6, 1.35], [bl, 0.4, 0.03]));
    for x in [bx + 0.05, bx + bl - 0.08] {
        s.push(cuboid([x, d - 0.45, 0.9], [0.03, 0.03, 0.45]));
    }
    let mut x = bx + 0.1;
    while x + 0.55 < bx + bl - 0.05 {
        if r.random::<f64>() < 0.7 {
            s.push(cuboid([x, d - 0.65, 0.9], [0.55, 0.35, u(r, 0.1, 0.2)]));
        }
        x += 0.65;
    }
    // The coffee station: a counter with machines and a juice dispenser.
    let coffee_left = r.random::<bool>();
    let cl = u(r, 1.2, 1.8);
    let cy = d - 1.0 - cl - u(r, 0.0, 1.0);
    let cx = if coffee_left { 0.0 } else { w - 0.65 };
    s.push(cuboid([cx, cy, 0.0], [0.65, cl, 0.9]));
    let mut y = cy + 0.1;
    while y + 0.45 < cy + cl {
        s.push(cuboid([cx + 0.12, y, 0.9], [0.4, 0.38, u(r, 0.4, 0.65)]));
        y += u(r, 0.5, 0.7);
    }
    // A banquette along the wall without the coffee station.
    let (mut x0, mut x1) = if coffee_left {
        (1.6, w - 0.3)
    } else {
        (0.3, w - 1.6)
    };
    // Clear of the doorway, a queue's width before the buffet.
    let (y0, y1) = (DOORWAY, d - 1.7);
    if r.random::<f64>() < 0.4 {
        let bench = Frame::at(
            if coffee_left { w } else { 0.0 },
            (y0 + y1) / 2.0,
            if coffee_left { PI } else { 0.0 },
        );
        let len = y1 - y0;
        bench.part(s, [0.28, 0.0], [0.55, len], 0.0, 0.45);
        bench.part(s, [0.08, 0.0], [0.15, len], 0.45, 0.6);
        let mut y = -len / 2.0 + 0.5;
        while y + 0.5 < len / 2.0 {
            let [tx, ty] = bench.point([0.95, y]);
            dining_table(s, &Frame::at(tx, ty, bench.yaw), [0.7, 0.7]);
            if r.random::<f64>() < 0.8 {
                let [cx, cy] = bench.point([1.55 + u(r, 0.0, 0.1), y + u(r, -0.1, 0.1)]);
                let at = Frame::at(cx, cy, bench.yaw + PI + u(r, -0.3, 0.3));
                dining_chair(s, r, &at);
            }
            y += u(r, 1.3, 1.5);
        }
        if coffee_left {
            x1 = w - 2.2;
        } else {
            x0 = 2.2;
        }
    }
    // A table and its chairs pulled out reach 1.1 m from its centre.
    let (px, py) = (u(r, 2.2, 2.5), u(r, 2.2, 2.5));
    let nx = ((x1 - x0 - 2.2) / px).floor().max(0.0) as usize + 1;
    let ny = ((y1 - y0 - 2.2) / py).floor().max(0.0) as usize + 1;
    let slack_x = (x1 - x0 - 2.2 - (nx - 1) as f64 * px).max(0.0) / 2.0;
    for i in 0..nx {
        for j in 0..ny {
            if r.random::<f64>() < 0.88 {
                let c = [x0 + 1.1 + slack_x + i as f64 * px, y0 + 1.1 + j as f64 * py];
                table_for_guests(s, r, c);
            }
        }
    }
}

/// A breakfast table at `c` with its chairs: for two (0.7 m square),
/// for four (0.8 m square, 1.2 x 0.75 m, or round), at a slight angle,
/// chairs pushed in or pulled out.
fn table_for_guests(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, c: [f64; 2]) {
    let f = Frame::at(c[0], c[1], u(r, -0.08, 0.08));
    let roll = r.random::<f64>();
    // Chair seats: local (x, y) and the way it faces.
    let seats: Vec<([f64; 2], f64)> = if roll < 0.3 {
        dining_table(s, &f, [0.7, 0.7]);
        vec![([-0.6, 0.0], 0.0), ([0.6, 0.0], PI)]
    } else if roll < 0.55 {
        dining_table(s, &f, [0.8, 0.8]);
        vec![
            ([-0.65, 0.0], 0.0),
            ([0.65, 0.0], PI),
            ([0.0, -0.65], FRAC_PI_2),
            ([0.0, 0.65], -FRAC_PI_2),
        ]
    } else if roll < 0.8 {
        dining_table(s, &f, [1.2, 0.75]);
        vec![
            ([-0.3, -0.6], FRAC_PI_2),
            ([0.3, -0.6], FRAC_PI_2),
            ([-0.3, 0.6], -FRAC_PI_2),
            ([0.3, 0.6], -FRAC_PI_2),
        ]
    } else {
        round_table(s, c, u(r, 0.4, 0.5), 0.75);
        let a0 = u(r, 0.0, TAU);
        (0..r.random_range(2..=4))
            .map(|k| {
                let a = a0 + k as f64 * TAU / 4.0;
                ([0.68 * a.cos(), 0.68 * a.sin()], a + PI)
            })
            .collect()
    };
    for (p, face) in seats {
        if r.random::<f64>() < 0.85 {
            let out = u(r, 0.0, 0.1);
            let n = (p[0].hypot(p[1])).max(1e-9);
            let [x, y] = f.point([p[0] * (1.0 + out / n), p[1] * (1.0 + out / n)]);
            let at = Frame::at(x, y, f.yaw + face + u(r, -0.3, 0.3));
            dining_chair(s, r, &at);
        }
    }
}

/// A lobby, laid out with reception at the x = 0 end and mirrored in one
/// of two: a reception counter (a high front at 1.1 m over a work surface)
/// with screens and staff chairs before a back counter, cabinets on the
/// wall behind; seating groups of a sofa, armchairs and a low table; on
/// some floors columns on the bay line; planters; a luggage trolley by
/// reception.
fn lobby(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mut t = Vec::new();
    let rx = u(r, 0.8, 1.5);
    let rl = u(r, 2.4, 4.0).min(w * 0.3);
    let ry = d - u(r, 2.0, 2.6);
    t.push(cuboid([rx, ry, 0.0], [rl, 0.3, 1.06]));
    t.push(cuboid([rx, ry - 0.05, 1.06], [rl, 0.4, 0.04]));
    t.push(cuboid([rx, ry + 0.3, 0.0], [rl, 0.45, 0.75]));
    if r.random::<bool>() {
        // The counter returns towards the back at its far end.
        t.push(cuboid([rx + rl - 0.3, ry + 0.3, 0.0], [0.3, 0.6, 1.06]));
    }
    for i in 0..r.random_range(1..=3) {
        let x = rx + 0.5 + i as f64 * 1.1;
        if x + 0.5 < rx + rl {
            t.push(cuboid([x, ry + 0.45, 0.75], [0.5, 0.05, 0.35]));
        }
    }
    t.push(cuboid([rx - 0.2, d - 0.5, 0.0], [rl + 0.4, 0.5, 0.9]));
    if r.random::<bool>() {
        t.push(cuboid([rx - 0.2, d - 0.35, 1.4], [rl + 0.4, 0.35, 0.8]));
    }
    let behind = d - 0.5 - (ry + 0.75);
    if behind >= 0.9 {
        for i in 0..r.random_range(0..=2) {
            let x = rx + 0.6 + i as f64 * 1.2;
            chair(
                &mut t,
                x.min(rx + rl - 0.4),
                ry + 0.75 + behind / 2.0,
                u(r, 0.0, TAU),
            );
        }
    }
    // Columns on the bay line between reception and the seating, and one
    // bay on.
    let gx0 = rx + rl + 0.9;
    let mut columns = Vec::new();
    if r.random::<f64>() < 0.5 {
        let bay = u(r, 7.2, 8.4);
        let cy = d * u(r, 0.35, 0.65);
        let radius = u(r, 0.2, 0.3);
        let mut x = gx0 - 0.1;
        while x < w - 1.0 && columns.len() < 2 {
            t.push(Shape::Cylinder {
                centre: [x, cy],
                radius,
                z0: 0.0,
                z1: h,
            });
            columns.push(x);
            x += bay;
        }
    }
    let mut x = gx0 + 0.3;
    while x + 2.6 <= w - 0.3 {
        let gw = u(r, 2.6, 3.2).min(w - 0.3 - x);
        if let Some(&c) = columns.iter().find(|&&c| c > x - 0.5 && c < x + gw + 0.5) {
            x = c + 0.6;
            continue;
        }
        let c = [x + gw / 2.0, d / 2.0 + u(r, -0.3, 0.3)];
        seating_group(&mut t, r, c, gw);
        x += gw + u(r, 0.6, 1.4);
    }
    // Planters in the corners away from reception, one beside it.
    for c in [
        [w - 0.5, 0.5],
        [w - 0.5, d - 0.5],
        [0.5, 0.5],
        [rx + rl + 0.5, d - 0.5],
    ] {
        if r.random::<f64>() < 0.7 {
            planter(&mut t, r, c);
        }
    }
    if r.random::<f64>() < 0.4 {
        luggage_trolley(&mut t, &Frame::at(rx + rl + 1.5, d - 0.45, u(r, -0.1, 0.1)));
    }
    mirrored_in_one_of_two(&t, w, r, s);
}

/// A seating group `gw` wide centred at `c`: a sofa facing a low table
/// across it, armchairs on the other side turned to it.
fn seating_group(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, c: [f64; 2], gw: f64) {
    let yaw = if r.random::<bool>() {
        FRAC_PI_2
    } else {
        -FRAC_PI_2
    };
    let f = Frame::at(c[0], c[1], yaw + u(r, -0.1, 0.1));
    let len = u(r, 1.8, 2.2).min(gw - 0.2);
    let [sx, sy] = f.point([-1.0, 0.0]);
    sofa(s, &Frame::at(sx, sy, f.yaw), len);
    f.part(s, [0.0, 0.0], [0.6, u(r, 1.0, 1.2)], 0.0, 0.4);
    let chairs = r.random_range(1..=2);
    for k in 0..chairs {
        let y = if chairs == 1 {
            0.0
        } else {
            (k as f64 - 0.5) * 0.95
        };
        let [ax, ay] = f.point([1.0, y]);
        lounge_chair(s, &Frame::at(ax, ay, f.yaw + PI + u(r, -0.4, 0.4)));
    }
}

/// A planter at `c`: a pot and the plant's crown, or a tall palm.
fn planter(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, c: [f64; 2]) {
    let pot = u(r, 0.45, 0.7);
    s.push(Shape::Cylinder {
        centre: c,
        radius: 0.28,
        z0: 0.0,
        z1: pot,
    });
    if r.random::<bool>() {
        s.push(Shape::Sphere {
            centre: [c[0], c[1], pot + 0.4],
            radius: u(r, 0.3, 0.42),
        });
    } else {
        s.push(Shape::Cylinder {
            centre: c,
            radius: 0.04,
            z0: pot,
            z1: pot + 0.8,
        });
        s.push(Shape::Sphere {
            centre: [c[0], c[1], pot + 1.1],
            radius: 0.42,
        });
    }
}

/// A bellman's luggage trolley centred on `f`: a carpeted deck on
/// castors, two posts and a top rail with its hanging bar.
fn luggage_trolley(s: &mut Vec<Shape>, f: &Frame) {
    f.part(s, [0.0, 0.0], [1.1, 0.6], 0.1, 0.08);
    for x in [-0.5, 0.5] {
        f.part(s, [x, 0.0], [0.04, 0.04], 0.18, 1.6);
    }
    f.part(s, [0.0, 0.0], [1.04, 0.04], 1.78, 0.04);
}

/// A conference room: a boardroom table with swivel chairs round it
/// along the room's long side, or rows of tables with chairs facing the
/// screen; the screen on the wall, a credenza on a side wall.
fn conference_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    if r.random::<f64>() < 0.55 {
        boardroom(w, d, r, s);
    } else {
        rows(w, d, r, s);
    }
}

/// A boardroom: the table along the longer side, chairs every 0.8 m on
/// both sides and at the end, the screen on the end wall facing it, a
/// credenza on a side wall.
fn boardroom(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let along_x = w > d;
    let (long, short) = if along_x { (w, d) } else { (d, w) };
    let f = Frame::at(w / 2.0, d / 2.0, if along_x { 0.0 } else { FRAC_PI_2 });
    let tl = (long - 2.8).clamp(2.4, 6.0) - u(r, 0.0, 0.4);
    let tw = (short - 3.0).clamp(1.0, 1.6) - u(r, 0.0, 0.2);
    f.part(s, [0.0, 0.0], [tl, tw], 0.72, 0.04);
    for x in [-tl / 2.0 + 0.5, tl / 2.0 - 0.5] {
        f.part(s, [x, 0.0], [0.4, tw * 0.5], 0.0, 0.72);
    }
    for side in [-1.0, 1.0] {
        let mut x = -tl / 2.0 + 0.45;
        while x < tl / 2.0 - 0.3 {
            if r.random::<f64>() < 0.9 {
                let [cx, cy] = f.point([x + u(r, -0.1, 0.1), side * (tw / 2.0 + u(r, 0.3, 0.5))]);
                chair(s, cx, cy, f.yaw - side * FRAC_PI_2 + u(r, -0.5, 0.5));
            }
            x += 0.8;
        }
    }
    if r.random::<f64>() < 0.6 {
        let [cx, cy] = f.point([-tl / 2.0 - u(r, 0.4, 0.55), 0.0]);
        chair(s, cx, cy, f.yaw + u(r, -0.4, 0.4));
    }
    let sw = u(r, 1.4, 2.0);
    f.part(s, [long / 2.0 - 0.04, 0.0], [0.06, sw], 1.0, sw * 0.56);
    let cl = u(r, 1.6, 2.4).min(long - 3.0);
    let side = if r.random::<bool>() { 1.0 } else { -1.0 };
    f.part(
        s,
        [0.0, side * (short / 2.0 - 0.23)],
        [cl, 0.45],
        0.0,
        u(r, 0.75, 0.85),
    );
}

/// Rows of tables in two blocks either side of an aisle, one to three
/// chairs behind each (as many as its length holds), facing the screen on the far wall; a lectern by
/// the screen, a credenza on the wider side aisle at the back.
fn rows(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let wide_left = r.random::<bool>();
    let (left, right) = if wide_left { (1.1, 0.6) } else { (0.6, 1.1) };
    let aisle = u(r, 1.0, 1.2);
    let block = (w - aisle - left - right) / 2.0;
    let per = (block / 1.8).ceil().max(1.0);
    let tl = block / per;
    let sw = u(r, 1.6, 2.2).min(w - 1.0);
    s.push(cuboid(
        [w / 2.0 - sw / 2.0, d - 0.06, 1.0],
        [sw, 0.06, sw * 0.56],
    ));
    let depth = u(r, 0.45, 0.6);
    let mut y = d - u(r, 2.0, 2.4);
    while y - 0.85 > 1.2 {
        for b in 0..2 {
            let x0 = left + b as f64 * (block + aisle);
            for k in 0..per as usize {
                let cx = x0 + (k as f64 + 0.5) * tl;
                let f = Frame::at(cx, y, 0.0);
                f.part(s, [0.0, 0.0], [tl - 0.04, depth], 0.72, 0.03);
                for side in [-1.0, 1.0] {
                    f.part(
                        s,
                        [side * (tl / 2.0 - 0.06), 0.0],
                        [0.04, depth * 0.8],
                        0.0,
                        0.72,
                    );
                }
                let n = ((tl / 0.65).round() as usize).max(1);
                for i in 0..n {
                    if r.random::<f64>() < 0.85 {
                        let x = cx - tl / 2.0 + (i as f64 + 0.5) * tl / n as f64;
                        let at = Frame::at(
                            x + u(r, -0.05, 0.05),
                            y - depth / 2.0 - u(r, 0.3, 0.4),
                            FRAC_PI_2 + u(r, -0.3, 0.3),
                        );
                        dining_chair(s, r, &at);
                    }
                }
            }
        }
        y -= u(r, 1.2, 1.4);
    }
    if r.random::<f64>() < 0.6 {
        let lx = if wide_left { w - 1.0 } else { 0.55 };
        s.push(cuboid([lx, d - 1.3, 0.0], [0.5, 0.45, 1.15]));
    }
    let cl = u(r, 1.4, 2.2);
    let cx = if wide_left { 0.0 } else { w - 0.45 };
    s.push(cuboid([cx, 1.1, 0.0], [0.45, cl, u(r, 0.75, 0.85)]));
}

/// A linen store (a gap left in a row, never scanned): shelving of linen
/// and towels on its side walls.
fn linen_store(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let depth = (w / 2.0 - 0.1).clamp(0.1, 0.5);
    for x in [0.0, w - depth] {
        for level in 0..5 {
            let z = 0.1 + level as f64 * 0.4;
            s.push(cuboid([x, 0.4, z], [depth, d - 0.8, 0.02]));
            if r.random::<f64>() < 0.8 {
                let run = u(r, 0.5, d - 1.0);
                s.push(cuboid(
                    [x, u(r, 0.4, d - 0.3 - run), z + 0.02],
                    [depth, run, u(r, 0.15, 0.35)],
                ));
            }
        }
        if w < 2.0 * depth + 0.6 {
            break;
        }
    }
}

/// Corridor fittings: a wall light on both walls at every guest room's
/// pitch, exit signs under the ceiling, and now and then a console table
/// under a mirror, a housekeeping cart or a room-service trolley against
/// one wall.
fn corridor_fittings(length: f64, cw: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let pitch = u(r, 3.6, 4.5);
    let z = u(r, 1.7, 1.9);
    let mut x = u(r, 1.0, 2.5);
    while x < length - 0.5 {
        for wall in [0.0, cw - 0.1] {
            s.push(cuboid([x, wall, z], [0.14, 0.1, 0.22]));
        }
        x += pitch;
    }
    let mut x = u(r, 4.0, 10.0);
    while x < length - 1.0 {
        s.push(cuboid([x, cw / 2.0 - 0.18, h - 0.4], [0.04, 0.36, 0.18]));
        x += u(r, 12.0, 20.0);
    }
    let mut x = u(r, 2.0, 6.0);
    while x < length - 2.2 {
        let near = r.random::<bool>();
        let against = |depth: f64| if near { 0.02 } else { cw - 0.02 - depth };
        let roll = r.random::<f64>();
        if roll < 0.3 {
            let (len, depth) = (u(r, 1.0, 1.4), u(r, 0.35, 0.42));
            let y = against(depth);
            s.push(cuboid([x, y, 0.76], [len, depth, 0.04]));
            for lx in [x + 0.05, x + len - 0.09] {
                s.push(cuboid([lx, y + 0.05, 0.0], [0.04, depth - 0.1, 0.76]));
            }
            let mirror = if near { 0.0 } else { cw - 0.03 };
            s.push(cuboid([x + 0.1, mirror, 1.1], [len - 0.2, 0.03, 0.8]));
            s.push(Shape::Cylinder {
                centre: [x + len * u(r, 0.25, 0.75), y + depth / 2.0],
                radius: 0.08,
                z0: 0.8,
                z1: 1.1,
            });
            x += len;
        } else if roll < 0.5 {
            let (len, depth) = (u(r, 1.5, 1.8), u(r, 0.55, 0.62));
            housekeeping_cart(
                s,
                &Frame::at(x + len / 2.0, against(depth) + depth / 2.0, 0.0),
                len,
                depth,
            );
            x += len;
        } else if roll < 0.6 {
            let y = against(0.5);
            s.push(cuboid([x, y, 0.1], [0.85, 0.5, 0.65]));
            s.push(cuboid([x + 0.1, y + 0.1, 0.75], [0.45, 0.3, 0.1]));
            x += 0.85;
        }
        x += u(r, 5.0, 12.0);
    }
}

/// A housekeeping cart centred on `f`, `len` by `depth`: shelves of
/// linen in a cabinet on castors, a laundry bag hung at one end, a
/// handle.
fn housekeeping_cart(s: &mut Vec<Shape>, f: &Frame, len: f64, depth: f64) {
    let body = len - 0.45;
    f.part(s, [-len / 2.0 + body / 2.0, 0.0], [body, depth], 0.1, 1.15);
    f.part(s, [len / 2.0 - 0.22, 0.0], [0.42, depth - 0.08], 0.25, 0.8);
    f.part(s, [len / 2.0 - 0.02, 0.0], [0.04, depth], 0.2, 1.0);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        for kind in HOTEL_KINDS.iter().skip(1).copied().chain(["storage"]) {
            let (wl, wh) = room_width(kind);
            for _ in 0..300 {
                let (w, d) = (u(&mut r, wl, wh), u(&mut r, 6.5, 9.0));
                let h = u(&mut r, 2.6, 2.9);
                let mut s = Vec::new();
                furnish(kind, [w, d, h], &mut r, &mut s);
                assert!(!s.is_empty(), "{kind}: empty");
                for shape in &s {
                    let (lo, hi, z0, z1) = extent(shape);
                    let inside =
                        lo[0] >= -0.02 && lo[1] >= -0.02 && hi[0] <= w + 0.02 && hi[1] <= d + 0.02;
                    assert!(inside, "{kind} {w:.2} x {d:.2}: {shape:?} outside");
                    assert!(
                        z0 >= -1e-9 && z1 <= h + 1e-9,
                        "{kind}: {shape:?} at {z0}..{z1} m"
                    );
                }
            }
        }
    }

    /// The bathroom box of a guest room: its raised floor's footprint
    /// grown by the partitions.
    fn bathroom_box(s: &[Shape]) -> Vec<([f64; 2], [f64; 2])> {
        s.iter()
            .filter_map(|s| match *s {
                Shape::Cuboid { min, max } if min[2] == 0.0 && max[2] == 0.02 => {
                    Some(([min[0] - 0.1, min[1]], [max[0] + 0.1, max[1] + 0.1]))
                }
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_guest_room_has_its_bathroom_by_the_door_a_bed_and_nothing_in_the_bathroom_s_way() {
        let mut r = crate::rng::rng(5);
        let (mut twins, mut mirrored) = (0, 0);
        for _ in 0..400 {
            let (w, d, h) = (u(&mut r, 3.6, 4.5), u(&mut r, 6.5, 9.0), 2.7);
            let mut s = Vec::new();
            let bathroom_shapes = guest_room(w, d, h, &mut r, &mut s);
            let boxes = bathroom_box(&s);
            assert_eq!(boxes.len(), 1, "one bathroom");
            let (lo, hi) = boxes[0];
            // Against the corridor wall and a side wall, 1.6-2.4 m by
            // 2.0-2.6 m (outside), the hall beside it at least 1.3 m.
            assert!(lo[1].abs() < 1e-9, "{lo:?}");
            let on_left = lo[0].abs() < 0.11;
            assert!(on_left || (hi[0] - w).abs() < 0.11, "{lo:?} {hi:?} in {w}");
            mirrored += usize::from(!on_left);
            let (bw, bd) = ((hi[0] - lo[0]) - 0.1, hi[1] - lo[1]);
            assert!(
                (1.6 - 1e-9..=2.4 + 1e-9).contains(&bw) && w - bw >= 1.3 - 1e-9,
                "{bw} of {w}"
            );
            assert!((2.0..=2.6 + 1e-9).contains(&bd), "{bd}");
            // Full-height partitions.
            let walls = s
                .iter()
                .filter(|s| matches!(s, Shape::Cuboid { min, max } if min[2] == 0.0 && (max[2] - h).abs() < 1e-9))
                .count();
            assert!(walls >= 3, "{walls} partitions");
            // One mattress a bed: one double or two singles.
            let mattresses: Vec<f64> = s
                .iter()
                .filter_map(|s| match *s {
                    // On the base, 0.3-0.4 m up, 0.22-0.3 m thick.
                    Shape::OrientedBox { centre, half, .. }
                        if (half[0] * 2.0 - 2.0).abs() < 0.1
                            && half[2] > 0.1
                            && centre[2] - half[2] >= 0.3 - 1e-9 =>
                    {
                        Some(half[1] * 2.0 + 0.02)
                    }
                    _ => None,
                })
                .collect();
            assert!(matches!(mattresses.len(), 1 | 2), "{mattresses:?}");
            twins += usize::from(mattresses.len() == 2);
            // The bathroom's shapes (the first ones) stand in its box,
            // and nothing else stands in it.
            let bath = (lo, [hi[0], hi[1]]);
            for (i, shape) in s.iter().enumerate() {
                let (a, b, _, _) = extent(shape);
                let within = a[0] >= lo[0] - 1e-9 && b[0] <= hi[0] + 1e-9 && b[1] <= hi[1] + 1e-9;
                if i < bathroom_shapes {
                    assert!(within, "{shape:?} outside the bathroom {bath:?}");
                } else {
                    assert!(!overlap((a, b), bath), "{shape:?} in the bathroom {bath:?}");
                }
            }
            // The door, when open, beside the bathroom and clear of all,
            // placed by the floor plan's own hook.
            for _ in 0..5 {
                if let Some(x) = (HOTEL.door)("guest_room", w, 0.9, false, &s, &mut r) {
                    let gap = ([x, 0.0], [x + 0.9, DOORWAY]);
                    assert!(x >= 0.1 - 1e-9 && x + 0.9 <= w - 0.1 + 1e-9, "{x} in {w}");
                    for shape in &s {
                        let (a, b, _, _) = extent(shape);
                        assert!(!overlap((a, b), gap), "door at {x}: {shape:?}");
                    }
                }
            }
        }
        assert!((60..=200).contains(&twins), "{twins} twin rooms of 400");
        assert!(
            (120..=280).contains(&mirrored),
            "{mirrored} mirrored of 400"
        );
    }

    #[test]
    fn guest_room_doors_are_mostly_shut_and_the_lobby_always_open() {
        let mut r = crate::rng::rng(9);
        let shut = (0..1000)
            .filter(|_| door("guest_room", 4.0, 0.9, false, &[], &mut r).is_none())
            .count();
        assert!((520..=680).contains(&shut), "{shut}");
        for _ in 0..200 {
            let (w, d) = (u(&mut r, 9.0, 15.0), u(&mut r, 6.5, 9.0));
            let mut s = Vec::new();
            lobby(w, d, 2.7, &mut r, &mut s);
            let x = door("lobby", w, 3.5, true, &s, &mut r).expect("open");
            let gap = ([x, 0.0], [x + 3.5, DOORWAY]);
            for shape in &s {
                let (a, b, _, _) = extent(shape);
                assert!(
                    !overlap((a, b), gap),
                    "lobby {w}: opening at {x}: {shape:?}"
                );
            }
        }
    }

    #[test]
    fn corridors_keep_a_way_through_and_their_fittings_inside() {
        for seed in 1..=8 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (45.0, 1.8, 2.6);
            let mut s = Vec::new();
            corridor_fittings(length, cw, h, &mut r, &mut s);
            // A wall light on each wall every 3.6-4.5 m.
            let lights = s
                .iter()
                .filter(|s| matches!(s, Shape::Cuboid { min, max } if min[2] >= 1.7 && max[2] < 2.2 && max[1] - min[1] < 0.11))
                .count();
            assert!((18..=26).contains(&lights), "seed {seed}: {lights} lights");
            for shape in &s {
                let (lo, hi, z0, z1) = extent(shape);
                assert!(
                    lo[0] >= 0.0 && hi[0] <= length && lo[1] >= 0.0 && hi[1] <= cw,
                    "{shape:?}"
                );
                assert!(z0 >= 0.0 && z1 <= h - 0.2, "{shape:?}");
                if z0 < 2.0 {
                    assert!(hi[1] <= cw - 1.1 || lo[1] >= 1.1, "seed {seed}: {shape:?}");
                }
            }
        }
    }
}
