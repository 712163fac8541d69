//! Hospital ward floors, a scene family written for issue 18's eighth
//! round by another hand while the descriptors it is to judge were being
//! developed, and run through none of them while it was written: the layout
//! of [`super::office_floor`] (a corridor between two rows of rooms, one
//! ceiling) with a ward's rooms. Patient rooms of one or two beds, each
//! with a bedside cabinet, an over-bed table, a bed-head trunking, a
//! visitor's armchair and (in most) a curtain rail round it; a nurse
//! station open to the corridor behind a long counter; treatment rooms
//! with an examination couch, cabinets and a dressing trolley; a day room
//! with sofas, armchairs, a table and a television; and wide corridors
//! with handrails on both walls, hanging signs, and a bed, a wheelchair or
//! a trolley parked now and then.

use super::geometry::{cuboid, Shape};
use super::office_floor::{door_anywhere, FloorPlan};
use super::scenes::{bookcase, chair, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The kinds of place on a hospital ward floor, its ground-truth labels.
pub const HOSPITAL_KINDS: [&str; 5] = [
    "corridor",
    "patient_room",
    "nurse_station",
    "treatment_room",
    "day_room",
];

/// The hospital ward floor.
pub const HOSPITAL: FloorPlan = FloorPlan {
    kinds: HOSPITAL_KINDS,
    width: room_width,
    // Deep enough for a 2.2 m bed with room to walk round its foot.
    row_depth: (5.4, 7.0),
    // Two beds must pass each other.
    corridor_width: (2.4, 3.0),
    // A suspended ceiling over the services.
    ceiling: (2.7, 3.1),
    north: ["day_room", "patient_room"],
    south: ["nurse_station", "treatment_room"],
    filler: "patient_room",
    open: &["nurse_station"],
    furnish,
    fittings: corridor_fittings,
    door: door_anywhere,
    glazed: &[],
};

/// Width along the corridor of a room of a hospital kind (m), lowest and
/// highest: single rooms from 3.4 m, two-bed rooms (from 5.8 m) to 7 m.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "patient_room" => (3.4, 7.0),
        "nurse_station" => (4.5, 7.5),
        "treatment_room" => (3.4, 4.8),
        "day_room" => (5.5, 9.0),
        _ /* store room */ => (0.5, 3.6),
    }
}

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// corridor wall at y = 0.
fn furnish(kind: &str, [w, d, _h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    match kind {
        "patient_room" => patient_room(w, d, r, s),
        "nurse_station" => nurse_station(w, d, r, s),
        "treatment_room" => treatment_room(w, d, r, s),
        "day_room" => day_room(w, d, r, s),
        _ => store_room(w, d, r, s),
    }
}

/// A hospital bed centred on `f`, its head towards local +x: castors, a
/// chassis on lifting columns, the deck at 0.35-0.6 m with a 0.16 m
/// mattress, head- and footboard, a pillow, side rails up or down and the
/// backrest raised in about half of them.
fn bed(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame) {
    let (len, width) = (2.2, 1.0);
    for (x, y) in [(-0.85, -0.38), (-0.85, 0.38), (0.85, -0.38), (0.85, 0.38)] {
        f.part(s, [x, y], [0.1, 0.08], 0.0, 0.13);
    }
    let deck = u(r, 0.35, 0.6);
    f.part(s, [0.0, 0.0], [1.9, 0.8], 0.13, 0.1);
    for x in [-0.5, 0.5] {
        f.part(s, [x, 0.0], [0.18, 0.3], 0.23, deck - 0.23);
    }
    let top = deck + 0.16;
    f.part(s, [0.0, 0.0], [2.0, 0.9], deck, 0.16);
    f.part(
        s,
        [len / 2.0 - 0.03, 0.0],
        [0.05, width],
        0.25,
        top + 0.35 - 0.25,
    );
    f.part(
        s,
        [-len / 2.0 + 0.03, 0.0],
        [0.05, width],
        0.25,
        top + 0.2 - 0.25,
    );
    if r.random::<f64>() < 0.5 {
        // The backrest raised: the head end of the mattress stands up.
        f.part(s, [0.75, 0.0], [0.25, 0.88], top, 0.4);
        f.part(s, [0.55, 0.0], [0.3, 0.55], top + 0.3, 0.12);
    } else {
        f.part(s, [0.8, 0.0], [0.35, 0.6], top, 0.12);
    }
    for side in [-1.0, 1.0] {
        let z = if r.random::<f64>() < 0.6 {
            top
        } else {
            deck - 0.25
        };
        f.part(s, [0.35, side * 0.48], [1.1, 0.03], z, 0.3);
    }
}

/// A high-backed armchair (the kind hospitals give patients and
/// visitors) centred on `f`, facing local +x: seat at 0.48 m, arms at
/// 0.65 m, back to 1.05-1.15 m.
fn armchair(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame) {
    f.part(s, [0.05, 0.0], [0.55, 0.5], 0.12, 0.36);
    f.part(s, [-0.3, 0.0], [0.14, 0.68], 0.12, u(r, 0.93, 1.03));
    for side in [-1.0, 1.0] {
        f.part(s, [0.0, side * 0.31], [0.72, 0.08], 0.0, 0.65);
    }
}

/// A sofa of `len` m centred on `f`, facing local +x: feet, seat at
/// 0.45 m, arms at 0.62 m, back to 0.86 m, 0.88 m deep.
fn sofa(s: &mut Vec<Shape>, f: &Frame, len: f64) {
    f.part(s, [0.1, 0.0], [0.68, len - 0.36], 0.08, 0.37);
    f.part(s, [-0.33, 0.0], [0.22, len], 0.08, 0.78);
    for side in [-1.0, 1.0] {
        f.part(
            s,
            [0.0, side * (len / 2.0 - 0.09)],
            [0.88, 0.18],
            0.08,
            0.54,
        );
    }
    for (x, y) in [(-0.38, -1.0), (-0.38, 1.0), (0.38, -1.0), (0.38, 1.0)] {
        f.part(s, [x, y * (len / 2.0 - 0.05)], [0.05, 0.05], 0.0, 0.08);
    }
}

/// A four-legged dining chair centred on `f`, facing local +x: seat at
/// 0.46 m, back to 0.88 m.
fn side_chair(s: &mut Vec<Shape>, f: &Frame) {
    for (x, y) in [(-0.2, -0.2), (-0.2, 0.2), (0.2, -0.2), (0.2, 0.2)] {
        f.part(s, [x, y], [0.03, 0.03], 0.0, 0.44);
    }
    f.part(s, [0.0, 0.0], [0.44, 0.44], 0.44, 0.03);
    f.part(s, [-0.21, 0.0], [0.03, 0.42], 0.62, 0.26);
}

/// A trolley of `size` (m) with shelves at 0.25 m and at `top`, four
/// posts and a push handle, centred on `f`.
fn trolley(s: &mut Vec<Shape>, f: &Frame, size: [f64; 2], top: f64) {
    let [a, b] = [size[0] / 2.0 - 0.02, size[1] / 2.0 - 0.02];
    for (x, y) in [(-a, -b), (-a, b), (a, -b), (a, b)] {
        f.part(s, [x, y], [0.025, 0.025], 0.0, top);
    }
    for z in [0.25, top - 0.03] {
        f.part(s, [0.0, 0.0], size, z, 0.03);
    }
    f.part(s, [-a - 0.04, 0.0], [0.025, size[1]], top + 0.05, 0.025);
}

/// Patient rooms: one bed, or two in a room 5.8 m wide or more, heads
/// against the far wall under a services trunking, each bed with a
/// cabinet, an over-bed table, an armchair and a curtain rail round it
/// (every bed of a two-bed room, half the single ones); a wardrobe and a
/// hand-wash basin under a mirror on the side walls near the door.
fn patient_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let beds = if w >= 5.8 { 2 } else { 1 };
    let space = w / beds as f64;
    let rail_z = u(r, 2.15, 2.35);
    for i in 0..beds {
        let centre = space * (i as f64 + 0.5);
        let cx = centre + u(r, -0.1, 0.1);
        let f = Frame::at(cx, d - 0.15 - 1.1, FRAC_PI_2 + u(r, -0.08, 0.08));
        bed(s, r, &f);
        // Medical gases, lights and sockets on the wall above the head.
        let trunk = (space - 0.6).min(2.4);
        s.push(cuboid(
            [cx - trunk / 2.0, d - 0.09, 1.35],
            [trunk, 0.09, 0.25],
        ));
        if r.random::<f64>() < 0.5 {
            s.push(cuboid([cx + 0.5, d - 0.18, 1.7], [0.35, 0.18, 0.3]));
        }
        // The cabinet at the head, on one side; the armchair on the other.
        let side = if r.random::<bool>() { 1.0 } else { -1.0 };
        let [bx, by] = f.point([0.75, side * 0.82]);
        s.push(Shape::OrientedBox {
            centre: [bx, by, 0.43],
            half: [0.24, 0.22, 0.43],
            yaw: f.yaw,
        });
        let [ax, ay] = f.point([u(r, -0.4, 0.2), -side * u(r, 0.85, 1.0)]);
        let ax = ax.clamp(0.55, w - 0.55);
        let chair_at = Frame::at(ax, ay, f.yaw + side * FRAC_PI_2 + u(r, -0.5, 0.5));
        armchair(s, r, &chair_at);
        // The over-bed table: across the bed, or pushed beside it.
        // Its column stands outside the bed, its foot runs under it.
        let (tx, ty, column) = if r.random::<f64>() < 0.6 {
            (u(r, -0.5, 0.1), 0.0, -side * 0.55)
        } else {
            (u(r, -0.6, 0.0), side * 0.85, side * 1.2)
        };
        f.part(s, [tx, ty], [0.4, 0.85], u(r, 0.85, 1.0), 0.03);
        f.part(s, [tx, column], [0.05, 0.05], 0.0, 0.85);
        f.part(
            s,
            [tx, (column + ty) / 2.0],
            [0.5, 0.1 + (column - ty).abs()],
            0.0,
            0.06,
        );
        if beds > 1 || r.random::<f64>() < 0.5 {
            curtain_rail(s, r, centre, (space / 2.0 - 0.15).min(1.4), d, rail_z);
        }
    }
    // A wardrobe on one side wall, a basin under a mirror on the other.
    let near = if r.random::<bool>() { 0.0 } else { w - 0.6 };
    s.push(cuboid([near, u(r, 1.0, 1.6), 0.0], [0.6, 0.6, 1.95]));
    let basin = if near == 0.0 { w - 0.45 } else { 0.0 };
    s.push(cuboid([basin, 0.4, 0.8], [0.45, 0.55, 0.08]));
    let mirror = if basin == 0.0 { 0.0 } else { w - 0.02 };
    s.push(cuboid([mirror, 0.4, 1.15], [0.02, 0.55, 0.6]));
}

