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
    /// The normalised matrices of every candidate orientation, one after
    /// another in one buffer, column-major (each range interval's class
    /// counts contiguous, so the per-column norm of Eq. 2 reads memory in
    /// order; measured in benches/stages.rs, delta_matrix), each column
    /// padded with zeros to `stride` (a multiple of 4) rows: the Delta
    /// matrix's inner loop then runs on whole SIMD lanes and one allocation
    /// (measured: see [`delta_prepared`]). Every metric gives the same
    /// value with or without the zero rows, so this is the only copy.
    pub padded: Vec<f32>,
    pub stride: usize,
}

/// A column-major rows x cols matrix with each column padded with zeros to
/// `stride` rows.
pub fn pad(m: &[f32], rows: usize, stride: usize) -> Vec<f32> {
    let cols = m.len() / rows.max(1);
    let mut out = vec![0f32; stride * cols];
    for (col, to) in m.chunks_exact(rows).zip(out.chunks_exact_mut(stride)) {
        to[..rows].copy_from_slice(col);
    }
    out
}

/// The inverse of [`pad`]: the first `rows` of every `stride`.
pub fn unpad(m: &[f32], rows: usize, stride: usize) -> Vec<f32> {
    m.chunks_exact(stride)
        .flat_map(|col| &col[..rows])
        .copied()
        .collect()
}

/// Row-major rows x cols to column-major with each column padded with
/// zeros to `stride` rows, appended to `out`.
fn extend_column_major_padded(
    out: &mut Vec<f32>,
    m: &[f32],
    rows: usize,
    cols: usize,
    stride: usize,
) {
    let start = out.len();
    out.resize(start + stride * cols, 0.0);
    for r in 0..rows {
        for c in 0..cols {
            out[start + c * stride + r] = m[r * cols + c];
        }
    }
}

impl Prepared {
    pub fn new(d: &Descriptor, opts: DistanceOptions) -> Result<Prepared> {
        d.validate()?;
        let total = d.total() as f32;
        let stride = d.rows.next_multiple_of(4);
        let mut padded = Vec::with_capacity(stride * d.cols * d.matrices.len());
        for m in &d.matrices {
            let normalised = normalise(m, d.rows, d.cols, opts.normalisation);
            extend_column_major_padded(&mut padded, &normalised, d.rows, d.cols, stride);
        }
        Ok(Prepared {
            rows: d.rows,
            cols: d.cols,
            total,
            padded,
            stride,
        })
    }

