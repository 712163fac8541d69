use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// Validated DBSCAN parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DbscanParams {
    pub epsilon: f32,
    /// Minimum neighbourhood size of a core scan, the scan itself included.
    pub min_points: usize,
}

impl DbscanParams {
    pub fn new(epsilon: f32, min_points: usize) -> Self {
        DbscanParams {
            epsilon,
            min_points,
        }
    }
    pub fn check(&self) -> Result<()> {
        if !self.epsilon.is_finite() || self.epsilon < 0.0 {
            return invalid(format!(
                "epsilon must be a finite number >= 0, got {}",
                self.epsilon
            ));
        }
        if self.min_points == 0 {
            return invalid("min_points must be at least 1");
        }
        Ok(())
    }
}
