//! Residential floors, a scene family written for issue 18's
//! twenty-fifth round by another hand, after the descriptors and the
//! recommended room setting existed, so that none of them was shaped on
//! it: the layout of [`super::office_floor`] (a corridor between two rows
//! of rooms, one ceiling) as an apartment building's floor, its rooms
//! furnished as real homes are. The building's shared corridor has
//! radiators, fire extinguisher cabinets, shoe racks and parcel boxes
//! along its walls and ceiling lights down its middle. Living rooms have
//! a sofa against a side wall facing a television on a low cabinet across
//! a coffee table, an armchair beside them, a floor lamp, a bookshelf by
//! the door and in deep rooms a dining table with chairs by the window.
//! Kitchens have a run of base cabinets under a worktop at about 0.9 m
//! along a side wall (and in some the back wall), wall cabinets above it
//! from about 1.4 to 2.1 m, a tall fridge at the run's end, and in wider
//! ones a small table with chairs or an island. Bedrooms have a bed
//! (0.9 to 1.8 m wide, its mattress about 0.5 m high) with its headboard
//! against the back wall between bedside tables with lamps, a wardrobe to
//! about 2.1 m along a side wall and sometimes a desk and chair. Bathrooms
//! have a bathtub across the back wall or a shower enclosure in a back
//! corner, a toilet and a washbasin on a vanity along a side wall, a
//! towel radiator and sometimes a washing machine. Doors are ordinary
//! residential doors in the corridor wall, shut in some rooms (the door
//! leaf itself is not modelled, as on the hotel floors), and stand where
//! the room leaves a door's swing clear. Gaps left in a row are utility
//! closets (never scanned) with shelving, behind a mostly shut door.
//!
//! What it leaves out: no apartments are modelled. Every room, bathrooms
//! included, opens onto the shared corridor through its own door, and
//! every room is as deep as its row (4.2 to 5.8 m, where a real flat's
//! bathroom is shallower). A floor has two living rooms, a kitchen and a
//! bathroom, and bedrooms in the rest of its rows.

use super::geometry::{cuboid, Shape};
use super::hotel::{dining_chair, dining_table, door_unless_shut};
use super::office_floor::{mirrored_in_one_of_two, FloorPlan};
use super::scenes::{bookcase, chair, table, u, Frame};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// The kinds of place on a residential floor, its ground-truth labels.
pub const HOME_KINDS: [&str; 5] = ["corridor", "living_room", "kitchen", "bedroom", "bathroom"];

/// The residential floor: a living room and a kitchen on one side, a
/// bathroom and another living room on the other, bedrooms filling both
/// rows.
pub const HOME: FloorPlan = FloorPlan {
    kinds: HOME_KINDS,
    width: room_width,
    // Apartment rooms, from the corridor to the window wall.
    row_depth: (4.2, 5.8),
    // A residential corridor: two people pass, a pram gets by.
    corridor_width: (1.6, 2.1),
    ceiling: (2.5, 2.7),
    north: ["living_room", "kitchen"],
    south: ["bathroom", "living_room"],
    filler: "bedroom",
    open: &[],
    furnish,
    fittings: corridor_fittings,
    door,
    glazed: &[],
};

/// Width along the corridor of a room of a residential kind (m), lowest
/// and highest.
pub fn room_width(kind: &str) -> (f64, f64) {
    match kind {
        "living_room" => (3.8, 5.5),
        "kitchen" => (2.4, 3.6),
        "bedroom" => (2.8, 4.0),
        "bathroom" => (1.7, 2.6),
        _ /* utility closet */ => (0.5, 2.8),
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
        "living_room" => living_room(w, d, h, r, &mut t),
        "kitchen" => kitchen(w, d, h, r, &mut t),
        "bedroom" => bedroom(w, d, h, r, &mut t),
        "bathroom" => bathroom(w, d, r, &mut t),
        _ => closet(w, d, h, r, &mut t),
    }
    mirrored_in_one_of_two(&t, w, r, s);
}

/// Where a room's door goes: shut in half the bathrooms, two bedrooms of
/// five, a living room or kitchen of four and most utility closets, else
/// where the corridor wall is clear of furniture for a door's swing
/// ([`SWING`]) into the room, anywhere along it if nowhere is (which the
/// layouts below never leave).
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
        "bathroom" => 0.5,
        "bedroom" => 0.4,
        "living_room" | "kitchen" => 0.25,
        _ => 0.8,
    };
    door_unless_shut(shut, width, door, SWING, furniture, r)
}

/// A table lamp standing at `c` on a top at `z`: a stem and a shade.
fn table_lamp(s: &mut Vec<Shape>, c: [f64; 2], z: f64, tall: f64) {
    for (radius, z0, z1) in [(0.04, z, z + tall * 0.6), (0.14, z + tall * 0.6, z + tall)] {
        s.push(Shape::Cylinder {
            centre: c,
            radius,
            z0,
            z1,
        });
    }
}

