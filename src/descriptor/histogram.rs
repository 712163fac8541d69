//! The NDT histogram: per candidate orientation, a matrix F whose rows are
//! shape classes (times height bands) and whose columns are range intervals,
//! holding raw voxel counts (paper Sec. III-C).
//!
//! Only a voxel whose class depends on the orientation (a planar or linear
//! one when its shape has more than one direction class) is looked at once
//! per orientation; the others are counted once, into the counts every
//! orientation starts from. The simulated outdoor scans of the page's
//! benchmark have 12 candidate orientations, and looking at every voxel for
//! each made this stage 65 instructions per point there, against 8.5 on a
//! KITTI scan with one (docs/wasm-floor.md). The counts are integers, so
//! adding them in another order changes no bit.

use super::alignment::{rotate, Rotation};
use super::directions;
use super::params::DescriptorParams;
use super::shape::{Shape, ShapedCell};

/// Which range intervals hold a distance, found by one binary search.
/// Between two consecutive interval ends, every distance is in the same
/// intervals (each `r >= lo` and `r < hi` test comes out the same, as no end
/// lies strictly inside), so the ends cut the line into segments and each
/// segment has one set of columns: the voxel's counts go to (row, segment),
/// one addition per voxel, and are spread to the columns per orientation.
struct Segments {
    /// The distinct interval ends, ascending.
    ends: Vec<f64>,
    /// Columns of segment k (distances in [ends[k-1], ends[k])); segment 0,
    /// below every end, is in no interval.
    columns: Vec<Vec<usize>>,
}

impl Segments {
    fn new(ranges: &[(f64, Option<f64>)]) -> Segments {
        let mut ends: Vec<f64> = ranges
            .iter()
            .flat_map(|&(lo, hi)| std::iter::once(lo).chain(hi))
            .collect();
        ends.sort_by(f64::total_cmp);
        ends.dedup_by(|a, b| a == b);
        let holding = |r: f64| -> Vec<usize> {
            (0..ranges.len())
                .filter(|&i| r >= ranges[i].0 && ranges[i].1.is_none_or(|h| r < h))
                .collect()
        };
        let columns = std::iter::once(Vec::new())
            .chain(ends.iter().map(|&e| holding(e)))
            .collect();
        Segments { ends, columns }
    }

    /// The segment of distance `r` (0 for NaN: in no interval, as the tests
    /// `r >= lo` say).
    #[inline]
    fn of(&self, r: f64) -> usize {
        self.ends.partition_point(|&e| e <= r)
    }
}

/// A voxel whose class depends on the orientation: the vector to rotate
/// (its normal or axis) and the index of its count for the class of the
/// shape's first direction (direction k adds k x segments).
struct Turning {
    v: [f64; 3],
    at: usize,
}

