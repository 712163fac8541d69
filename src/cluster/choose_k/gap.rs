//! The gap statistic (Tibshirani, Walther & Hastie 2001): compare
//! log W_k of the data with its expectation under a reference with no
//! categories, Gap(k) = E*[log W*_k] - log W_k, and take the smallest k
//! with Gap(k) >= Gap(k+1) - s_{k+1}, s = sd* x sqrt(1 + 1/B).
//!
//! The reference. Descriptors are not points of a box, so the uniform
//! reference of the paper does not apply; its permutation variant does:
//! a reference scan takes each range column (every class of one range
//! interval) from a scan drawn at random, independently per column, and
//! its |F| and number of candidate orientations from another. Delta is a
//! sum over range columns, so this keeps every column's spread of values
//! (the within-place noise as well as the differences between places)
//! and removes only what makes categories: that the columns of one scan
//! vary together. Scans all alike give a reference like the data and
//! Gap(1) >= Gap(2) - s_2, i.e. one category.
//!
//! Reference sets have min(n, `reference_size`) scans, and W is taken per
//! scan (W_k / n), so that sets of different sizes compare; each is
//! clustered as the data were (a tree or k-means with the same parameters).

use crate::distance::Prepared;
use crate::distance::Space;
use crate::rng::rng;
use rand::Rng;

/// A reference set of `m` scans drawn from `space` (see the module doc).
pub(crate) fn reference(space: &Space, m: usize, seed: u64) -> Space {
    let mut r = rng(seed);
    let n = space.len();
    let items = (0..m)
        .map(|_| {
            let mut item: Prepared = space.items[r.random_range(0..n)].clone();
            let size = item.stride * item.cols;
            let candidates = item.padded.len() / size;
            for c in 0..item.cols {
                let src = &space.items[r.random_range(0..n)];
                let src_candidates = src.padded.len() / size;
                for j in 0..candidates {
                    item.copy_column(j, c, src, j % src_candidates);
                }
            }
            // Extra parts come from yet another scan (drawn only when there
            // are parts, so the paper's descriptor draws as before).
            if !item.parts.is_empty() {
                item.parts
                    .clone_from(&space.items[r.random_range(0..n)].parts);
            }
            item
        })
        .collect();
    Space {
        items,
        metric: space.metric,
        options: space.options,
    }
}

/// Gap(k) and s_k from log(W_k / n) of the data (index k - 1) and of each
/// reference set.
pub(crate) fn gaps(data: &[f64], references: &[Vec<f64>]) -> (Vec<f64>, Vec<f64>) {
    let b = references.len() as f64;
    (0..data.len())
        .map(|k| {
            let vals: Vec<f64> = references.iter().map(|r| r[k]).collect();
            let mean = vals.iter().sum::<f64>() / b;
            let sd = (vals.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / b).sqrt();
            (mean - data[k], sd * (1.0 + 1.0 / b).sqrt())
        })
        .unzip()
}

/// Tibshirani's choice: the smallest k with Gap(k) >= Gap(k+1) - s_{k+1};
/// the largest k tried when none qualifies.
pub(crate) fn one_se_choice(gap: &[f64], s: &[f64]) -> usize {
    (0..gap.len().saturating_sub(1))
        .find(|&k| gap[k] >= gap[k + 1] - s[k + 1])
        .map_or(gap.len(), |k| k + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_se_rule_takes_the_first_k_not_beaten_by_more_than_s() {
        // Gap rises to k = 3 and stays level after it.
        let gap = [0.1, 0.5, 0.9, 0.92, 0.91];
        let s = [0.05; 5];
        assert_eq!(one_se_choice(&gap, &s), 3);
        // Level from the start: one category.
        assert_eq!(one_se_choice(&[0.0, 0.02, 0.03], &[0.05; 3]), 1);
        // Still rising at the end: the largest k tried.
        assert_eq!(one_se_choice(&[0.0, 0.5, 1.0], &[0.05; 3]), 3);
    }

    /// A reference scan drawn from a Hellinger space carries the roots of
    /// its own columns (copied with them), so its distances are those of
    /// its normalised matrices.
    #[test]
    fn reference_scans_keep_their_roots_with_their_columns() {
        use crate::descriptor::{Descriptor, Metric};
        use crate::distance::DistanceOptions;
        let scans: Vec<Descriptor> = (0..6u32)
            .map(|i| Descriptor {
                rows: 3,
                cols: 4,
                matrices: (0..1 + i as usize % 3)
                    .map(|k| {
                        (0..12)
                            .map(|e| (e * 7 + i * 5 + k as u32 * 3) % 11)
                            .collect()
                    })
                    .collect(),
                summary: Default::default(),
                parts: Vec::new(),
            })
            .collect();
        let opts = DistanceOptions {
            metric: Metric::Hellinger,
            ..DistanceOptions::default()
        };
        let space = Space::new(&scans, opts).unwrap();
        let drawn = reference(&space, 8, 3);
        for item in &drawn.items {
            let roots: Vec<f32> = item.padded.iter().map(|v| v.sqrt()).collect();
            assert_eq!(item.roots, roots);
        }
        // And some column came from another scan than the item's first.
        assert!(drawn
            .items
            .iter()
            .any(|d| space.items.iter().all(|s| s.padded != d.padded)));
    }
}