/// A floor lamp at `c`, `tall` high: a base disc, a pole and a shade.
fn floor_lamp(s: &mut Vec<Shape>, c: [f64; 2], tall: f64) {
    for (radius, z0, z1) in [
        (0.15, 0.0, 0.03),
        (0.02, 0.03, tall - 0.3),
        (0.2, tall - 0.3, tall),
    ] {
        s.push(Shape::Cylinder {
            centre: c,
            radius,
            z0,
            z1,
        });
    }
}

/// A sofa `len` long against the x = 0 wall, centred at `yc`, facing +x:
/// 0.9 m deep, seat at 0.43 m, arms at 0.62 m, back to 0.82 m, on short
/// legs.
fn sofa(s: &mut Vec<Shape>, yc: f64, len: f64) {
    let y0 = yc - len / 2.0;
    s.push(cuboid([0.2, y0 + 0.18, 0.1], [0.7, len - 0.36, 0.33]));
    s.push(cuboid([0.0, y0, 0.1], [0.24, len, 0.72]));
    for y in [y0, y0 + len - 0.18] {
        s.push(cuboid([0.0, y, 0.1], [0.9, 0.18, 0.52]));
    }
    for x in [0.05, 0.81] {
        for y in [y0 + 0.05, y0 + len - 0.09] {
            s.push(cuboid([x, y, 0.0], [0.04, 0.04, 0.1]));
        }
    }
}

/// An armchair centred at `c`, its back to -y (`back_low`) or to +y:
/// 0.8 m square, seat at 0.43 m, arms at 0.6 m, back to 0.85 m.
fn armchair(s: &mut Vec<Shape>, c: [f64; 2], back_low: bool) {
    let [x0, y0] = [c[0] - 0.4, c[1] - 0.4];
    let by = if back_low { y0 } else { y0 + 0.58 };
    let sy = if back_low { y0 + 0.22 } else { y0 };
    s.push(cuboid([x0 + 0.14, sy, 0.1], [0.52, 0.58, 0.33]));
    s.push(cuboid([x0, by, 0.1], [0.8, 0.22, 0.75]));
    for x in [x0, x0 + 0.66] {
        s.push(cuboid([x, y0, 0.1], [0.14, 0.8, 0.5]));
        for y in [y0 + 0.05, y0 + 0.71] {
            s.push(cuboid([x + 0.05, y, 0.0], [0.04, 0.04, 0.1]));
        }
    }
}

/// A low table `size` centred at `c`, its top at `h`, on four legs.
fn low_table(s: &mut Vec<Shape>, c: [f64; 2], size: [f64; 2], h: f64) {
    let [x0, y0] = [c[0] - size[0] / 2.0, c[1] - size[1] / 2.0];
    s.push(cuboid([x0, y0, h - 0.04], [size[0], size[1], 0.04]));
    for (x, y) in [
        (x0 + 0.03, y0 + 0.03),
        (x0 + size[0] - 0.07, y0 + 0.03),
        (x0 + 0.03, y0 + size[1] - 0.07),
        (x0 + size[0] - 0.07, y0 + size[1] - 0.07),
    ] {
        s.push(cuboid([x, y, 0.0], [0.04, 0.04, h - 0.04]));
    }
}

