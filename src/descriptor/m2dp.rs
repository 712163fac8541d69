//! M2DP after He, Wang and Zhang, "M2DP: A novel 3D point cloud descriptor
//! and its application in loop closure detection" (IROS 2016): the cloud is
//! centred and aligned by PCA, projected onto p x q planes (p azimuths, q
//! elevations of the plane's normal), each projection counted in l x t
//! polar bins (l rings, t angles) about the centroid; the p q rows of
//! counts make a matrix A, and the signature is A's first left and right
//! singular vectors, [u1; v1] (p q + l t values).
//!
//! The paper's numbers are kept: p = 4, q = 16, l = 8, t = 16 (192
//! values); ring k (1..=l) ends at (k / l)² of the largest distance of a
//! point from the centroid, so the part is scale-free (size is left to the
//! slice and ring parts). Where this differs from the paper, and why:
//!
//! - **thinned**: one point per 0.2 m voxel (its lowest, as the clutter
//!   part takes, so the same points whatever their order): a lidar samples
//!   near surfaces far more densely, and every point is projected onto
//!   and binned in each of the 64 planes, so the part's time grows with
//!   the points kept;
//! - **yaw-only PCA, z kept up**: the paper rotates by the full 3-D PCA;
//!   here the x and y axes are the principal axes of the points' horizontal
//!   spread and z stays up, as every other part assumes (a 3-D PCA of a
//!   room as wide as it is high swaps z with a wall's normal from scan to
//!   scan). Invariance to rotation about z is what the parts promise;
//! - **sign of the axes**: each horizontal principal axis points where the
//!   points' third moment along it is positive (the longer tail), a rule
//!   that turns with the scan. Each axis is flipped on its own, so the
//!   frame (x, y, z) can come out left-handed, a mirror of the scan: a
//!   scan and its mirror image get the same aligned points, and M2DP as
//!   built cannot tell a room from its mirror image. Where the rule has
//!   nothing to go on the frame follows the noise: in a near-square room
//!   (horizontal spreads nearly equal) the major axis is any direction,
//!   and along a near-symmetric axis (third moment near 0) the sign is,
//!   so two scans of one such room can be aligned a quarter or half turn
//!   apart and differ more than their points do;
//! - **plane axes**: the first in-plane axis is the horizontal one,
//!   ẑ x n normalised (never degenerate for elevations below pi/2; the
//!   paper's projected x axis vanishes when n = x̂), the second n x it;
//! - **sign of the singular vectors**: (u1, v1) and (-u1, -v1) are the same
//!   SVD; A's counts are non-negative, so its first singular vectors can
//!   be (Perron) and here are made to have a non-negative sum;
//! - **distance**: each of the 192 values is a scalar channel on [-1, 1]
//!   (see [`soft_bin`](super::parts::soft_bin)), so the part's distance is
//!   the mean absolute difference over 2 (L1, the paper's is L2), in
//!   [0, 1] like every other part's.
//!
//! Degenerate scans get a defined vector, never a panic: no finite point
//! puts every channel's mass in bin 0 (all values -1); points all at one
//! spot (largest distance 0) fall in the innermost ring; points on a line
//! have an arbitrary but deterministic second axis (its spread is 0).

use super::parts::{empty_channels, scalar_channel, voxel_lowest};
use nalgebra::DMatrix;

/// Azimuths of the planes' normals (paper's p).
const AZIMUTHS: usize = 4;
/// Elevations of the planes' normals (paper's q).
const ELEVATIONS: usize = 16;
/// Rings of each plane's polar grid (paper's l).
const RINGS: usize = 8;
/// Angular bins of each plane's polar grid (paper's t).
const ANGLES: usize = 16;
/// Voxel edge of the thinning (m).
const VOXEL: f32 = 0.2;
/// Values of the signature: u1 (one per plane), then v1 (one per bin).
const VALUES: usize = AZIMUTHS * ELEVATIONS + RINGS * ANGLES;

/// Bins of each channel: one scalar channel (2 bins) per signature value.
pub const CHANNELS: [usize; VALUES] = [2; VALUES];

/// The signature [u1; v1] of a scan's points (sensor frame, z up), each
/// value as a scalar channel on [-1, 1].
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    match signature(points) {
        Some(s) => s
            .iter()
            .flat_map(|&x| scalar_channel(2, x, -1.0, 1.0))
            .collect(),
        None => empty_channels(&CHANNELS),
    }
}

