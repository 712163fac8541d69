//! Shopping-mall floors, a scene family written for issue 18's
//! twenty-fourth round by another hand, after the descriptors and the
//! recommended room setting existed, so that none of them was shaped on
//! it: the layout of [`super::office_floor`] (a corridor between two rows
//! of rooms, one ceiling) as a mall's concourse between two rows of
//! shops, furnished as real malls are. Every shop opens onto the
//! concourse through a glazed shopfront (a low base, mullions and a
//! fascia; the glass, which a lidar mostly sees through, left out) with a
//! wide entrance where the shop leaves its front clear. Clothing stores
//! have window podiums with mannequins, wall bays of hanging garments and
//! folded-stock shelves, garment rails, round racks and tables of folded
//! stacks on the floor, a cash desk before a back shelf and fitting-room
//! cubicles at the back; cafés a service counter with a display case
//! before a back counter of machines under shelves and menu boards,
//! small tables for two or four with chairs and sometimes a bench seat
//! along a wall; supermarkets parallel gondola runs with end caps,
//! shelving along a side wall, open multideck fridges along the back wall,
//! checkouts and produce stands at the front; electronics stores a TV
//! wall above a low cabinet, shelving units of boxed goods, display
//! tables of laptops and tablets and a service counter before back
//! shelving. The concourse has benches with bins, planters, carts and
//! kiosks and directory totems down its middle, the lanes along the
//! shopfronts kept free. Gaps left in a row are service rooms (never
//! scanned) behind a mostly shut door.

use super::geometry::{cuboid, Shape};
use super::hotel::{dining_chair, dining_table, round_table};
use super::office_floor::{mirrored_in_one_of_two, FloorPlan};
use super::scenes::{bookcase, chair, table, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The kinds of place on a mall floor, its ground-truth labels.
pub const MALL_KINDS: [&str; 5] = [
    "corridor",
    "clothing_store",
    "cafe",
    "supermarket",
    "electronics_store",
];

/// The mall floor: a supermarket and a café on one side, an electronics
/// store and another café on the other, clothing stores filling both
/// rows.
pub const MALL: FloorPlan = FloorPlan {
    kinds: MALL_KINDS,
    width: room_width,
    // Mall units are deep and narrow: 15-25 m from the shopfront back.
    row_depth: (15.0, 25.0),
    // The concourse.
    corridor_width: (5.0, 8.0),
    ceiling: (3.5, 4.5),
    north: ["supermarket", "cafe"],
    south: ["electronics_store", "cafe"],
    filler: "clothing_store",
    open: &["clothing_store", "cafe", "supermarket", "electronics_store"],
    furnish,
    fittings: concourse,
    door,
    glazed: &["clothing_store", "cafe", "supermarket", "electronics_store"],
};

/// Width along the concourse of a room of a mall kind (m), lowest and
/// highest.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "clothing_store" => (7.0, 14.0),
        "cafe" => (6.0, 12.0),
        "supermarket" => (18.0, 30.0),
        "electronics_store" => (8.0, 15.0),
        _ /* service room */ => (0.5, 7.0),
    }
}

/// How far into a shop (m) its entrance is kept clear.
const ENTRANCE: f64 = 1.5;

/// Furniture of a room of `kind` whose interior is [0, w] x [0, d], the
/// shopfront at y = 0, `h` high.
fn furnish(kind: &str, [w, d, h]: [f64; 3], r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    match kind {
        "clothing_store" => clothing_store(w, d, r, s),
        "cafe" => cafe(w, d, r, s),
        "supermarket" => supermarket(w, d, r, s),
        "electronics_store" => electronics_store(w, d, r, s),
        _ => service_room(w, d, h, r, s),
    }
}

/// Where a shop's entrance or a service room's door goes: a service
/// door is shut in seven of ten, a shop always open. It stands where the
/// front is clear of furniture for [`ENTRANCE`] into the room, anywhere
/// along it if nowhere is.
fn door(
    _kind: &str,
    width: f64,
    door: f64,
    open: bool,
    furniture: &[Shape],
    r: &mut ChaCha8Rng,
) -> Option<f64> {
    if !open && r.random::<f64>() < 0.7 {
        return None;
    }
    super::hotel::door_in_clear_span(width, door, ENTRANCE, furniture, r)
}

/// A piece against a side wall of a room `w` wide (`left`: the x = 0
/// one), `off` to `off + depth` from it: its lowest x and its size in x.
fn at_wall(w: f64, left: bool, off: f64, depth: f64) -> (f64, f64) {
    if left {
        (off, depth)
    } else {
        (w - off - depth, depth)
    }
}

/// A mannequin standing at `c` on a floor or podium at `z`: a base disc,
/// legs, a torso and a head, 1.7 m tall.
fn mannequin(s: &mut Vec<Shape>, c: [f64; 2], z: f64) {
    for (radius, z0, z1) in [(0.18, 0.0, 0.02), (0.12, 0.02, 0.87), (0.17, 0.87, 1.47)] {
        s.push(Shape::Cylinder {
            centre: c,
            radius,
            z0: z + z0,
            z1: z + z1,
        });
    }
    s.push(Shape::Sphere {
        centre: [c[0], c[1], z + 1.6],
        radius: 0.11,
    });
}

