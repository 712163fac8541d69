//! k-means with Delta (paper Sec. IV-A) and its seedings: the paper's
//! three and spectral (issue 18).

mod algorithm;
mod hyperparams;

pub use crate::cluster::lloyd::{Seeding, MAX_RESTARTS};
pub(crate) use algorithm::check_seeding_size;
pub use algorithm::{KMeans, KMeansResult};
pub use hyperparams::{KMeansParams, KMeansValidParams};
