//! DBSCAN parameter sweep (paper Fig. 3): a grid of epsilon x c giving the
//! inlier ratio, AR and S.

use crate::cluster::{Dbscan, DbscanParams};
use crate::distance::DistanceMatrix;
use crate::error::Result;
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepPoint {
    pub epsilon: f32,
    pub min_points: usize,
    pub clusters: usize,
    pub inlier_ratio: f64,
    pub ari: f64,
    pub score: f64,
}

pub fn dbscan_sweep(
    matrix: &DistanceMatrix,
    truth: &[String],
    epsilons: &[f32],
    min_points: &[usize],
) -> Result<Vec<SweepPoint>> {
    let mut out = Vec::new();
    for &e in epsilons {
        for &c in min_points {
            let labels = Dbscan::fit(matrix, &DbscanParams::new(e, c))?;
            let ev = super::evaluate(truth, &labels)?;
            out.push(SweepPoint {
                epsilon: e,
                min_points: c,
                clusters: labels
                    .iter()
                    .copied()
                    .max()
                    .map_or(0, |m| (m + 1).max(0) as usize),
                inlier_ratio: ev.inliers as f64 / ev.total.max(1) as f64,
                ari: ev.ari,
                score: ev.score,
            });
        }
    }
    Ok(out)
}
