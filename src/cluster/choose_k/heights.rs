//! The largest relative gap between successive node heights of the tree
//! (the "largest jump" or "lifetime" cut of a dendrogram, e.g. Jain &
//! Dubes 1988, Sec. 3.2; here heights are node diameters). With
//! h_1 >= h_2 >= ... the split heights in the order `Tree::cut_k` makes
//! them, the cut at K makes splits 1..K-1 and leaves h_K; its score is
//! h_{K-1} / h_K, the factor by which the diameters drop at that cut.

use crate::cluster::Tree;

/// The split heights, highest first (the order of [`Tree::cut_k`]).
pub(crate) fn split_heights(tree: &Tree) -> Vec<f64> {
    let mut h: Vec<f64> = tree
        .nodes
        .iter()
        .filter(|n| !n.children.is_empty())
        .map(|n| n.height as f64)
        .collect();
    h.sort_by(|a, b| b.total_cmp(a));
    h
}

/// h_{K-1} / h_K for K = 2..=max_k (index K - 2); NaN where h_K is 0 or
/// missing (every split made: the ratio would be infinite at any tree's
/// last level and say nothing about categories).
pub(crate) fn height_ratios(tree: &Tree, max_k: usize) -> Vec<f64> {
    let h = split_heights(tree);
    (2..=max_k)
        .map(|k| {
            let above = h.get(k - 2).copied().unwrap_or(0.0);
            let below = h.get(k - 1).copied().unwrap_or(0.0);
            if below > 0.0 {
                above / below
            } else {
                f64::NAN
            }
        })
        .collect()
}
