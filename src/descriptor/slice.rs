//! Geometry of the free space around the sensor, after Mozos, Stachniss
//! and Burgard, "Supervised learning of places from range data using
//! AdaBoost" (ICRA 2005) and Mozos et al., "Supervised semantic labeling of
//! places using information extracted from sensor data" (RAS 2007), who
//! tell rooms, corridors and halls apart by features of a horizontal laser
//! scan: the mean and spread of beam lengths, and the area, perimeter,
//! compactness and elongation of the polygon the beams span.
//!
//! A 3-D scan has no single horizontal beam, so each of 180 azimuth
//! sectors takes its return of farthest horizontal range: in a
//! closed room every ray ends on the floor, a wall or the ceiling, and the
//! farthest of them lies on the wall, even behind furniture lower than the
//! sensor's view of the wall. Sectors without returns take the value of
//! their nearest neighbour with one. The polygon of these 180 returns gives
//! the features; every one is invariant to rotation about z.
//!
//! Channels, one scalar each (soft-binned over its range, 16 bins): log10
//! area (1 to 10^4 m²), log10 perimeter (1 to 10^3 m), log10 mean beam
//! (0.3 to 100 m), relative spread of beams (std / mean, 0 to 1),
//! compactness 4 pi area / perimeter² (0 to 1), elongation sqrt(l2 / l1) of
//! the polygon's second moments (0 to 1); and a histogram of the beam
//! lengths (log scale, 0.3 to 100 m, 24 bins).

use super::parts::{empty_channels, scalar_channel, soft_bin, unit_sum};
use super::polar::PolarScan;
use crate::cloud::is_finite;

/// Bins of each channel (see the module doc).
pub const CHANNELS: [usize; 7] = [16, 16, 16, 16, 16, 16, 24];

/// Azimuth sectors.
pub const SECTORS: usize = 180;
/// Returns nearer than this (m) are the sensor's own mount.
const MIN_RANGE: f32 = 0.3;

/// The polygon's features (for tests and display).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliceFeatures {
    /// Area of the polygon (m²).
    pub area: f64,
    /// Its perimeter (m).
    pub perimeter: f64,
    /// Mean of the sector ranges (m).
    pub mean: f64,
    /// Their standard deviation over the mean.
    pub spread: f64,
    /// 4 pi area / perimeter²: 1 for a circle, pi/4 for a square.
    pub compactness: f64,
    /// sqrt of the smaller over the larger eigenvalue of the polygon's
    /// second moments: 1 for a square, 1/2 for a 2:1 rectangle.
    pub elongation: f64,
}

/// The farthest return (x, y) of each sector, gaps filled with the range
/// of the nearest sector with a return, at the gap's own centre angle;
/// None when no sector has one. Vertices are returns themselves, not
/// ranges put at the sector's centre: along a corridor one 2-degree sector
/// spans metres of wall, and its farthest return lies far beyond the
/// wall point at its centre angle.
pub fn sector_points(points: &[[f32; 3]]) -> Option<Vec<[f64; 2]>> {
    sector_points_of(&PolarScan::new(points))
}

/// [`sector_points`] of a scan whose ranges and azimuths are known.
pub fn sector_points_of(scan: &PolarScan) -> Option<Vec<[f64; 2]>> {
    let mut far: Vec<Option<(f32, [f32; 2])>> = vec![None; SECTORS];
    for (i, p) in scan.points.iter().enumerate() {
        if !is_finite(p) {
            continue;
        }
        let r = scan.range(i);
        if r < MIN_RANGE {
            continue;
        }
        let s = scan.sector(i, SECTORS);
        // Ties of range go to the larger (x, y), so that the vertex, and
        // the part's every bit, does not depend on the points' order.
        let farther = |(best, xy): (f32, [f32; 2])| {
            r.total_cmp(&best)
                .then(p[0].total_cmp(&xy[0]))
                .then(p[1].total_cmp(&xy[1]))
                .is_gt()
        };
        if far[s].is_none_or(farther) {
            far[s] = Some((r, [p[0], p[1]]));
        }
    }
    let filled: Vec<usize> = (0..SECTORS).filter(|&s| far[s].is_some()).collect();
    if filled.is_empty() {
        return None;
    }
    Some(
        (0..SECTORS)
            .map(|s| match far[s] {
                Some((_, xy)) => [xy[0] as f64, xy[1] as f64],
                None => {
                    let near = filled
                        .iter()
                        .min_by_key(|&&f| {
                            let d = s.abs_diff(f);
                            d.min(SECTORS - d)
                        })
                        .and_then(|&f| far[f])
                        .map_or(0.0, |(r, _)| r as f64);
                    let a = (s as f64 + 0.5) / SECTORS as f64 * std::f64::consts::TAU
                        - std::f64::consts::PI;
                    [near * a.cos(), near * a.sin()]
                }
            })
            .collect(),
    )
}

