//! Scene primitives and ray intersection for the simulator.

/// A solid primitive the lidar can hit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Axis-aligned box, min and max corners.
    Cuboid {
        /// Lowest x, y, z (m).
        min: [f64; 3],
        /// Highest x, y, z (m).
        max: [f64; 3],
    },
    /// Box turned by `yaw` about the vertical through `centre` (chairs and
    /// furniture are rarely square to the walls). `half`: half sizes.
    OrientedBox {
        /// Centre (m).
        centre: [f64; 3],
        /// Half sizes along the box's own axes (m).
        half: [f64; 3],
        /// Turn about the vertical (radians, counter-clockwise).
        yaw: f64,
    },
    /// Vertical cylinder (tree trunks, pillars).
    Cylinder {
        /// Axis position x, y (m).
        centre: [f64; 2],
        /// Radius (m).
        radius: f64,
        /// Bottom height (m).
        z0: f64,
        /// Top height (m).
        z1: f64,
    },
    /// Sphere (tree crowns, bushes).
    Sphere {
        /// Centre (m).
        centre: [f64; 3],
        /// Radius (m).
        radius: f64,
    },
}

/// A ray: origin and unit direction.
#[derive(Debug, Clone, Copy)]
pub struct Ray {
    /// Origin (m).
    pub o: [f64; 3],
    /// Unit direction.
    pub d: [f64; 3],
}

impl Ray {
    /// From `o` towards `d` (any length but zero).
    pub fn towards(o: [f64; 3], d: [f64; 3]) -> Ray {
        let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        Ray {
            o,
            d: [d[0] / n, d[1] / n, d[2] / n],
        }
    }
}

impl Shape {
    /// Distance along the ray to the first hit beyond `t_min`, if any.
    pub fn hit(&self, ray: &Ray, t_min: f64) -> Option<f64> {
        let (o, d) = (ray.o, ray.d);
        match *self {
            Shape::Cuboid { min, max } => slab_hit(o, d, min, max, t_min),
            Shape::OrientedBox { centre, half, yaw } => {
                // The ray in the box's frame; rotation keeps t unchanged.
                let (s, c) = yaw.sin_cos();
                let (px, py) = (o[0] - centre[0], o[1] - centre[1]);
                let lo = [c * px + s * py, -s * px + c * py, o[2] - centre[2]];
                let ld = [c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]];
                let max = half;
                let min = [-half[0], -half[1], -half[2]];
                slab_hit(lo, ld, min, max, t_min)
            }
            Shape::Cylinder {
                centre,
                radius,
                z0,
                z1,
            } => {
                let (px, py) = (o[0] - centre[0], o[1] - centre[1]);
                let a = d[0] * d[0] + d[1] * d[1];
                if a < 1e-12 {
                    return None;
                }
                let b = px * d[0] + py * d[1];
                let c = px * px + py * py - radius * radius;
                let disc = b * b - a * c;
                if disc < 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                [(-b - s) / a, (-b + s) / a].into_iter().find(|&t| {
                    let z = o[2] + t * d[2];
                    t > t_min && z >= z0 && z <= z1
                })
            }
            Shape::Sphere { centre, radius } => {
                let p = [o[0] - centre[0], o[1] - centre[1], o[2] - centre[2]];
                let b = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
                let c = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - radius * radius;
                let disc = b * b - c;
                if disc < 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                [-b - s, -b + s].into_iter().find(|&t| t > t_min)
            }
        }
    }

    /// Horizontal distance from (x, y) to the shape's footprint (0 inside);
    /// infinite shapes are always near.
    pub fn horizontal_distance(&self, x: f64, y: f64) -> f64 {
        match *self {
            Shape::Cuboid { min, max } => {
                let dx = (min[0] - x).max(0.0).max(x - max[0]);
                let dy = (min[1] - y).max(0.0).max(y - max[1]);
                (dx * dx + dy * dy).sqrt()
            }
            Shape::OrientedBox { centre, half, yaw } => {
                let (s, c) = yaw.sin_cos();
                let (px, py) = (x - centre[0], y - centre[1]);
                let (lx, ly) = (c * px + s * py, -s * px + c * py);
                let dx = (lx.abs() - half[0]).max(0.0);
                let dy = (ly.abs() - half[1]).max(0.0);
                (dx * dx + dy * dy).sqrt()
            }
            Shape::Cylinder { centre, radius, .. } => {
                (((x - centre[0]).powi(2) + (y - centre[1]).powi(2)).sqrt() - radius).max(0.0)
            }
            Shape::Sphere { centre, radius } => {
                (((x - centre[0]).powi(2) + (y - centre[1]).powi(2)).sqrt() - radius).max(0.0)
            }
        }
    }
}

