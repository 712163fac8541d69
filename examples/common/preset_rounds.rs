//! What the rounds that compare presets on the same sets share (round 6,
//! `hellinger.rs`; round 7, `near_ranges.rs`): a preset's three
//! clusterings of a set at its true number of kinds. Include after
//! `families.rs`, `rounds.rs` and `site_rounds.rs`.

use crate::rounds::{once, over_seeds, Method, Res};
use crate::site_rounds::{trees, Trees};
use placecat::cluster::*;
use placecat::*;
use serde::{Deserialize, Serialize};

/// Trial splits per node and k-means++ restarts (rounds 4 and 5).
pub const TRIALS: usize = 10;

/// One preset's figures on one set (rounds 6 and 7).
#[derive(Serialize, Deserialize, Clone, Copy, Default)]
pub struct Figures {
    pub stride: Method,
    /// k-means++, best of 10 restarts (round 4).
    pub best_of_10: Method,
    /// Hierarchical k-means++, the cheapest of 10 trials per split (round 5).
    pub hk_trials: Method,
}

/// The three clusterings of `ds` under `params`' distance at `k`, and the
/// trees (with the space and its matrix) for other cuts.
pub fn measure(
    ds: &[Descriptor],
    params: &DescriptorParams,
    truth: &[String],
    k: usize,
) -> Res<(Figures, Space, DistanceMatrix, Trees)> {
    let space = Space::new(ds, DistanceOptions::from(params))?;
    let m = space.matrix();
    let stride = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels;
    let ten = trees(&space, &m, TRIALS)?;
    let figures = Figures {
        stride: once(truth, &stride)?,
        best_of_10: over_seeds(truth, |s| {
            Ok(KMeans::fit(&space, &KMeansParams::new(k).seed(s).restarts(TRIALS))?.labels)
        })?,
        hk_trials: over_seeds(truth, |s| Ok(ten[s as usize].1.cut_k(k)?.labels))?,
    };
    Ok((figures, space, m, ten))
}