/// Runs of hanging garments, 0.5 m deep, along local x from `x0` to
/// `x1` of frame `f` (centred on local y = `y`), hung from a bar at `bar`.
fn garments(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    f: &Frame,
    (x0, x1): (f64, f64),
    y: f64,
    bar: f64,
) {
    let mut x = x0;
    while x < x1 - 0.1 {
        let run = u(r, 0.2, 0.5).min(x1 - x);
        if r.random::<f64>() < 0.85 {
            let long = u(r, 0.6, 1.0).min(bar - 0.25);
            f.part(
                s,
                [x + run / 2.0, y],
                [run, u(r, 0.45, 0.55)],
                bar - 0.05 - long,
                long,
            );
        }
        x += run + u(r, 0.0, 0.1);
    }
}

/// A clothing store: window podiums with mannequins either side of the
/// entrance, wall bays along both side walls, fitting rooms in a back
/// corner, the cash desk before a back shelf in the other, and rails,
/// round racks, tables of folded stacks and mannequins on the floor
/// either side of a main aisle.
fn clothing_store(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    // Fitting rooms: two to five cubicles, half the back wall at most.
    let left_fit = r.random::<bool>();
    let cw = u(r, 0.95, 1.2);
    let n = r
        .random_range(2..=5)
        .min((w * 0.5 / cw).floor() as usize)
        .max(1);
    let (fw, fd) = (n as f64 * cw, u(r, 1.3, 1.6));
    let fx = if left_fit { 0.0 } else { w - fw };
    // A carpeted step the scans keep out of, partitions, a curtain rail
    // and curtains part drawn.
    s.push(cuboid([fx, d - fd, 0.0], [fw, fd, 0.02]));
    let ph = u(r, 2.1, 2.4);
    for i in 0..=n {
        let x = (fx + i as f64 * cw - 0.02).clamp(fx, fx + fw - 0.04);
        s.push(cuboid([x, d - fd, 0.02], [0.04, fd, ph - 0.02]));
    }
    s.push(cuboid([fx, d - fd, 2.0], [fw, 0.04, 0.05]));
    for i in 0..n {
        let drawn = cw * u(r, 0.3, 0.9);
        s.push(cuboid(
            [fx + i as f64 * cw + 0.05, d - fd, 0.15],
            [drawn, 0.03, 1.85],
        ));
    }
    // Wall bays, to the fitting rooms on their side.
    for left in [true, false] {
        let end = if left == left_fit {
            d - fd - 0.15
        } else {
            d - 0.1
        };
        let bays = ((end - 0.4) / 1.2).floor().max(0.0) as usize;
        let bl = (end - 0.4) / bays.max(1) as f64;
        for b in 0..bays {
            let y = 0.4 + b as f64 * bl;
            let (x, dx) = at_wall(w, left, 0.0, 0.05);
            s.push(cuboid([x, y, 0.0], [dx, bl - 0.02, u(r, 2.2, 2.5)]));
            let f = Frame::at(at_wall(w, left, 0.05, 0.5).0 + 0.25, y, FRAC_PI_2);
            if r.random::<f64>() < 0.55 {
                // Hanging: a long hang or two tiers.
                if r.random::<bool>() {
                    garments(s, r, &f, (0.05, bl - 0.05), 0.0, 1.75);
                } else {
                    garments(s, r, &f, (0.05, bl - 0.05), 0.0, 1.8);
                    garments(s, r, &f, (0.05, bl - 0.05), 0.0, 1.05);
                }
            } else {
                // Shelves of folded stacks.
                let (x, dx) = at_wall(w, left, 0.05, 0.4);
                for level in 0..5 {
                    let z = 0.1 + level as f64 * 0.4;
                    s.push(cuboid([x, y, z], [dx, bl - 0.02, 0.02]));
                    let mut yy = y + 0.05;
                    while yy + 0.3 < y + bl - 0.05 {
                        if r.random::<f64>() < 0.8 {
                            s.push(cuboid(
                                [x + 0.03, yy, z + 0.02],
                                [0.34, 0.3, u(r, 0.08, 0.3)],
                            ));
                        }
                        yy += 0.35;
                    }
                }
            }
        }
    }
    // The cash desk with a till, before a back shelf, beside the
    // fitting rooms.
    let (a, b) = if left_fit {
        (fw + 0.4, w - 0.7)
    } else {
        (0.7, w - fw - 0.4)
    };
    let cl = u(r, 1.6, 2.6).min(b - a);
    let cx = a + u(r, 0.0, (b - a - cl).max(0.0) + 1e-9);
    s.push(cuboid([cx, d - 2.2, 0.0], [cl, 0.7, 1.0]));
    s.push(cuboid([cx + 0.2, d - 2.0, 1.0], [0.4, 0.35, 0.35]));
    s.push(cuboid([cx, d - 0.45, 0.0], [cl, 0.45, u(r, 1.8, 2.2)]));
    // Window podiums with mannequins either side of the entrance, which
    // keeps 3.8 m between them.
    let mut budget = w - 1.2 - 3.8;
    for left in [true, false] {
        let len = u(r, 1.2, 2.0);
        if len > budget || r.random::<f64>() < 0.25 {
            continue;
        }
        budget -= len;
        let (pd, ph) = (u(r, 0.8, 1.1), u(r, 0.15, 0.3));
        let (x, _) = at_wall(w, left, 0.6, len);
        s.push(cuboid([x, 0.3, 0.0], [len, pd, ph]));
        let k = ((len / 0.6).floor() as usize).min(r.random_range(1..=3));
        for i in 0..k {
            let c = [x + (i as f64 + 0.5) * len / k as f64, 0.3 + pd / 2.0];
            mannequin(s, c, ph);
        }
    }
    // The floor: rails, round racks, tables and mannequins on a grid,
    // a main aisle kept free from the entrance to the back.
    let aisle = w / 2.0 + u(r, -0.8, 0.8);
    let (px, py) = (u(r, 2.4, 3.0), u(r, 2.4, 3.0));
    let mut y = 3.0;
    while y <= d - 4.2 {
        let mut x = 2.4;
        while x <= w - 2.4 {
            if (x - aisle).abs() >= 1.5 {
                let at = [x + u(r, -0.15, 0.15), y + u(r, -0.15, 0.15)];
                floor_fixture(s, r, at[0], at[1]);
            }
            x += px;
        }
        y += py;
    }
}