/// A curtain rail hung at `z` round a bed space centred at `cx`, `hw`
/// either side of it, from the head wall at `d` to 2.6 m into the room,
/// the curtains drawn back to the wall (or one side drawn along its
/// rail): fabric from 0.3 m to 0.45 m under the rail (mesh above).
fn curtain_rail(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, cx: f64, hw: f64, d: f64, z: f64) {
    let front = d - 2.6;
    for x in [cx - hw, cx + hw] {
        s.push(cuboid([x - 0.015, front, z], [0.03, 2.6, 0.03]));
    }
    s.push(cuboid([cx - hw, front - 0.015, z], [2.0 * hw, 0.03, 0.03]));
    let fabric = z - 0.45 - 0.3;
    for x in [cx - hw, cx + hw] {
        if r.random::<f64>() < 0.25 {
            s.push(cuboid([x - 0.01, front, 0.3], [0.02, 2.5, fabric]));
        } else {
            s.push(cuboid([x - 0.08, d - 0.5, 0.3], [0.16, 0.45, fabric]));
        }
    }
}

/// A nurse station: a counter the width of the room 1.2-1.8 m behind the
/// corridor opening, a 1.1 m high ledge in front of a 0.75 m desk with
/// monitors and task chairs, a return at one end; medicine cupboards
/// under and over a worktop on the back wall, a patient board, and the
/// notes and medicine trolleys.
fn nurse_station(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let y0 = u(r, 1.2, 1.8);
    let (x0, x1) = (u(r, 0.5, 1.0), w - u(r, 0.9, 1.4));
    s.push(cuboid([x0, y0, 0.0], [x1 - x0, 0.12, 1.05]));
    s.push(cuboid([x0, y0 - 0.1, 1.05], [x1 - x0, 0.34, 0.04]));
    s.push(cuboid([x0, y0 + 0.12, 0.72], [x1 - x0, 0.6, 0.03]));
    for px in [x0 + 0.65, x1 - 0.45] {
        s.push(cuboid([px, y0 + 0.15, 0.0], [0.4, 0.55, 0.68]));
    }
    let ret = u(r, 1.2, 2.0).min(d - y0 - 2.2);
    s.push(cuboid([x0, y0, 0.0], [0.6, ret, 0.75]));
    let mut x = x0 + 0.8;
    while x + 0.6 < x1 {
        if r.random::<f64>() < 0.75 {
            let yaw = u(r, -0.3, 0.3);
            let f = Frame::at(x + 0.3, y0 + 0.35, yaw);
            f.part(s, [0.0, 0.0], [0.55, 0.04], 0.85, 0.34);
            f.part(s, [0.0, 0.04], [0.2, 0.15], 0.75, 0.1);
            let [cx, cy] = f.point([u(r, -0.2, 0.2), u(r, 0.65, 0.95)]);
            chair(s, cx, cy, u(r, 0.0, TAU));
        }
        x += u(r, 1.1, 1.5);
    }
    // Back wall: base cupboards, a worktop, wall cupboards above.
    let back = (w - 1.2).min(4.5);
    let bx = u(r, 0.3, w - back - 0.3);
    s.push(cuboid([bx, d - 0.6, 0.0], [back, 0.6, 0.92]));
    s.push(cuboid([bx, d - 0.35, 1.45], [back, 0.35, 0.72]));
    if r.random::<f64>() < 0.7 {
        // The locked controlled-drugs cabinet, tall, at one end.
        let tx = if bx > 0.9 { bx - 0.7 } else { bx + back + 0.1 };
        if tx + 0.6 < w {
            s.push(cuboid([tx, d - 0.5, 0.0], [0.6, 0.5, 2.0]));
        }
    }
    let board = if r.random::<bool>() { 0.0 } else { w - 0.03 };
    s.push(cuboid(
        [board, y0 + 1.2, 0.95],
        [0.03, (d - y0 - 2.2).clamp(0.8, 2.4), 1.1],
    ));
    for size in [[0.6, 0.45], [0.55, 0.75]] {
        if r.random::<f64>() < 0.7 {
            let f = Frame::at(u(r, 1.0, w - 1.0), u(r, y0 + 1.6, d - 1.2), u(r, 0.0, TAU));
            f.part(s, [0.0, 0.0], size, 0.12, u(r, 0.85, 1.0));
        }
    }
}

