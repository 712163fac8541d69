//! A spinning multi-beam lidar, ray-cast into a scene.

use super::geometry::{Ray, Shape};
use super::terrain::{SensorPose, Terrain};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use serde::{Deserialize, Serialize};

/// The sensor model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LidarParams {
    /// Number of beams (rows).
    pub beams: usize,
    /// Lowest beam angle (degrees; negative below the horizon).
    pub fov_down: f64,
    /// Highest beam angle (degrees; positive above the horizon).
    pub fov_up: f64,
    /// Firings per revolution (columns).
    pub azimuth_steps: usize,
    /// Returns closer than this are lost (m): the sensor's blind zone.
    pub min_range: f64,
    /// Returns farther than this are lost (m).
    pub max_range: f64,
    /// Standard deviation of Gaussian range noise (m).
    pub range_noise: f64,
    /// Probability that a return is lost.
    pub dropout: f64,
}

impl LidarParams {
    /// A 128-beam wide-angle indoor sensor like an Ouster OS0-128 (90
    /// degrees vertical, ~131k rays): as dense as the real room scans in
    /// tests/data/real (~112k points).
    pub fn indoor() -> Self {
        LidarParams {
            beams: 128,
            fov_down: -45.0,
            fov_up: 45.0,
            azimuth_steps: 1024,
            min_range: 0.3,
            max_range: 40.0,
            range_noise: 0.01,
            dropout: 0.02,
        }
    }
    /// A 64-beam outdoor sensor like KITTI's (~115k rays).
    pub fn outdoor() -> Self {
        LidarParams {
            beams: 64,
            fov_down: -24.8,
            fov_up: 2.0,
            azimuth_steps: 1800,
            min_range: 0.9,
            max_range: 80.0,
            range_noise: 0.02,
            dropout: 0.03,
        }
    }
    pub(crate) fn validate(&self) -> crate::Result<()> {
        let ok = self.beams > 0
            && self.azimuth_steps > 0
            && self.beams * self.azimuth_steps <= 20_000_000
            && self.fov_down.is_finite()
            && self.fov_up >= self.fov_down
            && self.max_range > self.min_range
            && self.min_range >= 0.0
            && self.range_noise >= 0.0
            && (0.0..1.0).contains(&self.dropout);
        if ok {
            Ok(())
        } else {
            Err(crate::Error::InvalidParameter(format!(
                "lidar parameters out of range: {self:?}"
            )))
        }
    }
}