/// Build one count matrix (row-major, rows x cols) per rotation; also
/// returns how many voxels fall in at least one range interval.
pub fn histograms(
    cells: &[ShapedCell],
    rotations: &[Rotation],
    params: &DescriptorParams,
) -> (Vec<Vec<u32>>, usize) {
    let ns = params.spherical_classes;
    let np = params.planar_classes;
    let nl = params.linear_classes;
    let classes = ns + np + nl;
    let (rows, cols) = (params.rows(), params.cols());
    let planar_dirs = directions::hemisphere(np);
    let linear_dirs = directions::hemisphere(nl);
    let segments = Segments::new(&params.ranges);
    let nseg = segments.columns.len();

    // Counts per (row, segment), at row x nseg + segment.
    let mut common = vec![0u32; rows * nseg];
    let (mut planar, mut linear) = (Vec::new(), Vec::new());
    let mut in_range = 0;
    for c in cells {
        let r = (c.mean[0] * c.mean[0] + c.mean[1] * c.mean[1] + c.mean[2] * c.mean[2]).sqrt();
        let segment = segments.of(r);
        // Intervals overlap: a voxel counts in every one that holds it.
        if segments.columns[segment].is_empty() {
            continue;
        }
        in_range += 1;
        // Height bands use the sensor frame's z (the sensor is assumed
        // upright, as the bands are meant for ground robots).
        let band = params
            .height_bands
            .partition_point(|&edge| edge <= c.mean[2]);
        let at = |class: usize| (band * classes + class) * nseg + segment;
        // One direction is the nearest to every vector (NaN too), so with
        // one class for a shape the orientation does not matter.
        match c.shape {
            Shape::Spherical => {
                let roughness = c.eigenvalues[0] / c.eigenvalues[2];
                common[at(((roughness * ns as f64) as usize).min(ns - 1))] += 1;
            }
            Shape::Planar if np == 1 => common[at(ns)] += 1,
            Shape::Linear if nl == 1 => common[at(ns + np)] += 1,
            Shape::Planar => planar.push(Turning {
                v: c.normal,
                at: at(ns),
            }),
            Shape::Linear => linear.push(Turning {
                v: c.axis,
                at: at(ns + np),
            }),
        }
    }

    let matrices = rotations
        .iter()
        .map(|rot| {
            let mut counts = common.clone();
            for (turning, dirs) in [(&planar, &planar_dirs), (&linear, &linear_dirs)] {
                count_turning(&mut counts, turning, dirs, rot, nseg);
            }
            let mut f = vec![0u32; rows * cols];
            for (row, per_segment) in counts.chunks_exact(nseg).enumerate() {
                for (columns, &n) in segments.columns.iter().zip(per_segment) {
                    // Skipping the empty (row, segment) pairs keeps this within
                    // the old per-voxel loop's order (one addition per voxel and
                    // column) even with many classes and many nested ranges.
                    if n == 0 {
                        continue;
                    }
                    for &col in columns {
                        f[row * cols + col] += n;
                    }
                }
            }
            f
        })
        .collect();
    (matrices, in_range)
}

