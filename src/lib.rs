//! # placecat
//!
//! Unsupervised place categorisation of 3D lidar scans (Magnusson et al.,
//! IROS 2017). The pipeline, one module a stage:
//!
//! ```text
//! io (PLY, PCD, KITTI .bin, LAS/LAZ, E57) -> descriptor (NDT grid, shapes, alignment, histogram)
//!   -> distance (prepared matrices, the metric kernel, Delta matrix, Space)
//!   -> cluster (k-means, k-medoids, hierarchical k-means++, DBSCAN)
//!   -> eval (confusion, ARI), model (named categories)
//! ```
//!
//! Each stage imports only from the stages before it; `rng` (the one RNG)
//! and `error` serve all of them, and `sim` (a lidar simulator for data
//! with ground truth) stands beside. [`Collection`] holds a set of
//! described scans and runs the stages on it: the CLI and the JS API
//! (`wasm`, delegates only) both call it. The core knows nothing of the
//! browser.
//!
//! ## Example
//!
//! From files on disk to named categories and a model that classifies new
//! scans (the same code is in the README, which a test keeps in step):
//!
//! ```rust
//! use placecat::cluster::{hkmeans::HkMeansParams, HierarchicalKMeans, Space};
//! use placecat::io::{read_path, write, ReadLimits};
//! use placecat::model::LabelledModel;
//! use placecat::sim::{SceneKind, SimParams, Simulation};
//! use placecat::{describe, DescriptorParams, DistanceOptions};
//!
//! fn main() -> placecat::Result<()> {
//!     // Scans on disk with ground truth: 4 simulated scans of each indoor kind,
//!     // written as binary PLY (your own PLY / PCD / KITTI .bin files read the same).
//!     let dir = std::env::temp_dir().join(format!("placecat-doc-{}", std::process::id()));
//!     std::fs::create_dir_all(&dir)?;
//!     let mut sim = SimParams::new(SceneKind::Indoor, 1);
//!     sim.scans = 4;
//!     let sim = Simulation::new(&sim)?;
//!     let mut files = Vec::new();
//!     let mut truth = Vec::new();
//!     for i in 0..sim.len() {
//!         let scan = sim.scan(i);
//!         let path = dir.join(&scan.name);
//!         std::fs::write(
//!             &path,
//!             write::ply(&scan.points, write::PlyEncoding::BinaryLittleEndian, false),
//!         )?;
//!         files.push(path);
//!         truth.push(scan.label);
//!     }
//!
//!     // Read and describe each scan (the paper's indoor parameters).
//!     let params = DescriptorParams::indoor();
//!     let mut descriptors = Vec::new();
//!     for f in &files {
//!         let cloud = read_path(f, &ReadLimits::default())?; // errors name the file
//!         descriptors.push(describe(&cloud.points, &params)?);
//!     }
//!
//!     // Delta between every pair, then hierarchical k-means++: one tree, cut anywhere.
//!     let space = Space::new(&descriptors, DistanceOptions::from(&params))?;
//!     let tree = HierarchicalKMeans::fit(&space, &space.matrix(), &HkMeansParams::new(0))?;
//!     let cut = tree.cut_k(5)?; // or tree.cut(threshold)
//!     let ev = placecat::eval::evaluate(&truth, &cut.labels)?;
//!     println!("accuracy {:.3}, ARI {:.3}", ev.accuracy, ev.ari);
//!
//!     // Name the categories (here after the ground truth), save the model, and
//!     // classify a scan with it.
//!     let names: Vec<(i32, String)> = ev
//!         .confusion
//!         .cluster_class
//!         .iter()
//!         .filter_map(|(label, class)| Some((*label, class.clone()?)))
//!         .collect();
//!     let model = LabelledModel::build(&params, &descriptors, &cut.labels, &names)?;
//!     std::fs::write(dir.join("model.json"), model.to_json()?)?;
//!     let model = LabelledModel::from_json(&std::fs::read_to_string(dir.join("model.json"))?)?;
//!     let answer = model.classify(&descriptors[0])?;
//!     println!(
//!         "{}: {} (Delta {:.3})",
//!         files[0].display(),
//!         answer.name,
//!         answer.distance
//!     );
//!     assert_eq!(answer.name, truth[0]);
//!     std::fs::remove_dir_all(&dir)?;
//!     Ok(())
//! }
//! ```

#![warn(missing_docs)]

pub mod cloud;
pub mod cluster;
pub mod collection;
pub mod descriptor;
pub mod distance;
pub mod error;
pub mod eval;
pub mod io;
pub mod model;
pub mod rng;
pub mod sim;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use cloud::{Format, PointCloud};
pub use collection::Collection;
pub use descriptor::{describe, Descriptor, DescriptorParams};
pub use distance::{delta, delta_matrix, DistanceMatrix, DistanceOptions};
pub use error::{Error, Result};
