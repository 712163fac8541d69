//! The cluster tree: cut at any threshold without recomputing, and export
//! as a scipy-style linkage matrix.

use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// One node: its scans, its height (diameter: the largest Delta between two
/// of its scans) and its children (none for a leaf).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct TreeNode {
    /// Indices of the scans under this node.
    pub members: Vec<usize>,
    /// Diameter: the largest Delta between two members (0 for a leaf of one
    /// scan; an upper bound on large nodes built without a matrix).
    pub height: f32,
    /// Indices of the two children in [`Tree::nodes`]; empty for a leaf.
    pub children: Vec<usize>,
    /// Index of the parent in [`Tree::nodes`]; None for the root.
    pub parent: Option<usize>,
}

/// A binary tree over n scans; node 0 is the root. Deserialisation goes
/// through [`Tree::check`], so a tree read by serde is well formed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "TreeData")]
pub struct Tree {
    /// Number of scans.
    pub n: usize,
    /// The nodes, each after its parent.
    pub nodes: Vec<TreeNode>,
}

/// A tree as read, before its checks.
#[derive(Deserialize)]
struct TreeData {
    n: usize,
    nodes: Vec<TreeNode>,
}

impl TryFrom<TreeData> for Tree {
    type Error = crate::Error;
    fn try_from(t: TreeData) -> Result<Tree> {
        let tree = Tree {
            n: t.n,
            nodes: t.nodes,
        };
        tree.check()?;
        Ok(tree)
    }
}

/// Flat categories from a cut.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Cut {
    /// The height the tree was cut at: each category is a node at most this
    /// high whose parent is higher.
    pub threshold: f32,
    /// Category of each scan (0.., in order of the tree's left-to-right leaves).
    pub labels: Vec<i32>,
    /// The tree node of each category.
    pub nodes: Vec<usize>,
}

/// A threshold a tree can be cut at: finite and not negative.
fn check_threshold(t: f32) -> Result<()> {
    if !t.is_finite() || t < 0.0 {
        return invalid(format!("threshold must be a finite number >= 0, got {t}"));
    }
    Ok(())
}

impl Tree {
    pub(crate) fn new(nodes: Vec<TreeNode>, n: usize) -> Tree {
        Tree { n, nodes }
    }

    /// Check the shape every method relies on: a root (node 0) holding the
    /// n scans; every node with members below n, a height >= 0, and no
    /// children or two, numbered after it and naming it as their parent;
    /// every node but the root the child of one node.
    pub fn check(&self) -> Result<()> {
        let bad = |what: String| invalid(format!("malformed tree: {what}"));
        match self.nodes.first() {
            None => return bad("no nodes".into()),
            Some(root) if root.parent.is_some() || root.members.len() != self.n => {
                return bad(format!("the root does not hold the {} scans", self.n))
            }
            Some(_) => {}
        }
        let mut is_child = vec![false; self.nodes.len()];
        for (id, node) in self.nodes.iter().enumerate() {
            if node.members.is_empty() || node.members.iter().any(|&m| m >= self.n) {
                return bad(format!("node {id} has no members or one beyond {}", self.n));
            }
            if !(node.height >= 0.0 && node.height.is_finite()) {
                return bad(format!("node {id} has height {}", node.height));
            }
            if !matches!(node.children.len(), 0 | 2) {
                return bad(format!("node {id} has {} children", node.children.len()));
            }
            for &c in &node.children {
                let child = self.nodes.get(c).filter(|_| c > id && !is_child[c]);
                if child.is_none_or(|child| child.parent != Some(id)) {
                    return bad(format!("node {id} has a wrong child {c}"));
                }
                is_child[c] = true;
            }
        }
        if let Some(orphan) = (1..self.nodes.len()).find(|&id| !is_child[id]) {
            return bad(format!("node {orphan} is no node's child"));
        }
        Ok(())
    }

    /// Categories at threshold t: nodes whose height <= t and whose parent's
    /// height > t (the root alone when its height <= t).
    pub fn cut(&self, t: f32) -> Result<Cut> {
        check_threshold(t)?;
        Ok(self.categories(t, |id| self.nodes[id].height > t))
    }

