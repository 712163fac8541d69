//! Shape classes of a voxel from the eigenvalues of its covariance
//! (paper Sec. III-A): linear, planar or spherical.

use super::ndt_grid::Cell;
use nalgebra::{Matrix3, SymmetricEigen};
use serde::{Deserialize, Serialize};

/// The three shape classes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Shape {
    /// No dominant direction: lambda1 >= te * lambda2 and lambda2 >= te * lambda3.
    Spherical,
    /// A surface patch: lambda1 < te * lambda2 (not linear).
    Planar,
    /// An edge, pole or wire: lambda2 < te * lambda3.
    Linear,
}

/// A classified voxel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapedCell {
    /// Mean of the voxel's points in the sensor frame (m).
    pub mean: [f64; 3],
    /// Its shape class.
    pub shape: Shape,
    /// lambda1 <= lambda2 <= lambda3, after regularisation.
    pub eigenvalues: [f64; 3],
    /// Normal e1 (smallest eigenvalue's eigenvector).
    pub normal: [f64; 3],
    /// Direction e3 (largest eigenvalue's eigenvector).
    pub axis: [f64; 3],
}

mod eigen;

/// Eigen-decompose and classify. None when the covariance is degenerate
/// (all points equal: no shape to speak of).
pub fn classify(cell: &Cell, eigen_threshold: f64) -> Option<ShapedCell> {
    let eig = eigen::closed_form(&cell.cov).unwrap_or_else(|| general(&cell.cov));
    let l3 = eig.values[2];
    if l3.is_nan() || l3 <= 0.0 || !l3.is_finite() {
        return None;
    }
    // Regularise as the NDT literature does: no eigenvalue below l3 / 1000.
    let floor = l3 / 1000.0;
    let l1 = eig.values[0].max(floor);
    let l2 = eig.values[1].max(floor);
    let te = eigen_threshold;
    let shape = if l2 < te * l3 {
        Shape::Linear
    } else if l1 < te * l2 {
        Shape::Planar
    } else {
        Shape::Spherical
    };
    Some(ShapedCell {
        mean: cell.mean,
        shape,
        eigenvalues: [l1, l2, l3],
        normal: eig.e1,
        axis: eig.e3,
    })
}

/// nalgebra's general solver, for the near-degenerate spectra the closed
/// form leaves alone (see [`eigen`]).
fn general(cov: &[[f64; 3]; 3]) -> eigen::Eigen {
    let eig = SymmetricEigen::new(Matrix3::from_fn(|i, j| cov[i][j]));
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let col = |k: usize| {
        let c = eig.eigenvectors.column(order[k]);
        [c[0], c[1], c[2]]
    };
    eigen::Eigen {
        values: order.map(|k| eig.eigenvalues[k]),
        e1: col(0),
        e3: col(2),
    }
}
