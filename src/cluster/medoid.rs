//! The most central scan of each category (for thumbnails and names).

use crate::distance::Space;
use rand::seq::index::sample;

/// For each category label >= 0 (ascending), the member with the smallest
/// summed Delta to the others: exact for categories of up to `max_sample`
/// scans, else to `max_sample` members drawn with the seeded RNG, so the
/// cost is O(n * max_sample) and needs no n x n matrix.
pub fn medoids(space: &Space, labels: &[i32], max_sample: usize, seed: u64) -> Vec<(i32, usize)> {
    medoids_by(labels, max_sample, seed, |i, j| space.delta(i, j))
}

/// [`medoids`] with Delta(i, j) from `delta`: a Delta matrix's values give
/// the same medoids without computing Delta again (the page's cut of 1,000
/// scans into 3 spent 64,000 Deltas here, 80 ms of its main thread).
pub fn medoids_by(
    labels: &[i32],
    max_sample: usize,
    seed: u64,
    delta: impl Fn(usize, usize) -> f32,
) -> Vec<(i32, usize)> {
    let mut ids: Vec<i32> = labels.iter().copied().filter(|&l| l >= 0).collect();
    ids.sort_unstable();
    ids.dedup();
    let mut r = crate::rng::rng(seed);
    ids.into_iter()
        .map(|id| {
            let members: Vec<usize> = (0..labels.len()).filter(|&i| labels[i] == id).collect();
            let probe: Vec<usize> = if members.len() <= max_sample.max(1) {
                members.clone()
            } else {
                sample(&mut r, members.len(), max_sample.max(1))
                    .into_iter()
                    .map(|k| members[k])
                    .collect()
            };
            let best = members
                .iter()
                .copied()
                .map(|m| (m, probe.iter().map(|&p| delta(m, p) as f64).sum::<f64>()))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map_or(members[0], |(m, _)| m);
            (id, best)
        })
        .collect()
}
