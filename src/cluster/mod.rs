//! Clustering descriptors into categories (paper Sec. IV). One folder per
//! algorithm (`hyperparams` with the parameters and their validated form,
//! `algorithm`); what they share (seeding, Lloyd's iteration, the check of
//! k) is in `lloyd`.
//!
//! Labels are `i32`: 0, 1, ... for categories, -1 for DBSCAN noise.

pub mod dbscan;
pub mod hkmeans;
pub mod kmeans;
pub mod kmedoids;
mod lloyd;
mod medoid;

/// The space clustering works in lives with the distance it measures
/// (`crate::distance`); re-exported here, where most callers look for it.
pub use crate::distance::{Centre, Space};
pub use dbscan::{Dbscan, DbscanParams};
pub use hkmeans::{HierarchicalKMeans, Tree, TreeNode};
pub use kmeans::{KMeans, KMeansParams, Seeding};
pub use kmedoids::KMedoids;
pub use medoid::medoids;