/// One fixture of a clothing store's floor centred at (x, y), within
/// 0.8 m of it: a garment rail, a round rack, a table of folded stacks,
/// a mannequin, or nothing.
fn floor_fixture(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, x: f64, y: f64) {
    let roll = r.random::<f64>();
    let bar = u(r, 1.3, 1.6);
    if roll < 0.3 {
        let len = u(r, 1.2, 1.5);
        let yaw = if r.random::<bool>() { 0.0 } else { FRAC_PI_2 } + u(r, -0.05, 0.05);
        let f = Frame::at(x, y, yaw);
        for end in [-1.0, 1.0] {
            f.part(s, [end * len / 2.0, 0.0], [0.05, 0.5], 0.0, 0.04);
            f.part(s, [end * len / 2.0, 0.0], [0.04, 0.04], 0.04, bar - 0.04);
        }
        f.part(s, [0.0, 0.0], [len, 0.03], bar - 0.03, 0.03);
        garments(s, r, &f, (-len / 2.0 + 0.05, len / 2.0 - 0.05), 0.0, bar);
    } else if roll < 0.55 {
        let radius = u(r, 0.5, 0.65);
        let long = u(r, 0.6, 0.9);
        for (radius, z0, z1) in [
            (0.35, 0.0, 0.04),
            (0.03, 0.04, bar),
            (radius, bar - 0.05 - long, bar - 0.05),
        ] {
            s.push(Shape::Cylinder {
                centre: [x, y],
                radius,
                z0,
                z1,
            });
        }
    } else if roll < 0.8 {
        let f = Frame::at(x, y, u(r, -0.1, 0.1));
        let (tl, tw, th) = (u(r, 1.2, 1.5), u(r, 0.7, 0.9), u(r, 0.75, 0.85));
        table(s, &f, [0.0, 0.0], [tl, tw], th);
        for i in 0..((tl / 0.4).floor() as usize) {
            for side in [-1.0, 1.0] {
                if r.random::<f64>() < 0.8 {
                    let c = [-tl / 2.0 + 0.2 + i as f64 * 0.4, side * tw / 4.0];
                    f.part(s, c, [0.3, 0.33], th, u(r, 0.06, 0.3));
                }
            }
        }
    } else if roll < 0.9 {
        mannequin(s, [x, y], 0.0);
    }
}

/// A café, laid out with its counter from the x = 0 wall, then mirrored
/// in about one of two: a back counter of coffee machines along the back
/// wall under shelves and menu boards, the service counter with a till
/// and a display case of cakes before it, a drinks fridge in the staff
/// way where there is room, a queue's space, then tables for two and
/// four with chairs and in some a bench seat along the side wall.
fn cafe(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mut t = Vec::new();
    let bl = u(r, 2.5, 4.5).min(w - 2.0);
    t.push(cuboid([0.0, d - 0.6, 0.0], [bl, 0.6, 0.9]));
    let mut x = 0.1;
    while x + 0.4 < bl - 0.1 {
        let mw = u(r, 0.4, 0.7).min(bl - 0.1 - x);
        if r.random::<f64>() < 0.75 {
            t.push(cuboid([x, d - 0.55, 0.9], [mw, 0.45, u(r, 0.35, 0.6)]));
        }
        x += mw + u(r, 0.1, 0.4);
    }
    for z in [1.55, 1.9] {
        t.push(cuboid([0.0, d - 0.3, z], [bl, 0.3, 0.03]));
    }
    t.push(cuboid([0.2, d - 0.03, 2.05], [bl - 0.4, 0.03, 0.7]));
    // The service counter, a staff way behind it, open at its end.
    let cy = d - 0.6 - u(r, 1.0, 1.3) - 0.75;
    let cl = (bl + u(r, 0.5, 1.5)).min(w - 1.2);
    t.push(cuboid([0.0, cy, 0.0], [cl, 0.75, 1.0]));
    t.push(cuboid([0.3, cy + 0.3, 1.0], [0.35, 0.3, 0.3]));
    // The display case: a glass canopy's top and ends, cakes inside.
    let dl = u(r, 1.2, 1.8).min(cl - 0.8);
    let dx = cl - dl - u(r, 0.0, 0.2);
    t.push(cuboid([dx, cy, 1.33], [dl, 0.75, 0.02]));
    for x in [dx, dx + dl - 0.03] {
        t.push(cuboid([x, cy, 1.0], [0.03, 0.75, 0.33]));
    }
    let mut x = dx + 0.1;
    while x + 0.22 < dx + dl - 0.05 {
        if r.random::<f64>() < 0.7 {
            t.push(cuboid([x, cy + 0.2, 1.0], [0.22, 0.22, u(r, 0.06, 0.12)]));
        }
        x += 0.3;
    }
    if w - cl >= 1.8 && r.random::<f64>() < 0.6 {
        t.push(cuboid([w - 0.8, d - 0.75, 0.0], [0.75, 0.7, 2.0]));
    }
    // Seating from past the entrance to a queue's space before the
    // counter.
    let (y0, y1) = (ENTRANCE + 0.1, cy - 1.5);
    let mut x1 = w - 0.3;
    if y1 - y0 >= 2.5 && r.random::<f64>() < 0.5 {
        t.push(cuboid([w - 0.55, y0, 0.0], [0.55, y1 - y0, 0.45]));
        t.push(cuboid([w - 0.15, y0, 0.45], [0.15, y1 - y0, 0.55]));
        let mut y = y0 + 0.5;
        while y + 0.5 < y1 {
            dining_table(&mut t, &Frame::at(w - 0.95, y, 0.0), [0.6, 0.6]);
            if r.random::<f64>() < 0.85 {
                let f = Frame::at(w - 1.55, y + u(r, -0.1, 0.1), u(r, -0.3, 0.3));
                dining_chair(&mut t, r, &f);
            }
            y += u(r, 1.3, 1.5);
        }
        x1 = w - 2.0;
    }
    // A table and its chairs reach 0.95 m from its centre.
    let (px, py) = (u(r, 1.9, 2.3), u(r, 1.9, 2.3));
    let mut y = y0 + 0.95;
    while y <= y1 - 0.95 {
        let mut x = 0.3 + 0.95;
        while x <= x1 - 0.95 {
            if r.random::<f64>() < 0.85 {
                cafe_table(&mut t, r, [x, y]);
            }
            x += px;
        }
        y += py;
    }
    mirrored_in_one_of_two(&t, w, r, s);
}