    /// The cut with `k` categories: the tree's k - 1 highest splits, a
    /// parent's before its child's when both have one height (a child that
    /// keeps its parent's diameter pair has the parent's diameter, and no
    /// threshold separates the two splits; a threshold cut would jump from
    /// k - 1 to k + 1 categories there). Every category's height is at most
    /// the returned threshold. Fewer than k categories only when the tree
    /// has fewer than k leaves.
    pub fn cut_k(&self, k: usize) -> Result<Cut> {
        crate::cluster::lloyd::check_k(k, self.n)?;
        // Depth from the root orders ties: a parent before its child.
        let mut depth = vec![0usize; self.nodes.len()];
        let mut stack = vec![0usize];
        while let Some(id) = stack.pop() {
            for &c in &self.nodes[id].children {
                depth[c] = depth[id] + 1;
                stack.push(c);
            }
        }
        let mut order: Vec<usize> = (0..self.nodes.len())
            .filter(|&id| !self.nodes[id].children.is_empty())
            .collect();
        order.sort_by(|&a, &b| {
            let (ha, hb) = (self.nodes[a].height, self.nodes[b].height);
            hb.total_cmp(&ha)
                .then(depth[a].cmp(&depth[b]))
                .then(a.cmp(&b))
        });
        let mut split = vec![false; self.nodes.len()];
        for &id in order.iter().take(k - 1) {
            split[id] = true;
        }
        // The highest split not made (0 when every split is made).
        let t = order.get(k - 1).map_or(0.0, |&id| self.nodes[id].height);
        Ok(self.categories(t, |id| split[id]))
    }

    /// Walk down from the root, splitting the internal nodes `split` picks.
    fn categories(&self, t: f32, split: impl Fn(usize) -> bool) -> Cut {
        let mut cats = Vec::new();
        let mut stack = vec![0usize];
        while let Some(id) = stack.pop() {
            let node = &self.nodes[id];
            if node.children.is_empty() || !split(id) {
                cats.push(id);
            } else {
                stack.extend(node.children.iter().rev());
            }
        }
        let mut labels = vec![-1i32; self.n];
        for (c, &id) in cats.iter().enumerate() {
            for &m in &self.nodes[id].members {
                labels[m] = c as i32;
            }
        }
        Cut {
            threshold: t,
            labels,
            nodes: cats,
        }
    }

    /// Number of categories at threshold t (as many as `cut(t)` makes).
    pub fn count_at(&self, t: f32) -> Result<usize> {
        check_threshold(t)?;
        Ok(1 + self
            .nodes
            .iter()
            .filter(|n| !n.children.is_empty() && n.height > t)
            .count())
    }

