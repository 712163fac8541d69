use super::hyperparams::HkMeansValidParams;
use super::tree::{Tree, TreeNode};
use crate::cluster::lloyd::{cheaper, fit_subset, Picking};
use crate::cluster::ParamGuard;
use crate::distance::DistanceMatrix;
use crate::distance::Space;
use crate::error::Result;
use crate::rng::rng;
use rand_chacha::ChaCha8Rng;

/// Builds the whole tree once; any threshold is then a cut of it.
pub struct HierarchicalKMeans;

/// Nodes up to this size get their exact diameter when there is no matrix.
pub const EXACT_DIAMETER_LIMIT: usize = 1500;

impl HierarchicalKMeans {
    /// `matrix` is the Delta matrix of the same scans (for diameters).
    /// `params` is checked first (an [`HkMeansParams`](super::HkMeansParams)
    /// or its validated form).
    pub fn fit(
        space: &Space,
        matrix: &DistanceMatrix,
        params: &impl ParamGuard<Checked = HkMeansValidParams>,
    ) -> Result<Tree> {
        Self::fit_with(space, Some(matrix), params)
    }

    /// Without an n x n matrix, for data sets where it does not fit: node
    /// heights are exact diameters up to [`EXACT_DIAMETER_LIMIT`] scans, and
    /// above it twice the largest Delta to the node's centre (an upper bound
    /// of the diameter), never more than the parent's height.
    pub fn fit_without_matrix(
        space: &Space,
        params: &impl ParamGuard<Checked = HkMeansValidParams>,
    ) -> Result<Tree> {
        Self::fit_with(space, None, params)
    }

    fn fit_with(
        space: &Space,
        matrix: Option<&DistanceMatrix>,
        params: &impl ParamGuard<Checked = HkMeansValidParams>,
    ) -> Result<Tree> {
        let params = params.check()?;
        if space.is_empty() {
            return crate::error::invalid("no scans to cluster");
        }
        let mut nodes = Vec::with_capacity(2 * space.len());
        let mut r = rng(params.seed);
        let all: Vec<usize> = (0..space.len()).collect();
        // An explicit stack instead of recursion: a chain-like data set would
        // otherwise recurse n deep.
        build(space, matrix, &params, all, &mut nodes, &mut r);
        Ok(Tree::new(nodes, space.len()))
    }
}

/// The node's height and two far-apart members (to split around if 2-means
/// cannot split).
fn height(
    space: &Space,
    matrix: Option<&DistanceMatrix>,
    members: &[usize],
    parent: f32,
) -> (f32, usize, usize) {
    let d = |i: usize, j: usize| match matrix {
        Some(m) => m.get(i, j),
        None => space.delta(i, j),
    };
    if matrix.is_some() || members.len() <= EXACT_DIAMETER_LIMIT {
        let mut best = (0f32, members[0], members[0]);
        for (a, &i) in members.iter().enumerate() {
            for &j in &members[a + 1..] {
                let v = d(i, j);
                if v > best.0 {
                    best = (v, i, j);
                }
            }
        }
        return best;
    }
    // Bound: every member is within r of the centre, so any two within 2r.
    let mut centre = space.centre_of(members[0]);
    centre = space.mean(members, &centre).expect("members is not empty");
    let (mut far, mut r) = (members[0], 0f32);
    for &i in members {
        let v = space.to_centre(&centre, i).0;
        if v > r {
            r = v;
            far = i;
        }
    }
    let other = members
        .iter()
        .copied()
        .max_by(|&a, &b| d(far, a).total_cmp(&d(far, b)))
        .unwrap_or(far);
    ((2.0 * r).min(parent), far, other)
}

/// Members for which `goes_left(position, member)` holds, and the rest.
fn split(members: &[usize], goes_left: impl Fn(usize, usize) -> bool) -> (Vec<usize>, Vec<usize>) {
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for (p, &m) in members.iter().enumerate() {
        if goes_left(p, m) {
            left.push(m);
        } else {
            right.push(m);
        }
    }
    (left, right)
}

/// A node still to build: its members and (parent index, child slot).
type Pending = (Vec<usize>, Option<(usize, usize)>);

fn build(
    space: &Space,
    matrix: Option<&DistanceMatrix>,
    params: &HkMeansValidParams,
    root: Vec<usize>,
    nodes: &mut Vec<TreeNode>,
    r: &mut ChaCha8Rng,
) {
    let mut stack: Vec<Pending> = vec![(root, None)];
    while let Some((members, parent)) = stack.pop() {
        let parent_height = parent.map_or(f32::INFINITY, |(p, _)| nodes[p].height);
        let (height, far_a, far_b) = height(space, matrix, &members, parent_height);
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
        let labels = cheapest_split(space, &members, params, r);
        let (mut left, mut right) = split(&members, |p, _| labels[p] == 0);
        if left.is_empty() || right.is_empty() {
            // 2-means could not split (e.g. ties): split around the two
            // scans that make the diameter, so the tree always deepens.
            let d = |i: usize, j: usize| matrix.map_or_else(|| space.delta(i, j), |m| m.get(i, j));
            (left, right) = split(&members, |_, m| d(m, far_a) <= d(m, far_b));
            if left.is_empty() || right.is_empty() {
                // Not even those two tell the scans apart: a node over
                // EXACT_DIAMETER_LIMIT scans that are all one (its height
                // an upper bound above 0 only by rounding). A leaf, or the
                // same node would be pushed again for ever.
                continue;
            }
        }
        // Push right first so the left child is built (and numbered) first.
        stack.push((right, Some((id, 1))));
        stack.push((left, Some((id, 0))));
    }
}

/// The 2-means++ labels of `members` of lowest cost among `params.restarts`
/// trials drawn one after another from `r` (the earliest of equal costs).
/// One trial is the paper's split.
fn cheapest_split(
    space: &Space,
    members: &[usize],
    params: &HkMeansValidParams,
    r: &mut ChaCha8Rng,
) -> Vec<usize> {
    let trial = |r: &mut ChaCha8Rng| {
        fit_subset(
            space,
            members,
            2,
            Picking::PlusPlus,
            params.max_iterations,
            r,
        )
        .0
    };
    let mut kept = trial(r);
    for _ in 1..params.restarts {
        let other = trial(r);
        if cheaper(other.cost, kept.cost) {
            kept = other;
        }
    }
    kept.labels
}