/// Add the turning voxels' counts for one orientation.
fn count_turning(
    counts: &mut [u32],
    turning: &[Turning],
    dirs: &[[f64; 3]],
    rot: &Rotation,
    nseg: usize,
) {
    // 9 directions: every preset's planar classes.
    if let Ok(dirs) = <&[[f64; 3]; 9]>::try_from(dirs) {
        for t in turning {
            counts[t.at + directions::nearest_of(dirs, &rotate(rot, &t.v)) * nseg] += 1;
        }
    } else {
        for t in turning {
            counts[t.at + directions::nearest(dirs, &rotate(rot, &t.v)) * nseg] += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::descriptor::alignment::IDENTITY;
    use rand::{Rng, SeedableRng};

    /// The per-voxel loop this stage had before (main at 86ed595): every
    /// voxel looked at once per orientation, its columns tested one by one.
    /// The new code must give the same counts, bit for bit.
    fn reference(
        cells: &[ShapedCell],
        rotations: &[Rotation],
        params: &DescriptorParams,
    ) -> (Vec<Vec<u32>>, usize) {
        let (ns, np) = (params.spherical_classes, params.planar_classes);
        let classes = ns + np + params.linear_classes;
        let cols = params.cols();
        let planar_dirs = directions::hemisphere(np);
        let linear_dirs = directions::hemisphere(params.linear_classes);
        let mut placed = Vec::new();
        for c in cells {
            let r = (c.mean[0] * c.mean[0] + c.mean[1] * c.mean[1] + c.mean[2] * c.mean[2]).sqrt();
            let columns: Vec<usize> = (params.ranges.iter().enumerate())
                .filter(|(_, (lo, hi))| r >= *lo && hi.is_none_or(|h| r < h))
                .map(|(i, _)| i)
                .collect();
            if !columns.is_empty() {
                let band = params
                    .height_bands
                    .partition_point(|&edge| edge <= c.mean[2]);
                placed.push((c, band * classes, columns));
            }
        }
        let matrices = rotations
            .iter()
            .map(|rot| {
                let mut f = vec![0u32; params.rows() * cols];
                for (c, band_row, columns) in &placed {
                    let class = match c.shape {
                        Shape::Spherical => {
                            let roughness = c.eigenvalues[0] / c.eigenvalues[2];
                            ((roughness * ns as f64) as usize).min(ns - 1)
                        }
                        Shape::Planar => {
                            ns + directions::nearest(&planar_dirs, &rotate(rot, &c.normal))
                        }
                        Shape::Linear => {
                            ns + np + directions::nearest(&linear_dirs, &rotate(rot, &c.axis))
                        }
                    };
                    for &col in columns {
                        f[(band_row + class) * cols + col] += 1;
                    }
                }
                f
            })
            .collect();
        (matrices, placed.len())
    }

    fn unit(r: &mut impl Rng) -> [f64; 3] {
        let v: [f64; 3] = std::array::from_fn(|_| r.random_range(-1.0..1.0));
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|x| x / n)
    }

    /// A rotation from a random unit quaternion.
    fn rotation(r: &mut impl Rng) -> Rotation {
        let [x, y, z] = unit(r);
        let half = r.random_range(0.0..std::f64::consts::PI);
        let (s, w) = half.sin_cos();
        let (x, y, z) = (x * s, y * s, z * s);
        [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ]
    }

    /// Voxels of every shape; some exactly on an interval end or a band
    /// edge (sqrt(e * e) is e exactly), some with a NaN mean or direction.
    fn cells(r: &mut impl Rng, ends: &[f64], edges: &[f64]) -> Vec<ShapedCell> {
        (0..400)
            .map(|k| {
                let mut mean: [f64; 3] = std::array::from_fn(|_| r.random_range(-40.0..40.0));
                let (mut normal, mut axis) = (unit(r), unit(r));
                match k % 7 {
                    0 => mean = [ends[r.random_range(0..ends.len())], 0.0, 0.0],
                    1 => mean = [0.0, 0.0, -ends[r.random_range(0..ends.len())]],
                    2 if !edges.is_empty() => mean[2] = edges[r.random_range(0..edges.len())],
                    3 => mean[r.random_range(0..3)] = f64::NAN,
                    4 => {
                        normal[r.random_range(0..3)] = f64::NAN;
                        axis[r.random_range(0..3)] = f64::NAN;
                    }
                    _ => {}
                }
                let mut eigenvalues: [f64; 3] = std::array::from_fn(|_| r.random_range(0.01..1.0));
                eigenvalues.sort_by(f64::total_cmp);
                if k % 11 == 0 {
                    eigenvalues = [0.5; 3];
                }
                let shape = [Shape::Spherical, Shape::Planar, Shape::Linear][k % 3];
                ShapedCell {
                    mean,
                    shape,
                    eigenvalues,
                    normal,
                    axis,
                }
            })
            .collect()
    }

    #[test]
    fn same_counts_as_the_per_voxel_loop() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(20);
        // Overlapping, nested, touching, an infinite end and an open one.
        let ranges = vec![
            (0.0, Some(5.0)),
            (2.0, Some(20.0)),
            (0.5, Some(2.0)),
            (5.0, Some(f64::INFINITY)),
            (10.0, None),
            (2.0, Some(20.0)),
        ];
        let ends = [0.0, 0.5, 2.0, 5.0, 10.0, 20.0, 39.0];
        let mut rotations = vec![IDENTITY];
        rotations.extend((0..5).map(|_| rotation(&mut r)));
        for np in [1, 4, 9] {
            for nl in [1, 3] {
                for edges in [vec![], vec![-0.8, 0.3, 1.5, 5.0]] {
                    let params = DescriptorParams {
                        spherical_classes: 3,
                        planar_classes: np,
                        linear_classes: nl,
                        ranges: ranges.clone(),
                        height_bands: edges.clone(),
                        ..DescriptorParams::indoor()
                    };
                    let cells = cells(&mut r, &ends, &edges);
                    let (got, in_range) = histograms(&cells, &rotations, &params);
                    let (want, want_in_range) = reference(&cells, &rotations, &params);
                    assert_eq!(in_range, want_in_range, "np {np} nl {nl} bands {edges:?}");
                    assert_eq!(got, want, "np {np} nl {nl} bands {edges:?}");
                    // The test means something: most voxels counted, and the
                    // orientation moves some of them.
                    assert!(in_range > 300, "{in_range}");
                    if np > 1 {
                        assert_ne!(got[0], got[1], "np {np} nl {nl}");
                    }
                }
            }
        }
    }
}
