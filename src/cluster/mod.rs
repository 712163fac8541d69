//! Clustering descriptors into categories (paper Sec. IV). One folder per
//! algorithm (`hyperparams` with a validated builder, `algorithm`).
//!
//! Labels are `i32`: 0, 1, ... for categories, -1 for DBSCAN noise.

pub mod choose_k;
pub mod dbscan;
pub mod hkmeans;
pub mod kmeans;
pub mod kmedoids;
mod medoid;
mod space;

pub use dbscan::{Dbscan, DbscanParams};
pub use hkmeans::{HierarchicalKMeans, Tree, TreeNode};
pub use kmeans::{KMeans, KMeansParams, Seeding};
pub use kmedoids::KMedoids;
pub use medoid::medoids;
pub use space::{Centre, Space};

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The one RNG of placecat: ChaCha8 is specified bit for bit, so the same
/// seed gives the same labels natively and in wasm.
pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// Renumber labels 0.. in order of first appearance (noise stays -1), so
/// that equal partitions print equal.
pub fn canonical_labels(labels: &[i32]) -> Vec<i32> {
    let mut map = std::collections::HashMap::new();
    labels
        .iter()
        .map(|&l| {
            if l < 0 {
                -1
            } else {
                let next = map.len() as i32;
                *map.entry(l).or_insert(next)
            }
        })
        .collect()
}
