//! The NDT histogram: per candidate orientation, a matrix F whose rows are
//! shape classes (times height bands) and whose columns are range intervals,
//! holding raw voxel counts (paper Sec. III-C).

use super::alignment::{rotate, Rotation};
use super::directions;
use super::params::DescriptorParams;
use super::shape::{Shape, ShapedCell};

/// What does not depend on the orientation: the columns and band of a voxel.
struct Placement {
    cols: Vec<u16>,
    band: usize,
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

    let placements: Vec<Placement> = cells
        .iter()
        .map(|c| {
            let r = (c.mean[0] * c.mean[0] + c.mean[1] * c.mean[1] + c.mean[2] * c.mean[2]).sqrt();
            // Intervals overlap: a voxel counts in every one that holds it.
            let cols = params
                .ranges
                .iter()
                .enumerate()
                .filter(|(_, (lo, hi))| r >= *lo && hi.is_none_or(|h| r < h))
                .map(|(i, _)| i as u16)
                .collect();
            // Height bands use the sensor frame's z (the sensor is assumed
            // upright, as the bands are meant for ground robots).
            let band = params
                .height_bands
                .partition_point(|&edge| edge <= c.mean[2]);
            Placement { cols, band }
        })
        .collect();

    let in_range = placements.iter().filter(|p| !p.cols.is_empty()).count();
    let matrices = rotations
        .iter()
        .map(|rot| {
            let mut f = vec![0u32; params.rows() * cols];
            for (c, p) in cells.iter().zip(&placements) {
                if p.cols.is_empty() {
                    continue;
                }
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
                let row = p.band * classes + class;
                for &col in &p.cols {
                    f[row * cols + col as usize] += 1;
                }
            }
            f
        })
        .collect();
    (matrices, in_range)
}