/// A living room: a bookshelf by the door on the corridor wall; from
/// the swing's edge on, an armchair (before the sofa, or past it where
/// there is room), the sofa against the x = 0 wall, the coffee table
/// before it and the television on a low cabinet against the other wall;
/// a floor lamp beside the sofa; by the window a dining table with chairs
/// in a deep room, else a plant.
fn living_room(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    // The bookshelf on the corridor wall at the television's end, the
    // door's way left along the rest.
    let bl = u(r, 0.8, (w - 1.6).min(2.0));
    let bh = u(r, 1.8, 2.1).min(h - 0.4);
    bookcase(s, r, &Frame::at(w - bl - 0.05, 0.0, 0.0), 0.0, bl, bh);
    let y_from = SWING + u(r, 0.15, 0.3);
    let len0 = u(r, 1.8, 2.3);
    // The armchair goes past the sofa in one room of three where that
    // leaves it room, else before it.
    let back_room = d - 0.1 - y_from - len0 >= 1.1;
    let behind = back_room && r.random::<f64>() < 0.35;
    let y0 = if behind { y_from } else { y_from + 1.0 };
    let len = len0.min(d - 0.1 - y0);
    let yc = y0 + len / 2.0;
    sofa(s, yc, len);
    let (ct_w, ct_l) = (u(r, 0.5, 0.65), u(r, 0.9, 1.2).min(len - 0.2));
    let ct_x = 0.9 + u(r, 0.35, 0.5) + ct_w / 2.0;
    low_table(s, [ct_x, yc], [ct_w, ct_l], u(r, 0.38, 0.45));
    let ac_y = if behind { y0 + len + 0.5 } else { y0 - 0.5 };
    armchair(s, [ct_x + u(r, -0.1, 0.2), ac_y], !behind);
    // The television on its low cabinet across the room.
    let (cd, cl, ch) = (u(r, 0.4, 0.45), u(r, 1.2, 1.8).min(len), u(r, 0.4, 0.55));
    s.push(cuboid([w - cd, yc - cl / 2.0, 0.0], [cd, cl, ch]));
    let tv = u(r, 0.9, 1.3).min(cl);
    s.push(cuboid(
        [w - cd / 2.0 - 0.1, yc - 0.15, ch],
        [0.2, 0.3, 0.05],
    ));
    s.push(cuboid(
        [w - cd / 2.0 - 0.03, yc - tv / 2.0, ch + 0.08],
        [0.06, tv, tv * 0.58],
    ));
    if r.random::<f64>() < 0.5 {
        s.push(cuboid(
            [w - cd + 0.05, yc + cl / 2.0 - 0.3, ch],
            [0.3, 0.12, u(r, 0.25, 0.4)],
        ));
    }
    // By the window: a dining table against the back wall with chairs
    // at its ends (and before it where the room is deep), else a plant.
    let top = if behind { y0 + len + 0.9 } else { y0 + len };
    let left = d - top;
    let dining = left >= 1.0 && r.random::<f64>() < 0.75;
    // The floor lamp by the wall at an end of the sofa (past the
    // armchair's side, which stands clear of the wall), clear of the
    // dining chairs.
    if r.random::<f64>() < 0.8 {
        let ly = y0 + len + 0.3;
        if ly + 0.2 <= d - 0.05 && !dining {
            floor_lamp(s, [0.3, ly], u(r, 1.5, 1.8));
        } else if !behind {
            floor_lamp(s, [0.3, y0 - 0.3], u(r, 1.5, 1.8));
        }
    }
    if dining {
        let (tl, tw) = (u(r, 1.1, 1.5), u(r, 0.75, 0.85));
        let tx = (w / 2.0 + u(r, -0.3, 0.3)).clamp(tl / 2.0 + 1.1, w - tl / 2.0 - 1.0);
        let ty = d - 0.05 - tw / 2.0;
        dining_table(s, &Frame::at(tx, ty, 0.0), [tl, tw]);
        let mut x = tx - tl / 2.0 + 0.35;
        while left >= 1.6 && x <= tx + tl / 2.0 - 0.3 {
            if r.random::<f64>() < 0.85 {
                let at = Frame::at(x, ty - tw / 2.0 - u(r, 0.15, 0.3), FRAC_PI_2);
                dining_chair(s, r, &at);
            }
            x += u(r, 0.55, 0.65);
        }
        for side in [-1.0, 1.0] {
            let cx = tx + side * (tl / 2.0 + u(r, 0.15, 0.25));
            if r.random::<f64>() < 0.85 && cx - 0.3 >= 0.05 && cx + 0.3 <= w - 0.05 {
                let yaw = if side < 0.0 { 0.0 } else { PI };
                dining_chair(s, r, &Frame::at(cx, ty, yaw));
            }
        }
    } else if left >= 0.7 && r.random::<f64>() < 0.7 {
        let c = [w * u(r, 0.35, 0.65), d - 0.35];
        s.push(Shape::Cylinder {
            centre: c,
            radius: 0.2,
            z0: 0.0,
            z1: 0.4,
        });
        s.push(Shape::Sphere {
            centre: [c[0], c[1], u(r, 0.8, 1.1)],
            radius: u(r, 0.25, 0.3),
        });
    }
}

/// The top of a kitchen's worktop (m), lowest and highest.
const WORKTOP: (f64, f64) = (0.88, 0.92);

