use crate::cluster::lloyd::{check_iterations, check_k_positive, check_runs, one_run, Seeding};
use crate::cluster::{setters, validated, ParamGuard};
use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// k-means parameters as given; [`ParamGuard::check`] turns them into the
/// [`KMeansValidParams`] that [`KMeans::fit`](super::KMeans::fit) requires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KMeansParams {
    /// Number of categories (at least 1, at most the number of scans).
    pub k: usize,
    /// How the k initial centres are chosen.
    pub seeding: Seeding,
    /// Seed of the RNG (random and k-means++ seedings; spectral seeding's
    /// spectral clustering).
    pub seed: u64,
    /// Iteration cap (at least 1).
    pub max_iterations: usize,
    /// Runs of k-means, each from its own seeding, keeping the one of
    /// lowest cost. As scikit-learn's `n_init`, except for the cost
    /// compared: the sum of (unsquared) Delta to the centres, the paper's
    /// metric, not the squared-distance inertia (Arthur and Vassilvitskii
    /// 2007 recommend restarting k-means++). At least 1, at most
    /// [`MAX_RESTARTS`](crate::cluster::MAX_RESTARTS); 1 (the default, and
    /// what parameters written without this field read as) is the paper's
    /// single run. Run r draws from stream r of the RNG seeded with `seed`
    /// ([`crate::rng::rng_stream`]), so run 0 is the single run. More than
    /// 1 only with a random seeding: stride seeding would run the same
    /// clustering every time, and spectral seeding keeps the cheapest of
    /// its own runs.
    #[serde(default = "one_run")]
    pub restarts: usize,
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
        check_restarts(self.restarts, self.seeding)?;
        Ok(KMeansValidParams(self.clone()))
    }
}

impl KMeansParams {
    /// k categories, k-means++ seeding, seed 0, at most 100 iterations,
    /// one run.
    pub fn new(k: usize) -> Self {
        KMeansParams {
            k,
            seeding: Seeding::PlusPlus,
            seed: 0,
            max_iterations: 100,
            restarts: one_run(),
        }
    }
}

/// Reject 0 runs, more than [`MAX_RESTARTS`](crate::cluster::MAX_RESTARTS), and restarts of a seeding that draws nothing (every run
/// would be the first again).
fn check_restarts(restarts: usize, seeding: Seeding) -> Result<()> {
    check_runs(restarts, "runs of k-means")?;
    if restarts > 1 && seeding == Seeding::Stride {
        return invalid(format!(
            "restarts = {restarts} with stride (deterministic) seeding: every run would start \
             from the same centres and give the same clustering; use plusplus or random \
             seeding, or restarts = 1"
        ));
    }
    if restarts > 1 && seeding == Seeding::Spectral {
        return invalid(format!(
            "restarts = {restarts} with spectral seeding: it starts from spectral clustering's \
             groups, which keeps the cheapest of its own 10 runs; use restarts = 1"
        ));
    }
    Ok(())
}

setters!(KMeansParams {
    /// Set the seeding.
    seeding: Seeding,
    /// Set the RNG seed.
    seed: u64,
    /// Set the iteration cap.
    max_iterations: usize,
    /// Set the number of runs (the cheapest is kept).
    restarts: usize,
});
