//! DBSCAN parameter sweep (paper Fig. 3): a grid of epsilon x c giving the
//! number of clusters, the inlier ratio and, with ground truth, AR and S.

use crate::cluster::{Dbscan, DbscanParams};
use crate::distance::DistanceMatrix;
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// DBSCAN at one (epsilon, c).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct SweepPoint {
    /// The neighbourhood radius, in Delta.
    pub epsilon: f32,
    /// c: the least neighbours of a core scan, itself included.
    pub min_points: usize,
    /// Clusters found (noise not counted).
    pub clusters: usize,
    /// Scans in a cluster / all scans.
    pub inlier_ratio: f64,
    /// ARI over the inliers; `None` without ground truth.
    pub ari: Option<f64>,
    /// S = ARI * inlier ratio; `None` without ground truth.
    pub score: Option<f64>,
}

/// Min points (the scan itself included) a sweep tries unless told: the
/// paper's Fig. 3 range, from pairs to groups of a dozen scans.
pub const SWEEP_MIN_POINTS: [usize; 5] = [2, 3, 5, 8, 12];

/// Quantiles of the Delta between two different scans at which
/// [`epsilon_grid`] puts epsilon: from pairs of near-duplicates up to the
/// median pair. With k equal categories about 1/k of all pairs lie within
/// one, so the useful epsilons of 2 to 20 categories fall inside.
pub const GRID_QUANTILES: [f64; 12] = [
    0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5,
];

/// Above this many pairs the quantiles are taken from an even sample of
/// them (a sort of all 12.5 million pairs of 5,000 scans would need 50 MB
/// more).
const GRID_SAMPLE: usize = 1 << 20;

/// Epsilons for a sweep when the user has no idea of the scale of Delta on
/// their data: the [`GRID_QUANTILES`] of the Delta between two different
/// scans, rounded up to 3 significant digits (short enough to type back as
/// `--eps`; up, so the pair at the quantile stays within epsilon), equal
/// values once. Empty with fewer than two scans.
pub fn epsilon_grid(matrix: &DistanceMatrix) -> Vec<f32> {
    let n = matrix.n;
    let pairs = n * n.saturating_sub(1) / 2;
    if pairs == 0 {
        return Vec::new();
    }
    let step = pairs.div_ceil(GRID_SAMPLE);
    let mut values: Vec<f32> = (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .step_by(step)
        .map(|(i, j)| matrix.get(i, j))
        .collect();
    values.sort_unstable_by(f32::total_cmp);
    let mut grid: Vec<f32> = GRID_QUANTILES
        .iter()
        .map(|q| {
            let at = ((values.len() - 1) as f64 * q).round() as usize;
            ceil_significant(values[at], 3)
        })
        .collect();
    grid.dedup();
    grid
}

/// The smallest number of `digits` significant digits that is >= `x`, as
/// the nearest f32 (which is still >= `x`: rounding to f32 is monotone and
/// `x` is an f32). 0 stays 0.
fn ceil_significant(x: f32, digits: i32) -> f32 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(digits - 1 - (x as f64).abs().log10().floor() as i32);
    ((x as f64 * scale).ceil() / scale) as f32
}

/// DBSCAN at every (epsilon, c) of the grid, epsilon-major. `truth` (a class
/// name per scan) adds AR and S.
pub fn dbscan_sweep(
    matrix: &DistanceMatrix,
    truth: Option<&[String]>,
    epsilons: &[f32],
    min_points: &[usize],
) -> Result<Vec<SweepPoint>> {
    if epsilons.is_empty() || min_points.is_empty() {
        return Err(Error::InvalidParameter(
            "a sweep needs at least one epsilon and one min points".into(),
        ));
    }
    let mut out = Vec::with_capacity(epsilons.len() * min_points.len());
    for &e in epsilons {
        for &c in min_points {
            let labels = Dbscan::fit(matrix, &DbscanParams::new(e, c))?;
            let inliers = labels.iter().filter(|&&l| l >= 0).count();
            let (ari, score) = match truth {
                Some(t) => {
                    let ev = super::evaluate(t, &labels)?;
                    (Some(ev.ari), Some(ev.score))
                }
                None => (None, None),
            };
            out.push(SweepPoint {
                epsilon: e,
                min_points: c,
                clusters: labels
                    .iter()
                    .copied()
                    .max()
                    .map_or(0, |m| (m + 1).max(0) as usize),
                inlier_ratio: inliers as f64 / labels.len().max(1) as f64,
                ari,
                score,
            });
        }
    }
    Ok(out)
}