/// A treatment room: an examination couch off one side wall with its
/// back raised, base cupboards with a sink and wall cupboards on the other
/// side wall, a tall cupboard, a dressing trolley, an examination lamp on
/// a stand, a stool, waste bins, and a writing desk with a chair.
fn treatment_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let left = r.random::<bool>();
    let (couch_x, bench_x) = if left {
        (0.75, w - 0.6)
    } else {
        (w - 0.75, 0.0)
    };
    let cy = u(r, 2.5, d - 1.4);
    let f = Frame::at(couch_x, cy, FRAC_PI_2);
    f.part(s, [0.0, 0.0], [1.3, 0.45], 0.0, 0.55);
    f.part(s, [0.0, 0.0], [1.95, 0.68], 0.55, 0.15);
    f.part(s, [0.7, 0.0], [0.5, 0.66], 0.7, u(r, 0.2, 0.45));
    // Along the other side wall: cupboards under a worktop with a sink,
    // wall cupboards over it, a tall cupboard at the end.
    let run = (d - 1.6).min(3.6);
    let y = u(r, 1.0, d - run - 0.2);
    s.push(cuboid([bench_x, y, 0.0], [0.6, run, 0.9]));
    s.push(cuboid(
        [bench_x + if left { 0.25 } else { 0.0 }, y, 1.45],
        [0.35, run, 0.7],
    ));
    let tall = (d - y - run - 0.05).min(0.6);
    if tall > 0.4 {
        s.push(cuboid([bench_x, y + run + 0.05, 0.0], [0.6, tall, 2.0]));
    }
    let [tx, ty] = [w * u(r, 0.45, 0.55), u(r, 1.2, d - 1.0)];
    trolley(s, &Frame::at(tx, ty, u(r, 0.0, TAU)), [0.6, 0.45], 0.9);
    let lamp = f.point([u(r, 0.7, 1.0), if left { -0.75 } else { 0.75 }]);
    for (radius, z0, z1) in [(0.28, 0.0, 0.05), (0.02, 0.05, 1.6)] {
        s.push(Shape::Cylinder {
            centre: lamp,
            radius,
            z0,
            z1,
        });
    }
    s.push(Shape::Sphere {
        centre: [lamp[0], lamp[1], 1.7],
        radius: 0.12,
    });
    let stool = [w * u(r, 0.35, 0.65), u(r, 1.0, d - 1.0)];
    for (radius, z0, z1) in [(0.27, 0.0, 0.05), (0.03, 0.05, 0.5), (0.2, 0.5, 0.57)] {
        s.push(Shape::Cylinder {
            centre: stool,
            radius,
            z0,
            z1,
        });
    }
    // Waste and sharps bins by the couch's wall, near the door.
    for i in 0..r.random_range(1..=3) {
        let x = if left { 0.05 } else { w - 0.43 };
        s.push(cuboid([x, 0.25 + 0.42 * i as f64, 0.0], [0.38, 0.38, 0.65]));
    }
    if w > 3.8 && r.random::<f64>() < 0.7 {
        let desk = Frame::at(w / 2.0, d - 0.35, PI);
        desk.part(s, [0.0, 0.0], [1.2, 0.6], 0.72, 0.03);
        desk.part(s, [0.5, 0.0], [0.4, 0.55], 0.0, 0.72);
        let [cx, cy] = desk.point([u(r, -0.3, 0.1), 0.75]);
        chair(s, cx, cy, u(r, 0.0, TAU));
    }
}

