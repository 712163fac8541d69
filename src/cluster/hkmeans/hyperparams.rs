use crate::cluster::lloyd::{check_iterations, check_runs, one_run};
use crate::cluster::{setters, validated, ParamGuard};
use crate::error::Result;
use serde::{Deserialize, Serialize};

/// Parameters of hierarchical k-means++ as given; [`ParamGuard::check`]
/// turns them into the [`HkMeansValidParams`] that
/// [`HierarchicalKMeans::fit`](super::HierarchicalKMeans::fit) requires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HkMeansParams {
    /// Seed of the RNG of every 2-means++ split.
    pub seed: u64,
    /// Iteration cap of each 2-means split (at least 1).
    pub max_iterations: usize,
    /// Trial 2-means++ runs at every split, the one of lowest cost kept
    /// (the sum over the node's scans of Delta to their centre, as
    /// [`KMeansResult::cost`](crate::cluster::KMeansResult::cost)): the
    /// bisecting k-means of Steinbach, Karypis and Kumar (2000), which
    /// tries several splits of a cluster (ITER in the paper) and keeps the best. 1 (the default,
    /// and what parameters written without this field read as) is the
    /// paper's single run, the same tree as before the field existed; at
    /// most [`MAX_RESTARTS`](crate::cluster::MAX_RESTARTS). The trials draw
    /// one after another from the tree's one RNG.
    #[serde(default = "one_run")]
    pub restarts: usize,
}

/// Hierarchical k-means++ parameters that passed [`ParamGuard::check`]; a
/// deserialised one is checked too. Read its fields through `Deref`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "HkMeansParams", into = "HkMeansParams")]
pub struct HkMeansValidParams(HkMeansParams);

validated!(HkMeansValidParams, HkMeansParams);

impl Default for HkMeansParams {
    fn default() -> Self {
        HkMeansParams {
            seed: 0,
            max_iterations: 100,
            restarts: one_run(),
        }
    }
}

impl HkMeansParams {
    /// Seed `seed`, at most 100 iterations per split, one run per split.
    pub fn new(seed: u64) -> Self {
        HkMeansParams {
            seed,
            ..Self::default()
        }
    }
}

impl ParamGuard for HkMeansParams {
    type Checked = HkMeansValidParams;
    fn check(&self) -> Result<HkMeansValidParams> {
        check_iterations(self.max_iterations)?;
        check_runs(self.restarts, "2-means runs per split")?;
        Ok(HkMeansValidParams(self.clone()))
    }
}

setters!(HkMeansParams {
    /// Set the iteration cap of each split.
    max_iterations: usize,
    /// Set the trial runs per split (the cheapest is kept).
    restarts: usize,
});
