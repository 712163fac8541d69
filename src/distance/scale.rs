//! Scaling each term of the combined distance by its typical size in the
//! collection (issue 18, ninth round).
//!
//! The combined distance is `ndt_weight * Delta + sum_k weight_k * d_k`.
//! Each d_k lies in [0, 1], but how far apart two scans typically are in a
//! part changes with the sensor and the scenes: with 16 beams a room's
//! contents are hit at fewer heights, so the height parts spread less and
//! fixed weights give them a smaller share than with 64. With
//! [`Scale::Median`], each term is divided by its median over the
//! collection's pairs of scans before it is weighted, as features are
//! standardised before k-means (e.g. Hastie, Tibshirani and Friedman, *The
//! Elements of Statistical Learning*, 2nd ed., section 14.3.3): a weight is
//! then the term's share of a typical distance, whatever the sensor.
//!
//! The medians are taken once, when a [`Space`](super::Space) is made, and
//! the weights they give are kept with it ([`Space::options`](super::Space::options)),
//! so a model built from the space classifies new scans with the same
//! weights ([`LabelledModel`](crate::model::LabelledModel)).

use super::{delta_prepared, prepare_all, DistanceOptions};
use crate::descriptor::parts::{cumulative_len, parts_distance, MAX_PARTS};
use crate::descriptor::{Descriptor, Scale};
use crate::error::Result;
use crate::rng::rng;
use rand::Rng;

/// Pairs the medians are taken over: every pair up to this many, else this
/// many drawn. The median of 20 000 drawn pairs is within about 1 % of the
/// whole set's (its standard error is about 1.25 / sqrt(20 000) standard
/// deviations), and it costs a small share of the n x n matrix.
const MEDIAN_PAIRS: usize = 20_000;

/// Seed of the drawn pairs: fixed, so every worker of the page, and every
/// run, finds the same weights for the same scans.
const PAIR_SEED: u64 = 0x5ca1e;

/// The pairs of `n` scans the medians are taken over.
fn pairs(n: usize) -> Vec<(usize, usize)> {
    if n < 2 {
        return Vec::new();
    }
    if n * (n - 1) / 2 <= MEDIAN_PAIRS {
        return (0..n)
            .flat_map(|i| ((i + 1)..n).map(move |j| (i, j)))
            .collect();
    }
    let mut r = rng(PAIR_SEED);
    (0..MEDIAN_PAIRS)
        .map(|_| {
            let i = r.random_range(0..n);
            let j = (i + r.random_range(1..n)) % n;
            (i, j)
        })
        .collect()
}

fn median(mut v: Vec<f32>) -> f32 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f32::total_cmp);
    v[v.len() / 2]
}

/// A term's weight divided by its median; a term whose median is 0 (most
/// pairs alike in it, or fewer than two scans) keeps its weight.
fn scaled(weight: f32, median: f32) -> f32 {
    if median > 0.0 && median.is_finite() {
        weight / median
    } else {
        weight
    }
}

/// `opts` fixed, with Delta's weight `ndt` and every part's `part`.
fn with_weights(opts: DistanceOptions, ndt: f32, part: f32) -> DistanceOptions {
    DistanceOptions {
        ndt_weight: ndt,
        part_weights: [part; MAX_PARTS],
        scale: Scale::Fixed,
        ..opts
    }
}

/// `opts` with [`Scale::Fixed`] and the weights that [`Scale::Median`]
/// gives on `descriptors`; `opts` as it is when it is fixed already.
pub fn resolve(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<DistanceOptions> {
    if opts.scale.is_fixed() {
        return Ok(opts);
    }
    let mut out = DistanceOptions {
        scale: Scale::Fixed,
        ..opts
    };
    let pairs = pairs(descriptors.len());
    if opts.ndt_weight > 0.0 {
        // Delta alone: every part at weight 0.
        let ndt = prepare_all(descriptors, with_weights(opts, 1.0, 0.0))?;
        let d = pairs
            .iter()
            .map(|&(i, j)| delta_prepared(&ndt[i], &ndt[j], opts.metric))
            .collect();
        out.ndt_weight = scaled(opts.ndt_weight, median(d));
    }
    // Every part at weight 1, each read from its own span of the
    // cumulative form.
    let parts = prepare_all(descriptors, with_weights(opts, 0.0, 1.0))?;
    let Some(first) = parts.first() else {
        return Ok(out);
    };
    let mut at = 0;
    for kind in &first.part_kinds {
        let span = at..at + cumulative_len(*kind);
        let d = pairs
            .iter()
            .map(|&(i, j)| {
                parts_distance(&parts[i].parts[span.clone()], &parts[j].parts[span.clone()])
            })
            .collect();
        let w = &mut out.part_weights[kind.index()];
        *w = scaled(*w, median(d));
        at = span.end;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::Space;
    use rand::SeedableRng;

    /// A descriptor of random counts, without parts.
    fn random_descriptor(r: &mut rand_chacha::ChaCha8Rng) -> Descriptor {
        Descriptor {
            rows: 6,
            cols: 3,
            matrices: vec![(0..18).map(|_| r.random_range(0..40)).collect()],
            summary: Default::default(),
            parts: Vec::new(),
        }
    }

    fn exact_median(space: &Space) -> f32 {
        let n = space.len();
        let all = (0..n).flat_map(|i| ((i + 1)..n).map(move |j| (i, j)));
        median(all.map(|(i, j)| space.delta(i, j)).collect())
    }

    #[test]
    fn small_sets_take_every_pair_and_large_ones_draw_distinct_scans() {
        assert!(pairs(1).is_empty());
        assert_eq!(
            pairs(4),
            vec![(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
        );
        assert_eq!(pairs(200).len(), 200 * 199 / 2);
        let drawn = pairs(1000);
        assert_eq!(drawn.len(), MEDIAN_PAIRS);
        assert!(drawn.iter().all(|&(i, j)| i != j && i < 1000 && j < 1000));
        assert_eq!(drawn, pairs(1000), "the same pairs every time");
    }

    /// Below the pair limit the weight is the exact median's inverse; above
    /// it (300 scans, 44 850 pairs, 20 000 drawn) within 3 % of it.
    #[test]
    fn the_median_weight_is_the_inverse_of_the_median_delta() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let ds: Vec<Descriptor> = (0..300).map(|_| random_descriptor(&mut r)).collect();
        let scaled = DistanceOptions {
            scale: Scale::Median,
            ..DistanceOptions::default()
        };
        for n in [50, 300] {
            let fixed = Space::new(&ds[..n], DistanceOptions::default()).unwrap();
            let want = 1.0 / exact_median(&fixed);
            let got = resolve(&ds[..n], scaled).unwrap();
            assert_eq!(got.scale, Scale::Fixed);
            let tolerance = if n == 50 { 1e-6 } else { 0.03 };
            assert!(
                (got.ndt_weight / want - 1.0).abs() <= tolerance,
                "{n} scans: {} against {want}",
                got.ndt_weight
            );
        }
    }

    /// A fixed scale is returned as it is, and one scan (no pair) keeps the
    /// weights it had.
    #[test]
    fn fixed_options_and_single_scans_keep_their_weights() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(8);
        let ds = vec![random_descriptor(&mut r), random_descriptor(&mut r)];
        let opts = DistanceOptions {
            ndt_weight: 2.5,
            ..DistanceOptions::default()
        };
        assert_eq!(resolve(&ds, opts).unwrap(), opts);
        let median = DistanceOptions {
            scale: Scale::Median,
            ..opts
        };
        assert_eq!(resolve(&ds[..1], median).unwrap().ndt_weight, 2.5);
    }
}
