//! The distance Delta between descriptors (paper Eq. 2, 3):
//!
//! ```text
//! delta(F, G) = sum_i || f_i/|F| - g_i/|G| ||_2 * max(|F|,|G|) / min(|F|,|G|)
//! Delta(X1, X2) = min over F in X1, G in X2 of delta(F, G)
//! ```
//!
//! Options: per-column normalisation, and Hellinger / chi-squared in place of
//! the column-wise L2 (the size factor max/min is kept for all metrics).
//!
//! With extra parts (issue 18, `descriptor::parts`), the distance is
//! `ndt_weight * Delta + sum_k weight_k * d_k`, each part's d_k in [0, 1]
//! (channel-wise earth mover's distance over its largest value); with
//! `ndt_weight` 1 and no parts it is Delta, bit for bit.
//!
//! - `prepared`: descriptors normalised and padded once;
//! - `kernel`: the one loop per metric, and Delta between prepared items;
//! - `matrix`: the n x n Delta matrix;
//! - `space`: prepared items with their metric, and cluster centres;
//! - `scale`: each term sized by its median over the collection (optional).

mod kernel;
mod matrix;
mod prepared;
pub mod scale;
mod space;

pub use kernel::{delta_prepared, matrix_distance, matrix_distance_below, size_factor};
pub use matrix::DistanceMatrix;
pub use prepared::{normalise, pad, prepare_all, unpad, Prepared};
pub use space::{Centre, Space};

use crate::descriptor::parts::MAX_PARTS;
use crate::descriptor::{Descriptor, DescriptorParams, Metric, Normalisation, Scale};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// How two descriptors are compared.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DistanceOptions {
    /// How each matrix F is normalised (by |F|, or per column).
    pub normalisation: Normalisation,
    /// The distance between two normalised matrices.
    pub metric: Metric,
    /// Weight of Delta (1: the paper's distance).
    #[serde(default = "one")]
    pub ndt_weight: f32,
    /// Weight of each kind of extra part, indexed by
    /// [`PartKind::index`](crate::descriptor::PartKind::index) (0: not used).
    #[serde(default)]
    pub part_weights: [f32; MAX_PARTS],
    /// How the terms are sized before weighting; a [`Space`] resolves
    /// [`Scale::Median`] into weights ([`scale::resolve`]).
    #[serde(default)]
    pub scale: Scale,
}

fn one() -> f32 {
    1.0
}

impl Default for DistanceOptions {
    fn default() -> Self {
        DistanceOptions {
            normalisation: Normalisation::Total,
            metric: Metric::Paper,
            ndt_weight: 1.0,
            part_weights: [0.0; MAX_PARTS],
            scale: Scale::Fixed,
        }
    }
}

impl From<&DescriptorParams> for DistanceOptions {
    fn from(p: &DescriptorParams) -> Self {
        let mut part_weights = [0.0; MAX_PARTS];
        for part in &p.parts {
            part_weights[part.kind.index()] = part.weight as f32;
        }
        DistanceOptions {
            normalisation: p.normalisation,
            metric: p.metric,
            ndt_weight: p.ndt_weight as f32,
            part_weights,
            scale: p.scale,
        }
    }
}

/// The one shape check, for distances and models: a descriptor of `found`
/// (rows, cols) where `expected` (another descriptor's, or a model's) is
/// needed.
pub(crate) fn check_shape(found: (usize, usize), expected: (usize, usize)) -> Result<()> {
    if found != expected {
        return Err(Error::Mismatch(format!(
            "descriptors of different shapes ({}x{} and {}x{}): made with different parameters",
            found.0, found.1, expected.0, expected.1
        )));
    }
    Ok(())
}

/// Two prepared descriptors must hold the same parts to be compared.
pub(crate) fn check_parts(a: &Prepared, b: &Prepared) -> Result<()> {
    if a.part_kinds != b.part_kinds {
        return Err(Error::Mismatch(format!(
            "descriptors with different parts ({:?} and {:?}): made with different parameters",
            a.part_kinds, b.part_kinds
        )));
    }
    Ok(())
}

