//! The cluster tree: cut at any threshold without recomputing, and export
//! as a scipy-style linkage matrix.

use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// One node: its scans, its height (diameter: the largest Delta between two
/// of its scans) and its children (none for a leaf).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TreeNode {
    pub members: Vec<usize>,
    pub height: f32,
    pub children: Vec<usize>,
    pub parent: Option<usize>,
}

/// A binary tree over n scans; node 0 is the root.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Tree {
    pub n: usize,
    pub nodes: Vec<TreeNode>,
}

/// Flat categories from a cut.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Cut {
    pub threshold: f32,
    /// Category of each scan (0.., in order of the tree's left-to-right leaves).
    pub labels: Vec<i32>,
    /// The tree node of each category.
    pub nodes: Vec<usize>,
}

impl Tree {
    pub(crate) fn new(nodes: Vec<TreeNode>, n: usize) -> Tree {
        Tree { n, nodes }
    }

    /// Categories at threshold t: nodes whose height <= t and whose parent's
    /// height > t (the root alone when its height <= t).
    pub fn cut(&self, t: f32) -> Result<Cut> {
        if !t.is_finite() || t < 0.0 {
            return invalid(format!("threshold must be a finite number >= 0, got {t}"));
        }
        let mut cats = Vec::new();
        let mut stack = vec![0usize];
        while let Some(id) = stack.pop() {
            let node = &self.nodes[id];
            if node.height <= t || node.children.is_empty() {
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
        Ok(Cut {
            threshold: t,
            labels,
            nodes: cats,
        })
    }

    /// The cut with `k` categories, or the nearest count the tree allows
    /// (ties in heights can make some counts impossible).
    pub fn cut_k(&self, k: usize) -> Result<Cut> {
        crate::cluster::space::check_k(k, self.n)?;
        let mut heights: Vec<f32> = self
            .nodes
            .iter()
            .filter(|n| !n.children.is_empty())
            .map(|n| n.height)
            .collect();
        heights.sort_by(|a, b| b.total_cmp(a));
        // Cutting at the k-th largest internal height splits the k-1 above it.
        let t = if k > heights.len() {
            0.0
        } else {
            heights[k - 1]
        };
        self.cut(t)
    }

    /// Number of categories at threshold t.
    pub fn count_at(&self, t: f32) -> usize {
        1 + self
            .nodes
            .iter()
            .filter(|n| !n.children.is_empty() && n.height > t)
            .count()
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