/// A day room: a sofa and armchairs round a low table facing a television
/// on a low unit, a table with dining chairs, a bookcase of books and
/// games, a water dispenser, a plant.
fn day_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    // The sitting group in the far half: sofa along a side wall facing
    // the television on the other.
    let tv_right = r.random::<bool>();
    let (sofa_x, face) = if tv_right {
        (0.45, 0.0)
    } else {
        (w - 0.45, PI)
    };
    let sy = d - u(r, 1.6, 2.2);
    let len = u(r, 1.6, 2.2);
    let sf = Frame::at(sofa_x, sy, face);
    sofa(s, &sf, len);
    let [ctx, cty] = sf.point([1.15, 0.0]);
    s.push(cuboid([ctx - 0.3, cty - 0.5, 0.0], [0.6, 1.0, 0.42]));
    for _ in 0..r.random_range(1..=3) {
        let side = if r.random::<bool>() { 1.0 } else { -1.0 };
        let [ax, ay] = sf.point([u(r, 1.0, 1.8), side * u(r, 0.9, 1.3)]);
        let (ax, ay) = (ax.clamp(0.6, w - 0.6), ay.min(d - 0.6));
        let towards = (cty - ay).atan2(ctx - ax);
        let chair_at = Frame::at(ax, ay, towards + u(r, -0.3, 0.3));
        armchair(s, r, &chair_at);
    }
    // The television on the other wall over a low unit.
    let unit = if tv_right { w - 0.45 } else { 0.0 };
    s.push(cuboid([unit, sy - 0.7, 0.0], [0.45, 1.4, 0.5]));
    let tv = if tv_right { w - 0.08 } else { 0.0 };
    s.push(cuboid([tv, sy - 0.6, u(r, 1.1, 1.3)], [0.08, 1.2, 0.7]));
    // A table with dining chairs in the near half, off the sofa's side.
    let tx = if tv_right {
        u(r, 0.55, 0.7)
    } else {
        u(r, 0.3, 0.45)
    };
    let tf = Frame::at(w * tx, u(r, 1.4, 1.9), u(r, -0.1, 0.1));
    let tl = u(r, 1.4, 1.8);
    tf.part(s, [0.0, 0.0], [tl, 0.9], 0.72, 0.04);
    for (x, y) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
        tf.part(
            s,
            [x * (tl / 2.0 - 0.06), y * 0.39],
            [0.05, 0.05],
            0.0,
            0.72,
        );
    }
    for side in [-1.0, 1.0] {
        for x in [-tl / 4.0, tl / 4.0] {
            if r.random::<f64>() < 0.8 {
                let [cx, cy] = tf.point([x + u(r, -0.1, 0.1), side * u(r, 0.6, 0.8)]);
                side_chair(
                    s,
                    &Frame::at(cx, cy, tf.yaw - side * FRAC_PI_2 + u(r, -0.3, 0.3)),
                );
            }
        }
    }
    if r.random::<f64>() < 0.7 {
        let wall = Frame::at(w, d, PI);
        let (x0, tall) = (u(r, 1.0, w - 2.5), u(r, 1.2, 1.8));
        bookcase(s, r, &wall, x0, 1.0, tall);
    }
    let corner = if tv_right { 0.1 } else { w - 0.45 };
    s.push(cuboid([corner, 0.4, 0.0], [0.35, 0.35, 1.1]));
    let plant = [if tv_right { w - 0.4 } else { 0.4 }, d - 0.4];
    s.push(Shape::Cylinder {
        centre: plant,
        radius: 0.2,
        z0: 0.0,
        z1: 0.4,
    });
    s.push(Shape::Sphere {
        centre: [plant[0], plant[1], u(r, 0.8, 1.1)],
        radius: u(r, 0.25, 0.4),
    });
}

