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
/// eigen-decomposition grows with the cube of the scans. The whole fit
/// (affinity, eigen-decomposition, 10 k-means runs) took 0.09 s for 500
/// scans and 6.8 s for 2,000 natively on one core (`cargo bench --bench
/// stages -- spectral`); wasm is slower.
pub const MAX_SCANS: usize = 2000;

/// What spectral clustering returns.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct SpectralResult {
    /// Category of each scan, numbered in order of first appearance; k
    /// categories, each of at least one scan.
    pub labels: Vec<i32>,
    /// The k leading eigenvalues of the normalised affinity, largest
    /// first: 1 for each group of scans joined to each other and to no
    /// other scan (a lone scan joined to none gives 0); a gap after the
    /// k-th says k groups stand apart.
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
    /// is checked first. An error for more than [`MAX_SCANS`] scans, a
    /// matrix that is not n x n, a non-finite or negative Delta, or an
    /// eigen-decomposition that does not converge.
    pub fn fit(
        matrix: &DistanceMatrix,
        params: &impl ParamGuard<Checked = SpectralValidParams>,
    ) -> Result<SpectralResult> {
        let params = params.check()?;
        let n = matrix.n;
        check_k(params.k, n)?;
        check_size(n)?;
        if matrix.data.len() != n * n {
            return invalid(format!(
                "Delta matrix: {} values for {n} scans, not {n} x {n}",
                matrix.data.len()
            ));
        }
        let bad = |d: &f32| !(d.is_finite() && *d >= 0.0);
        if let Some(at) = matrix.data.iter().position(bad) {
            return invalid(format!(
                "Delta matrix: ({}, {}) is {}, not a finite Delta",
                at / n,
                at % n,
                matrix.data[at]
            ));
        }
        let embedded = embed(matrix, params.k, params.neighbours)?;
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

fn embed(matrix: &DistanceMatrix, k: usize, neighbours: usize) -> Result<Embedded> {
    let n = matrix.n;
    let d = |i: usize, j: usize| f64::from(matrix.get(i, j));
    // A scan's scale is its distance to its `neighbours`-th nearest other
    // scan (the farthest when there are fewer), its copies (Delta 0) not
    // counted: else a scan with that many copies would have a scale of 0
    // and be joined to nothing but them, while one copy fewer would change
    // nothing. A scan whose others are all copies keeps 0, its affinity 1
    // to them (below, with no 0/0).
    let scales: Vec<f64> = (0..n)
        .map(|i| {
            let mut row: Vec<f64> = (0..n)
                .filter(|&j| j != i)
                .map(|j| d(i, j))
                .filter(|&x| x > 0.0)
                .collect();
            if row.is_empty() {
                return 0.0;
            }
            let at = neighbours.min(row.len()) - 1;
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
    // A cap on the solver's sweeps, far above what it needs: nalgebra's
    // `new` has none and can loop on some matrices of zeros and ones.
    let sweeps = 30 * n.max(1);
    let eigen = SymmetricEigen::try_new(a, f64::EPSILON, sweeps).ok_or_else(|| {
        Error::Limit(format!(
            "spectral clustering: the eigen-decomposition of {n} scans did not converge in {sweeps} sweeps"
        ))
    })?;
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
    Ok(Embedded {
        points,
        eigenvalues: leading.iter().map(|&c| eigen.eigenvalues[c]).collect(),
    })
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
    let mut labels: Vec<usize> = vec![usize::MAX; n];
    for _ in 0..max_iterations {
        let mut next: Vec<usize> = points.iter().map(|p| nearest(p, &centres).0).collect();
        refill_empty(points, &centres, &mut next, k);
        let settled = next == labels;
        labels = next;
        for (c, centre) in centres.iter_mut().enumerate() {
            let members: Vec<&Vec<f64>> = (points.iter().zip(&labels))
                .filter(|(_, &l)| l == c)
                .map(|(p, _)| p)
                .collect();
            for (d, v) in centre.iter_mut().enumerate() {
                *v = members.iter().map(|p| p[d]).sum::<f64>() / members.len() as f64;
            }
        }
        if settled {
            break;
        }
    }
    let cost = (points.iter().zip(&labels))
        .map(|(p, &l)| squared(p, &centres[l]))
        .sum();
    (cost, labels)
}

/// Give each category left empty the point farthest from its own centre
/// among those of categories of more than one point, so that k categories
/// stay k, as the crate's k-means does (n >= k, so there is always one).
fn refill_empty(points: &[Vec<f64>], centres: &[Vec<f64>], labels: &mut [usize], k: usize) {
    let mut counts = vec![0usize; k];
    for &l in labels.iter() {
        counts[l] += 1;
    }
    for c in 0..k {
        if counts[c] > 0 {
            continue;
        }
        let off = |i: usize| squared(&points[i], &centres[labels[i]]);
        let farthest = (0..points.len())
            .filter(|&i| counts[labels[i]] > 1)
            .max_by(|&a, &b| off(a).total_cmp(&off(b)).then(b.cmp(&a)));
        if let Some(i) = farthest {
            counts[labels[i]] -= 1;
            labels[i] = c;
            counts[c] = 1;
        }
    }
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
        // All scans the same: every affinity 1, so the normalised affinity
        // is (J - I) / (n - 1), of eigenvalues 1 and -1 / (n - 1); any split
        // is as good, and k categories stay k.
        let same = DistanceMatrix::from_fn(5, |_, _| 0.0);
        let r = Spectral::fit(&same, &SpectralParams::new(2)).unwrap();
        assert!(
            (r.eigenvalues[0] - 1.0).abs() < 1e-12,
            "{:?}",
            r.eigenvalues
        );
        assert!(
            (r.eigenvalues[1] + 0.25).abs() < 1e-12,
            "{:?}",
            r.eigenvalues
        );
        let mut seen = r.labels.clone();
        seen.sort();
        seen.dedup();
        assert_eq!(seen, vec![0, 1], "{:?}", r.labels);
    }

    #[test]
    fn copies_take_the_scale_of_their_nearest_other_scans() {
        // Ten copies at the centre of a ring of 20: counted as neighbours,
        // the copies would have a scale of 0, be joined to nothing but each
        // other and make a second group (a second eigenvalue of 1).
        let mut points = ring(20, 1.0);
        points.extend(vec![[0.0, 0.0]; 10]);
        let r = Spectral::fit(&matrix_of(&points), &SpectralParams::new(2)).unwrap();
        assert!((r.eigenvalues[0] - 1.0).abs() < 1e-9, "{:?}", r.eigenvalues);
        assert!(r.eigenvalues[1] < 0.99, "{:?}", r.eigenvalues);
    }

    #[test]
    fn a_scan_joined_to_nothing_is_still_placed_and_k_stays_k() {
        // Twelve scans round a ring and one a million away: its affinity to
        // every other underflows to 0, so its point in the embedding is 0.
        let mut points = ring(12, 1.0);
        points.push([1e6, 0.0]);
        for k in [2, 3] {
            let r = Spectral::fit(&matrix_of(&points), &SpectralParams::new(k)).unwrap();
            assert_eq!(r.labels.len(), 13);
            assert!(r.cost.is_finite() && r.eigenvalues.iter().all(|e| e.is_finite()));
            let top = *r.labels.iter().max().unwrap();
            assert_eq!(top, k as i32 - 1, "{:?}", r.labels);
        }
        // Two scans in two categories; k = n.
        let two = matrix_of(&[[0.0, 0.0], [1.0, 0.0]]);
        let r = Spectral::fit(&two, &SpectralParams::new(2)).unwrap();
        assert_eq!(r.labels, vec![0, 1]);
        let five = matrix_of(&ring(5, 1.0));
        let mut all = Spectral::fit(&five, &SpectralParams::new(5))
            .unwrap()
            .labels;
        all.sort();
        assert_eq!(all, vec![0, 1, 2, 3, 4]);
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
        assert!(e.contains("(2, 3) is NaN, not a finite Delta"), "{e}");
        let mut short = m.clone();
        short.data.pop();
        let e = Spectral::fit(&short, &SpectralParams::new(2))
            .unwrap_err()
            .to_string();
        assert!(e.contains("24 values for 5 scans"), "{e}");
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
