//! Confusion matrix with clusters mapped to classes: one-to-one by the
//! Hungarian method when there are no more clusters than classes, else each
//! cluster to its majority class.

use pathfinding::prelude::{kuhn_munkres, Matrix};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// How clusters were mapped to classes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
#[serde(rename_all = "lowercase")]
pub enum Mapping {
    /// One-to-one, maximising the scans matched (no more clusters than classes).
    Hungarian,
    /// Each cluster to its most frequent class (more clusters than classes).
    Majority,
}

/// Rows: ground-truth classes. Columns: the same classes (predictions via
/// the cluster mapping) plus "unassigned" (noise, and clusters the mapping
/// left without a class).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Confusion {
    /// The ground-truth classes, sorted.
    pub rows: Vec<String>,
    /// The same classes, then "unassigned".
    pub cols: Vec<String>,
    /// Scans of row class r predicted as column c, `counts[r][c]`.
    pub counts: Vec<Vec<usize>>,
    /// Row-normalised rates (paper Tab. I).
    pub rates: Vec<Vec<f64>>,
    /// Share of all scans whose cluster maps to their own class (0..1).
    pub accuracy: f64,
    /// How clusters were mapped to classes.
    pub mapping: Mapping,
    /// cluster label -> class name (None: unassigned).
    pub cluster_class: Vec<(i32, Option<String>)>,
}

impl Confusion {
    /// The class cluster `label` was mapped to; None for noise, a cluster
    /// mapped to no class, or a label not in the clustering.
    pub fn class_of(&self, label: i32) -> Option<&str> {
        self.cluster_class
            .iter()
            .find(|(k, _)| *k == label)
            .and_then(|(_, c)| c.as_deref())
    }
}

/// The confusion matrix of `labels` (-1 = noise) against the class names
/// `truth`, one of each per scan.
pub fn confusion(truth: &[String], labels: &[i32]) -> Confusion {
    let classes: Vec<String> = truth
        .iter()
        .cloned()
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let clusters: Vec<i32> = labels
        .iter()
        .copied()
        .filter(|&l| l >= 0)
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let ci = |name: &str| {
        classes
            .iter()
            .position(|c| c == name)
            .expect("class listed")
    };
    let ki = |l: i32| {
        clusters
            .iter()
            .position(|&c| c == l)
            .expect("cluster listed")
    };
    // counts[cluster][class]
    let mut table = vec![vec![0usize; classes.len()]; clusters.len()];
    for (t, &l) in truth.iter().zip(labels) {
        if l >= 0 {
            table[ki(l)][ci(t)] += 1;
        }
    }
    let (mapping, class_of): (Mapping, Vec<Option<usize>>) =
        if !clusters.is_empty() && clusters.len() <= classes.len() {
            let weights = Matrix::from_rows(
                table
                    .iter()
                    .map(|r| r.iter().map(|&v| v as i64).collect::<Vec<_>>()),
            )
            .expect("rectangular");
            let (_, assign) = kuhn_munkres(&weights);
            (Mapping::Hungarian, assign.into_iter().map(Some).collect())
        } else {
            let maj = table
                .iter()
                .map(|r| (0..classes.len()).max_by_key(|&c| (r[c], std::cmp::Reverse(c))))
                .collect();
            (Mapping::Majority, maj)
        };
    let unassigned = classes.len();
    let mut counts = vec![vec![0usize; classes.len() + 1]; classes.len()];
    let mut correct = 0;
    for (t, &l) in truth.iter().zip(labels) {
        let row = ci(t);
        let col = if l < 0 {
            unassigned
        } else {
            class_of[ki(l)].unwrap_or(unassigned)
        };
        counts[row][col] += 1;
        if col == row {
            correct += 1;
        }
    }
    let rates = counts
        .iter()
        .map(|r| {
            let s: usize = r.iter().sum();
            r.iter()
                .map(|&v| if s > 0 { v as f64 / s as f64 } else { 0.0 })
                .collect()
        })
        .collect();
    let mut cols = classes.clone();
    cols.push("unassigned".into());
    Confusion {
        rows: classes.clone(),
        cols,
        counts,
        rates,
        accuracy: if truth.is_empty() {
            0.0
        } else {
            correct as f64 / truth.len() as f64
        },
        mapping,
        cluster_class: clusters
            .iter()
            .zip(&class_of)
            .map(|(&k, c)| (k, c.map(|c| classes[c].clone())))
            .collect(),
    }
}
