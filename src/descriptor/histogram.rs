//! The NDT histogram: per candidate orientation, a matrix F whose rows are
//! shape classes (times height bands) and whose columns are range intervals,
//! holding raw voxel counts (paper Sec. III-C).

use super::alignment::{rotate, Rotation};
use super::directions;
use super::params::DescriptorParams;
use super::shape::{Shape, ShapedCell};

/// What does not depend on the orientation, for the voxels in at least one
/// range interval: the voxel, its row offset (band x classes) and its
/// columns, as a slice of one shared list (no allocation per voxel).
struct Placed<'a> {
    cell: &'a ShapedCell,
    band_row: usize,
    cols: std::ops::Range<usize>,
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
    let cols = params.cols();
    let planar_dirs = directions::hemisphere(np);
    let linear_dirs = directions::hemisphere(nl);

    let mut col_list: Vec<u16> = Vec::with_capacity(cells.len() * 2);
    let mut placed: Vec<Placed> = Vec::with_capacity(cells.len());
    for c in cells {
        let r = (c.mean[0] * c.mean[0] + c.mean[1] * c.mean[1] + c.mean[2] * c.mean[2]).sqrt();
        // Intervals overlap: a voxel counts in every one that holds it.
        let first = col_list.len();
        for (i, (lo, hi)) in params.ranges.iter().enumerate() {
            if r >= *lo && hi.is_none_or(|h| r < h) {
                col_list.push(i as u16);
            }
        }
        if col_list.len() == first {
            continue;
        }
        // Height bands use the sensor frame's z (the sensor is assumed
        // upright, as the bands are meant for ground robots).
        let band = params
            .height_bands
            .partition_point(|&edge| edge <= c.mean[2]);
        placed.push(Placed {
            cell: c,
            band_row: band * classes,
            cols: first..col_list.len(),
        });
    }

    let matrices = rotations
        .iter()
        .map(|rot| {
            let mut f = vec![0u32; params.rows() * cols];
            for p in &placed {
                let c = p.cell;
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
                let row = p.band_row + class;
                for &col in &col_list[p.cols.clone()] {
                    f[row * cols + col as usize] += 1;
                }
            }
            f
        })
        .collect();
    (matrices, placed.len())
}
