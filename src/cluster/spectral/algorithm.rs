use super::hyperparams::SpectralValidParams;
use crate::cluster::lloyd::{cheaper, check_k};
use crate::cluster::ParamGuard;
use crate::distance::DistanceMatrix;
use crate::error::{invalid, Error, Result};
use crate::rng::rng_stream;
use nalgebra::{DMatrix, SymmetricEigen};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// The most scans spectral clustering takes: its dense
/// eigen-decomposition grows with the cube of the scans (0.09 s for 500
/// and 6.8 s for 2,000 on one core natively; `cargo bench --bench stages
/// -- spectral`).
pub const MAX_SCANS: usize = 2000;

/// What spectral clustering returns.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct SpectralResult {
    /// Category of each scan, numbered in order of first appearance.
    pub labels: Vec<i32>,
    /// The k leading eigenvalues of the normalised affinity, largest
    /// first (1 for each group of scans that no affinity joins to the
    /// rest; a gap after the k-th says k groups stand apart).
    pub eigenvalues: Vec<f64>,
    /// The kept k-means run's sum of squared distances of the embedded
    /// scans to their centres.
    pub cost: f64,
    /// Which of the runs was kept, from 0.
    pub restart: usize,
}

/// Spectral clustering on a Delta matrix.
pub struct Spectral;

impl Spectral {
    /// Labels of the `matrix`'s scans in `params.k` categories; `params`
    /// is checked first. An error for more than [`MAX_SCANS`] scans or a
    /// non-finite or negative Delta.
    pub fn fit(
        matrix: &DistanceMatrix,
        params: &impl ParamGuard<Checked = SpectralValidParams>,
    ) -> Result<SpectralResult> {
        let params = params.check()?;
        let n = matrix.n;
        check_k(params.k, n)?;
        check_size(n)?;
        if let Some(at) = matrix
            .data
            .iter()
            .position(|d| !(d.is_finite() && *d >= 0.0))
        {
            return Err(Error::Mismatch(format!(
                "Delta matrix: ({}, {}) is {}, not a finite distance",
                at / n,
                at % n,
                matrix.data[at]
            )));
        }
        let embedded = embed(matrix, params.k, params.neighbours);
        let mut kept: Option<(f64, Vec<usize>, usize)> = None;
        for run in 0..params.restarts {
            let mut r = rng_stream(params.seed, run as u64);
            let (cost, labels) = kmeans(&embedded.points, params.k, params.max_iterations, &mut r);
            if kept.as_ref().is_none_or(|k| cheaper(cost, k.0)) {
                kept = Some((cost, labels, run));
            }
        }
        let (cost, labels, restart) = kept.expect("restarts is at least 1");
        Ok(SpectralResult {
            labels: in_order_of_appearance(&labels),
            eigenvalues: embedded.eigenvalues,
            cost,
            restart,
        })
    }
}

/// Reject more than [`MAX_SCANS`] scans (before their matrix is built).
pub(crate) fn check_size(n: usize) -> Result<()> {
    if n > MAX_SCANS {
        return invalid(format!(
            "spectral clustering takes at most {MAX_SCANS} scans (its eigen-decomposition grows with the cube of their number), got {n}; use k-means or hierarchical k-means++"
        ));
    }
    Ok(())
}

/// The scans as points on the unit sphere of the k leading eigenvectors.
struct Embedded {
    points: Vec<Vec<f64>>,
    eigenvalues: Vec<f64>,
}