/// A café table at `c`: a round one for two or a square one for two to
/// four, its chairs pulled up round it.
fn cafe_table(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, c: [f64; 2]) {
    let turn = u(r, 0.0, TAU);
    let (seats, reach) = if r.random::<bool>() {
        round_table(s, c, u(r, 0.3, 0.35), 0.75);
        (2, 0.55)
    } else {
        dining_table(s, &Frame::at(c[0], c[1], turn), [0.7, 0.7]);
        (r.random_range(2..=4), 0.6)
    };
    for k in 0..seats {
        if r.random::<f64>() < 0.9 {
            let a = turn + PI * (k % 2) as f64 + FRAC_PI_2 * (k / 2) as f64;
            let at = [c[0] + reach * a.cos(), c[1] + reach * a.sin()];
            let f = Frame::at(at[0], at[1], a + PI + u(r, -0.3, 0.3));
            dining_chair(s, r, &f);
        }
    }
}

/// A supermarket: open multideck fridges along the back wall, shelving
/// along a side wall, parallel gondola runs (two runs end to end about a
/// cross aisle where they are long) with end caps, checkouts at the
/// front on one side and produce stands on the other.
fn supermarket(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let fd = u(r, 0.85, 1.0);
    let mut x = 0.3;
    while x + 1.0 < w - 0.3 {
        let len = [1.875f64, 2.5][r.random_range(0..2)].min(w - 0.3 - x);
        multideck(s, r, x, d - fd, len, fd);
        x += len + 0.02;
    }
    // Checkouts: belt counters with a till and a lane light, a chair for
    // the cashier in the lane.
    let pitch = u(r, 1.9, 2.2);
    let n = r
        .random_range(2..=6)
        .min((w * 0.5 / pitch).floor() as usize);
    let cl = u(r, 2.4, 3.0);
    let left = r.random::<bool>();
    let x0 = if left {
        1.0
    } else {
        w - 1.0 - n as f64 * pitch
    };
    let y0 = ENTRANCE + 0.1;
    for i in 0..n {
        let x = x0 + i as f64 * pitch;
        s.push(cuboid([x, y0, 0.0], [0.9, cl, 0.9]));
        s.push(cuboid([x + 0.1, y0 + 0.1, 0.9], [0.5, 0.4, 0.35]));
        s.push(cuboid([x + 0.05, y0 + cl - 0.1, 0.9], [0.04, 0.04, 1.3]));
        s.push(cuboid([x, y0 + cl - 0.1, 2.2], [0.3, 0.04, 0.2]));
        chair(s, x + 0.9 + (pitch - 0.9) / 2.0, y0 + 0.5, u(r, 0.0, TAU));
    }
    // Produce stands on the other side of the front.
    let (a, b) = if left {
        (x0 + n as f64 * pitch + 1.0, w - 1.0)
    } else {
        (1.0, x0 - 1.0)
    };
    let mut x = a;
    while x + 1.3 <= b {
        if r.random::<f64>() < 0.7 {
            s.push(cuboid([x, y0 + 0.5, 0.0], [1.3, 1.0, u(r, 0.8, 0.9)]));
        }
        x += u(r, 2.2, 2.8);
    }
    // The runs: from a cross aisle behind the checkouts to a back aisle
    // before the fridges.
    let (gd, gh, aisle) = (u(r, 1.0, 1.2), u(r, 1.6, 2.0), u(r, 1.8, 2.4));
    let front = y0 + cl + u(r, 1.8, 2.4) + 0.45;
    let back = d - fd - u(r, 2.0, 2.6) - 0.45;
    let shelf_left = r.random::<bool>();
    let (sx, sdx) = at_wall(w, shelf_left, 0.0, 0.6);
    wall_shelving(
        s,
        r,
        [sx, front - 0.45],
        [sdx, d - fd - 0.1 - front + 0.45],
        gh,
    );
    let runs = if back - front > 12.0 {
        let mid = (front + back) / 2.0;
        vec![(front, mid - 1.0 - 0.45), (mid + 1.0 + 0.45, back)]
    } else {
        vec![(front, back)]
    };
    let mut x = 0.6 + aisle;
    while x + gd <= w - 0.6 - aisle + 1e-9 {
        for &(ya, yb) in &runs {
            gondola(s, r, x, (ya, yb), gd, gh);
        }
        x += gd + aisle;
    }
}

