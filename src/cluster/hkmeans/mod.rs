//! Hierarchical k-means++ (paper Sec. IV-B): split with 2-means++
//! recursively down to single scans; a node's height is its diameter.

mod algorithm;
mod hyperparams;
mod tree;

pub use algorithm::{HierarchicalKMeans, EXACT_DIAMETER_LIMIT};
pub use hyperparams::{HkMeansParams, HkMeansValidParams};
pub use tree::{Cut, Tree, TreeNode};
