use crate::cluster::lloyd::{check_iterations, check_k_positive, Seeding};
use crate::cluster::{setters, validated, ParamGuard};
use crate::error::Result;
use serde::{Deserialize, Serialize};

/// k-means parameters as given; [`ParamGuard::check`] turns them into the
/// [`KMeansValidParams`] that [`KMeans::fit`](super::KMeans::fit) requires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KMeansParams {
    /// Number of categories (at least 1, at most the number of scans).
    pub k: usize,
    /// How the k initial centres are chosen.
    pub seeding: Seeding,
    /// Seed of the RNG (random and k-means++ seedings).
    pub seed: u64,
    /// Iteration cap (at least 1).
    pub max_iterations: usize,
}

/// k-means parameters that passed [`ParamGuard::check`]; a deserialised one
/// is checked too. Read its fields through `Deref`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "KMeansParams", into = "KMeansParams")]
pub struct KMeansValidParams(KMeansParams);

validated!(KMeansValidParams, KMeansParams);

impl ParamGuard for KMeansParams {
    type Checked = KMeansValidParams;
    fn check(&self) -> Result<KMeansValidParams> {
        check_k_positive(self.k)?;
        check_iterations(self.max_iterations)?;
        Ok(KMeansValidParams(self.clone()))
    }
}

impl KMeansParams {
    /// k categories, k-means++ seeding, seed 0, at most 100 iterations.
    pub fn new(k: usize) -> Self {
        KMeansParams {
            k,
            seeding: Seeding::PlusPlus,
            seed: 0,
            max_iterations: 100,
        }
    }
}

setters!(KMeansParams {
    /// Set the seeding.
    seeding: Seeding,
    /// Set the RNG seed.
    seed: u64,
    /// Set the iteration cap.
    max_iterations: usize,
});
