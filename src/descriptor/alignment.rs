//! Candidate orientations (paper Sec. III-B, rotation invariance).
//!
//! Planar normals are directions up to sign. They are histogrammed over a
//! fine Fibonacci set of directions; the dominant ones (count >= ta * max)
//! give d1, and for each d1 the dominant directions at least 45 degrees away
//! give d2. Each pair gives the rotation that maps d1 to +z and puts d2 in the
//! yz plane.
//!
//! Choices where the paper is silent (documented here, tested in tests/):
//! - Near-duplicates: a dominant direction within 15 degrees of one already
//!   taken is skipped; neighbouring fine bins of one wall add no information.
//! - Signs: d and -d are the same line, but mapping d or -d to +z gives
//!   different frames. The sign is taken from the data (the side of the scan
//!   where the voxel means lie, summed along d), which rotates with the scan;
//!   when that is too balanced to trust (|sum| < 10% of sum |.|), both signs
//!   become candidates.

use super::directions;
use super::params::{Alignment, DescriptorParams};
use super::shape::{Shape, ShapedCell};

/// A rotation as three rows (the new x, y, z axes in the sensor frame).
pub type Rotation = [[f64; 3]; 3];

/// No rotation: the sensor's own frame (alignment `none`, or no planar voxel).
pub const IDENTITY: Rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Apply a rotation to a vector.
#[inline]
pub fn rotate(r: &Rotation, v: &[f64; 3]) -> [f64; 3] {
    [dot(&r[0], v), dot(&r[1], v), dot(&r[2], v)]
}

#[inline]
fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn normalise(v: [f64; 3]) -> Option<[f64; 3]> {
    let n = dot(&v, &v).sqrt();
    (n > 1e-12).then(|| [v[0] / n, v[1] / n, v[2] / n])
}

fn scale(v: &[f64; 3], s: f64) -> [f64; 3] {
    [v[0] * s, v[1] * s, v[2] * s]
}

/// Angle below which two dominant directions count as the same.
const SAME_DIRECTION_COS: f64 = 0.965_925_826; // cos 15 deg
/// d2 must be at least this far from d1.
const SECOND_DIRECTION_COS: f64 = std::f64::consts::FRAC_1_SQRT_2; // cos 45 deg

/// Signs of `d` to use: from the voxel means' side, or both when balanced.
fn signs(cells: &[ShapedCell], d: &[f64; 3]) -> Vec<f64> {
    let (mut sum, mut abs) = (0.0, 0.0);
    for c in cells {
        let p = dot(&c.mean, d);
        sum += p;
        abs += p.abs();
    }
    if sum.abs() < 0.1 * abs || abs == 0.0 {
        vec![1.0, -1.0]
    } else {
        vec![sum.signum()]
    }
}

/// Dominant entries of a histogram: indices with count >= ta * max among
/// those `allowed`, strongest first, skipping near-duplicates of earlier ones.
fn dominant(
    counts: &[u32],
    dirs: &[[f64; 3]],
    ta: f64,
    allowed: impl Fn(usize) -> bool,
) -> Vec<usize> {
    let max = (0..counts.len())
        .filter(|&i| allowed(i))
        .map(|i| counts[i])
        .max()
        .unwrap_or(0);
    if max == 0 {
        return Vec::new();
    }
    let mut idx: Vec<usize> = (0..counts.len())
        .filter(|&i| allowed(i) && counts[i] as f64 >= ta * max as f64)
        .collect();
    idx.sort_by(|&a, &b| counts[b].cmp(&counts[a]).then(a.cmp(&b)));
    let mut taken: Vec<usize> = Vec::new();
    for i in idx {
        if taken
            .iter()
            .all(|&t| dot(&dirs[t], &dirs[i]).abs() < SAME_DIRECTION_COS)
        {
            taken.push(i);
        }
    }
    taken
}