    /// The candidate orientations' padded matrices (`stride` x `cols`).
    pub fn candidates(&self) -> std::slice::ChunksExact<'_, f32> {
        self.padded.chunks_exact(self.stride * self.cols)
    }

    /// Candidate k's padded matrix (`stride` x `cols`).
    pub fn candidate(&self, k: usize) -> &[f32] {
        let size = self.stride * self.cols;
        &self.padded[k * size..(k + 1) * size]
    }

    /// Bytes this item holds on the heap; `examples/scaling.rs` reports it
    /// beside the Delta matrix's size.
    pub fn heap_bytes(&self) -> usize {
        self.padded.capacity() * std::mem::size_of::<f32>()
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
                sum += squared_l2(ca, cb).sqrt();
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

/// Squared Euclidean distance in four independent lanes: a plain `sum()`
/// of f32 must keep its order, so the compiler cannot use SIMD for it; four
/// lanes let it. A short last chunk goes to the first lanes, so a column
/// padded with zeros to a multiple of four (as in [`Prepared::padded`])
/// gives exactly the same value.
#[inline]
fn squared_l2(a: &[f32], b: &[f32]) -> f32 {
    let mut lanes = [0f32; 4];
    let (a4, b4) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (a4.remainder(), b4.remainder());
    for (x, y) in a4.zip(b4) {
        for k in 0..4 {
            let d = x[k] - y[k];
            lanes[k] += d * d;
        }
    }
    for (k, (x, y)) in ra.iter().zip(rb).enumerate() {
        lanes[k] += (x - y) * (x - y);
    }
    (lanes[0] + lanes[2]) + (lanes[1] + lanes[3])
}

/// The size factor max(|F|,|G|) / min(|F|,|G|).
#[inline]
pub fn size_factor(ta: f32, tb: f32) -> f32 {
    ta.max(tb) / ta.min(tb)
}

/// Delta between two prepared descriptors. With the paper's metric it runs
/// on the padded buffers: the Delta matrix of 3,000 simulated indoor
/// descriptors on one core took 1.28-1.42 s summing each column in order
/// and 0.95-1.05 s padded, in four lanes, unrolled (callgrind: half the
/// instructions of four lanes on unpadded columns). Same values either way.
pub fn delta_prepared(a: &Prepared, b: &Prepared, metric: Metric) -> f32 {
    let best = if metric == Metric::Paper {
        // A fixed number of lanes lets the compiler unroll the columns of
        // the usual shapes (11 rows -> 3 chunks of 4).
        match a.stride / 4 {
            1 => best_padded_pair::<1>(a, b),
            2 => best_padded_pair::<2>(a, b),
            3 => best_padded_pair::<3>(a, b),
            4 => best_padded_pair::<4>(a, b),
            _ => best_padded_pair::<0>(a, b),
        }
    } else {
        let mut best = f32::INFINITY;
        for fa in a.candidates() {
            for fb in b.candidates() {
                best = best.min(matrix_distance_below(
                    fa, fb, a.stride, a.cols, metric, best,
                ));
            }
        }
        best
    };
    best * size_factor(a.total, b.total)
}

/// The smallest Eq. 2 distance over candidate pairs, on the padded buffers.
#[inline]
fn best_padded_pair<const CHUNKS: usize>(a: &Prepared, b: &Prepared) -> f32 {
    let size = a.stride * a.cols;
    let mut best = f32::INFINITY;
    for fa in a.padded.chunks_exact(size) {
        for fb in b.padded.chunks_exact(size) {
            best = best.min(paper_distance_below::<CHUNKS>(fa, fb, a.stride, best));
        }
    }
    best
}

/// Eq. 2 before the size factor on padded matrices, stopping once it
/// reaches `bound`. `CHUNKS`: stride / 4, or 0 for any stride.
#[inline]
fn paper_distance_below<const CHUNKS: usize>(
    a: &[f32],
    b: &[f32],
    stride: usize,
    bound: f32,
) -> f32 {
    let stride = if CHUNKS > 0 { 4 * CHUNKS } else { stride };
    let mut sum = 0f32;
    for (ca, cb) in a.chunks_exact(stride).zip(b.chunks_exact(stride)) {
        sum += squared_l2(ca, cb).sqrt();
        if sum >= bound {
            return sum;
        }
    }
    sum
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

    /// The scan nearest to scan i other than itself (the first of equals);
    /// None when there is no other scan.
    pub fn nearest_other(&self, i: usize) -> Option<usize> {
        (0..self.n)
            .filter(|&j| j != i)
            .min_by(|&a, &b| self.get(i, a).total_cmp(&self.get(i, b)))
    }

    /// Build from a function of (i, j), i < j, each pair computed once.
    pub fn from_fn(n: usize, f: impl Fn(usize, usize) -> f32 + Sync) -> DistanceMatrix {
        // Each row's upper part is written in place (no row vectors to
        // allocate and copy: 50 MB of them at n = 5,000).
        let mut data = vec![0f32; n * n];
        let fill = |(i, row): (usize, &mut [f32])| {
            for (j, v) in row.iter_mut().enumerate().skip(i + 1) {
                *v = f(i, j);
            }
        };
        #[cfg(not(target_arch = "wasm32"))]
        {
            use rayon::prelude::*;
            data.par_chunks_mut(n.max(1)).enumerate().for_each(fill);
        }
        #[cfg(target_arch = "wasm32")]
        {
            data.chunks_mut(n.max(1)).enumerate().for_each(fill);
        }
        // Mirror into the lower triangle tile by tile: element by element,
        // every write would land in another cache line (0.1 s at n = 5,000).
        const TILE: usize = 64;
        for bi in (0..n).step_by(TILE) {
            for bj in (0..=bi).step_by(TILE) {
                for i in bi..(bi + TILE).min(n) {
                    for j in bj..(bj + TILE).min(i) {
                        data[i * n + j] = data[j * n + i];
                    }
                }
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
    /// strides 4 to 16 (unrolled) and 20 and more (the general loop).
    #[test]
    fn padded_delta_equals_the_plain_definition_for_every_shape() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        for rows in [1, 3, 4, 5, 8, 11, 12, 13, 16, 17, 21, 44] {
            for _ in 0..20 {
                let cols = r.random_range(1..9);
                let (a, b) = (
                    random_descriptor(&mut r, rows, cols),
                    random_descriptor(&mut r, rows, cols),
                );
                let opts = DistanceOptions::default();
                let (pa, pb) = (
                    Prepared::new(&a, opts).unwrap(),
                    Prepared::new(&b, opts).unwrap(),
                );
                let mut plain = f32::INFINITY;
                for ka in 0..a.matrices.len() {
                    for kb in 0..b.matrices.len() {
                        let fa = unpad(pa.candidate(ka), rows, pa.stride);
                        let fb = unpad(pb.candidate(kb), rows, pb.stride);
                        plain = plain.min(matrix_distance(&fa, &fb, rows, cols, Metric::Paper));
                    }
                }
                let plain = plain * size_factor(pa.total, pb.total);
                assert_eq!(
                    delta_prepared(&pa, &pb, Metric::Paper),
                    plain,
                    "{rows} x {cols}"
                );
            }
        }
    }
}
