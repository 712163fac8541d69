//! Clustering descriptors into categories (paper Sec. IV). One folder per
//! algorithm (`hyperparams` with the parameters and their validated form,
//! `algorithm`); what they share (seeding, Lloyd's iteration, the check of
//! k) is in `lloyd`.
//!
//! Labels are `i32`: 0, 1, ... for categories, -1 for DBSCAN noise.

pub mod choose_k;
pub mod dbscan;
pub mod hkmeans;
pub mod kmeans;
pub mod kmedoids;
mod lloyd;
mod medoid;
pub mod spectral;

/// The space clustering works in lives with the distance it measures
/// (`crate::distance`); re-exported here, where most callers look for it.
pub use crate::distance::{Centre, Space};
pub use dbscan::{Dbscan, DbscanParams};
pub use hkmeans::{HierarchicalKMeans, Tree, TreeNode};
pub use kmeans::{KMeans, KMeansParams, KMeansResult, Seeding, MAX_RESTARTS};
pub use kmedoids::{KMedoids, KMedoidsParams, KMedoidsResult};
pub use medoid::{medoids, medoids_by};
pub use spectral::{Spectral, SpectralParams, SpectralResult};

/// Parameters checked once into the validated form an algorithm requires,
/// in the manner of linfa's `ParamGuard`: `params.check()?` gives the
/// validated parameters, and every `fit` takes either (a validated form
/// checks as itself), so no algorithm runs on unchecked values. Checks
/// that need the data (k against the number of scans) stay in `fit`.
pub trait ParamGuard {
    /// The validated form.
    type Checked;
    /// Check every field, returning the validated form or an
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming the field.
    fn check(&self) -> crate::Result<Self::Checked>;
}

/// `ParamGuard` for a validated type (it checks as itself) and serde
/// deserialisation through validation, for `$valid` wrapping `$params`.
macro_rules! validated {
    ($valid:ident, $params:ident) => {
        impl $crate::cluster::ParamGuard for $valid {
            type Checked = $valid;
            fn check(&self) -> $crate::Result<$valid> {
                Ok(self.clone())
            }
        }
        impl TryFrom<$params> for $valid {
            type Error = $crate::Error;
            fn try_from(p: $params) -> $crate::Result<$valid> {
                $crate::cluster::ParamGuard::check(&p)
            }
        }
        impl From<$valid> for $params {
            fn from(v: $valid) -> $params {
                v.0
            }
        }
        impl std::ops::Deref for $valid {
            type Target = $params;
            fn deref(&self) -> &$params {
                &self.0
            }
        }
    };
}
pub(crate) use validated;

/// Builder setters, one per `field: Type` with its doc line.
macro_rules! setters {
    ($params:ident { $($(#[$doc:meta])* $field:ident: $ty:ty),* $(,)? }) => {
        impl $params {
            $(
                $(#[$doc])*
                pub fn $field(mut self, v: $ty) -> Self {
                    self.$field = v;
                    self
                }
            )*
        }
    };
}
pub(crate) use setters;
