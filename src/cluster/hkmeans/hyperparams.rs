use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// Parameters of hierarchical k-means++.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HkMeansParams {
    pub seed: u64,
    /// Iteration cap of each 2-means split.
    pub max_iterations: usize,
}

impl Default for HkMeansParams {
    fn default() -> Self {
        HkMeansParams {
            seed: 0,
            max_iterations: 100,
        }
    }
}

impl HkMeansParams {
    pub fn new(seed: u64) -> Self {
        HkMeansParams {
            seed,
            ..Self::default()
        }
    }
    pub fn check(&self, n: usize) -> Result<()> {
        if n == 0 {
            return invalid("no scans to cluster");
        }
        if self.max_iterations == 0 {
            return invalid("max_iterations must be at least 1");
        }
        Ok(())
    }
}
