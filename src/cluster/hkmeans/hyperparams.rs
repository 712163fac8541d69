use crate::cluster::lloyd::check_iterations;
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
        }
    }
}

impl HkMeansParams {
    /// Seed `seed`, at most 100 iterations per split.
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
        Ok(HkMeansValidParams(self.clone()))
    }
}

setters!(HkMeansParams {
    /// Set the iteration cap of each split.
    max_iterations: usize,
});