/// The rotation mapping `d1` to +z with `d2` in the yz plane (y >= 0).
fn frame(d1: &[f64; 3], d2: &[f64; 3]) -> Option<Rotation> {
    let z = *d1;
    let y = normalise([
        d2[0] - dot(d2, d1) * d1[0],
        d2[1] - dot(d2, d1) * d1[1],
        d2[2] - dot(d2, d1) * d1[2],
    ])?;
    let x = cross(&y, &z);
    Some([x, y, z])
}

/// Any unit vector orthogonal to `d` (for a frame from d1 alone).
fn any_orthogonal(d: &[f64; 3]) -> [f64; 3] {
    let helper = if d[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    normalise(cross(d, &helper)).unwrap_or([0.0, 1.0, 0.0])
}

/// The candidate orientations of a scan.
pub fn candidates(cells: &[ShapedCell], params: &DescriptorParams) -> Vec<Rotation> {
    let mut out = match params.alignment {
        Alignment::None => vec![IDENTITY],
        Alignment::Paper => paper(cells, params),
        Alignment::Yaw => yaw(cells, params),
    };
    if out.is_empty() {
        out.push(IDENTITY);
    }
    out.truncate(params.max_alignments);
    out
}

fn paper(cells: &[ShapedCell], params: &DescriptorParams) -> Vec<Rotation> {
    let index = directions::DirectionIndex::hemisphere(params.alignment_directions);
    let dirs = index.directions();
    let mut counts = vec![0u32; dirs.len()];
    for c in cells.iter().filter(|c| c.shape == Shape::Planar) {
        counts[index.nearest(&c.normal)] += 1;
    }
    let ta = params.ambiguity_threshold;
    let d1s = dominant(&counts, dirs, ta, |_| true);
    let mut out = Vec::new();
    for &i in &d1s {
        let d1 = dirs[i];
        let d2s = dominant(&counts, dirs, ta, |j| {
            dot(&dirs[j], &d1).abs() <= SECOND_DIRECTION_COS
        });
        let d2s: Vec<[f64; 3]> = if d2s.is_empty() {
            vec![any_orthogonal(&d1)]
        } else {
            d2s.iter().map(|&j| dirs[j]).collect()
        };
        for s1 in signs(cells, &d1) {
            let z = scale(&d1, s1);
            for d2 in &d2s {
                // The sign of the in-plane axis, from the data too.
                let y0 = frame(&z, d2).map(|f| f[1]).unwrap_or([0.0, 1.0, 0.0]);
                for s2 in signs(cells, &y0) {
                    if let Some(r) = frame(&z, &scale(&y0, s2)) {
                        out.push(r);
                    }
                    if out.len() >= params.max_alignments {
                        return out;
                    }
                }
            }
        }
    }
    out
}

/// z stays up; the dominant vertical planes (normals within 30 degrees of
/// horizontal) give the heading.
fn yaw(cells: &[ShapedCell], params: &DescriptorParams) -> Vec<Rotation> {
    const BINS: usize = 180;
    let mut counts = vec![0u32; BINS];
    for c in cells.iter().filter(|c| c.shape == Shape::Planar) {
        let n = c.normal;
        if n[2].abs() > 0.5 {
            continue;
        }
        // Angle of the line in [0, pi).
        let a = n[1].atan2(n[0]).rem_euclid(std::f64::consts::PI);
        counts[((a / std::f64::consts::PI * BINS as f64) as usize).min(BINS - 1)] += 1;
    }
    let dirs: Vec<[f64; 3]> = (0..BINS)
        .map(|i| {
            let a = (i as f64 + 0.5) / BINS as f64 * std::f64::consts::PI;
            [a.cos(), a.sin(), 0.0]
        })
        .collect();
    let mut out = Vec::new();
    for i in dominant(&counts, &dirs, params.ambiguity_threshold, |_| true) {
        for s in signs(cells, &dirs[i]) {
            let x = scale(&dirs[i], s);
            // New x axis = the wall normal; z unchanged.
            let y = cross(&[0.0, 0.0, 1.0], &x);
            out.push([x, y, [0.0, 0.0, 1.0]]);
        }
    }
    out
}
