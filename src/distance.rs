//! The distance Delta between descriptors (paper Eq. 2, 3):
//!
//! ```text
//! delta(F, G) = sum_i || f_i/|F| - g_i/|G| ||_2 * max(|F|,|G|) / min(|F|,|G|)
//! Delta(X1, X2) = min over F in X1, G in X2 of delta(F, G)
//! ```
//!
//! Options: per-column normalisation, and Hellinger / chi-squared in place of
//! the column-wise L2 (the size factor max/min is kept for all metrics).

use crate::descriptor::{Descriptor, DescriptorParams, Metric, Normalisation};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// How two descriptors are compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct DistanceOptions {
    pub normalisation: Normalisation,
    pub metric: Metric,
}

impl Default for DistanceOptions {
    fn default() -> Self {
        DistanceOptions {
            normalisation: Normalisation::Total,
            metric: Metric::Paper,
        }
    }
}

impl From<&DescriptorParams> for DistanceOptions {
    fn from(p: &DescriptorParams) -> Self {
        DistanceOptions {
            normalisation: p.normalisation,
            metric: p.metric,
        }
    }
}

/// A descriptor with its matrices normalised once, for many comparisons.
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared {
    pub rows: usize,
    pub cols: usize,
    /// |F|.
    pub total: f32,
    /// Normalised matrices, column-major (each range interval's class
    /// counts contiguous, so the per-column norm of Eq. 2 reads memory in
    /// order; measured in benches/stages.rs, delta_matrix).
    pub matrices: Vec<Vec<f32>>,
}

/// Row-major rows x cols to column-major.
fn transpose(m: &[f32], rows: usize, cols: usize) -> Vec<f32> {
    let mut out = vec![0f32; m.len()];
    for r in 0..rows {
        for c in 0..cols {
            out[c * rows + r] = m[r * cols + c];
        }
    }
    out
}

impl Prepared {
    pub fn new(d: &Descriptor, opts: DistanceOptions) -> Result<Prepared> {
        d.validate()?;
        let total = d.total() as f32;
        let matrices = d
            .matrices
            .iter()
            .map(|m| {
                transpose(
                    &normalise(m, d.rows, d.cols, opts.normalisation),
                    d.rows,
                    d.cols,
                )
            })
            .collect();
        Ok(Prepared {
            rows: d.rows,
            cols: d.cols,
            total,
            matrices,
        })
    }
}

/// Normalise one count matrix.
pub fn normalise(m: &[u32], rows: usize, cols: usize, how: Normalisation) -> Vec<f32> {
    match how {
        Normalisation::Total => {
            let t: u64 = m.iter().map(|&v| v as u64).sum();
            let inv = if t > 0 { 1.0 / t as f32 } else { 0.0 };
            m.iter().map(|&v| v as f32 * inv).collect()
        }
        Normalisation::PerColumn => {
            let mut out = vec![0f32; m.len()];
            for c in 0..cols {
                let t: u64 = (0..rows).map(|r| m[r * cols + c] as u64).sum();
                if t > 0 {
                    for r in 0..rows {
                        out[r * cols + c] = m[r * cols + c] as f32 / t as f32;
                    }
                }
            }
            out
        }
    }
}

/// Distance between two normalised column-major matrices (as in
/// [`Prepared`]), before the size factor.
#[inline]
pub fn matrix_distance(a: &[f32], b: &[f32], rows: usize, cols: usize, metric: Metric) -> f32 {
    matrix_distance_below(a, b, rows, cols, metric, f32::INFINITY)
}