/// A kitchen: the fridge then a run of base cabinets under a worktop
/// along the x = 0 wall from the swing's edge to the back wall, in
/// about half the kitchens a second run along the back wall, wall
/// cabinets above the runs and a hood over the hob; in a wide kitchen a
/// small table with chairs against the other wall or an island.
fn kitchen(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let top = u(r, WORKTOP.0, WORKTOP.1);
    let y0 = SWING + u(r, 0.05, 0.3);
    let fh = u(r, 1.75, 2.0).min(h - 0.3);
    s.push(cuboid([0.0, y0, 0.0], [0.65, 0.6, fh]));
    let run0 = y0 + 0.62;
    // Base cabinets on a plinth, the worktop over them.
    s.push(cuboid([0.0, run0, 0.0], [0.58, d - run0, top - 0.04]));
    s.push(cuboid([0.0, run0, top - 0.04], [0.62, d - run0, 0.04]));
    let wall_from = u(r, 1.4, 1.5);
    let wall_to = u(r, 2.05, 2.15).min(h - 0.3);
    // Wall cabinets in stretches, a gap for the hood.
    let hob = u(r, run0 + 0.5, (d - 0.5).max(run0 + 0.51));
    for (a, b) in [(run0, hob - 0.35), (hob + 0.35, d)] {
        if b - a >= 0.3 {
            s.push(cuboid(
                [0.0, a, wall_from],
                [0.34, b - a, wall_to - wall_from],
            ));
        }
    }
    s.push(cuboid([0.0, hob - 0.3, 1.55], [0.5, 0.6, 0.12]));
    s.push(cuboid([0.0, hob - 0.15, 1.67], [0.25, 0.3, wall_to - 1.67]));
    // A sink's tap on the worktop.
    let tap = (hob + u(r, 0.8, 1.2)).min(d - 0.3);
    if (tap - hob).abs() > 0.5 {
        s.push(Shape::Cylinder {
            centre: [0.1, tap],
            radius: 0.02,
            z0: top,
            z1: top + 0.3,
        });
    }
    // A second run along the back wall.
    let corner = w >= 2.7 && r.random::<f64>() < 0.5;
    let back_end = if corner {
        let end = u(r, 0.6 + 1.0, w - 0.05);
        s.push(cuboid(
            [0.58, d - 0.58, 0.0],
            [end - 0.58, 0.58, top - 0.04],
        ));
        s.push(cuboid(
            [0.62, d - 0.62, top - 0.04],
            [end - 0.62, 0.62, 0.04],
        ));
        if r.random::<f64>() < 0.7 {
            s.push(cuboid(
                [0.34, d - 0.34, wall_from],
                [end - 0.34, 0.34, wall_to - wall_from],
            ));
        }
        d - 0.62
    } else {
        d
    };
    // Where the table or island may go: past the fridge's aisle, before
    // the back run's.
    let free_x = w - 0.65 - 1.0;
    let (ya, yb) = (SWING + 0.3, back_end - 0.9);
    let roll = r.random::<f64>();
    if w >= 3.4 && yb - ya >= 2.0 && roll < 0.35 {
        // An island with a worktop, a metre from the run.
        let (il, iw) = (u(r, 1.2, 1.6).min(yb - ya - 0.9), 0.9);
        let iy = u(r, ya + 0.4, yb - 0.4 - il);
        s.push(cuboid([1.65, iy, 0.0], [iw - 0.04, il, top - 0.04]));
        s.push(cuboid([1.63, iy, top - 0.04], [iw, il, 0.04]));
    } else if free_x >= 1.4 && yb - ya >= 1.6 && roll < 0.8 {
        // A small table against the other wall, two or three chairs.
        let (tl, tw) = (u(r, 0.9, 1.2).min(yb - ya - 0.8), u(r, 0.6, 0.75));
        let ty = u(r, ya + 0.35 + tl / 2.0, yb - 0.35 - tl / 2.0);
        let tx = w - 0.05 - tw / 2.0;
        dining_table(s, &Frame::at(tx, ty, FRAC_PI_2), [tl, tw]);
        let cx = tx - tw / 2.0 - u(r, 0.1, 0.2);
        for k in [-1.0, 1.0] {
            if r.random::<f64>() < 0.85 {
                dining_chair(s, r, &Frame::at(cx, ty + k * tl / 4.0, 0.0));
            }
        }
        if r.random::<f64>() < 0.4 {
            dining_chair(s, r, &Frame::at(tx, ty + tl / 2.0 + 0.2, -FRAC_PI_2));
        }
    }
}

/// A bedroom: the bed's headboard against the back wall between bedside
/// tables with lamps, a wardrobe along the x = 0 wall from the swing's
/// edge, and in about half the rooms a desk with its chair along the other
/// wall.
fn bedroom(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    // The bed: a single, a small double or a double, as the room allows
    // with bedside tables (0.4-0.5 m) either side.
    let widths: Vec<f64> = [0.9, 1.2, 1.4, 1.6, 1.8]
        .into_iter()
        .filter(|bw| bw + 1.0 <= w - 0.2)
        .collect();
    let bw = widths[r.random_range(0..widths.len())];
    let bl = u(r, 1.95, 2.1);
    let sw = u(r, 0.4, 0.5);
    let ext = bw + 2.0 * (sw + 0.04);
    let xc = u(
        r,
        ext / 2.0 + 0.05,
        (w - ext / 2.0 - 0.05).max(ext / 2.0 + 0.06),
    );
    let base = u(r, 0.25, 0.32);
    let top = base + u(r, 0.2, 0.25);
    let x0 = xc - bw / 2.0;
    // The headboard, the bed frame and mattress, pillows and a folded
    // duvet.
    s.push(cuboid(
        [x0 - 0.02, d - 0.07, 0.0],
        [bw + 0.04, 0.07, u(r, 0.9, 1.2)],
    ));
    s.push(cuboid([x0, d - 0.07 - bl, 0.0], [bw, bl, base]));
    s.push(cuboid(
        [x0 + 0.01, d - 0.07 - bl + 0.01, base],
        [bw - 0.02, bl - 0.02, top - base],
    ));
    let pillows = if bw >= 1.2 { 2 } else { 1 };
    let pw = bw / pillows as f64;
    for i in 0..pillows {
        s.push(cuboid(
            [x0 + i as f64 * pw + 0.05, d - 0.5, top],
            [pw - 0.1, 0.38, 0.14],
        ));
    }
    s.push(cuboid(
        [x0, d - 0.07 - bl * 0.45, top],
        [bw, u(r, 0.4, 0.7), 0.08],
    ));
    let sh = u(r, 0.5, 0.6);
    for x in [x0 - 0.04 - sw, x0 + bw + 0.04] {
        if x >= 0.0 && x + sw <= w {
            s.push(cuboid([x, d - 0.45, 0.0], [sw, 0.4, sh]));
            if r.random::<f64>() < 0.8 {
                table_lamp(s, [x + sw / 2.0, d - 0.25], sh, 0.4);
            }
        }
    }
    // The wardrobe along the x = 0 wall from the swing's edge, beside
    // the bed where it leaves room, else short of its foot; where that
    // leaves less than 0.8 m, on the corridor wall beside the door.
    let foot = d - 0.07 - bl;
    let group_left = x0 - 0.04 - sw;
    let end = if group_left >= 0.7 {
        d - 0.05
    } else {
        foot - 0.6
    };
    let wy = SWING + u(r, 0.05, 0.25);
    let wl = u(r, 1.0, 2.2).min(end - wy);
    let wtop = u(r, 2.0, 2.2).min(h - 0.3);
    if wl >= 0.8 {
        s.push(cuboid([0.0, wy, 0.0], [0.6, wl, wtop]));
    } else {
        let wl = u(r, 0.9, (w - 1.3).min(1.8));
        s.push(cuboid([0.0, 0.0, 0.0], [wl, 0.6, wtop]));
    }
    // A desk along the other wall, its chair pulled out, where the
    // wardrobe leaves a walk between them.
    let (dl, dd) = (u(r, 1.0, 1.4), u(r, 0.5, 0.6));
    if w - 0.6 - dd >= 1.6 && foot - 0.9 - (SWING + 0.2) >= dl && r.random::<f64>() < 0.5 {
        let y = SWING + 0.2 + dl / 2.0;
        let f = Frame::at(w - dd / 2.0, y, FRAC_PI_2);
        table(s, &f, [0.0, 0.0], [dl, dd], 0.74);
        chair(
            s,
            w - dd - u(r, 0.25, 0.4),
            y + u(r, -0.2, 0.2),
            PI + u(r, -0.5, 0.5),
        );
    }
}