/// The features of the polygon with vertices `pts` (in angular order
/// about the origin).
pub fn features(pts: &[[f64; 2]]) -> SliceFeatures {
    let n = pts.len();
    let ranges: Vec<f64> = pts.iter().map(|p| p[0].hypot(p[1])).collect();
    let (mut area, mut perimeter) = (0f64, 0f64);
    // Second moments of the polygon as a lamina (sums over the triangles
    // origin - p - q, whose centroid terms are exact for each triangle).
    let (mut sxx, mut syy, mut sxy, mut sx, mut sy) = (0f64, 0f64, 0f64, 0f64, 0f64);
    for i in 0..n {
        let (p, q) = (pts[i], pts[(i + 1) % n]);
        let cross = p[0] * q[1] - q[0] * p[1];
        area += cross / 2.0;
        perimeter += (q[0] - p[0]).hypot(q[1] - p[1]);
        sx += cross * (p[0] + q[0]) / 6.0;
        sy += cross * (p[1] + q[1]) / 6.0;
        sxx += cross * (p[0] * p[0] + p[0] * q[0] + q[0] * q[0]) / 12.0;
        syy += cross * (p[1] * p[1] + p[1] * q[1] + q[1] * q[1]) / 12.0;
        sxy += cross * (2.0 * p[0] * p[1] + p[0] * q[1] + q[0] * p[1] + 2.0 * q[0] * q[1]) / 24.0;
    }
    let elongation = if area > 0.0 {
        let (cx, cy) = (sx / area, sy / area);
        let (a, b, c) = (
            sxx / area - cx * cx,
            syy / area - cy * cy,
            sxy / area - cx * cy,
        );
        let mid = (a + b) / 2.0;
        let half = (((a - b) / 2.0).powi(2) + c * c).sqrt();
        let (l1, l2) = (mid + half, (mid - half).max(0.0));
        if l1 > 0.0 {
            (l2 / l1).sqrt()
        } else {
            0.0
        }
    } else {
        0.0
    };
    let mean = ranges.iter().sum::<f64>() / n as f64;
    let var = ranges.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / n as f64;
    SliceFeatures {
        area,
        perimeter,
        mean,
        spread: if mean > 0.0 { var.sqrt() / mean } else { 0.0 },
        compactness: if perimeter > 0.0 {
            4.0 * std::f64::consts::PI * area / (perimeter * perimeter)
        } else {
            0.0
        },
        elongation,
    }
}

/// The channels (see the module doc); a scan with no return beyond 0.3 m
/// puts every channel's mass in bin 0.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// [`describe`] of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    let Some(pts) = scan.polygon() else {
        return empty_channels(&CHANNELS);
    };
    let f = features(pts);
    let log = |x: f64| x.max(1e-6).log10();
    let mut v = Vec::with_capacity(CHANNELS.iter().sum());
    v.extend(scalar_channel(CHANNELS[0], log(f.area), 0.0, 4.0));
    v.extend(scalar_channel(CHANNELS[1], log(f.perimeter), 0.0, 3.0));
    v.extend(scalar_channel(CHANNELS[2], log(f.mean), -0.5, 2.0));
    v.extend(scalar_channel(CHANNELS[3], f.spread, 0.0, 1.0));
    v.extend(scalar_channel(CHANNELS[4], f.compactness, 0.0, 1.0));
    v.extend(scalar_channel(CHANNELS[5], f.elongation, 0.0, 1.0));
    let bins = CHANNELS[6];
    let mut beams = vec![0f32; bins];
    for p in pts {
        soft_bin(
            &mut beams,
            (log(p[0].hypot(p[1])) + 0.5) / 2.5 * (bins - 1) as f64,
            1.0,
        );
    }
    unit_sum(&mut beams);
    v.extend(beams);
    v
}