/// As [`matrix_distance`], but may stop early and return any value >=
/// `bound` once the distance is known to reach it (every term is >= 0).
#[inline]
pub fn matrix_distance_below(
    a: &[f32],
    b: &[f32],
    rows: usize,
    cols: usize,
    metric: Metric,
    bound: f32,
) -> f32 {
    match metric {
        Metric::Paper => {
            let mut sum = 0f32;
            for (ca, cb) in a.chunks_exact(rows).zip(b.chunks_exact(rows)).take(cols) {
                let sq: f32 = ca.iter().zip(cb).map(|(x, y)| (x - y) * (x - y)).sum();
                sum += sq.sqrt();
                if sum >= bound {
                    return sum;
                }
            }
            sum
        }
        Metric::Hellinger => {
            let s: f32 = a
                .iter()
                .zip(b)
                .map(|(x, y)| (x.sqrt() - y.sqrt()).powi(2))
                .sum();
            (0.5 * s).sqrt()
        }
        Metric::ChiSquared => {
            0.5 * a
                .iter()
                .zip(b)
                .map(|(x, y)| {
                    if x + y > 0.0 {
                        (x - y).powi(2) / (x + y)
                    } else {
                        0.0
                    }
                })
                .sum::<f32>()
        }
    }
}

/// The size factor max(|F|,|G|) / min(|F|,|G|).
#[inline]
pub fn size_factor(ta: f32, tb: f32) -> f32 {
    ta.max(tb) / ta.min(tb)
}

/// Delta between two prepared descriptors.
pub fn delta_prepared(a: &Prepared, b: &Prepared, metric: Metric) -> f32 {
    let mut best = f32::INFINITY;
    for fa in &a.matrices {
        for fb in &b.matrices {
            best = best.min(matrix_distance_below(fa, fb, a.rows, a.cols, metric, best));
        }
    }
    best * size_factor(a.total, b.total)
}

fn check_shapes(a: &Descriptor, b: &Descriptor) -> Result<()> {
    if a.rows != b.rows || a.cols != b.cols {
        return Err(Error::Mismatch(format!(
            "descriptors of different shapes ({}x{} and {}x{}): made with different parameters",
            a.rows, a.cols, b.rows, b.cols
        )));
    }
    Ok(())
}

/// Delta between two descriptors.
pub fn delta(a: &Descriptor, b: &Descriptor, opts: DistanceOptions) -> Result<f32> {
    check_shapes(a, b)?;
    Ok(delta_prepared(
        &Prepared::new(a, opts)?,
        &Prepared::new(b, opts)?,
        opts.metric,
    ))
}

/// A symmetric n x n matrix of Delta, row-major, zero diagonal.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DistanceMatrix {
    pub n: usize,
    pub data: Vec<f32>,
}

impl DistanceMatrix {
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> f32 {
        self.data[i * self.n + j]
    }

    /// Build from a function of (i, j), i < j, each pair computed once.
    pub fn from_fn(n: usize, f: impl Fn(usize, usize) -> f32 + Sync) -> DistanceMatrix {
        let rows: Vec<Vec<f32>> = {
            let row = |i: usize| ((i + 1)..n).map(|j| f(i, j)).collect::<Vec<f32>>();
            #[cfg(not(target_arch = "wasm32"))]
            {
                use rayon::prelude::*;
                (0..n).into_par_iter().map(row).collect()
            }
            #[cfg(target_arch = "wasm32")]
            {
                (0..n).map(row).collect()
            }
        };
        let mut data = vec![0f32; n * n];
        for (i, r) in rows.into_iter().enumerate() {
            for (k, v) in r.into_iter().enumerate() {
                let j = i + 1 + k;
                data[i * n + j] = v;
                data[j * n + i] = v;
            }
        }
        DistanceMatrix { n, data }
    }
}

/// Prepare many descriptors, checking they share one shape.
pub fn prepare_all(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<Vec<Prepared>> {
    if let Some(first) = descriptors.first() {
        for d in descriptors {
            check_shapes(first, d)?;
        }
    }
    descriptors
        .iter()
        .enumerate()
        .map(|(i, d)| Prepared::new(d, opts).map_err(|e| e.in_file(format!("descriptor {i}"))))
        .collect()
}

/// The full pairwise Delta matrix (parallel natively).
pub fn delta_matrix(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<DistanceMatrix> {
    Ok(crate::cluster::Space::new(descriptors, opts)?.matrix())
}
