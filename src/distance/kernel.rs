//! The metric kernel: one loop per metric over two normalised, padded
//! column-major matrices, used by the Delta matrix, by distances to cluster
//! centres and by models alike.

use super::Prepared;
use crate::descriptor::Metric;

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
    debug_assert!(a.len() == rows * cols && b.len() == rows * cols);
    kernel::<0, false>(a, b, rows, metric, bound)
}

/// The kernel. `CHUNKS` is `rows / 4` when the caller knows it (the
/// compiler then unrolls the columns of the usual shapes: 11 rows padded
/// to 12 -> 3 chunks of 4), or 0 for any number of rows. `ROOTED`: for
/// Hellinger, `a` and `b` are already square roots ([`Prepared::roots`]);
/// the same operations in the same order follow, so the value is the same
/// to the bit.
#[inline]
fn kernel<const CHUNKS: usize, const ROOTED: bool>(
    a: &[f32],
    b: &[f32],
    rows: usize,
    metric: Metric,
    bound: f32,
) -> f32 {
    match metric {
        Metric::Paper => {
            let rows = if CHUNKS > 0 { 4 * CHUNKS } else { rows };
            let mut sum = 0f32;
            for (ca, cb) in a.chunks_exact(rows).zip(b.chunks_exact(rows)) {
                sum += squared_l2(ca, cb).sqrt();
                if sum >= bound {
                    return sum;
                }
            }
            sum
        }
        Metric::Hellinger => {
            // Column by column in four lanes, as the paper's metric, and
            // stop once half the sum reaches bound^2. The Delta matrix of
            // 1,000 outdoor scans took 3.7 s of CPU summing the whole
            // matrix in order with the roots taken here, 2.0 s in lanes,
            // and 0.6 s with the roots taken once (`Prepared::roots`),
            // against the paper metric's 0.5 s (docs/hellinger.md).
            let rows = if CHUNKS > 0 { 4 * CHUNKS } else { rows };
            let stop = 2.0 * bound * bound;
            let mut sum = 0f32;
            for (ca, cb) in a.chunks_exact(rows).zip(b.chunks_exact(rows)) {
                sum += if ROOTED {
                    squared_l2(ca, cb)
                } else {
                    lane_sum(ca, cb, |x, y| {
                        let d = x.sqrt() - y.sqrt();
                        d * d
                    })
                };
                if sum >= stop {
                    // Rounding must not take it under the bound.
                    return (0.5 * sum).sqrt().max(bound);
                }
            }
            (0.5 * sum).sqrt()
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

/// Squared Euclidean distance in four independent lanes (see [`lane_sum`]).
#[inline]
fn squared_l2(a: &[f32], b: &[f32]) -> f32 {
    lane_sum(a, b, |x, y| {
        let d = x - y;
        d * d
    })
}

/// The sum of `term(a[i], b[i])` in four independent lanes: a plain `sum()`
/// of f32 must keep its order, so the compiler cannot use SIMD for it; four
/// lanes let it. A short last chunk goes to the first lanes, so a column
/// padded with zeros to a multiple of four (as in [`Prepared::padded`])
/// gives exactly the same value when `term(0, 0)` is 0.
#[inline(always)]
fn lane_sum(a: &[f32], b: &[f32], term: impl Fn(f32, f32) -> f32) -> f32 {
    let mut lanes = [0f32; 4];
    let (a4, b4) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (a4.remainder(), b4.remainder());
    for (x, y) in a4.zip(b4) {
        for k in 0..4 {
            lanes[k] += term(x[k], y[k]);
        }
    }
    for (k, (x, y)) in ra.iter().zip(rb).enumerate() {
        lanes[k] += term(*x, *y);
    }
    (lanes[0] + lanes[2]) + (lanes[1] + lanes[3])
}

/// The size factor max(|F|,|G|) / min(|F|,|G|).
#[inline]
pub fn size_factor(ta: f32, tb: f32) -> f32 {
    ta.max(tb) / ta.min(tb)
}

/// Delta between two prepared descriptors, on the padded buffers: the
/// Delta matrix of 3,000 simulated indoor descriptors on one core took
/// 1.28-1.42 s summing each column in order and 0.95-1.05 s padded, in
/// four lanes, unrolled (callgrind: half the instructions of four lanes on
/// unpadded columns). Same values either way.
///
/// With extra parts: `ndt_weight` times that, plus the weighted part
/// distances ([`crate::descriptor::parts::parts_distance`]); the NDT histogram is not compared at all
/// when its weight is 0.
pub fn delta_prepared(a: &Prepared, b: &Prepared, metric: Metric) -> f32 {
    a.combined(|| ndt_delta(a, b, metric), &b.parts)
}

/// Delta of the NDT histograms alone (paper Eq. 2, 3).
fn ndt_delta(a: &Prepared, b: &Prepared, metric: Metric) -> f32 {
    let best = match a.stride / 4 {
        1 => best_pair::<1>(a, b, metric),
        2 => best_pair::<2>(a, b, metric),
        3 => best_pair::<3>(a, b, metric),
        4 => best_pair::<4>(a, b, metric),
        _ => best_pair::<0>(a, b, metric),
    };
    best * size_factor(a.total, b.total)
}

/// The smallest kernel distance over candidate pairs, each pair stopping
/// once it reaches the best so far.
#[inline]
fn best_pair<const CHUNKS: usize>(a: &Prepared, b: &Prepared, metric: Metric) -> f32 {
    let mut best = f32::INFINITY;
    if metric == Metric::Hellinger && !a.roots.is_empty() && !b.roots.is_empty() {
        for fa in a.root_candidates() {
            for fb in b.root_candidates() {
                best = best.min(kernel::<CHUNKS, true>(fa, fb, a.stride, metric, best));
            }
        }
    } else {
        for fa in a.candidates() {
            for fb in b.candidates() {
                best = best.min(kernel::<CHUNKS, false>(fa, fb, a.stride, metric, best));
            }
        }
    }
    best
}