/// The signature [u1; v1] (`VALUES` numbers), None without a finite point
/// (or if the SVD gave no singular vectors, which it was asked for and
/// has not been seen to do).
pub fn signature(points: &[[f32; 3]]) -> Option<Vec<f64>> {
    let mut pts = voxel_lowest(points, VOXEL);
    if pts.is_empty() {
        return None;
    }
    // Sums below run in a fixed order, so any order of the scan gives the
    // same bits (voxel_lowest's list is in hash order).
    pts.sort_unstable_by(|a, b| {
        (a[0].total_cmp(&b[0]))
            .then(a[1].total_cmp(&b[1]))
            .then(a[2].total_cmp(&b[2]))
    });
    let aligned = align(&pts);
    let a = signature_matrix(&aligned);
    first_singular_vectors(a)
}

/// The points centred on their centroid, x and y turned onto the
/// principal axes of their horizontal spread (signs by the third moment),
/// z kept up.
fn align(pts: &[[f32; 3]]) -> Vec<[f64; 3]> {
    let n = pts.len() as f64;
    let mut c = [0f64; 3];
    for p in pts {
        for k in 0..3 {
            c[k] += p[k] as f64 / n;
        }
    }
    let centred: Vec<[f64; 3]> = pts
        .iter()
        .map(|p| [p[0] as f64 - c[0], p[1] as f64 - c[1], p[2] as f64 - c[2]])
        .collect();
    let (mut sxx, mut syy, mut sxy) = (0f64, 0f64, 0f64);
    for p in &centred {
        sxx += p[0] * p[0];
        syy += p[1] * p[1];
        sxy += p[0] * p[1];
    }
    // The major axis of a 2x2 covariance in closed form.
    let phi = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let mut e1 = [phi.cos(), phi.sin()];
    let mut e2 = [-e1[1], e1[0]];
    for e in [&mut e1, &mut e2] {
        let skew: f64 = centred
            .iter()
            .map(|p| (p[0] * e[0] + p[1] * e[1]).powi(3))
            .sum();
        if skew < 0.0 {
            *e = [-e[0], -e[1]];
        }
    }
    centred
        .iter()
        .map(|p| {
            [
                p[0] * e1[0] + p[1] * e1[1],
                p[0] * e2[0] + p[1] * e2[1],
                p[2],
            ]
        })
        .collect()
}

/// The p q x l t matrix A: row (azimuth, elevation) holds the counts of
/// the points projected onto that plane in its polar bins.
///
/// The bins are found without `atan2` or `hypot` (measured: with them the
/// part took 20 times the NDT histogram's time on a 112k-point room
/// scan): the ring from the squared radius, the angle from the "diamond
/// angle", a monotone stand-in for the angle, against the diamond angles
/// of the sector edges. That this gives the bins of `atan2` and `hypot`
/// is measured, not proved: the part's digests on the 28 scans of
/// tests/it/parts.rs did not change when the binning did, and the unit
/// test below checks 3600 angles off the edges. The two differ by
/// construction on seams: a point on the negative x axis with y = +0 is
/// in the first angle bin here but in the last with `atan2(+0, x < 0)` =
/// pi (y = -0 gives the first bin in both); and a point whose angle or
/// radius is within rounding of a bin edge (the edges' cos and sin, the
/// fourth root against sqrt of hypot) may fall on either side.
fn signature_matrix(pts: &[[f64; 3]]) -> DMatrix<f64> {
    let largest_sq = pts
        .iter()
        .map(|p| p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
        .fold(0f64, f64::max);
    // Ring k ends at (k / l)² of the largest distance R, so the ring of
    // radius r is l sqrt(r / R) = l (r² / R²)^(1/4).
    let inv_sq = if largest_sq > 0.0 && largest_sq.is_finite() {
        1.0 / largest_sq
    } else {
        0.0
    };
    let ring_of =
        |r_sq: f64| (((r_sq * inv_sq).sqrt().sqrt() * RINGS as f64) as usize).min(RINGS - 1);
    let edges = sector_edges();
    let mut a = DMatrix::<f64>::zeros(AZIMUTHS * ELEVATIONS, RINGS * ANGLES);
    for i in 0..AZIMUTHS {
        let theta = i as f64 * std::f64::consts::PI / AZIMUTHS as f64;
        for j in 0..ELEVATIONS {
            let elev = j as f64 * std::f64::consts::FRAC_PI_2 / ELEVATIONS as f64;
            let n = [
                elev.cos() * theta.cos(),
                elev.cos() * theta.sin(),
                elev.sin(),
            ];
            // ẑ x n, normalised: (-sin theta, cos theta, 0).
            let u = [-theta.sin(), theta.cos(), 0.0];
            // n x u.
            let w = [
                n[1] * u[2] - n[2] * u[1],
                n[2] * u[0] - n[0] * u[2],
                n[0] * u[1] - n[1] * u[0],
            ];
            let row = i * ELEVATIONS + j;
            let mut counts = [0u32; RINGS * ANGLES];
            for p in pts {
                let x = p[0] * u[0] + p[1] * u[1];
                let y = p[0] * w[0] + p[1] * w[1] + p[2] * w[2];
                counts[ring_of(x * x + y * y) * ANGLES + angle_bin(&edges, x, y)] += 1;
            }
            for (col, &c) in counts.iter().enumerate() {
                a[(row, col)] = c as f64;
            }
        }
    }
    a
}

/// Diamond angles of the sector edges k 2 pi / t, k = 0..t.
fn sector_edges() -> Vec<f64> {
    (0..ANGLES)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / ANGLES as f64;
            diamond(a.cos(), a.sin())
        })
        .collect()
}