/// A store room (a gap left in a row, never scanned): wire shelving of
/// boxes and linen on its side walls, a hoist or a folded wheelchair.
fn store_room(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let depth = (w / 2.0 - 0.1).clamp(0.1, 0.5);
    for x in [0.0, w - depth] {
        for level in 0..5 {
            let z = 0.15 + level as f64 * 0.42;
            s.push(cuboid([x, 0.5, z], [depth, d - 0.9, 0.02]));
            if r.random::<f64>() < 0.8 {
                let run = u(r, 0.5, d - 1.0);
                s.push(cuboid(
                    [x, u(r, 0.5, d - 0.4 - run), z + 0.02],
                    [depth, run, u(r, 0.15, 0.35)],
                ));
            }
        }
        if w < 2.0 * depth + 0.6 {
            break;
        }
    }
}

/// Corridor fittings: handrails at 0.9 m on both walls, broken now and
/// then (where doors are), on some floors a bumper rail below them;
/// direction signs hanging from the ceiling; and now and then a bed, a
/// wheelchair, a linen trolley or a resuscitation trolley parked against
/// a wall.
fn corridor_fittings(length: f64, cw: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let bumper = r.random::<f64>() < 0.5;
    for wall in [0.0, cw - 0.09] {
        let mut x = u(r, 0.2, 1.0);
        while x < length - 0.5 {
            let run = u(r, 3.0, 9.0).min(length - 0.2 - x);
            s.push(cuboid([x, wall, 0.86], [run, 0.09, 0.06]));
            if bumper {
                s.push(cuboid([x, wall + 0.04, 0.2], [run, 0.05, 0.2]));
            }
            x += run + u(r, 1.0, 1.6);
        }
    }
    let mut x = u(r, 3.0, 8.0);
    while x < length - 1.0 {
        s.push(cuboid(
            [x, cw / 2.0 - 0.6, (h - 0.55).min(2.3)],
            [0.04, 1.2, 0.25],
        ));
        x += u(r, 8.0, 15.0);
    }
    let mut x = u(r, 1.0, 4.0);
    while x < length - 2.5 {
        let near = r.random::<bool>();
        let toward = |depth: f64| {
            if near {
                0.1 + depth / 2.0
            } else {
                cw - 0.1 - depth / 2.0
            }
        };
        let yaw = if r.random::<bool>() { 0.0 } else { PI };
        let roll = r.random::<f64>();
        if roll < 0.22 {
            bed(s, r, &Frame::at(x + 1.1, toward(1.0), yaw));
            x += 2.2;
        } else if roll < 0.4 {
            wheelchair(s, &Frame::at(x + 0.5, toward(0.65), yaw + u(r, -0.2, 0.2)));
            x += 1.0;
        } else if roll < 0.5 {
            trolley(s, &Frame::at(x + 0.5, toward(0.55), yaw), [0.9, 0.55], 1.2);
            x += 1.0;
        } else if roll < 0.56 {
            // The resuscitation trolley: a chest of drawers on castors with
            // a defibrillator on top.
            let f = Frame::at(x + 0.35, toward(0.5), yaw);
            f.part(s, [0.0, 0.0], [0.65, 0.5], 0.1, 0.9);
            f.part(s, [0.0, 0.0], [0.35, 0.3], 1.0, 0.25);
            x += 0.7;
        }
        x += u(r, 4.0, 9.0);
    }
}