/// A bathroom: a bathtub across the back wall or a shower enclosure in a
/// back corner, the toilet and the vanity with its basin and mirror
/// cabinet along the x = 0 wall, a towel radiator on the other wall, in
/// some a washing machine.
fn bathroom(w: f64, d: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    // The bath or shower; `back`: where the fixtures along the side wall
    // must end.
    let back = if w >= 1.75 && r.random::<f64>() < 0.6 {
        let (tl, td) = (u(r, 1.6, 1.7).min(w - 0.05), u(r, 0.7, 0.8));
        s.push(cuboid([0.0, d - td, 0.0], [tl, td, u(r, 0.55, 0.6)]));
        d - td
    } else {
        let (sx, sy) = (u(r, 0.8, 1.0), u(r, 0.8, 1.0));
        s.push(cuboid([0.0, d - sy, 0.0], [sx, sy, 0.06]));
        // The enclosure's frame: a side screen and a front with its door.
        s.push(cuboid([sx - 0.02, d - sy, 0.06], [0.02, sy, 1.9]));
        s.push(cuboid([0.0, d - sy, 0.06], [sx * 0.4, 0.02, 1.9]));
        s.push(cuboid([0.0, d - sy, 1.94], [sx, 0.02, 0.03]));
        d - sy
    };
    // The toilet by the bath, its cistern against the wall.
    let ty = back - u(r, 0.3, 0.6) - 0.19;
    s.push(cuboid([0.0, ty - 0.19, 0.0], [0.62, 0.38, 0.41]));
    s.push(cuboid(
        [0.0, ty - 0.22, 0.41],
        [0.18, 0.44, u(r, 0.38, 0.45)],
    ));
    // The vanity nearer the door, a basin on it, a mirror cabinet above.
    let vl = u(r, 0.6, 0.9);
    let vy = (ty - 0.19 - 0.3 - vl).max(SWING + 0.1);
    if vy + vl <= ty - 0.22 - 0.1 {
        s.push(cuboid([0.0, vy, 0.0], [0.48, vl, 0.82]));
        s.push(cuboid([0.05, vy + vl / 2.0 - 0.25, 0.82], [0.4, 0.5, 0.06]));
        s.push(Shape::Cylinder {
            centre: [0.07, vy + vl / 2.0],
            radius: 0.02,
            z0: 0.88,
            z1: 1.08,
        });
        s.push(cuboid([0.0, vy, 1.3], [0.14, vl, 0.65]));
    }
    // The towel radiator on the other wall.
    let (rl, rh) = (u(r, 0.45, 0.6), u(r, 1.1, 1.6));
    let ry = u(r, SWING + 0.2, (back - rl - 0.1).max(SWING + 0.21));
    s.push(cuboid([w - 0.08, ry, 0.2], [0.08, rl, rh]));
    if w >= 2.2 && r.random::<f64>() < 0.4 {
        let my = ry + rl + 0.1;
        if my + 0.6 <= back - 0.05 {
            s.push(cuboid([w - 0.6, my, 0.0], [0.6, 0.6, 0.85]));
        }
    }
}

