//! Evaluation against ground truth (paper Sec. V): confusion matrix with
//! clusters mapped to classes, accuracy, adjusted Rand index, the DBSCAN
//! score S = AR * inliers / all, and a DBSCAN parameter sweep.

mod ari;
mod confusion;
mod sweep;

pub use ari::adjusted_rand_index;
pub use confusion::{confusion, Confusion, Mapping};
pub use sweep::{
    best_score, dbscan_sweep, epsilon_grid, SweepPoint, GRID_QUANTILES, SWEEP_MIN_POINTS,
};

use serde::{Deserialize, Serialize};

/// Everything `placecat evaluate` prints.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Evaluation {
    /// Share of all scans put in a cluster mapped to their class (0..1).
    pub accuracy: f64,
    /// ARI over the inliers (all scans when there is no noise).
    pub ari: f64,
    /// S = ari * inliers / all (= ari without noise).
    pub score: f64,
    /// Scans not labelled noise.
    pub inliers: usize,
    /// All scans.
    pub total: usize,
    /// The confusion matrix behind `accuracy`.
    pub confusion: Confusion,
}

/// Evaluate labels (-1 = noise) against ground-truth class names.
pub fn evaluate(truth: &[String], labels: &[i32]) -> crate::Result<Evaluation> {
    if truth.len() != labels.len() {
        return Err(crate::Error::Mismatch(format!(
            "{} ground-truth labels for {} scans",
            truth.len(),
            labels.len()
        )));
    }
    let inl: Vec<usize> = (0..labels.len()).filter(|&i| labels[i] >= 0).collect();
    let t: Vec<&str> = inl.iter().map(|&i| truth[i].as_str()).collect();
    let l: Vec<i32> = inl.iter().map(|&i| labels[i]).collect();
    let ari = adjusted_rand_index(&t, &l);
    let score = if labels.is_empty() {
        0.0
    } else {
        ari * inl.len() as f64 / labels.len() as f64
    };
    let confusion = confusion(truth, labels);
    Ok(Evaluation {
        accuracy: confusion.accuracy,
        ari,
        score,
        inliers: inl.len(),
        total: labels.len(),
        confusion,
    })
}
