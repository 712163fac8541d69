use super::hyperparams::KMeansValidParams;
use crate::cluster::lloyd::fit_subset;
use crate::cluster::ParamGuard;
use crate::distance::Space;
use crate::error::Result;
use crate::rng::rng;
use serde::{Deserialize, Serialize};

/// The outcome of k-means.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct KMeansResult {
    /// Category of each scan, 0..k.
    pub labels: Vec<i32>,
    /// Scans the centres started at.
    pub seeds: Vec<usize>,
    /// Assign/update rounds run.
    pub iterations: usize,
    /// True if no label changed in the last round (false: stopped at the cap).
    pub converged: bool,
    /// Sum over scans of Delta to their centre.
    pub cost: f64,
}

/// k-means over a [`Space`].
pub struct KMeans;

impl KMeans {
    /// Cluster the space's items; `params` is checked first (a
    /// [`KMeansParams`](super::KMeansParams) or its validated form).
    pub fn fit(
        space: &Space,
        params: &impl ParamGuard<Checked = KMeansValidParams>,
    ) -> Result<KMeansResult> {
        let params = params.check()?;
        let all: Vec<usize> = (0..space.len()).collect();
        crate::cluster::lloyd::check_k(params.k, all.len())?;
        let mut r = rng(params.seed);
        let (labels, seeds, iterations, converged, cost) = fit_subset(
            space,
            &all,
            params.k,
            params.seeding,
            params.max_iterations,
            &mut r,
        );
        Ok(KMeansResult {
            labels: labels.into_iter().map(|l| l as i32).collect(),
            seeds: seeds.iter().map(|&s| all[s]).collect(),
            iterations,
            converged,
            cost,
        })
    }
}