/// An open multideck fridge from (x, y) against the back wall, `len`
/// long and `depth` deep: a base, a canopy, a back, and shelves of goods.
fn multideck(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, x: f64, y: f64, len: f64, depth: f64) {
    let top = u(r, 2.0, 2.2);
    s.push(cuboid([x, y, 0.0], [len, depth, 0.35]));
    s.push(cuboid([x, y, top - 0.25], [len, depth, 0.25]));
    s.push(cuboid([x, y + depth - 0.1, 0.35], [len, 0.1, top - 0.6]));
    for level in 0..4 {
        let z = 0.35 + level as f64 * 0.35;
        let sd = depth - 0.1 - 0.1 * level as f64;
        s.push(cuboid([x, y + depth - 0.1 - sd, z], [len, sd, 0.02]));
        let mut xx = x + 0.02;
        while xx < x + len - 0.2 {
            let run = u(r, 0.2, 0.6).min(x + len - 0.02 - xx);
            if r.random::<f64>() < 0.85 {
                let pd = sd * u(r, 0.6, 0.95);
                let pz = z + 0.02;
                s.push(cuboid(
                    [xx, y + depth - 0.1 - pd, pz],
                    [run, pd, u(r, 0.12, 0.3)],
                ));
            }
            xx += run + u(r, 0.0, 0.08);
        }
    }
}

/// Single-sided shelving of footprint `at` (lowest x and y), `size`,
/// `h` high, against a wall: a back, shelves and goods in bays.
fn wall_shelving(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, at: [f64; 2], size: [f64; 2], h: f64) {
    s.push(cuboid([at[0], at[1], 0.0], [size[0], size[1], 0.12]));
    for level in 1..5 {
        let z = 0.12 + level as f64 * (h - 0.15) / 5.0;
        s.push(cuboid([at[0], at[1], z], [size[0], size[1], 0.02]));
    }
    let mut y = at[1];
    while y + 1.0 <= at[1] + size[1] {
        for level in 0..5 {
            if r.random::<f64>() < 0.85 {
                let z = 0.14 + level as f64 * (h - 0.15) / 5.0;
                let top = ((h - 0.15) / 5.0 - 0.05).min(h - z);
                s.push(cuboid(
                    [at[0] + 0.05, y + 0.02, z],
                    [size[0] - 0.1, 0.96, u(r, 0.12, top)],
                ));
            }
        }
        y += 1.0;
    }
}

/// A double-sided gondola run at x (its lowest x), from y0 to y1 along
/// y, `gd` deep and `gh` high: a base deck, a spine, shelves on both
/// sides with goods bay by bay, and an end cap at each end.
fn gondola(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, x: f64, (y0, y1): (f64, f64), gd: f64, gh: f64) {
    let len = y1 - y0;
    s.push(cuboid([x, y0, 0.0], [gd, len, 0.12]));
    s.push(cuboid(
        [x + gd / 2.0 - 0.03, y0, 0.12],
        [0.06, len, gh - 0.12],
    ));
    let levels = r.random_range(4..=5);
    let gap = (gh - 0.15) / levels as f64;
    let half = gd / 2.0 - 0.03;
    let bays = (len / 1.25).round().max(1.0) as usize;
    let bl = len / bays as f64;
    for (side, sx) in [(0, x), (1, x + gd / 2.0 + 0.03)] {
        for level in 0..levels {
            let z = 0.12 + level as f64 * gap;
            if level > 0 {
                s.push(cuboid([sx, y0, z], [half, len, 0.02]));
            }
            for b in 0..bays {
                if r.random::<f64>() < 0.9 {
                    let pd = half * u(r, 0.6, 0.95);
                    let px = if side == 0 {
                        x + gd / 2.0 - 0.03 - pd
                    } else {
                        sx
                    };
                    let ph = u(r, 0.1, gap - 0.05);
                    let y = y0 + b as f64 * bl + 0.02;
                    s.push(cuboid([px, y, z + 0.02], [pd, bl - 0.04, ph]));
                }
            }
        }
    }
    for y in [y0 - 0.45, y1] {
        s.push(cuboid([x, y, 0.0], [gd, 0.45, u(r, 1.2, 1.5)]));
    }
}