    /// scipy.cluster.hierarchy linkage matrix: n-1 rows [a, b, height, count];
    /// ids < n are scans, id n+i is the cluster made in row i. Leaves holding
    /// several indistinguishable scans are merged at height 0 first.
    pub fn linkage(&self) -> Vec<[f64; 4]> {
        // (height, post-order rank, left id, right id, count) per merge, then
        // rows sorted by height, children before parents.
        struct Merge {
            height: f32,
            rank: usize,
            left: Ref,
            right: Ref,
            count: usize,
        }
        #[derive(Clone, Copy)]
        enum Ref {
            Scan(usize),
            Merge(usize),
        }
        let mut merges: Vec<Merge> = Vec::new();
        let mut node_ref: Vec<Option<Ref>> = vec![None; self.nodes.len()];
        // Post-order over the tree.
        let mut order = Vec::with_capacity(self.nodes.len());
        let mut stack = vec![(0usize, false)];
        while let Some((id, done)) = stack.pop() {
            if done || self.nodes[id].children.is_empty() {
                order.push(id);
            } else {
                stack.push((id, true));
                for &c in self.nodes[id].children.iter().rev() {
                    stack.push((c, false));
                }
            }
        }
        for id in order {
            let node = &self.nodes[id];
            let r = if node.children.is_empty() {
                let mut acc = Ref::Scan(node.members[0]);
                for (k, &m) in node.members.iter().enumerate().skip(1) {
                    merges.push(Merge {
                        height: 0.0,
                        rank: merges.len(),
                        left: acc,
                        right: Ref::Scan(m),
                        count: k + 1,
                    });
                    acc = Ref::Merge(merges.len() - 1);
                }
                acc
            } else {
                let l = node_ref[node.children[0]].expect("post-order");
                let rr = node_ref[node.children[1]].expect("post-order");
                merges.push(Merge {
                    height: node.height,
                    rank: merges.len(),
                    left: l,
                    right: rr,
                    count: node.members.len(),
                });
                Ref::Merge(merges.len() - 1)
            };
            node_ref[id] = Some(r);
        }
        let mut rows: Vec<usize> = (0..merges.len()).collect();
        rows.sort_by(|&a, &b| {
            merges[a]
                .height
                .total_cmp(&merges[b].height)
                .then(merges[a].rank.cmp(&merges[b].rank))
        });
        let mut row_of = vec![0usize; merges.len()];
        for (row, &m) in rows.iter().enumerate() {
            row_of[m] = row;
        }
        let id = |r: Ref| match r {
            Ref::Scan(s) => s as f64,
            Ref::Merge(m) => (self.n + row_of[m]) as f64,
        };
        rows.iter()
            .map(|&m| {
                let g = &merges[m];
                let (a, b) = (id(g.left), id(g.right));
                [a.min(b), a.max(b), g.height as f64, g.count as f64]
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(members: &[usize], height: f32, children: &[usize], parent: Option<usize>) -> TreeNode {
        TreeNode {
            members: members.to_vec(),
            height,
            children: children.to_vec(),
            parent,
        }
    }

    /// Scans 0..4. The root (height 2) splits off scan 0; its other child
    /// keeps the root's diameter pair (scans 1 and 3), so it is as high as
    /// the root. No threshold gives 2 or 3 categories; cut_k does.
    fn tied() -> Tree {
        Tree::new(
            vec![
                node(&[0, 1, 2, 3], 2.0, &[1, 2], None),
                node(&[0], 0.0, &[], Some(0)),
                node(&[1, 2, 3], 2.0, &[3, 4], Some(0)),
                node(&[1], 0.0, &[], Some(2)),
                node(&[2, 3], 1.0, &[5, 6], Some(2)),
                node(&[2], 0.0, &[], Some(4)),
                node(&[3], 0.0, &[], Some(4)),
            ],
            4,
        )
    }

    #[test]
    fn threshold_cuts_jump_over_tied_heights() {
        let t = tied();
        let counts: Vec<usize> = [2.5f32, 2.0, 1.999, 1.0, 0.999]
            .iter()
            .map(|&h| t.cut(h).unwrap().nodes.len())
            .collect();
        assert_eq!(counts, [1, 1, 3, 3, 4]);
    }

    #[test]
    fn cut_k_splits_a_tied_parent_before_its_child() {
        let t = tied();
        let want: [&[i32]; 4] = [&[0, 0, 0, 0], &[0, 1, 1, 1], &[0, 1, 2, 2], &[0, 1, 2, 3]];
        for (k, labels) in (1..=4).zip(want) {
            let cut = t.cut_k(k).unwrap();
            assert_eq!(cut.labels, labels, "k = {k}");
            assert_eq!(cut.nodes.len(), k);
            // Every category is no higher than the threshold reported.
            assert!(cut
                .nodes
                .iter()
                .all(|&id| t.nodes[id].height <= cut.threshold));
        }
        assert_eq!(t.cut_k(2).unwrap().threshold, 2.0);
        assert_eq!(t.cut_k(3).unwrap().threshold, 1.0);
        assert!(t.cut_k(5).is_err(), "more categories than scans");
    }

    /// serde reads a tree through its checks: the tied tree round-trips;
    /// a child pointing back at the root, a leaf with no members or a
    /// member beyond n is refused with a message, not a panic later.
    #[test]
    fn a_deserialised_tree_is_checked() {
        let t = tied();
        let json = serde_json::to_string(&t).unwrap();
        assert_eq!(serde_json::from_str::<Tree>(&json).unwrap(), t);
        for (from, to) in [
            ("\"children\":[5,6]", "\"children\":[0,6]"),
            ("\"members\":[3],", "\"members\":[],"),
            ("\"members\":[3],", "\"members\":[9],"),
        ] {
            assert!(json.contains(from), "{json}");
            let err = serde_json::from_str::<Tree>(&json.replacen(from, to, 1))
                .unwrap_err()
                .to_string();
            assert!(err.contains("malformed tree"), "{err}");
        }
    }
}
