//! Within-category dispersion against category centres (the element-wise
//! means of [`Space::mean`]), so it needs no n x n matrix: O(n) Delta
//! evaluations per partition.

use crate::distance::Space;

/// Sum over scans of the squared Delta to their category's centre, for
/// labels 0..k (the W_k of Tibshirani et al. 2001 and Calinski-Harabasz,
/// with Delta for the Euclidean distance).
pub(crate) fn within(space: &Space, labels: &[i32]) -> f64 {
    let k = labels.iter().copied().max().map_or(0, |m| m as usize + 1);
    let mut members = vec![Vec::new(); k];
    for (i, &l) in labels.iter().enumerate() {
        members[l as usize].push(i);
    }
    members
        .iter()
        .filter(|m| !m.is_empty())
        .map(|m| {
            // One refinement from the first member, as hierarchical
            // k-means makes its centres.
            let centre = space
                .mean(m, &space.centre_of(m[0]))
                .expect("members is not empty");
            m.iter()
                .map(|&i| (space.to_centre(&centre, i).0 as f64).powi(2))
                .sum::<f64>()
        })
        .sum()
}