/// A utility closet (a gap left in a row, never scanned): shelving along
/// a side wall, a boiler or a water heater on the back wall.
fn closet(w: f64, d: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let depth = (w - 0.1).min(0.5);
    for level in 0..4 {
        let z = 0.2 + level as f64 * 0.5;
        s.push(cuboid([0.0, SWING, z], [depth, d - SWING - 0.05, 0.02]));
        if r.random::<f64>() < 0.7 {
            let run = u(r, 0.3, d - SWING - 0.1);
            s.push(cuboid(
                [0.0, SWING, z + 0.02],
                [depth, run, u(r, 0.2, 0.45)],
            ));
        }
    }
    if w >= 1.2 {
        s.push(Shape::Cylinder {
            centre: [w - 0.3, d - 0.3],
            radius: 0.25,
            z0: 0.3,
            z1: (h - 0.4).min(1.8),
        });
    }
}

/// The building's shared corridor, `length` by `width`, `h` high:
/// ceiling lights down its middle; along the walls radiators, fire
/// extinguisher cabinets, shoe racks and parcels left by doors, and now
/// and then a pram. Nothing stands more than 0.35 m out from a wall.
fn corridor_fittings(length: f64, width: f64, h: f64, r: &mut ChaCha8Rng, s: &mut Vec<Shape>) {
    let mut x = u(r, 1.0, 3.0);
    while x < length - 0.5 {
        let ld = u(r, 0.3, 0.45);
        s.push(Shape::Cylinder {
            centre: [x, width / 2.0],
            radius: ld / 2.0,
            z0: h - 0.08,
            z1: h,
        });
        x += u(r, 3.0, 5.0);
    }
    // Against a wall: `south` (y = 0) or the other, `depth` out.
    let at = |south: bool, depth: f64| if south { 0.0 } else { width - depth };
    let mut x = u(r, 0.3, 2.0);
    while x < length - 1.5 {
        let south = r.random::<bool>();
        let roll = r.random::<f64>();
        let used = if roll < 0.25 {
            // A radiator under the sills' height.
            let len = u(r, 0.8, 1.4);
            s.push(cuboid(
                [x, at(south, 0.1), 0.15],
                [len, 0.1, u(r, 0.5, 0.6)],
            ));
            len
        } else if roll < 0.4 {
            // A fire extinguisher cabinet on the wall.
            let (len, z0) = (u(r, 0.5, 0.7), u(r, 0.6, 0.9));
            s.push(cuboid(
                [x, at(south, 0.18), z0],
                [len, 0.18, u(r, 0.8, 1.0)],
            ));
            len
        } else if roll < 0.6 {
            // A shoe rack, shoes on it and before it.
            let (len, rh) = (u(r, 0.6, 1.0), u(r, 0.4, 0.9));
            s.push(cuboid([x, at(south, 0.3), 0.0], [len, 0.3, rh]));
            let mut sx = x + 0.05;
            while sx + 0.2 < x + len {
                if r.random::<f64>() < 0.6 {
                    s.push(cuboid([sx, at(south, 0.3), rh], [0.2, 0.3, 0.12]));
                }
                sx += 0.25;
            }
            len
        } else if roll < 0.75 {
            // Parcels stacked by a door.
            let mut z = 0.0;
            let mut widest: f64 = 0.0;
            for _ in 0..r.random_range(1..=3) {
                let (bl, bd, bh) = (u(r, 0.25, 0.6), u(r, 0.2, 0.35), u(r, 0.1, 0.35));
                s.push(cuboid([x, at(south, bd), z], [bl, bd, bh]));
                z += bh;
                widest = widest.max(bl);
            }
            widest
        } else if roll < 0.8 {
            // A folded pram or a scooter parked by a wall.
            let len = u(r, 0.7, 0.9);
            s.push(cuboid([x, at(south, 0.3), 0.0], [len, 0.3, u(r, 0.8, 1.0)]));
            len
        } else {
            0.0
        };
        x += used + u(r, 1.5, 4.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::hotel::extent;
    use crate::sim::office_floor::{
        assert_doors_swing_clear, boxes, furnished_room, has_free_spot,
    };

    /// A room of `kind` of a size drawn from the plan's ranges.
    fn room(kind: &str, r: &mut ChaCha8Rng) -> ([f64; 3], Vec<Shape>) {
        furnished_room(&HOME, kind, r)
    }

    fn size(b: &([f64; 3], [f64; 3])) -> [f64; 3] {
        [b.1[0] - b.0[0], b.1[1] - b.0[1], b.1[2] - b.0[2]]
    }

    #[test]
    fn furniture_stands_inside_its_room_on_the_floor_and_under_the_ceiling() {
        let mut r = crate::rng::rng(11);
        for kind in HOME_KINDS.iter().skip(1).copied().chain(["storage"]) {
            for _ in 0..300 {
                let ([w, d, h], s) = room(kind, &mut r);
                assert!(!s.is_empty(), "{kind}: empty");
                for shape in &s {
                    let (lo, hi, z0, z1) = extent(shape);
                    let inside =
                        lo[0] >= -1e-9 && lo[1] >= -1e-9 && hi[0] <= w + 1e-9 && hi[1] <= d + 1e-9;
                    assert!(inside, "{kind} {w:.2} x {d:.2}: {shape:?} outside");
                    // Under the ceiling, below where the floor tests look
                    // for the walls (0.15 m under it).
                    assert!(
                        z0 >= -1e-9 && z1 <= h - 0.25 && z1 <= 2.3,
                        "{kind}: {shape:?} at {z0}..{z1} m under {h}"
                    );
                }
            }
        }
    }

    #[test]
    fn doors_keep_their_swing_clear_and_some_are_shut() {
        let mut r = crate::rng::rng(3);
        assert_doors_swing_clear(&HOME, &HOME_KINDS[1..], SWING, &mut r);
        for (kind, lo, hi) in [
            ("bathroom", 430, 570),
            ("bedroom", 330, 470),
            ("kitchen", 190, 310),
            ("living_room", 190, 310),
        ] {
            let shut = (0..1000)
                .filter(|_| door(kind, 3.0, 0.9, false, &[], &mut r).is_none())
                .count();
            assert!((lo..=hi).contains(&shut), "{kind}: {shut}");
        }
    }

    #[test]
    fn every_room_leaves_a_free_spot_for_a_scan() {
        let mut r = crate::rng::rng(4);
        for kind in &HOME_KINDS[1..] {
            for _ in 0..300 {
                let ([w, d, _], s) = room(kind, &mut r);
                assert!(has_free_spot(w, d, &s), "{kind} {w:.2} x {d:.2}");
            }
        }
    }

    #[test]
    fn a_bathroom_has_a_toilet_a_bath_or_shower_a_basin_and_a_towel_radiator() {
        let mut r = crate::rng::rng(5);
        let (mut baths, mut showers) = (0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("bathroom", &mut r);
            let b = boxes(&s);
            let toilet = b.iter().any(|b| {
                let [x, y, z] = size(b);
                b.0[2] == 0.0
                    && (0.55..=0.7).contains(&x)
                    && (0.34..=0.42).contains(&y)
                    && (0.38..=0.45).contains(&z)
            });
            assert!(toilet, "{w:.2} x {d:.2}: no toilet");
            let bath = b.iter().any(|b| {
                let [x, y, z] = size(b);
                b.0[2] == 0.0 && x >= 1.55 && (0.7..=0.8).contains(&y) && (0.55..=0.6).contains(&z)
            });
            let shower = b.iter().any(|b| {
                let [x, y, z] = size(b);
                b.0[2] == 0.0 && (0.8..=1.0).contains(&x) && (0.8..=1.0).contains(&y) && z == 0.06
            }) && b.iter().any(|b| size(b)[2] == 1.9);
            assert!(bath || shower, "{w:.2}: no bath or shower");
            baths += bath as usize;
            showers += shower as usize;
            let basin = b
                .iter()
                .any(|b| (0.8..=0.9).contains(&b.0[2]) && size(b)[0] >= 0.39);
            assert!(basin, "no basin");
            let radiator = b.iter().any(|b| {
                let [x, _, z] = size(b);
                x <= 0.08 + 1e-9 && z >= 1.1 && b.0[2] == 0.2
            });
            assert!(radiator, "no towel radiator");
        }
        assert!(
            baths >= 60 && showers >= 60,
            "{baths} baths, {showers} showers"
        );
    }

    #[test]
    fn a_kitchen_has_a_worktop_run_wall_cabinets_and_a_fridge() {
        let mut r = crate::rng::rng(6);
        let (mut tables, mut islands, mut corners) = (0, 0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("kitchen", &mut r);
            let b = boxes(&s);
            // Worktops: 0.04 m thick, their tops at 0.85-0.95 m, 2 m long
            // at least in all.
            let tops: Vec<_> = b
                .iter()
                .filter(|b| (0.85..=0.95).contains(&b.1[2]) && (size(b)[2] - 0.04).abs() < 1e-9)
                .collect();
            let run: f64 = tops.iter().map(|b| size(b)[0].max(size(b)[1])).sum();
            assert!(run >= 2.0, "{w:.2} x {d:.2}: {run} m of worktop");
            let wall = b
                .iter()
                .any(|b| (1.4..=1.5).contains(&b.0[2]) && (2.0..=2.2).contains(&b.1[2]));
            assert!(wall, "no wall cabinets");
            let fridge = b.iter().any(|b| {
                let [x, y, z] = size(b);
                b.0[2] == 0.0 && z >= 1.75 && x <= 0.7 && y <= 0.7
            });
            assert!(fridge, "no fridge");
            corners += (tops.len() >= 2) as usize;
            islands += (tops.len() >= 3) as usize;
            tables += s
                .iter()
                .any(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] + half[2] - 0.75).abs() < 1e-9 && half[0] >= 0.25))
                as usize;
        }
        assert!(
            corners >= 30 && tables >= 30 && islands >= 1,
            "{corners} {tables} {islands}"
        );
    }

    #[test]
    fn a_bedroom_has_a_bed_with_a_headboard_bedside_tables_and_a_wardrobe() {
        let mut r = crate::rng::rng(7);
        let (mut wardrobes, mut desks, mut doubles) = (0, 0, 0);
        for _ in 0..300 {
            let ([w, d, _], s) = room("bedroom", &mut r);
            let b = boxes(&s);
            // The mattress: 0.9-1.8 m by about 2 m, its top 0.45-0.57 m.
            let bed = b.iter().find(|b| {
                let [x, y, _] = size(b);
                (0.87..=1.8).contains(&x)
                    && (1.9..=2.1).contains(&y)
                    && (0.45..=0.57).contains(&b.1[2])
                    && b.0[2] > 0.2
            });
            let bed = bed.unwrap_or_else(|| panic!("{w:.2} x {d:.2}: no bed"));
            doubles += (size(bed)[0] >= 1.38) as usize;
            let headboard = b
                .iter()
                .any(|b| (b.1[1] - d).abs() < 1e-9 && size(b)[1] < 0.1 && b.1[2] >= 0.9);
            assert!(headboard, "no headboard");
            let stands = b
                .iter()
                .filter(|b| {
                    b.0[2] == 0.0
                        && (0.5..=0.6).contains(&b.1[2])
                        && (size(b)[1] - 0.4).abs() < 1e-9
                })
                .count();
            assert!(stands >= 1, "no bedside table");
            wardrobes += b.iter().any(|b| {
                let [x, y, _] = size(b);
                (2.0..=2.2).contains(&b.1[2]) && ((x - 0.6).abs() < 1e-9 || (y - 0.6).abs() < 1e-9)
            }) as usize;
            desks += s
                .iter()
                .any(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] + half[2] - 0.74).abs() < 1e-9))
                as usize;
        }
        // Every bedroom has a wardrobe.
        assert_eq!(wardrobes, 300, "{wardrobes} wardrobes in 300 bedrooms");
        assert!(
            desks >= 30 && doubles >= 100,
            "{desks} desks, {doubles} doubles"
        );
    }

    #[test]
    fn a_living_room_has_a_sofa_facing_a_television_a_coffee_table_and_an_armchair() {
        let mut r = crate::rng::rng(8);
        let mut dining = 0;
        for _ in 0..300 {
            let ([w, d, _], s) = room("living_room", &mut r);
            let b = boxes(&s);
            // The sofa's back: 1.8-2.3 m long (or as the room allows),
            // to 0.82 m, against a side wall.
            let sofa = b.iter().any(|b| {
                (b.1[2] - 0.82).abs() < 1e-9
                    && size(b)[1] >= 1.2
                    && (b.0[0] < 1e-9 || b.1[0] > w - 1e-9)
            });
            assert!(sofa, "{w:.2} x {d:.2}: no sofa");
            let armchair = b
                .iter()
                .any(|b| (b.1[2] - 0.85).abs() < 1e-9 && (size(b)[0] - 0.8).abs() < 1e-9);
            assert!(armchair, "no armchair");
            let tv = b
                .iter()
                .any(|b| (size(b)[0] - 0.06).abs() < 1e-9 && b.0[2] >= 0.45 && size(b)[1] >= 0.9);
            assert!(tv, "no television");
            let coffee = b
                .iter()
                .any(|b| (0.34..=0.41).contains(&b.0[2]) && (size(b)[2] - 0.04).abs() < 1e-9);
            assert!(coffee, "no coffee table");
            dining += s
                .iter()
                .any(|s| matches!(s, Shape::OrientedBox { centre, half, .. } if (centre[2] + half[2] - 0.75).abs() < 1e-9 && half[0] >= 0.5))
                as usize;
        }
        assert!(dining >= 30, "{dining} dining tables in 300 living rooms");
    }

    #[test]
    fn the_corridor_has_lights_and_fittings_along_its_walls() {
        for seed in 1..=8 {
            let mut r = crate::rng::rng(seed);
            let (length, cw, h) = (20.0, 1.6, 2.5);
            let mut s = Vec::new();
            corridor_fittings(length, cw, h, &mut r, &mut s);
            let lights = s
                .iter()
                .filter(|s| matches!(s, Shape::Cylinder { z1, .. } if *z1 == h))
                .count();
            assert!(lights >= 3, "seed {seed}: {lights} lights");
            assert!(
                s.len() >= lights + 2,
                "seed {seed}: {} fittings",
                s.len() - lights
            );
            for shape in &s {
                let (lo, hi, z0, z1) = extent(shape);
                assert!(lo[0] >= 0.0 && hi[0] <= length, "{shape:?}");
                assert!(z0 >= 0.0 && z1 <= h + 1e-9, "{shape:?}");
                if z1 < h {
                    // Along a wall, the middle left free.
                    assert!(
                        hi[1] <= 0.35 + 1e-9 || lo[1] >= cw - 0.35 - 1e-9,
                        "seed {seed}: {shape:?} in the way"
                    );
                }
            }
        }
    }
}
