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
//! the sensor from -4 m to +12 m (32 bins of 0.5 m: floor and ceiling);
//! then three scalars of those distributions, which do not change as the
//! sensor moves about one room or hall (the histograms do, with the
//! distance to the nearest wall): the 98th percentile of height (the
//! ceiling, -4 to 16 m), the 2nd (the floor, -4 to 4 m) and the 95th
//! percentile of range (the far walls, square-root scale to 64 m), 16 bins
//! each.

use super::parts::{scalar_channel, soft_bin, unit_sum, voxel_sample};

/// Bins of each channel: range, height, ceiling, floor, far walls.
pub const CHANNELS: [usize; 5] = [32, 32, 16, 16, 16];

/// Largest range counted (m); farther points land in the last bin.
const MAX_RANGE: f64 = 64.0;
/// Height range (m, relative to the sensor).
const HEIGHT: (f64, f64) = (-4.0, 12.0);

/// The two histograms, range then height, each of unit sum.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    let (rb, hb) = (CHANNELS[0], CHANNELS[1]);
    let mut range = vec![0f32; rb];
    let mut height = vec![0f32; hb];
    let sample = voxel_sample(points, 0.2);
    let (mut zs, mut rs) = (
        Vec::with_capacity(sample.len()),
        Vec::with_capacity(sample.len()),
    );
    for p in &sample {
        let r = (p[0] as f64).hypot(p[1] as f64);
        soft_bin(&mut range, (r / MAX_RANGE).sqrt() * (rb - 1) as f64, 1.0);
        let z = (p[2] as f64 - HEIGHT.0) / (HEIGHT.1 - HEIGHT.0);
        soft_bin(&mut height, z * (hb - 1) as f64, 1.0);
        zs.push(p[2] as f64);
        rs.push(r);
    }
    unit_sum(&mut range);
    unit_sum(&mut height);
    let mut out = range;
    out.extend(height);
    let (top, bottom, far) = (
        percentile(&mut zs, 0.98),
        percentile(&mut zs, 0.02),
        percentile(&mut rs, 0.95),
    );
    out.extend(scalar_channel(CHANNELS[2], top, -4.0, 16.0));
    out.extend(scalar_channel(CHANNELS[3], bottom, -4.0, 4.0));
    out.extend(scalar_channel(
        CHANNELS[4],
        (far / MAX_RANGE).sqrt(),
        0.0,
        1.0,
    ));
    out
}

/// The q-quantile of `v` (reordered); 0 for no values.
fn percentile(v: &mut [f64], q: f64) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    let k = ((v.len() - 1) as f64 * q).round() as usize;
    *v.select_nth_unstable_by(k, f64::total_cmp).1
}
