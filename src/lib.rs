//! # placecat
//!
//! Unsupervised place categorisation of 3D lidar scans (Magnusson et al.,
//! IROS 2017). The pipeline, one module a stage:
//!
//! ```text
//! io (PLY, PCD, KITTI .bin) -> descriptor (NDT grid, shapes, alignment, histogram)
//!   -> distance (Delta) -> cluster (k-means, hierarchical k-means++, DBSCAN)
//!   -> eval (confusion, ARI) ; sim (a lidar simulator for data with ground truth)
//! ```
//!
//! The core knows nothing of the browser; `wasm` holds the JS boundary.

pub mod cloud;
pub mod cluster;
pub mod descriptor;
pub mod distance;
pub mod error;
pub mod eval;
pub mod io;
pub mod model;
pub mod sim;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use cloud::{Format, PointCloud};
pub use descriptor::{describe, Descriptor, DescriptorParams};
pub use distance::{delta, delta_matrix, DistanceMatrix, DistanceOptions};
pub use error::{Error, Result};
