//! k-medoids (alternating, "Voronoi iteration") on the precomputed Delta
//! matrix: centres are scans, so no mean of matrices is needed.

use crate::cluster::lloyd::{check_iterations, check_k, check_k_positive, seeds, Picking};
use crate::cluster::{setters, validated, ParamGuard};
use crate::distance::{DistanceMatrix, Space};
use crate::error::Result;
use crate::rng::rng;
use serde::{Deserialize, Serialize};

/// k-medoids parameters as given; [`ParamGuard::check`] turns them into the
/// [`KMedoidsValidParams`] that [`KMedoids::fit`] requires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KMedoidsParams {
    /// Number of categories (at least 1, at most the number of scans).
    pub k: usize,
    /// Seed of the k-means++ choice of the first medoids.
    pub seed: u64,
    /// Iteration cap (at least 1).
    pub max_iterations: usize,
}

/// k-medoids parameters that passed [`ParamGuard::check`]; a deserialised
/// one is checked too. Read its fields through `Deref`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "KMedoidsParams", into = "KMedoidsParams")]
pub struct KMedoidsValidParams(KMedoidsParams);

validated!(KMedoidsValidParams, KMedoidsParams);

impl KMedoidsParams {
    /// k categories, seed 0, at most 100 iterations.
    pub fn new(k: usize) -> Self {
        KMedoidsParams {
            k,
            seed: 0,
            max_iterations: 100,
        }
    }
}

impl ParamGuard for KMedoidsParams {
    type Checked = KMedoidsValidParams;
    fn check(&self) -> Result<KMedoidsValidParams> {
        check_k_positive(self.k)?;
        check_iterations(self.max_iterations)?;
        Ok(KMedoidsValidParams(self.clone()))
    }
}

setters!(KMedoidsParams {
    /// Set the RNG seed.
    seed: u64,
    /// Set the iteration cap.
    max_iterations: usize,
});

/// What k-medoids returns.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct KMedoidsResult {
    /// Category of each scan.
    pub labels: Vec<i32>,
    /// The scan at the centre of each category.
    pub medoids: Vec<usize>,
}

/// k-medoids on the Delta matrix of a [`Space`].
pub struct KMedoids;

impl KMedoids {
    /// Labels and the medoid of each cluster; `matrix` is the Delta matrix
    /// of the space's items, `params` is checked first.
    pub fn fit(
        space: &Space,
        matrix: &DistanceMatrix,
        params: &impl ParamGuard<Checked = KMedoidsValidParams>,
    ) -> Result<KMedoidsResult> {
        let params = params.check()?;
        let k = params.k;
        check_k(k, matrix.n)?;
        let n = matrix.n;
        let all: Vec<usize> = (0..n).collect();
        let mut medoids = seeds(space, &all, k, Picking::PlusPlus, &mut rng(params.seed));
        let mut labels = vec![0usize; n];
        for _ in 0..params.max_iterations {
            for (i, l) in labels.iter_mut().enumerate() {
                *l = (0..k)
                    .min_by(|&a, &b| {
                        matrix
                            .get(i, medoids[a])
                            .total_cmp(&matrix.get(i, medoids[b]))
                    })
                    .unwrap_or(0);
            }
            let mut changed = false;
            for (c, medoid) in medoids.iter_mut().enumerate() {
                let members: Vec<usize> = (0..n).filter(|&i| labels[i] == c).collect();
                let best = members
                    .iter()
                    .copied()
                    .min_by(|&a, &b| {
                        let ca: f32 = members.iter().map(|&m| matrix.get(a, m)).sum();
                        let cb: f32 = members.iter().map(|&m| matrix.get(b, m)).sum();
                        ca.total_cmp(&cb)
                    })
                    .unwrap_or(*medoid);
                if best != *medoid {
                    *medoid = best;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        Ok(KMedoidsResult {
            labels: labels.into_iter().map(|l| l as i32).collect(),
            medoids,
        })
    }
}
