//! k-means with Delta (paper Sec. IV-A) and three seedings.

mod algorithm;
mod hyperparams;

pub use crate::cluster::lloyd::{Seeding, MAX_RESTARTS};
pub use algorithm::{KMeans, KMeansResult};
pub use hyperparams::{KMeansParams, KMeansValidParams};