/// The point with the highest S (the first of equals), if the sweep had
/// ground truth.
pub fn best_score(sweep: &[SweepPoint]) -> Option<&SweepPoint> {
    sweep
        .iter()
        .filter(|p| p.score.is_some())
        .fold(None, |best: Option<&SweepPoint>, p| match best {
            Some(b) if b.score >= p.score => Some(b),
            _ => Some(p),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Scans on a line at these positions; Delta = distance along it.
    fn line(xs: &[f32]) -> DistanceMatrix {
        DistanceMatrix::from_fn(xs.len(), |i, j| (xs[i] - xs[j]).abs())
    }

    #[test]
    fn rounding_up_keeps_three_significant_digits() {
        assert_eq!(ceil_significant(0.123456, 3), 0.124);
        assert_eq!(ceil_significant(12.3456, 3), 12.4);
        assert_eq!(ceil_significant(0.0004561, 3), 0.000457);
        assert_eq!(ceil_significant(0.5, 3), 0.5);
        assert_eq!(ceil_significant(250.0, 3), 250.0);
        assert_eq!(ceil_significant(0.0, 3), 0.0);
        // Never below the value: the pair at a quantile is a neighbour.
        for x in [0.27901f32, 0.1 + 1e-7, 2.71830, 1e-6 + 3e-13] {
            assert!(ceil_significant(x, 3) >= x, "{x}");
        }
    }

    #[test]
    fn the_grid_is_quantiles_of_pair_distances() {
        // 0..=100 on a line: 5050 pairs; distance d occurs 101 - d times.
        let xs: Vec<f32> = (0..=100).map(|i| i as f32).collect();
        let grid = epsilon_grid(&line(&xs));
        let mut all: Vec<f32> = (0..=100)
            .flat_map(|i| (i + 1..=100).map(move |j| (j - i) as f32))
            .collect();
        all.sort_unstable_by(f32::total_cmp);
        let mut expect: Vec<f32> = GRID_QUANTILES
            .iter()
            .map(|q| all[((all.len() - 1) as f64 * q).round() as usize])
            .collect();
        expect.dedup();
        assert_eq!(grid, expect);
        // The median pair is 30 apart: 2,494 of the 5,050 pairs are 1..=29
        // apart (100 + 99 + ... + 72), 2,565 are 1..=30.
        assert_eq!(grid.len(), 10);
        assert_eq!(*grid.last().unwrap(), 30.0);
        assert!(epsilon_grid(&line(&[1.0])).is_empty());
        // Equal quantiles appear once.
        assert_eq!(epsilon_grid(&line(&[0.0, 1.0])), vec![1.0]);
    }

    #[test]
    fn each_grid_epsilon_takes_in_the_pairs_up_to_its_quantile() {
        // Positions with no round distances, so rounding matters.
        let xs: Vec<f32> = (0..40).map(|i| 0.0173 * (i as f32).powf(1.37)).collect();
        let m = line(&xs);
        let grid = epsilon_grid(&m);
        let mut all: Vec<f32> = (0..40)
            .flat_map(|i| (i + 1..40).map(move |j| (i, j)))
            .map(|(i, j)| m.get(i, j))
            .collect();
        all.sort_unstable_by(f32::total_cmp);
        for q in GRID_QUANTILES {
            let at = ((all.len() - 1) as f64 * q).round() as usize;
            let e = *grid.iter().find(|&&e| e >= all[at]).unwrap();
            // The grid's epsilon for this quantile is the next at or above
            // the quantile's pair, within 1 % (3 significant digits).
            assert!(e <= all[at] * 1.01, "q {q}: {e} for {}", all[at]);
            assert!(all.iter().filter(|&&d| d <= e).count() > at);
        }
    }

    #[test]
    fn a_large_set_takes_its_quantiles_from_an_even_sample_of_pairs() {
        // 1,500 scans 1 apart: 1,124,250 pairs, over GRID_SAMPLE, so every
        // second pair is sorted. Distance d occurs n - d times, so the share
        // of pairs within e is known exactly for each epsilon.
        let n = 1500usize;
        let xs: Vec<f32> = (0..n).map(|i| i as f32).collect();
        let pairs = n * (n - 1) / 2;
        assert!(pairs > GRID_SAMPLE);
        let grid = epsilon_grid(&line(&xs));
        assert_eq!(grid.len(), GRID_QUANTILES.len(), "{grid:?}");
        for (e, q) in grid.iter().zip(GRID_QUANTILES) {
            let within: usize = (1..=*e as usize).map(|d| n - d).sum();
            let share = within as f64 / pairs as f64;
            // One distance holds at most (n - 1) / pairs = 0.13 % of pairs.
            assert!(
                (share - q).abs() < 0.003,
                "epsilon {e}: {share} within, quantile {q}"
            );
        }
    }

    #[test]
    fn sweep_counts_clusters_inliers_and_scores() {
        // Two tight groups and one far scan.
        let m = line(&[0.0, 0.1, 0.2, 5.0, 5.1, 5.2, 20.0]);
        let truth: Vec<String> = ["a", "a", "a", "b", "b", "b", "c"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let sweep = dbscan_sweep(&m, Some(&truth), &[0.1, 1.0, 100.0], &[1, 3]).unwrap();
        let at = |e: f32, c: usize| {
            sweep
                .iter()
                .find(|p| p.epsilon == e && p.min_points == c)
                .unwrap()
        };
        // eps 1, c 3: the two groups, the far scan is noise.
        let p = at(1.0, 3);
        assert_eq!((p.clusters, p.ari), (2, Some(1.0)));
        assert!((p.inlier_ratio - 6.0 / 7.0).abs() < 1e-12);
        assert!((p.score.unwrap() - 6.0 / 7.0).abs() < 1e-12);
        // eps 1, c 1: every scan is a core, the far one its own cluster.
        assert_eq!((at(1.0, 1).clusters, at(1.0, 1).score), (3, Some(1.0)));
        // eps 100: one cluster of all, ARI 0.
        assert_eq!((at(100.0, 3).clusters, at(100.0, 3).ari), (1, Some(0.0)));
        assert_eq!(sweep.len(), 6);
        assert_eq!(best_score(&sweep).unwrap().min_points, 1);
        // Without truth: the same clusters, no AR.
        let plain = dbscan_sweep(&m, None, &[1.0], &[3]).unwrap();
        assert_eq!(
            (plain[0].clusters, plain[0].ari, plain[0].score),
            (2, None, None)
        );
        assert!(best_score(&plain).is_none());
    }

    #[test]
    fn bad_sweeps_are_errors() {
        let m = line(&[0.0, 1.0]);
        assert!(dbscan_sweep(&m, None, &[], &[2]).is_err());
        assert!(dbscan_sweep(&m, None, &[1.0], &[]).is_err());
        assert!(dbscan_sweep(&m, None, &[-1.0], &[2]).is_err());
        assert!(dbscan_sweep(&m, None, &[1.0], &[0]).is_err());
        let short = vec!["a".to_string()];
        assert!(dbscan_sweep(&m, Some(&short), &[1.0], &[2]).is_err());
    }
}
