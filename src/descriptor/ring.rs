//! Ring statistics of a polar height grid, after Scan Context (Kim and
//! Kim, "Scan Context: egocentric spatial descriptor for place recognition
//! within 3D point cloud map", IROS 2018). Scan Context bins the points
//! into rings and sectors around the sensor and keeps the largest height
//! in each bin; its rotation-invariant "ring key" summarises each ring by
//! its share of occupied sectors. Here each ring keeps the whole
//! distribution of its sectors' largest heights, with "empty" as the
//! lowest value: the ring key is its first bin (1 - occupancy), and the
//! rest says how high the walls, shelves and ceilings at that distance
//! reach. Rotating the scan permutes the sectors and changes nothing.
//!
//! Channels: one per ring (edges 0.5, 1.5, 3, 4.5, 6, 8, 11, 15, 20, 30,
//! 45, 64 m: 11 rings), each 17 bins: empty, then the sector's largest
//! height above the sensor from -3 m to 13 m in 1 m steps.

use super::parts::soft_bin;
use super::polar::PolarScan;
use crate::cloud::is_finite;

/// Ring edges (m).
const EDGES: [f32; 12] = [
    0.5, 1.5, 3.0, 4.5, 6.0, 8.0, 11.0, 15.0, 20.0, 30.0, 45.0, 64.0,
];
/// Sectors per ring (Scan Context's 60).
const SECTORS: usize = 60;
/// Bins of each ring's channel: empty, then 16 heights.
const BINS: usize = 17;
/// Lowest height of bin 1 (m, relative to the sensor); bins are 1 m.
const LOW: f64 = -3.0;

/// Bins of each channel: 17 per ring.
pub const CHANNELS: [usize; EDGES.len() - 1] = [BINS; EDGES.len() - 1];

/// One histogram per ring, each of unit sum.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// [`describe`] of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    let rings = EDGES.len() - 1;
    let mut top = vec![f32::NEG_INFINITY; rings * SECTORS];
    for (i, p) in scan.points.iter().enumerate() {
        if !is_finite(p) {
            continue;
        }
        let r = scan.range(i);
        let Some(ring) = EDGES.windows(2).position(|w| r >= w[0] && r < w[1]) else {
            continue;
        };
        let s = scan.sector(i, SECTORS);
        let t = &mut top[ring * SECTORS + s];
        *t = t.max(p[2]);
    }
    let mut out = vec![0f32; rings * BINS];
    let mass = 1.0 / SECTORS as f32;
    for (ring, sectors) in top.chunks_exact(SECTORS).enumerate() {
        let h = &mut out[ring * BINS..(ring + 1) * BINS];
        for &z in sectors {
            if z == f32::NEG_INFINITY {
                h[0] += mass;
            } else {
                // Bin 1 is LOW; heights below land there, above in the last.
                let x = 1.0 + (z as f64 - LOW).clamp(0.0, (BINS - 2) as f64);
                soft_bin(h, x, mass);
            }
        }
    }
    out
}