/// The angle bin of (x, y): its sector in [0, 2 pi), then counted from
/// -pi as `atan2(y, x) + pi` would be: half a turn on.
fn angle_bin(edges: &[f64], x: f64, y: f64) -> usize {
    // diamond >= 0 = edges[0], so the point is never before the first edge.
    let sector = edges.partition_point(|&e| e <= diamond(x, y)).max(1) - 1;
    (sector + ANGLES / 2) % ANGLES
}

/// A number in [0, 4) that grows with the angle of (x, y) in [0, 2 pi)
/// as the angle does (0 at (1, 0), 1 at (0, 1), 2 at (-1, 0), 3 at
/// (0, -1)); 0 at the origin.
fn diamond(x: f64, y: f64) -> f64 {
    let d = if y >= 0.0 {
        if x >= 0.0 {
            y / (x + y)
        } else {
            1.0 - x / (y - x)
        }
    } else if x < 0.0 {
        2.0 - y / (-x - y)
    } else {
        3.0 + x / (x - y)
    };
    if d.is_nan() {
        0.0
    } else {
        d
    }
}

/// [u1; v1] of A, signed so that their sum is non-negative; None if the
/// SVD gave no U or V (it was asked for both).
fn first_singular_vectors(a: DMatrix<f64>) -> Option<Vec<f64>> {
    let svd = a.svd(true, true);
    let (u, v_t) = (svd.u?, svd.v_t?);
    let top = svd
        .singular_values
        .iter()
        .enumerate()
        .max_by(|x, y| x.1.total_cmp(y.1))
        .map_or(0, |(k, _)| k);
    let mut s: Vec<f64> = u.column(top).iter().copied().collect();
    s.extend(v_t.row(top).iter().copied());
    let v_sum: f64 = s[AZIMUTHS * ELEVATIONS..].iter().sum();
    if v_sum < 0.0 {
        s.iter_mut().for_each(|x| *x = -*x);
    }
    Some(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on the walls, floor and ceiling of a w x d x h box around
    /// the sensor at `(sx, sy)`, 1.2 m above the floor, every 0.1 m.
    fn box_room(w: f32, d: f32, h: f32, sx: f32, sy: f32) -> Vec<[f32; 3]> {
        let mut pts = Vec::new();
        let step = 0.1;
        let (nx, ny, nz) = ((w / step) as i32, (d / step) as i32, (h / step) as i32);
        let at = |x: f32, y: f32, z: f32| [x - sx, y - sy, z - 1.2];
        for i in 0..=nx {
            for j in 0..=ny {
                let (x, y) = (i as f32 * step, j as f32 * step);
                pts.push(at(x, y, 0.0));
                pts.push(at(x, y, h));
            }
            for k in 0..=nz {
                let (x, z) = (i as f32 * step, k as f32 * step);
                pts.push(at(x, 0.0, z));
                pts.push(at(x, d, z));
            }
        }
        for j in 0..=ny {
            for k in 0..=nz {
                let (y, z) = (j as f32 * step, k as f32 * step);
                pts.push(at(0.0, y, z));
                pts.push(at(w, y, z));
            }
        }
        pts
    }

    fn l1(a: &[f64], b: &[f64]) -> f64 {
        a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f64>() / a.len() as f64
    }

    #[test]
    fn the_signature_is_two_unit_vectors_of_the_paper_sizes() {
        let s = signature(&box_room(6.0, 4.0, 3.0, 2.0, 1.5)).unwrap();
        assert_eq!(s.len(), 64 + 128);
        let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((norm(&s[..64]) - 1.0).abs() < 1e-9);
        assert!((norm(&s[64..]) - 1.0).abs() < 1e-9);
        // Counts are non-negative, so the first singular vectors are too.
        assert!(s.iter().all(|&x| x > -1e-9), "{s:?}");
        let d = describe(&box_room(6.0, 4.0, 3.0, 2.0, 1.5));
        assert_eq!(d.len(), CHANNELS.iter().sum::<usize>());
    }

    #[test]
    fn two_rooms_differ_more_than_two_spots_in_one() {
        let a = signature(&box_room(6.0, 4.0, 3.0, 2.0, 1.5)).unwrap();
        let a2 = signature(&box_room(6.0, 4.0, 3.0, 3.5, 2.5)).unwrap();
        let corridor = signature(&box_room(20.0, 2.2, 3.0, 8.0, 1.0)).unwrap();
        let same = l1(&a, &a2);
        let other = l1(&a, &corridor);
        assert!(other > 3.0 * same, "same room {same}, corridor {other}");
    }

    #[test]
    fn degenerate_scans_give_a_defined_vector() {
        // No point, no finite point: every value -1 (bin 0).
        assert_eq!(describe(&[]), empty_channels(&CHANNELS));
        assert_eq!(
            describe(&[[f32::NAN, 0.0, 0.0], [f32::INFINITY, 1.0, 1.0]]),
            empty_channels(&CHANNELS)
        );
        // One spot, points on a line, points on a plane, wild values.
        let line: Vec<[f32; 3]> = (0..500).map(|i| [i as f32 * 0.05, 0.0, 0.0]).collect();
        let plane: Vec<[f32; 3]> = (0..900)
            .map(|i| [(i % 30) as f32 * 0.3, (i / 30) as f32 * 0.3, -1.0])
            .collect();
        let wild = vec![[1e30, -1e30, 3e38], [0.0, 0.0, 0.0], [-3e38, 1.0, 1.0]];
        for pts in [vec![[1.0, 2.0, 3.0]; 10], line, plane, wild] {
            let s = signature(&pts).unwrap();
            assert!(s.iter().all(|x| x.is_finite()), "{s:?}");
            let d = describe(&pts);
            assert!(d.iter().all(|x| x.is_finite() && *x >= 0.0));
        }
    }

    /// The diamond angle's sectors are atan2's, away from the edges.
    #[test]
    fn diamond_sectors_are_the_angle_sectors() {
        let edges = sector_edges();
        for i in 0..3600 {
            // Off the edges (every 22.5 degrees) by at least 0.05 degrees.
            let deg = i as f64 * 0.1 + 0.05;
            let a = deg.to_radians();
            let (x, y) = (2.5 * a.cos(), 2.5 * a.sin());
            assert_eq!(angle_bin(&edges, x, y), atan2_bin(x, y), "{deg}");
        }
        assert_eq!(diamond(0.0, 0.0), 0.0);
        // A seam where they differ by construction: atan2(+0, x < 0) = pi
        // (the last bin), the diamond angle 2 (the first); with y = -0
        // both give the first.
        assert_eq!(
            (angle_bin(&edges, -1.0, 0.0), atan2_bin(-1.0, 0.0)),
            (0, 15)
        );
        assert_eq!(
            (angle_bin(&edges, -1.0, -0.0), atan2_bin(-1.0, -0.0)),
            (0, 0)
        );
    }

    /// The bin M2DP's first form took: atan2's angle + pi in t sectors.
    fn atan2_bin(x: f64, y: f64) -> usize {
        let t = (y.atan2(x) + std::f64::consts::PI) / std::f64::consts::TAU * ANGLES as f64;
        (t as usize).min(ANGLES - 1)
    }

    /// Each principal axis is signed on its own, so a scan and its mirror
    /// image are aligned onto the same points (M2DP cannot tell them
    /// apart), while the frame keeps z up.
    #[test]
    fn a_mirror_image_is_aligned_onto_the_same_points() {
        // A room with a cupboard in one corner: both horizontal axes have
        // a tail, so neither sign is left to noise.
        let mut room = box_room(6.0, 4.0, 3.0, 2.0, 1.5);
        room.extend((0..400).map(|i| [3.0 + (i % 20) as f32 * 0.05, 2.0, (i / 20) as f32 * 0.1]));
        let mirror: Vec<[f32; 3]> = room.iter().map(|p| [-p[0], p[1], p[2]]).collect();
        let (a, m) = (align(&room), align(&mirror));
        let apart = a
            .iter()
            .zip(&m)
            .flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs()))
            .fold(0f64, f64::max);
        assert!(apart < 1e-9, "mirror aligned {apart} apart");
    }

    #[test]
    fn the_order_of_the_points_changes_nothing() {
        let pts = box_room(5.0, 3.0, 2.8, 1.0, 1.0);
        let mut rev = pts.clone();
        rev.reverse();
        assert_eq!(describe(&pts), describe(&rev));
    }
}