/// A wheelchair centred on `f`, facing local +x: two rear wheels of
/// 0.6 m, a sling seat at 0.5 m, arm rests, a back with push handles to
/// 0.95 m and footrests.
fn wheelchair(s: &mut Vec<Shape>, f: &Frame) {
    for side in [-1.0, 1.0] {
        f.part(s, [-0.1, side * 0.31], [0.6, 0.04], 0.0, 0.6);
        f.part(s, [0.3, side * 0.22], [0.1, 0.03], 0.0, 0.12);
        f.part(s, [0.0, side * 0.24], [0.4, 0.04], 0.68, 0.04);
    }
    f.part(s, [0.0, 0.0], [0.44, 0.44], 0.48, 0.04);
    f.part(s, [-0.22, 0.0], [0.04, 0.42], 0.52, 0.43);
    f.part(s, [0.42, 0.0], [0.2, 0.36], 0.12, 0.03);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The highest point and the footprint's corners (or its bounding
    /// square, for round shapes) of a shape.
    fn extent(s: &Shape) -> ([f64; 2], [f64; 2], f64, f64) {
        let (lo, hi, z0, z1) = match *s {
            Shape::Cylinder {
                centre,
                radius,
                z0,
                z1,
            } => (
                [centre[0] - radius, centre[1] - radius],
                [centre[0] + radius, centre[1] + radius],
                z0,
                z1,
            ),
            Shape::Sphere { centre, radius } => (
                [centre[0] - radius, centre[1] - radius],
                [centre[0] + radius, centre[1] + radius],
                centre[2] - radius,
                centre[2] + radius,
            ),
            Shape::Cuboid { min, max } => ([min[0], min[1]], [max[0], max[1]], min[2], max[2]),
            Shape::OrientedBox { centre, half, .. } => {
                let c = s.footprint_corners().unwrap();
                let xs = c.map(|p| p[0]);
                let ys = c.map(|p| p[1]);
                let min = |v: [f64; 4]| v.into_iter().fold(f64::INFINITY, f64::min);
                let max = |v: [f64; 4]| v.into_iter().fold(f64::NEG_INFINITY, f64::max);
                (
                    [min(xs), min(ys)],
                    [max(xs), max(ys)],
                    centre[2] - half[2],
                    centre[2] + half[2],
                )
            }
        };
        (lo, hi, z0, z1)
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(7);
        for kind in HOSPITAL_KINDS.iter().skip(1).copied().chain(["storage"]) {
            let (wl, wh) = room_width(kind);
            for _ in 0..200 {
                let (w, d) = (u(&mut r, wl, wh), u(&mut r, 5.4, 7.0));
                let h = 2.7;
                let mut s = Vec::new();
                furnish(kind, [w, d, h], &mut r, &mut s);
                assert!(!s.is_empty(), "{kind}: empty");
                for shape in &s {
                    let (lo, hi, z0, z1) = extent(shape);
                    let inside =
                        lo[0] >= -0.02 && lo[1] >= -0.02 && hi[0] <= w + 0.02 && hi[1] <= d + 0.02;
                    assert!(inside, "{kind} {w:.2} x {d:.2}: {shape:?} outside");
                    assert!(
                        z0 >= -1e-9 && z1 <= 2.4,
                        "{kind}: {shape:?} at {z0}..{z1} m"
                    );
                }
            }
        }
    }

    #[test]
    fn patient_rooms_hold_one_bed_and_the_wide_ones_two() {
        let mut r = crate::rng::rng(3);
        for (w, beds) in [(3.4, 1), (5.7, 1), (5.8, 2), (7.0, 2)] {
            let mut s = Vec::new();
            patient_room(w, 6.0, &mut r, &mut s);
            // Each bed has one mattress: 2.0 x 0.9 m, 0.16 m thick.
            let mattresses = s
                .iter()
                .filter(|s| matches!(s, Shape::OrientedBox { half, .. } if (half[0] - 1.0).abs() < 1e-9 && (half[1] - 0.45).abs() < 1e-9 && (half[2] - 0.08).abs() < 1e-9))
                .count();
            assert_eq!(mattresses, beds, "{w} m wide");
        }
    }

    #[test]
    fn corridors_have_handrails_at_0_9_m_on_both_walls_and_keep_a_way_through() {
        for seed in 1..=6 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (40.0, 2.6, 2.8);
            let mut s = Vec::new();
            corridor_fittings(length, cw, h, &mut r, &mut s);
            let rail = |y0: f64| -> f64 {
                s.iter()
                    .filter_map(|s| match *s {
                        Shape::Cuboid { min, max }
                            if (min[2] - 0.86).abs() < 1e-9 && (min[1] - y0).abs() < 1e-9 =>
                        {
                            Some(max[0] - min[0])
                        }
                        _ => None,
                    })
                    .sum()
            };
            for wall in [0.0, cw - 0.09] {
                let run = rail(wall);
                assert!(
                    run > 0.6 * length && run < length,
                    "seed {seed}: {run} m of rail at y = {wall}"
                );
            }
            for shape in &s {
                let (lo, hi, z0, z1) = extent(shape);
                assert!(
                    lo[0] >= 0.0 && hi[0] <= length && lo[1] >= 0.0 && hi[1] <= cw,
                    "{shape:?}"
                );
                assert!(z0 >= 0.0 && z1 <= h - 0.3, "{shape:?}");
                // Nothing below the signs narrows the corridor to less
                // than 1.3 m: parked things stand against one wall.
                if z0 < 2.0 {
                    assert!(hi[1] < cw - 1.3 || lo[1] > 1.3, "seed {seed}: {shape:?}");
                }
            }
        }
    }
}