fn embed(matrix: &DistanceMatrix, k: usize, neighbours: usize) -> Embedded {
    let n = matrix.n;
    let d = |i: usize, j: usize| f64::from(matrix.get(i, j));
    // A scan's scale is its distance to its `neighbours`-th nearest other
    // scan (the farthest when there are fewer). A scan with that many
    // copies has a scale of 0: its affinity is 1 to its copies and 0 to
    // the rest (below, with no 0/0).
    let scales: Vec<f64> = (0..n)
        .map(|i| {
            let mut row: Vec<f64> = (0..n).filter(|&j| j != i).map(|j| d(i, j)).collect();
            let at = neighbours.min(row.len()).saturating_sub(1);
            if row.is_empty() {
                return 1.0;
            }
            *row.select_nth_unstable_by(at, f64::total_cmp).1
        })
        .collect();
    let mut a = DMatrix::<f64>::from_fn(n, n, |i, j| {
        if i == j {
            0.0
        } else {
            let (x, scale) = (d(i, j), scales[i] * scales[j]);
            match (x > 0.0, scale > 0.0) {
                (false, _) => 1.0,
                (true, false) => 0.0,
                (true, true) => (-(x * x) / scale).exp(),
            }
        }
    });
    // A scan whose every affinity underflows to 0 keeps a zero row, and so
    // a zero point that k-means puts with the nearest centre.
    let inv_sqrt: Vec<f64> = (0..n)
        .map(|i| {
            let degree = a.row(i).sum();
            if degree > 0.0 {
                1.0 / degree.sqrt()
            } else {
                0.0
            }
        })
        .collect();
    for j in 0..n {
        for i in 0..n {
            a[(i, j)] *= inv_sqrt[i] * inv_sqrt[j];
        }
    }
    let eigen = SymmetricEigen::new(a);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&x, &y| {
        eigen.eigenvalues[y]
            .total_cmp(&eigen.eigenvalues[x])
            .then(x.cmp(&y))
    });
    let leading = &order[..k];
    let points = (0..n)
        .map(|i| {
            let row: Vec<f64> = leading
                .iter()
                .map(|&c| eigen.eigenvectors[(i, c)])
                .collect();
            let norm = row.iter().map(|x| x * x).sum::<f64>().sqrt();
            if norm > 0.0 {
                row.iter().map(|x| x / norm).collect()
            } else {
                row
            }
        })
        .collect();
    Embedded {
        points,
        eigenvalues: leading.iter().map(|&c| eigen.eigenvalues[c]).collect(),
    }
}

fn squared(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

/// Euclidean k-means with k-means++ seeding (Arthur and Vassilvitskii
/// 2007) on the embedded scans: the cost (sum of squared distances to the
/// centres) and each point's centre. The crate's own k-means works on
/// descriptors with Delta, not on points, hence this small one.
fn kmeans(
    points: &[Vec<f64>],
    k: usize,
    max_iterations: usize,
    r: &mut ChaCha8Rng,
) -> (f64, Vec<usize>) {
    let n = points.len();
    let nearest = |p: &[f64], centres: &[Vec<f64>]| -> (usize, f64) {
        (0..centres.len())
            .map(|c| (c, squared(p, &centres[c])))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0))
    };
    let mut centres: Vec<Vec<f64>> = vec![points[r.random_range(0..n)].clone()];
    while centres.len() < k {
        let weights: Vec<f64> = points.iter().map(|p| nearest(p, &centres).1).collect();
        let total: f64 = weights.iter().sum();
        let pick = if total > 0.0 {
            let mut t = r.random::<f64>() * total;
            weights
                .iter()
                .position(|&w| {
                    t -= w;
                    t < 0.0
                })
                .unwrap_or_else(|| weights.iter().rposition(|&w| w > 0.0).unwrap_or(n - 1))
        } else {
            r.random_range(0..n)
        };
        centres.push(points[pick].clone());
    }
    let mut labels: Vec<usize> = points.iter().map(|p| nearest(p, &centres).0).collect();
    for _ in 0..max_iterations {
        for (c, centre) in centres.iter_mut().enumerate() {
            let members: Vec<&Vec<f64>> = (points.iter().zip(&labels))
                .filter(|(_, &l)| l == c)
                .map(|(p, _)| p)
                .collect();
            // An emptied centre stays where it was.
            if !members.is_empty() {
                for (d, v) in centre.iter_mut().enumerate() {
                    *v = members.iter().map(|p| p[d]).sum::<f64>() / members.len() as f64;
                }
            }
        }
        let next: Vec<usize> = points.iter().map(|p| nearest(p, &centres).0).collect();
        if next == labels {
            break;
        }
        labels = next;
    }
    let cost = points
        .iter()
        .zip(&labels)
        .map(|(p, &l)| squared(p, &centres[l]))
        .sum();
    (cost, labels)
}

