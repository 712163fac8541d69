//! Other room plans for the indoor kinds (`--buildings varied`): rooms of a
//! kind drawn over its whole size range, with the furniture layout
//! mirrored (so it stands at other places relative to the walls) and, in
//! about half of the rooms that are not corridors, an L-shaped floor: one
//! corner of the rectangle walled off. Written for issue 18, so that an
//! evaluation does not see only the plans the descriptors were built on.

use super::geometry::{cuboid, Shape};
use super::scenes::{indoor_room, room_size, u, Room};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

/// `s` mirrored in x (`flip[0]`) and/or y (`flip[1]`) about 0, then moved
/// by `shift`.
pub fn place(s: &Shape, flip: [bool; 2], shift: [f64; 2]) -> Shape {
    let sign = flip.map(|f| if f { -1.0 } else { 1.0 });
    let at = |v: f64, k: usize| sign[k] * v + shift[k];
    match *s {
        Shape::Cuboid { min, max } => {
            let (a, b) = (
                [at(min[0], 0), at(min[1], 1)],
                [at(max[0], 0), at(max[1], 1)],
            );
            Shape::Cuboid {
                min: [a[0].min(b[0]), a[1].min(b[1]), min[2]],
                max: [a[0].max(b[0]), a[1].max(b[1]), max[2]],
            }
        }
        Shape::OrientedBox { centre, half, yaw } => {
            // A mirror in x turns the heading to pi - yaw, in y to -yaw.
            let mut y = yaw;
            if flip[0] {
                y = PI - y;
            }
            if flip[1] {
                y = -y;
            }
            Shape::OrientedBox {
                centre: [at(centre[0], 0), at(centre[1], 1), centre[2]],
                half,
                yaw: y,
            }
        }
        Shape::Cylinder {
            centre,
            radius,
            z0,
            z1,
        } => Shape::Cylinder {
            centre: [at(centre[0], 0), at(centre[1], 1)],
            radius,
            z0,
            z1,
        },
        Shape::Sphere { centre, radius } => Shape::Sphere {
            centre: [at(centre[0], 0), at(centre[1], 1), centre[2]],
            radius,
        },
    }
}

/// The centre of a shape's footprint.
fn footprint_centre(s: &Shape) -> [f64; 2] {
    match *s {
        Shape::Cuboid { min, max } => [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0],
        Shape::OrientedBox { centre, .. } | Shape::Sphere { centre, .. } => [centre[0], centre[1]],
        Shape::Cylinder { centre, .. } => centre,
    }
}

/// A room of `kind` with another plan: any size of the kind's range, the
/// layout mirrored at random and, with probability one half (never for
/// corridors), the corner at (l, w) walled off to leave an L-shaped floor
/// (the cut takes 30 to 50 % of each side). The block that walls it off
/// counts as furniture, so scans keep clear of it.
pub fn varied_room(kind: &str, r: &mut ChaCha8Rng) -> Room {
    let size = room_size(kind, r);
    let [l, w, h] = size;
    let room = indoor_room(kind, size, r);
    let flip = [r.random::<bool>(), r.random::<bool>()];
    let shift = [if flip[0] { l } else { 0.0 }, if flip[1] { w } else { 0.0 }];
    let mut furniture: Vec<Shape> = room.shapes[..room.furniture]
        .iter()
        .map(|s| place(s, flip, shift))
        .collect();
    let rest = room.shapes[room.furniture..]
        .iter()
        .map(|s| place(s, flip, shift));
    if kind != "corridor" && r.random::<bool>() {
        let (cx, cy) = (l * u(r, 0.5, 0.7), w * u(r, 0.5, 0.7));
        furniture.retain(|s| {
            let [x, y] = footprint_centre(s);
            x < cx || y < cy
        });
        furniture.insert(0, cuboid([cx, cy, 0.0], [l - cx, w - cy, h]));
    }
    let n = furniture.len();
    furniture.extend(rest);
    Room {
        shapes: furniture,
        size: [l, w],
        furniture: n,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::geometry::Ray;

    #[test]
    fn a_mirrored_box_is_hit_where_its_mirror_image_stands() {
        let b = Shape::OrientedBox {
            centre: [2.0, 1.0, 0.5],
            half: [0.5, 0.2, 0.5],
            yaw: 0.3,
        };
        let m = place(&b, [true, false], [0.0, 0.0]);
        for d in [[1.0, 0.4, 0.0], [1.0, 0.6, 0.0], [1.0, 0.2, 0.0]] {
            let t = b.hit(&Ray::towards([0.0, 0.0, 0.5], d), 0.0);
            let tm = m.hit(&Ray::towards([0.0, 0.0, 0.5], [-d[0], d[1], d[2]]), 0.0);
            assert_eq!(t.is_some(), tm.is_some(), "{d:?}");
            if let (Some(a), Some(b)) = (t, tm) {
                assert!((a - b).abs() < 1e-9, "{a} vs {b}");
            }
        }
    }
}