impl Shape {
    /// Corners of the footprint of a box-like shape, for angular spans.
    pub fn footprint_corners(&self) -> Option<[[f64; 2]; 4]> {
        match *self {
            Shape::Cuboid { min, max } => Some([
                [min[0], min[1]],
                [min[0], max[1]],
                [max[0], min[1]],
                [max[0], max[1]],
            ]),
            Shape::OrientedBox { centre, half, yaw } => {
                let (s, c) = yaw.sin_cos();
                let corner = |a: f64, b: f64| {
                    let (lx, ly) = (a * half[0], b * half[1]);
                    [centre[0] + c * lx - s * ly, centre[1] + s * lx + c * ly]
                };
                Some([
                    corner(-1.0, -1.0),
                    corner(-1.0, 1.0),
                    corner(1.0, -1.0),
                    corner(1.0, 1.0),
                ])
            }
            _ => None,
        }
    }
}

/// Ray against an axis-aligned box (slab method): the first hit beyond
/// `t_min`. From inside the box the ray hits its far side (rooms are made
/// of slabs, so this only matters for odd placements).
fn slab_hit(o: [f64; 3], d: [f64; 3], min: [f64; 3], max: [f64; 3], t_min: f64) -> Option<f64> {
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..3 {
        if d[k].abs() < 1e-12 {
            if o[k] < min[k] || o[k] > max[k] {
                return None;
            }
            continue;
        }
        let inv = 1.0 / d[k];
        let (a, b) = ((min[k] - o[k]) * inv, (max[k] - o[k]) * inv);
        t0 = t0.max(a.min(b));
        t1 = t1.min(a.max(b));
    }
    if t0 > t1 {
        return None;
    }
    [t0, t1].into_iter().find(|&t| t > t_min)
}

/// Axis-aligned box from its minimum corner and size.
pub fn cuboid(origin: [f64; 3], size: [f64; 3]) -> Shape {
    Shape::Cuboid {
        min: origin,
        max: [
            origin[0] + size[0],
            origin[1] + size[1],
            origin[2] + size[2],
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: [f64; 3], d: [f64; 3]) -> Ray {
        Ray::towards(o, d)
    }

    #[test]
    fn an_unturned_oriented_box_is_the_cuboid() {
        let b = Shape::OrientedBox {
            centre: [3.0, 1.0, 0.5],
            half: [0.5, 1.0, 0.5],
            yaw: 0.0,
        };
        let c = cuboid([2.5, 0.0, 0.0], [1.0, 2.0, 1.0]);
        for d in [
            [1.0, 0.0, 0.0],
            [1.0, 0.3, 0.1],
            [0.9, -0.2, 0.05],
            [0.0, 1.0, 0.0],
        ] {
            let r = ray([0.0, 0.5, 0.5], d);
            assert_eq!(b.hit(&r, 0.0).is_some(), c.hit(&r, 0.0).is_some(), "{d:?}");
            if let (Some(a), Some(e)) = (b.hit(&r, 0.0), c.hit(&r, 0.0)) {
                assert!((a - e).abs() < 1e-9, "{d:?}: {a} vs {e}");
            }
        }
        assert!((b.horizontal_distance(0.0, 0.5) - 2.5).abs() < 1e-12);
    }

    #[test]
    fn a_box_turned_45_degrees_shows_its_corner() {
        // A 1 m square turned by 45 degrees at x = 5: its near corner is at
        // x = 5 - sqrt(0.5), where an unturned square's face would be 4.5.
        let b = Shape::OrientedBox {
            centre: [5.0, 0.0, 0.0],
            half: [0.5, 0.5, 1.0],
            yaw: std::f64::consts::FRAC_PI_4,
        };
        let t = b.hit(&ray([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), 0.0).unwrap();
        assert!((t - (5.0 - 0.5f64.sqrt())).abs() < 1e-9, "{t}");
        // Turned, the square reaches 0.707 m to each side (unturned: 0.5).
        assert!(b.hit(&ray([0.0, 0.6, 0.0], [1.0, 0.0, 0.0]), 0.0).is_some());
        assert!(b
            .hit(&ray([0.0, 0.75, 0.0], [1.0, 0.0, 0.0]), 0.0)
            .is_none());
        // Footprint distance from a point on the diagonal.
        let d = b.horizontal_distance(3.0, 0.0);
        assert!((d - (2.0 - 0.5f64.sqrt())).abs() < 1e-9, "{d}");
        let corners = b.footprint_corners().unwrap();
        let xmin = corners.iter().map(|c| c[0]).fold(f64::INFINITY, f64::min);
        assert!((xmin - (5.0 - 0.5f64.sqrt())).abs() < 1e-9);
    }
}