/// An electronics store: a TV wall of two tiers of screens above a low
/// cabinet on one side wall, shelving units of boxed goods on the other,
/// display tables of laptops and tablets in rows, a service counter
/// before back shelving.
fn electronics_store(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let tv_left = r.random::<bool>();
    let (y0, y1) = (1.8, d - 2.6);
    let (cx, cdx) = at_wall(w, tv_left, 0.0, 0.45);
    s.push(cuboid([cx, y0, 0.0], [cdx, y1 - y0, 0.6]));
    for tier in 0..2 {
        let z = 0.8 + tier as f64 * 0.95;
        let mut y = y0 + u(r, 0.05, 0.3);
        loop {
            let tw = u(r, 0.9, 1.45);
            if y + tw > y1 {
                break;
            }
            let (x, dx) = at_wall(w, tv_left, 0.05, 0.06);
            s.push(cuboid([x, y, z], [dx, tw, tw * 0.58]));
            y += tw + u(r, 0.15, 0.3);
        }
    }
    // Shelving units on the other wall.
    let mut y = 1.0;
    while y + 1.0 <= d - 2.6 {
        if r.random::<f64>() < 0.9 {
            let f = if tv_left {
                Frame::at(w, y, FRAC_PI_2)
            } else {
                Frame::at(0.0, y + 1.0, -FRAC_PI_2)
            };
            let tall = u(r, 1.8, 2.2);
            bookcase(s, r, &f, 0.0, 1.0, tall);
        }
        y += 1.02;
    }
    // The service counter with screens on it, back shelving behind.
    let cl = u(r, 2.4, 4.0).min(w - 3.0);
    let cx = u(r, 1.5, w - 1.5 - cl);
    s.push(cuboid([cx, d - 2.0, 0.0], [cl, 0.7, 1.05]));
    for k in 0..r.random_range(1..=2) {
        s.push(cuboid(
            [cx + 0.3 + k as f64 * 1.2, d - 1.5, 1.05],
            [0.55, 0.03, 0.38],
        ));
    }
    let bx = (cx - 0.5).max(1.0);
    let bl = (cl + 1.0).min(w - 1.0 - bx);
    let f = Frame::at(bx + bl, d, PI);
    let tall = u(r, 2.0, 2.4);
    bookcase(s, r, &f, 0.0, bl, tall);
    // Display tables along the depth, in rows either side of aisles.
    let (tl, tw) = (u(r, 1.6, 2.4), u(r, 0.9, 1.1));
    let (px, py) = (tw + u(r, 1.4, 1.8), tl + u(r, 1.2, 1.6));
    let mut x = 0.45 + 1.3 + tw / 2.0;
    while x + tw / 2.0 <= w - 0.4 - 1.3 {
        let mut y = 2.2 + tl / 2.0;
        while y + tl / 2.0 <= d - 2.0 - 1.4 {
            if r.random::<f64>() < 0.9 {
                display_table(s, r, &Frame::at(x, y, FRAC_PI_2), tl, tw);
            }
            y += py;
        }
        x += px;
    }
}

/// A display table `tl` by `tw` on `f` (its length along local x), its
/// top at 0.9 m: laptops open and tablets on stands along both sides.
fn display_table(s: &mut Vec<Shape>, r: &mut ChaCha8Rng, f: &Frame, tl: f64, tw: f64) {
    table(s, f, [0.0, 0.0], [tl, tw], 0.9);
    let n = (tl / 0.5).floor() as usize;
    for side in [-1.0, 1.0] {
        for i in 0..n {
            if r.random::<f64>() < 0.2 {
                continue;
            }
            let x = -tl / 2.0 + (i as f64 + 0.5) * tl / n as f64;
            let y = side * (tw / 2.0 - 0.2);
            if r.random::<f64>() < 0.6 {
                f.part(s, [x, y], [0.33, 0.23], 0.9, 0.02);
                f.part(s, [x, y - side * 0.11], [0.33, 0.01], 0.92, 0.22);
            } else {
                f.part(s, [x, y], [0.12, 0.08], 0.9, 0.16);
            }
        }
    }
}

/// A service room (a gap left in a row, never scanned): racking of
/// stock along its side walls.
fn service_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let depth = (w / 2.0 - 0.1).clamp(0.1, 0.6);
    for x in [0.0, w - depth] {
        for level in 0..5 {
            let z = 0.1 + level as f64 * 0.5;
            s.push(cuboid([x, 1.0, z], [depth, d - 1.2, 0.02]));
            if r.random::<f64>() < 0.8 {
                let run = u(r, 0.5, d - 1.4);
                let y = u(r, 1.0, d - 0.2 - run);
                s.push(cuboid(
                    [x, y, z + 0.02],
                    [depth, run, u(r, 0.2, 0.45).min(h - z - 0.1)],
                ));
            }
        }
        if w < 2.0 * depth + 0.6 {
            break;
        }
    }
}

/// How far from the concourse's middle line (m) its fittings reach.
const MIDDLE: f64 = 1.25;

