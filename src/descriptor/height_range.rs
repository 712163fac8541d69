//! Distributions of range and height, after Röhling, Mack and Schulz, "A
//! fast histogram-based similarity measure for detecting loop closures in
//! 3-D LIDAR data" (IROS 2015), who compare 1-D histograms of point ranges
//! and heights with the Wasserstein (earth mover's) distance. Here the
//! points are first thinned to one per 0.2 m voxel ([`voxel_sample`]), so
//! that walls and ceilings count by their area rather than by how close
//! they are to the sensor: a 60 m hall and a 10 m room then differ in
//! where their mass lies, not only in how far the last returns are.
//!
//! Channels: horizontal range on a square-root scale from 0 to 64 m (32
//! bins: finer near the sensor, where rooms differ), and height relative to
//! the sensor from -4 m to +12 m (32 bins of 0.5 m: floor and ceiling).

use super::parts::{soft_bin, unit_sum, voxel_sample};

/// Bins of each channel: range, height.
pub const CHANNELS: [usize; 2] = [32, 32];

/// Largest range counted (m); farther points land in the last bin.
const MAX_RANGE: f64 = 64.0;
/// Height range (m, relative to the sensor).
const HEIGHT: (f64, f64) = (-4.0, 12.0);

/// The two histograms, range then height, each of unit sum.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    let (rb, hb) = (CHANNELS[0], CHANNELS[1]);
    let mut range = vec![0f32; rb];
    let mut height = vec![0f32; hb];
    for p in voxel_sample(points, 0.2) {
        let r = (p[0] as f64).hypot(p[1] as f64);
        soft_bin(&mut range, (r / MAX_RANGE).sqrt() * (rb - 1) as f64, 1.0);
        let z = (p[2] as f64 - HEIGHT.0) / (HEIGHT.1 - HEIGHT.0);
        soft_bin(&mut height, z * (hb - 1) as f64, 1.0);
    }
    unit_sum(&mut range);
    unit_sum(&mut height);
    range.extend(height);
    range
}