/// Cast every ray from the sensor at `pose` into the shapes and the ground
/// (if any) and return the hits in the sensor frame: a tilted sensor sees
/// the world tilted, as one on a vehicle does.
pub fn scan(
    shapes: &[Shape],
    ground: Option<&Terrain>,
    pose: &SensorPose,
    lidar: &LidarParams,
    rng: &mut ChaCha8Rng,
) -> Vec<[f32; 3]> {
    let (position, yaw) = (pose.position, pose.yaw);
    // A level sensor keeps the plain turn about z (and so the indoor scans
    // made before tilt existed, bit for bit).
    let tilt = (pose.pitch != 0.0 || pose.roll != 0.0).then(|| pose.rotation());
    // Only shapes that can be within range matter, and each ray tests only
    // the shapes whose azimuth span covers its sector: forests have
    // hundreds of trees in range (measured: 435 ms -> see benches). Nearest
    // first, so that a ray stops at the first shape that lies beyond its
    // nearest hit so far (a forest hides what stands behind its first
    // trees; outdoor scans took 112 -> ?? ms of CPU).
    let mut near: Vec<(f64, &Shape)> = shapes
        .iter()
        .map(|s| (s.horizontal_distance(position[0], position[1]), s))
        .filter(|(d, _)| *d < lidar.max_range)
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let shapes_near: Vec<&Shape> = near.iter().map(|n| n.1).collect();
    let sectors = sector_index(&shapes_near, position);
    let noise = Normal::new(0.0, lidar.range_noise.max(1e-12)).expect("finite sigma");
    let (sy, cy) = yaw.sin_cos();
    let mut out = Vec::with_capacity(lidar.beams * lidar.azimuth_steps);
    for b in 0..lidar.beams {
        let elev = if lidar.beams == 1 {
            0.0
        } else {
            lidar.fov_down + (lidar.fov_up - lidar.fov_down) * b as f64 / (lidar.beams - 1) as f64
        }
        .to_radians();
        let (se, ce) = elev.sin_cos();
        for a in 0..lidar.azimuth_steps {
            let az = std::f64::consts::TAU * a as f64 / lidar.azimuth_steps as f64;
            let (sa, ca) = az.sin_cos();
            // Direction in the sensor frame, then rotated by the heading.
            let local = [ce * ca, ce * sa, se];
            let (d, world_az) = match &tilt {
                None => (
                    [
                        cy * local[0] - sy * local[1],
                        sy * local[0] + cy * local[1],
                        local[2],
                    ],
                    (az + yaw).rem_euclid(std::f64::consts::TAU),
                ),
                Some(m) => {
                    let d = [0, 1, 2]
                        .map(|k| m[k][0] * local[0] + m[k][1] * local[1] + m[k][2] * local[2]);
                    (d, d[1].atan2(d[0]).rem_euclid(std::f64::consts::TAU))
                }
            };
            let ray = Ray { o: position, d };
            // The ground first: most rays of an outdoor sensor end on it,
            // and then nothing beyond it needs testing.
            let mut best = ground
                .and_then(|g| g.hit(&ray, lidar.min_range, lidar.max_range))
                .unwrap_or(lidar.max_range);
            let sector =
                ((world_az / std::f64::consts::TAU * SECTORS as f64) as usize).min(SECTORS - 1);
            // A hit on a shape whose footprint is D away horizontally is at
            // least D / |d_xy| along the ray (1 um of slack for rounding).
            let reach = d[0].hypot(d[1]);
            for &k in &sectors[sector] {
                let (dist, s) = near[k];
                if dist > best * reach + 1e-6 {
                    break;
                }
                if let Some(t) = s.hit(&ray, lidar.min_range) {
                    if t < best {
                        best = t;
                    }
                }
            }
            if best >= lidar.max_range || rng.random::<f64>() < lidar.dropout {
                continue;
            }
            let r = best + noise.sample(rng);
            out.push([
                (local[0] * r) as f32,
                (local[1] * r) as f32,
                (local[2] * r) as f32,
            ]);
        }
    }
    out
}

const SECTORS: usize = 180;

/// For each azimuth sector (world frame, seen from `position`), the shapes
/// that a ray in it can hit.
fn sector_index(shapes: &[&Shape], position: [f64; 3]) -> Vec<Vec<usize>> {
    use std::f64::consts::{PI, TAU};
    let mut out = vec![Vec::new(); SECTORS];
    let (px, py) = (position[0], position[1]);
    for (k, s) in shapes.iter().enumerate() {
        // Angular span (centre, half-width); None = every sector.
        let span = match **s {
            Shape::Cylinder {
                centre: [cx, cy],
                radius,
                ..
            }
            | Shape::Sphere {
                centre: [cx, cy, _],
                radius,
            } => {
                let (dx, dy) = (cx - px, cy - py);
                let dist = (dx * dx + dy * dy).sqrt();
                (dist > radius + 1e-3).then(|| (dy.atan2(dx), (radius / dist).asin()))
            }
            Shape::Cuboid { .. } | Shape::OrientedBox { .. } => {
                let corners = s.footprint_corners().expect("box-like");
                if s.horizontal_distance(px, py) < 1e-3 {
                    None
                } else {
                    let (cx, cy) = corners
                        .iter()
                        .fold((0.0, 0.0), |(a, b), p| (a + p[0] / 4.0, b + p[1] / 4.0));
                    let c = (cy - py).atan2(cx - px);
                    let (mut lo, mut hi) = (0f64, 0f64);
                    for [x, y] in corners {
                        let a = ((y - py).atan2(x - px) - c + PI).rem_euclid(TAU) - PI;
                        lo = lo.min(a);
                        hi = hi.max(a);
                    }
                    Some((c + (lo + hi) / 2.0, (hi - lo) / 2.0))
                }
            }
        };
        match span {
            Some((c, hw)) if hw < PI - 0.1 => {
                let width = TAU / SECTORS as f64;
                // One sector of slack each side for rounding.
                let first = ((c - hw) / width).floor() as i64 - 1;
                let last = ((c + hw) / width).floor() as i64 + 1;
                for b in first..=last {
                    out[b.rem_euclid(SECTORS as i64) as usize].push(k);
                }
            }
            _ => out.iter_mut().for_each(|v| v.push(k)),
        }
    }
    for v in &mut out {
        v.dedup();
    }
    out
}