/// Labels renumbered so that category 0 is the first scan's, 1 the next
/// new one's, and so on.
fn in_order_of_appearance(labels: &[usize]) -> Vec<i32> {
    let mut names: Vec<Option<i32>> = vec![None; labels.iter().max().map_or(0, |m| m + 1)];
    let mut next = 0;
    labels
        .iter()
        .map(|&l| {
            *names[l].get_or_insert_with(|| {
                next += 1;
                next - 1
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cluster::spectral::SpectralParams;
    use std::f64::consts::TAU;

    fn matrix_of(points: &[[f64; 2]]) -> DistanceMatrix {
        DistanceMatrix::from_fn(points.len(), |i, j| {
            ((points[i][0] - points[j][0]).hypot(points[i][1] - points[j][1])) as f32
        })
    }

    /// `count` points evenly round a circle of `radius`.
    fn ring(count: usize, radius: f64) -> Vec<[f64; 2]> {
        (0..count)
            .map(|i| {
                let a = TAU * i as f64 / count as f64;
                [radius * a.cos(), radius * a.sin()]
            })
            .collect()
    }

    #[test]
    fn two_rings_one_inside_the_other_are_told_apart() {
        // No two round groups separate a ring from the ring round it (any
        // split by centres cuts both), so k-means cannot; neighbours can.
        let mut points = ring(30, 1.0);
        points.extend(ring(60, 3.0));
        let r = Spectral::fit(&matrix_of(&points), &SpectralParams::new(2)).unwrap();
        let inner = &r.labels[..30];
        let outer = &r.labels[30..];
        assert!(inner.iter().all(|&l| l == 0), "{:?}", r.labels);
        assert!(outer.iter().all(|&l| l == 1), "{:?}", r.labels);
        assert_eq!(r.eigenvalues.len(), 2);
        // The leading eigenvalue of a degree-normalised affinity is 1; the
        // second is near it, as two groups barely joined give.
        assert!((r.eigenvalues[0] - 1.0).abs() < 1e-9, "{:?}", r.eigenvalues);
        assert!(r.eigenvalues[1] > 0.9, "{:?}", r.eigenvalues);
    }

    #[test]
    fn three_groups_are_found_and_the_eigengap_follows_the_third() {
        let mut points = Vec::new();
        for (cx, cy) in [(0.0, 0.0), (10.0, 0.0), (0.0, 10.0)] {
            points.extend(ring(12, 0.5).iter().map(|p| [p[0] + cx, p[1] + cy]));
        }
        let mut params = SpectralParams::new(4);
        let r = Spectral::fit(&matrix_of(&points), &params).unwrap();
        assert!((r.eigenvalues[2] - 1.0).abs() < 1e-6, "{:?}", r.eigenvalues);
        assert!(r.eigenvalues[3] < 0.9, "{:?}", r.eigenvalues);
        params.k = 3;
        let r = Spectral::fit(&matrix_of(&points), &params).unwrap();
        let expected: Vec<i32> = (0..36).map(|i| i / 12).collect();
        assert_eq!(r.labels, expected);
    }

    #[test]
    fn the_same_seed_gives_the_same_labels_and_copies_give_no_nan() {
        let mut points = ring(20, 1.0);
        points.extend(ring(20, 1.0)); // every scan twice
        points.extend(vec![[5.0, 5.0]; 10]); // ten copies of one scan
        let m = matrix_of(&points);
        let params = SpectralParams::new(3).seed(7);
        let a = Spectral::fit(&m, &params).unwrap();
        assert_eq!(a, Spectral::fit(&m, &params).unwrap());
        assert!(a.cost.is_finite() && a.eigenvalues.iter().all(|e| e.is_finite()));
        assert!(a.labels[40..].iter().all(|&l| l == a.labels[40]));
        assert!(a.labels[..40].iter().all(|&l| l != a.labels[40]));
        // All scans the same: one group, whatever k.
        let same = DistanceMatrix::from_fn(5, |_, _| 0.0);
        let r = Spectral::fit(&same, &SpectralParams::new(2)).unwrap();
        assert_eq!(r.labels.len(), 5);
    }

    #[test]
    fn bad_parameters_and_matrices_are_errors_that_name_them() {
        let m = matrix_of(&ring(5, 1.0));
        let err = |p: SpectralParams| Spectral::fit(&m, &p).unwrap_err().to_string();
        assert!(err(SpectralParams::new(0)).contains("k must be at least 1"));
        assert!(err(SpectralParams::new(6)).contains("more than the 5 scans"));
        assert!(err(SpectralParams::new(2).neighbours(0)).contains("neighbours"));
        assert!(err(SpectralParams::new(2).restarts(0)).contains("restarts"));
        assert!(err(SpectralParams::new(2).max_iterations(0)).contains("max_iterations"));
        let mut nan = m.clone();
        nan.data[2 * 5 + 3] = f32::NAN;
        let e = Spectral::fit(&nan, &SpectralParams::new(2))
            .unwrap_err()
            .to_string();
        assert!(e.contains("(2, 3) is NaN"), "{e}");
        let big = DistanceMatrix {
            n: MAX_SCANS + 1,
            data: Vec::new(),
        };
        let e = Spectral::fit(&big, &SpectralParams::new(2))
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("at most {MAX_SCANS} scans")), "{e}");
    }

    #[test]
    fn one_scan_one_category() {
        let m = DistanceMatrix::from_fn(1, |_, _| 0.0);
        let r = Spectral::fit(&m, &SpectralParams::new(1)).unwrap();
        assert_eq!(r.labels, vec![0]);
    }
}
