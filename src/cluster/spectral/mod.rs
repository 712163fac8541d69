//! Spectral clustering on the Delta matrix (issue 18, eighteenth round):
//! Ng, Jordan and Weiss, "On spectral clustering: analysis and an
//! algorithm" (NIPS 2001), with the local scale of Zelnik-Manor and
//! Perona, "Self-tuning spectral clustering" (NIPS 2004).
//!
//! Why beside k-means: k-means groups scans round centres, so a kind whose
//! scans lie along a stretch (a room seen from its door and from its
//! window) is cut in two while two nearby kinds merge. Spectral clustering
//! groups scans through their neighbours: scans of a kind that are each
//! near some other scan of it end up together. On issue 18's room
//! families the best presets find a scan of the same kind as a scan's
//! nearest neighbour (from another room) 5 to 15 points more often than
//! k-means groups it right (docs/spectral.md).
//!
//! Steps: the affinity of scans i and j is exp(-D² / (s_i s_j)), s_i the
//! distance of scan i to its `neighbours`-th nearest other scan (7, the
//! paper's choice); its rows and columns are divided by the square roots
//! of their sums; the k leading eigenvectors of that matrix, each scan's
//! row of them scaled to unit length, are points that k-means (Euclidean,
//! k-means++ seeding, the cheapest of `restarts` runs) groups.
//!
//! The eigen-decomposition is dense, O(n³) in time and n² in memory, so
//! it is limited to [`MAX_SCANS`] scans.

mod algorithm;
mod hyperparams;

pub(crate) use algorithm::check_size;
pub use algorithm::{Spectral, SpectralResult, MAX_SCANS};
pub use hyperparams::{SpectralParams, SpectralValidParams};
