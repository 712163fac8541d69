use crate::cluster::{validated, ParamGuard};
use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// DBSCAN parameters as given; [`ParamGuard::check`] turns them into the
/// [`DbscanValidParams`] that [`Dbscan::fit`](super::Dbscan::fit) requires.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DbscanParams {
    /// Neighbourhood radius: Delta <= epsilon are neighbours (finite, >= 0).
    pub epsilon: f32,
    /// Minimum neighbourhood size of a core scan, the scan itself included.
    pub min_points: usize,
}

/// DBSCAN parameters that passed [`ParamGuard::check`]; a deserialised one
/// is checked too. Read its fields through `Deref`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "DbscanParams", into = "DbscanParams")]
pub struct DbscanValidParams(DbscanParams);

validated!(DbscanValidParams, DbscanParams);

impl DbscanParams {
    /// Parameters of one DBSCAN run.
    pub fn new(epsilon: f32, min_points: usize) -> Self {
        DbscanParams {
            epsilon,
            min_points,
        }
    }
}

impl ParamGuard for DbscanParams {
    type Checked = DbscanValidParams;
    fn check(&self) -> Result<DbscanValidParams> {
        if !self.epsilon.is_finite() || self.epsilon < 0.0 {
            return invalid(format!(
                "epsilon must be a finite number >= 0, got {}",
                self.epsilon
            ));
        }
        if self.min_points == 0 {
            return invalid("min_points must be at least 1");
        }
        Ok(DbscanValidParams(*self))
    }
}