/// Delta between two descriptors.
pub fn delta(a: &Descriptor, b: &Descriptor, opts: DistanceOptions) -> Result<f32> {
    check_shape((a.rows, a.cols), (b.rows, b.cols))?;
    let (pa, pb) = (Prepared::new(a, opts)?, Prepared::new(b, opts)?);
    check_parts(&pa, &pb)?;
    Ok(delta_prepared(&pa, &pb, opts.metric))
}

/// The full pairwise Delta matrix (parallel natively).
pub fn delta_matrix(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<DistanceMatrix> {
    Ok(Space::new(descriptors, opts)?.matrix())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn random_descriptor(r: &mut rand_chacha::ChaCha8Rng, rows: usize, cols: usize) -> Descriptor {
        let candidates = r.random_range(1..5);
        Descriptor {
            rows,
            cols,
            matrices: (0..candidates)
                .map(|_| (0..rows * cols).map(|_| r.random_range(0..40)).collect())
                .collect(),
            summary: Default::default(),
            parts: Vec::new(),
        }
    }

    /// 11 x 7 matrices are held once, padded to 12 x 7 = 84 floats.
    #[test]
    fn a_prepared_descriptor_holds_each_candidate_once_padded() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(2);
        let d = random_descriptor(&mut r, 11, 7);
        let p = Prepared::new(&d, DistanceOptions::default()).unwrap();
        let n = d.matrices.len();
        assert_eq!(p.stride, 12);
        assert_eq!(p.heap_bytes(), n * 84 * 4);
        assert_eq!(p.candidates().len(), n);
        for (k, m) in d.matrices.iter().enumerate() {
            // Row-major counts in, normalised column-major out: entry
            // (row 3, column 5) is at 5 * 11 + 3 unpadded, 5 * 12 + 3 padded.
            let total: u32 = m.iter().sum();
            let want = m[3 * 7 + 5] as f32 / total as f32;
            let unpadded = unpad(p.candidate(k), 11, 12);
            assert_eq!(unpadded[5 * 11 + 3], want);
            assert_eq!(p.candidate(k)[5 * 12 + 3], want);
            assert_eq!(p.candidates().nth(k).unwrap(), p.candidate(k));
            assert_eq!(pad(&unpadded, 11, 12), p.candidate(k));
        }
    }

    /// Zero rows change no metric: Hellinger and chi-squared give the same
    /// value on padded and unpadded matrices.
    #[test]
    fn every_metric_ignores_the_padding() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for metric in [Metric::Paper, Metric::Hellinger, Metric::ChiSquared] {
            let opts = DistanceOptions {
                metric,
                ..DistanceOptions::default()
            };
            let (a, b) = (
                random_descriptor(&mut r, 11, 7),
                random_descriptor(&mut r, 11, 7),
            );
            let (pa, pb) = (
                Prepared::new(&a, opts).unwrap(),
                Prepared::new(&b, opts).unwrap(),
            );
            let (fa, fb) = (pa.candidate(0), pb.candidate(0));
            let plain = matrix_distance(&unpad(fa, 11, 12), &unpad(fb, 11, 12), 11, 7, metric);
            let padded = matrix_distance(fa, fb, 12, 7, metric);
            assert_eq!(plain, padded, "{metric:?}");
            assert!(plain > 0.0);
        }
    }

    /// The Hellinger option on counts worked by hand: F = [[1, 3]] (|F| 4)
    /// and G = [[4, 0], [0, 4]] (|G| 8, one more row of zeros in F's
    /// shape): sqrt(1/2 ((1/2 - sqrt(1/2))^2 + (sqrt(3)/2 - 0)^2 +
    /// (0 - sqrt(1/2))^2)) = sqrt(1 - sqrt(1/8)) = 0.80402..., times the
    /// size factor 8/4 = 2.
    #[test]
    fn hellinger_on_counts_worked_by_hand() {
        let one = |m: Vec<u32>| Descriptor {
            rows: 2,
            cols: 2,
            matrices: vec![m],
            summary: Default::default(),
            parts: Vec::new(),
        };
        // Row-major: F = [[1, 3], [0, 0]], G = [[4, 0], [0, 4]].
        let (f, g) = (one(vec![1, 3, 0, 0]), one(vec![4, 0, 0, 4]));
        let opts = DistanceOptions {
            metric: Metric::Hellinger,
            ..DistanceOptions::default()
        };
        let (pf, pg) = (
            Prepared::new(&f, opts).unwrap(),
            Prepared::new(&g, opts).unwrap(),
        );
        let want = 2.0 * (1.0 - (1.0f64 / 8.0).sqrt()).sqrt();
        let got = delta_prepared(&pf, &pg, Metric::Hellinger) as f64;
        assert!((got - want).abs() < 1e-6, "{got} against {want}");
        // Identical histograms of any size are at 0 before the size factor.
        let f2 = one(vec![2, 6, 0, 0]);
        let pf2 = Prepared::new(&f2, opts).unwrap();
        assert_eq!(delta_prepared(&pf, &pf2, Metric::Hellinger), 0.0);
    }

    #[test]
    fn nearest_other_skips_the_scan_itself() {
        // Distances 0-1: 1.0, 0-2: 0.5, 1-2: 2.0.
        let m = DistanceMatrix::from_fn(3, |i, j| [[0.0, 1.0, 0.5], [0.0, 0.0, 2.0]][i][j]);
        assert_eq!(m.nearest_other(0), Some(2));
        assert_eq!(m.nearest_other(1), Some(0));
        assert_eq!(m.nearest_other(2), Some(0));
        assert_eq!(
            DistanceMatrix::from_fn(1, |_, _| 0.0).nearest_other(0),
            None
        );
    }

    /// The padded, unrolled path of `delta_prepared` must give exactly the
    /// minimum of `matrix_distance` over candidate pairs, for every shape:
    /// strides 4 to 16 (unrolled) and 20 and more (the general loop). For
    /// Hellinger that path compares the roots taken once
    /// ([`Prepared::roots`]) and stops early; `matrix_distance` takes them
    /// in the kernel and never stops: the same value to the bit.
    #[test]
    fn padded_delta_equals_the_plain_definition_for_every_shape() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        for metric in [Metric::Paper, Metric::Hellinger] {
            for rows in [1, 3, 4, 5, 8, 11, 12, 13, 16, 17, 21, 44] {
                for _ in 0..20 {
                    let cols = r.random_range(1..9);
                    let (a, b) = (
                        random_descriptor(&mut r, rows, cols),
                        random_descriptor(&mut r, rows, cols),
                    );
                    let opts = DistanceOptions {
                        metric,
                        ..DistanceOptions::default()
                    };
                    let (pa, pb) = (
                        Prepared::new(&a, opts).unwrap(),
                        Prepared::new(&b, opts).unwrap(),
                    );
                    assert_eq!(pa.roots.is_empty(), metric != Metric::Hellinger);
                    let mut plain = f32::INFINITY;
                    for ka in 0..a.matrices.len() {
                        for kb in 0..b.matrices.len() {
                            let fa = unpad(pa.candidate(ka), rows, pa.stride);
                            let fb = unpad(pb.candidate(kb), rows, pb.stride);
                            plain = plain.min(matrix_distance(&fa, &fb, rows, cols, metric));
                        }
                    }
                    let plain = plain * size_factor(pa.total, pb.total);
                    assert_eq!(
                        delta_prepared(&pa, &pb, metric),
                        plain,
                        "{metric:?} {rows} x {cols}"
                    );
                }
            }
        }
    }
}