/// The concourse's fittings down its middle, `length` by `width`, `h`
/// high, 4-10 m apart: benches (some back to back) with a bin, low
/// planters of shrubs, and carts and kiosks (a counter under a sign
/// canopy on corner posts), the lanes along both shopfronts free. Below
/// the canopies nothing stands higher than a counter, so the concourse
/// is seen along over them, as in a mall.
fn concourse(length: f64, width: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mid = width / 2.0;
    let mut x = u(r, 2.0, 6.0);
    while x < length - 4.0 {
        let roll = r.random::<f64>();
        let used = if roll < 0.4 {
            let len = u(r, 1.6, 2.0);
            let pair = r.random::<bool>();
            for side in if pair { vec![-1.0, 1.0] } else { vec![1.0] } {
                let y = mid + side * 0.3 - 0.25;
                s.push(cuboid([x, y, 0.0], [len, 0.5, 0.45]));
                if pair || r.random::<bool>() {
                    let by = if side > 0.0 { y + 0.45 } else { y };
                    s.push(cuboid([x, by, 0.45], [len, 0.05, 0.4]));
                }
            }
            if r.random::<f64>() < 0.6 {
                s.push(Shape::Cylinder {
                    centre: [x + len + 0.5, mid],
                    radius: 0.25,
                    z0: 0.0,
                    z1: 0.9,
                });
                len + 0.8
            } else {
                len
            }
        } else if roll < 0.7 {
            // A round or long planter with shrubs.
            let (len, dep, ph) = (u(r, 1.0, 2.5), u(r, 0.8, 1.6), u(r, 0.45, 0.6));
            let y = mid - dep / 2.0;
            s.push(cuboid([x, y, 0.0], [len, dep, ph]));
            let mut px = x + 0.3;
            while px + 0.3 < x + len {
                s.push(Shape::Sphere {
                    centre: [px, mid + u(r, -0.1, 0.1) * dep, ph + 0.05],
                    radius: u(r, 0.2, 0.3),
                });
                px += u(r, 0.4, 0.6);
            }
            len
        } else {
            // A cart or a kiosk: a counter, goods on it, a sign canopy on
            // corner posts.
            let (len, dep) = if r.random::<bool>() {
                (u(r, 1.2, 2.4), u(r, 0.8, 1.2))
            } else {
                (u(r, 2.5, 3.5), u(r, 1.5, 2.0 * MIDDLE - 0.5))
            };
            let y = mid - dep / 2.0;
            s.push(cuboid([x, y, 0.0], [len, dep, 0.93]));
            let mut gx = x + 0.1;
            while gx + 0.3 < x + len - 0.1 {
                if r.random::<f64>() < 0.6 {
                    s.push(cuboid([gx, y + 0.1, 0.93], [0.3, dep - 0.2, 0.02]));
                }
                gx += 0.4;
            }
            let canopy = u(r, 2.4, 2.6).min(h - 0.8);
            for (px, py) in [
                (0.0, 0.0),
                (len - 0.04, 0.0),
                (0.0, dep - 0.04),
                (len - 0.04, dep - 0.04),
            ] {
                s.push(cuboid([x + px, y + py, 0.93], [0.04, 0.04, canopy - 0.93]));
            }
            s.push(cuboid([x, y, canopy], [len, dep, 0.1]));
            len
        };
        x += used + u(r, 4.0, 10.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::hotel::{extent, overlap};
    use crate::sim::office_floor::{boxes, furnished_room};

    /// A room of `kind` of a size drawn from the plan's ranges.
    fn room(kind: &str, r: &mut ChaCha8Rng) -> ([f64; 3], Vec<Shape>) {
        furnished_room(&MALL, kind, r)
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        for kind in MALL_KINDS.iter().skip(1).copied().chain(["storage"]) {
            for _ in 0..200 {
                let ([w, d, h], s) = room(kind, &mut r);
                assert!(!s.is_empty(), "{kind}: empty");
                for shape in &s {
                    let (lo, hi, z0, z1) = extent(shape);
                    let inside =
                        lo[0] >= -1e-9 && lo[1] >= -1e-9 && hi[0] <= w + 1e-9 && hi[1] <= d + 1e-9;
                    assert!(inside, "{kind} {w:.2} x {d:.2}: {shape:?} outside");
                    // Under the ceiling and the shopfront's fascia.
                    assert!(
                        z0 >= -1e-9 && z1 <= (h - 0.6).min(2.9),
                        "{kind}: {shape:?} at {z0}..{z1} m"
                    );
                }
            }
        }
    }

    #[test]
    fn shop_entrances_are_clear_and_open_and_service_doors_mostly_shut() {
        let mut r = crate::rng::rng(3);
        for kind in &MALL_KINDS[1..] {
            for _ in 0..200 {
                let ([w, ..], s) = room(kind, &mut r);
                let x = (MALL.door)(kind, w, 3.5, true, &s, &mut r).expect("open");
                let gap = ([x, 0.0], [x + 3.5, ENTRANCE]);
                assert!(
                    x >= 0.1 - 1e-9 && x + 3.5 <= w - 0.1 + 1e-9,
                    "{kind}: {x} in {w}"
                );
                for shape in &s {
                    let (a, b, _, _) = extent(shape);
                    assert!(
                        !overlap((a, b), gap),
                        "{kind} {w}: entrance at {x}: {shape:?}"
                    );
                }
            }
        }
        let shut = (0..1000)
            .filter(|_| door("storage", 3.0, 0.8, false, &[], &mut r).is_none())
            .count();
        assert!((630..=770).contains(&shut), "{shut}");
    }

    #[test]
    fn a_supermarket_has_parallel_gondola_runs_checkouts_and_fridges_along_the_back() {
        let mut r = crate::rng::rng(5);
        for _ in 0..200 {
            let ([w, d, _], s) = room("supermarket", &mut r);
            let b = boxes(&s);
            // Spines: thin, 1.6-2.0 m high, 2.5 m long at least, along y.
            let mut spines: Vec<f64> = b
                .iter()
                .filter(|(lo, hi)| {
                    hi[0] - lo[0] < 0.07 && hi[1] - lo[1] > 2.5 && (1.6..=2.0).contains(&hi[2])
                })
                .map(|(lo, _)| lo[0])
                .collect();
            spines.sort_by(f64::total_cmp);
            spines.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
            assert!(spines.len() >= 3, "{w:.1} m: {} runs", spines.len());
            // Aisles of 1.8 m at least between them.
            for p in spines.windows(2) {
                assert!(p[1] - p[0] >= 1.0 + 1.8 - 1e-9, "{spines:?}");
            }
            let checkouts = b
                .iter()
                .filter(|(lo, hi)| {
                    (hi[0] - lo[0] - 0.9).abs() < 1e-9 && hi[2] == 0.9 && hi[1] - lo[1] >= 2.4
                })
                .count();
            assert!(checkouts >= 2, "{checkouts} checkouts");
            let fridge: f64 = b
                .iter()
                .filter(|(lo, hi)| (hi[1] - d).abs() < 1e-9 && lo[2] == 0.0 && hi[2] == 0.35)
                .map(|(lo, hi)| hi[0] - lo[0])
                .sum();
            assert!(fridge >= 0.8 * (w - 0.6), "{fridge} m of fridges in {w}");
        }
    }

    #[test]
    fn a_clothing_store_has_fitting_rooms_a_cash_desk_and_garments() {
        let mut r = crate::rng::rng(6);
        let mut mannequins = 0;
        for _ in 0..200 {
            let ([w, d, _], s) = room("clothing_store", &mut r);
            let b = boxes(&s);
            let cubicles = b
                .iter()
                .filter(|(lo, hi)| {
                    (hi[0] - lo[0] - 0.04).abs() < 1e-9 && (hi[1] - d).abs() < 1e-9 && hi[2] >= 2.1
                })
                .count();
            assert!(cubicles >= 2, "{w}: {cubicles} partitions");
            let desk = b
                .iter()
                .any(|(lo, hi)| hi[2] == 1.0 && (hi[1] - lo[1] - 0.7).abs() < 1e-9);
            assert!(desk, "no cash desk");
            // Garments hang in the wall bays at least.
            let hung = s
                .iter()
                .filter(|s| matches!(s, Shape::OrientedBox { centre, half, .. }
                    if (0.22..=0.28).contains(&half[1]) && half[2] >= 0.25 && centre[2] - half[2] >= 0.15))
                .count();
            assert!(hung >= 4, "{hung} garment runs");
            mannequins += s
                .iter()
                .filter(|s| matches!(s, Shape::Sphere { .. }))
                .count();
        }
        assert!(mannequins >= 200, "{mannequins} mannequins in 200 stores");
    }

    #[test]
    fn a_cafe_has_a_counter_with_a_display_case_and_tables_with_chairs() {
        let mut r = crate::rng::rng(7);
        for _ in 0..200 {
            let ([w, ..], s) = room("cafe", &mut r);
            let b = boxes(&s);
            assert!(b
                .iter()
                .any(|(lo, hi)| hi[2] == 1.0 && (hi[1] - lo[1] - 0.75).abs() < 1e-9));
            assert!(b.iter().any(|(lo, _)| lo[2] == 1.33), "no display case");
            // Chair seats: 0.45 m square at 0.41-0.47 m.
            let seats = s
                .iter()
                .filter(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] - 0.44).abs() < 1e-9 && (half[0] - 0.225).abs() < 1e-9))
                .count();
            assert!(seats >= 4, "{w}: {seats} chairs");
        }
    }

    #[test]
    fn an_electronics_store_has_a_tv_wall_display_tables_and_a_counter() {
        let mut r = crate::rng::rng(8);
        for _ in 0..200 {
            let ([w, ..], s) = room("electronics_store", &mut r);
            let b = boxes(&s);
            let tvs = b
                .iter()
                .filter(|(lo, hi)| (hi[0] - lo[0] - 0.06).abs() < 1e-9 && lo[2] >= 0.8)
                .count();
            assert!(tvs >= 6, "{w}: {tvs} screens");
            assert!(b.iter().any(|(_, hi)| hi[2] == 1.05), "no counter");
            let tops = s
                .iter()
                .filter(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] + half[2] - 0.9).abs() < 1e-9 && half[0] >= 0.8))
                .count();
            assert!(tops >= 1, "{w}: no display table");
        }
    }

    #[test]
    fn the_concourse_keeps_its_lanes_free_and_has_fittings() {
        for seed in 1..=8 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (60.0, 5.0, 3.5);
            let mut s = Vec::new();
            concourse(length, cw, h, &mut r, &mut s);
            assert!(s.len() >= 6, "seed {seed}: {} fittings", s.len());
            for shape in &s {
                let (lo, hi, z0, z1) = extent(shape);
                assert!(lo[0] >= 0.0 && hi[0] <= length, "{shape:?}");
                assert!(z0 >= 0.0 && z1 <= h - 0.5, "{shape:?}");
                assert!(
                    lo[1] >= cw / 2.0 - MIDDLE - 1e-9 && hi[1] <= cw / 2.0 + MIDDLE + 1e-9,
                    "seed {seed}: {shape:?} in a lane"
                );
                // Between counter height and the canopies only posts.
                let thin = hi[0] - lo[0] <= 0.05 && hi[1] - lo[1] <= 0.05;
                assert!(
                    z1 <= 0.95 + 1e-9 || z0 >= 2.4 - 1e-9 || thin,
                    "seed {seed}: {shape:?} across the view"
                );
            }
            let benches = s
                .iter()
                .filter(|s| matches!(s, Shape::Cuboid { max, .. } if max[2] == 0.45))
                .count();
            let canopies = s
                .iter()
                .filter(|s| matches!(s, Shape::Cuboid { min, .. } if min[2] >= 2.4))
                .count();
            assert!(
                benches >= 1 && canopies >= 1,
                "seed {seed}: {benches} benches, {canopies} carts"
            );
        }
    }
}
