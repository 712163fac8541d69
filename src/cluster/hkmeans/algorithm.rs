use super::hyperparams::HkMeansParams;
use super::tree::{Tree, TreeNode};
use crate::cluster::kmeans::{algorithm::fit_subset, Seeding};
use crate::cluster::{rng, Space};
use crate::distance::DistanceMatrix;
use crate::error::Result;
use rand_chacha::ChaCha8Rng;

/// Builds the whole tree once; any threshold is then a cut of it.
pub struct HierarchicalKMeans;

impl HierarchicalKMeans {
    /// `matrix` is the Delta matrix of the same scans (for diameters).
    pub fn fit(space: &Space, matrix: &DistanceMatrix, params: &HkMeansParams) -> Result<Tree> {
        params.check(space.len())?;
        let mut nodes = Vec::with_capacity(2 * space.len());
        let mut r = rng(params.seed);
        let all: Vec<usize> = (0..space.len()).collect();
        // An explicit stack instead of recursion: a chain-like data set would
        // otherwise recurse n deep.
        build(space, matrix, params, all, &mut nodes, &mut r);
        Ok(Tree::new(nodes, space.len()))
    }
}

fn diameter(matrix: &DistanceMatrix, members: &[usize]) -> (f32, usize, usize) {
    let mut best = (0f32, members[0], members[0]);
    for (a, &i) in members.iter().enumerate() {
        for &j in &members[a + 1..] {
            let d = matrix.get(i, j);
            if d > best.0 {
                best = (d, i, j);
            }
        }
    }
    best
}

/// A node still to build: its members and (parent index, child slot).
type Pending = (Vec<usize>, Option<(usize, usize)>);

fn build(
    space: &Space,
    matrix: &DistanceMatrix,
    params: &HkMeansParams,
    root: Vec<usize>,
    nodes: &mut Vec<TreeNode>,
    r: &mut ChaCha8Rng,
) {
    let mut stack: Vec<Pending> = vec![(root, None)];
    while let Some((members, parent)) = stack.pop() {
        let (height, far_a, far_b) = diameter(matrix, &members);
        let id = nodes.len();
        nodes.push(TreeNode {
            members: members.clone(),
            height,
            children: Vec::new(),
            parent: parent.map(|p| p.0),
        });
        if let Some((p, _)) = parent {
            nodes[p].children.push(id);
        }
        if members.len() < 2 || height == 0.0 {
            continue; // a leaf: one scan, or scans Delta cannot tell apart
        }
        let (labels, ..) = fit_subset(
            space,
            &members,
            2,
            Seeding::PlusPlus,
            params.max_iterations,
            r,
        );
        let mut left: Vec<usize> = members
            .iter()
            .zip(&labels)
            .filter(|(_, &l)| l == 0)
            .map(|(&m, _)| m)
            .collect();
        let mut right: Vec<usize> = members
            .iter()
            .zip(&labels)
            .filter(|(_, &l)| l == 1)
            .map(|(&m, _)| m)
            .collect();
        if left.is_empty() || right.is_empty() {
            // 2-means could not split (e.g. ties): split around the two
            // scans that make the diameter, so the tree always deepens.
            left.clear();
            right.clear();
            for &m in &members {
                if matrix.get(m, far_a) <= matrix.get(m, far_b) {
                    left.push(m);
                } else {
                    right.push(m);
                }
            }
        }
        // Push right first so the left child is built (and numbered) first.
        stack.push((right, Some((id, 1))));
        stack.push((left, Some((id, 0))));
    }
}
