//! DBSCAN on the Delta matrix (paper Sec. IV-C).
//!
//! Boundary conventions (as scikit-learn): a scan is a neighbour of another
//! when Delta <= epsilon (exactly epsilon counts), and a scan is a core scan
//! when its neighbourhood, *counting the scan itself*, holds at least
//! `min_points` scans. Noise gets label -1.

mod algorithm;
mod hyperparams;

pub use algorithm::Dbscan;
pub use hyperparams::{DbscanParams, DbscanValidParams};
