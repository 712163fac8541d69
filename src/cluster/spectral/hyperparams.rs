use crate::cluster::lloyd::{check_iterations, check_k_positive, check_runs};
use crate::cluster::{setters, validated, ParamGuard};
use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// Spectral clustering parameters as given; [`ParamGuard::check`] turns
/// them into the [`SpectralValidParams`] that
/// [`Spectral::fit`](super::Spectral::fit) requires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpectralParams {
    /// Number of categories (at least 1, at most the number of scans).
    pub k: usize,
    /// Which nearest neighbour sets a scan's local scale (at least 1;
    /// 7, Zelnik-Manor and Perona's choice).
    pub neighbours: usize,
    /// Seed of the k-means++ seeding of the embedded scans.
    pub seed: u64,
    /// Runs of k-means on the embedded scans, the cheapest kept (at least
    /// 1, at most [`MAX_RESTARTS`](crate::cluster::MAX_RESTARTS); 10).
    pub restarts: usize,
    /// Iteration cap of each k-means run (at least 1).
    pub max_iterations: usize,
}

/// Spectral clustering parameters that passed [`ParamGuard::check`]; a
/// deserialised one is checked too. Read its fields through `Deref`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "SpectralParams", into = "SpectralParams")]
pub struct SpectralValidParams(SpectralParams);

validated!(SpectralValidParams, SpectralParams);

impl SpectralParams {
    /// k categories, the 7th neighbour's scale, seed 0, 10 runs of
    /// k-means of at most 100 iterations each.
    pub fn new(k: usize) -> Self {
        SpectralParams {
            k,
            neighbours: 7,
            seed: 0,
            restarts: 10,
            max_iterations: 100,
        }
    }
}

impl ParamGuard for SpectralParams {
    type Checked = SpectralValidParams;
    fn check(&self) -> Result<SpectralValidParams> {
        check_k_positive(self.k)?;
        if self.neighbours == 0 {
            return invalid(
                "neighbours must be at least 1 (the neighbour that sets a scan's scale), got 0",
            );
        }
        check_runs(self.restarts, "runs of k-means on the embedded scans")?;
        check_iterations(self.max_iterations)?;
        Ok(SpectralValidParams(self.clone()))
    }
}

setters!(SpectralParams {
    /// Set which nearest neighbour sets a scan's scale.
    neighbours: usize,
    /// Set the RNG seed.
    seed: u64,
    /// Set the number of k-means runs (the cheapest is kept).
    restarts: usize,
    /// Set the iteration cap of each k-means run.
    max_iterations: usize,
});
