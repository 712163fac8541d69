//! The NDT histogram: per candidate orientation, a matrix F whose rows are
//! shape classes (times height bands) and whose columns are range intervals,
//! holding raw voxel counts (paper Sec. III-C).
//!
//! Only a voxel whose class depends on the orientation (a planar or linear
//! one when its shape has more than one direction class) is looked at once
//! per orientation; the others are counted once, into the counts every
//! orientation starts from. The simulated outdoor scans of the page's
//! benchmark have 12 candidate orientations, and looking at every voxel for
//! each made this stage 65 instructions per point there, against 8.6 on a
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
    let mut placed = 0;
    for c in cells {
        let r = (c.mean[0] * c.mean[0] + c.mean[1] * c.mean[1] + c.mean[2] * c.mean[2]).sqrt();
        let segment = segments.of(r);
        // Intervals overlap: a voxel counts in every one that holds it.
        if segments.columns[segment].is_empty() {
            continue;
        }
        placed += 1;
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
                    for &col in columns {
                        f[row * cols + col] += n;
                    }
                }
            }
            f
        })
        .collect();
    (matrices, placed)
}

/// Add the turning voxels' counts for one orientation.
fn count_turning(
    counts: &mut [u32],
    turning: &[Turning],
    dirs: &[[f64; 3]],
    rot: &Rotation,
    nseg: usize,
) {
    // Every preset has 9 planar directions.
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
