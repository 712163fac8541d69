//! k-means restarts (issue 18, fourth round): the cheapest of N k-means++
//! runs, an option beside the paper's single run.

use placecat::cluster::kmeans::KMeansValidParams;
use placecat::cluster::*;
use placecat::eval::evaluate;
use placecat::DistanceOptions;

/// The paper's descriptor on 5 indoor kinds of 4 scans (seed 1), k = 5.
fn set() -> (Space, Vec<String>) {
    let (ds, truth) = crate::clustering::sim_set(4, 1);
    (Space::new(&ds, DistanceOptions::default()).unwrap(), truth)
}

#[test]
fn one_run_is_the_single_run_and_the_first_of_every_restart() {
    let (space, _) = set();
    for seed in 0..5 {
        // Checks only that the default is restarts(1) (the same run twice);
        // that run 0 is main's single run is guarded by rng.rs
        // (rng_stream(s, 0) == rng(s)) and the parity fixture.
        let plain = KMeans::fit(&space, &KMeansParams::new(5).seed(seed)).unwrap();
        let one = KMeans::fit(&space, &KMeansParams::new(5).seed(seed).restarts(1)).unwrap();
        assert_eq!(plain, one);
        assert_eq!(one.restart, 0);
        let runs = KMeans::runs(&space, &KMeansParams::new(5).seed(seed).restarts(4)).unwrap();
        assert_eq!(runs.len(), 4);
        assert_eq!(runs[0], one, "run 0 of 4 restarts is the single run");
    }
}

#[test]
fn restarts_recover_from_a_bad_kmeans_plus_plus_draw() {
    // Seed 15's single k-means++ draw puts two seeds in one kind: its
    // cost is 3.012, 60 % of the scans right. The cheapest of 10 (run 4)
    // costs 2.794 and gets 95 % right.
    let (space, truth) = set();
    let one = KMeans::fit(&space, &KMeansParams::new(5).seed(15)).unwrap();
    let ten = KMeans::fit(&space, &KMeansParams::new(5).seed(15).restarts(10)).unwrap();
    assert!((one.cost - 3.0124).abs() < 1e-3, "{}", one.cost);
    assert!((ten.cost - 2.7937).abs() < 1e-3, "{}", ten.cost);
    assert_eq!(ten.restart, 4);
    let acc = |l: &[i32]| evaluate(&truth, l).unwrap().accuracy;
    assert_eq!(acc(&one.labels), 0.60);
    assert_eq!(acc(&ten.labels), 0.95);
}

#[test]
fn the_kept_run_is_the_cheapest_of_the_runs_computed_one_by_one() {
    let (space, _) = set();
    let mut improved = 0;
    for seed in 0..20 {
        let params = KMeansParams::new(5).seed(seed).restarts(10);
        let runs = KMeans::runs(&space, &params).unwrap();
        let cheapest = runs.iter().map(|r| r.cost).fold(f64::INFINITY, f64::min);
        let first = runs.iter().position(|r| r.cost == cheapest).unwrap();
        let kept = KMeans::fit(&space, &params).unwrap();
        assert_eq!(kept, runs[first], "seed {seed}: the earliest cheapest run");
        assert_eq!(kept.restart, first);
        // Run r depends on the seed and r only: 3 restarts are a prefix.
        let three = KMeans::runs(&space, &params.clone().restarts(3)).unwrap();
        assert_eq!(three[..], runs[..3]);
        // Each run is a different draw (the streams are independent).
        assert!(runs.iter().any(|r| r.seeds != runs[0].seeds));
        improved += usize::from(kept.cost < runs[0].cost);
    }
    // 16 of the 20 single runs were beaten by a later run.
    assert_eq!(improved, 16);
}

#[test]
fn restarts_are_checked() {
    let (space, _) = set();
    let err = |p: KMeansParams| KMeans::fit(&space, &p).unwrap_err().to_string();
    assert!(err(KMeansParams::new(5).restarts(0)).contains("restarts must be at least 1"));
    // A huge count is refused before any run (it used to panic on
    // "capacity overflow" collecting the runs).
    for huge in [MAX_RESTARTS + 1, u32::MAX as usize, usize::MAX] {
        let e = err(KMeansParams::new(5).restarts(huge));
        assert!(
            e.contains(&format!("restarts = {huge} is more than the limit of 1000")),
            "{e}"
        );
    }
    assert!(KMeansParams::new(5).restarts(MAX_RESTARTS).check().is_ok());
    let stride = err(KMeansParams::new(5).seeding(Seeding::Stride).restarts(10));
    assert!(stride.contains("restarts = 10 with stride"), "{stride}");
    assert!(KMeans::fit(
        &space,
        &KMeansParams::new(5).seeding(Seeding::Stride).restarts(1)
    )
    .is_ok());
    let random = KMeansParams::new(5)
        .seeding(Seeding::Random)
        .seed(3)
        .restarts(3);
    assert!(KMeans::fit(&space, &random).unwrap().iterations > 0);
    // Parameters written before restarts existed read as one run; a 0 in
    // JSON is refused as the setter's is.
    let old: KMeansValidParams =
        serde_json::from_str(r#"{"k":5,"seeding":"plusplus","seed":0,"max_iterations":100}"#)
            .unwrap();
    assert_eq!(old.restarts, 1);
    let zero = serde_json::from_str::<KMeansValidParams>(
        r#"{"k":5,"seeding":"plusplus","seed":0,"max_iterations":100,"restarts":0}"#,
    );
    assert!(zero
        .unwrap_err()
        .to_string()
        .contains("restarts must be at least 1"));
}

/// A result written before restarts existed (no `restart` key) still
/// reads, as run 0.
#[test]
fn a_result_without_restart_reads_as_run_0() {
    let (space, _) = set();
    let fit = KMeans::fit(&space, &KMeansParams::new(3).seed(2)).unwrap();
    let mut json = serde_json::to_value(&fit).unwrap();
    json.as_object_mut().unwrap().remove("restart").unwrap();
    let old: KMeansResult = serde_json::from_value(json).unwrap();
    assert_eq!(old, fit);
}

/// Hierarchical k-means++ with trial splits (issues 14 and 18, fifth
/// round): every node keeps the cheapest of N 2-means++ runs.
mod trial_splits {
    use super::set;
    use placecat::cluster::hkmeans::{HkMeansParams, HkMeansValidParams};
    use placecat::cluster::*;
    use placecat::eval::evaluate;

    fn tree(space: &Space, seed: u64, restarts: usize) -> Tree {
        let params = HkMeansParams::new(seed).restarts(restarts);
        HierarchicalKMeans::fit(space, &space.matrix(), &params).unwrap()
    }

    /// Only that the default is one trial (the same tree twice); that one
    /// trial is the paper's tree, RNG draw for draw, is guarded by the
    /// parity fixture's `hkmeans_cut4` (native, wasm and Python).
    #[test]
    fn the_default_is_one_trial() {
        let (space, _) = set();
        for seed in 0..5 {
            let plain = HierarchicalKMeans::fit(&space, &space.matrix(), &HkMeansParams::new(seed));
            assert_eq!(
                plain.unwrap().cut_k(5).unwrap(),
                tree(&space, seed, 1).cut_k(5).unwrap()
            );
        }
        // Parameters written before the field existed read as one trial.
        let old: HkMeansValidParams =
            serde_json::from_str(r#"{"seed":3,"max_iterations":100}"#).unwrap();
        assert_eq!(old.restarts, 1);
    }

    #[test]
    fn trial_splits_find_the_same_cheapest_tree_from_every_seed() {
        // The 5 indoor kinds of 4 scans, cut at 5, over tree seeds 0-19.
        // One trial a split: 4 distinct cuts, 81 % right on average
        // (lowest 75 %). Ten trials: every seed finds the same splits, and
        // that tree is the 75 % one. The cheapest split is not always the
        // one that parts the kinds: trials buy stability, not accuracy.
        let (space, truth) = set();
        let cuts = |restarts| -> Vec<Vec<i32>> {
            (0..20)
                .map(|s| tree(&space, s, restarts).cut_k(5).unwrap().labels)
                .collect()
        };
        let figures = |cuts: &[Vec<i32>]| {
            let acc: Vec<f64> = cuts
                .iter()
                .map(|l| evaluate(&truth, l).unwrap().accuracy)
                .collect();
            // The same partition may number its categories otherwise.
            let mut distinct: Vec<Vec<usize>> = cuts.iter().map(|l| first_seen(l)).collect();
            distinct.sort();
            distinct.dedup();
            let mean = acc.iter().sum::<f64>() / acc.len() as f64;
            let low = acc.iter().copied().fold(1.0, f64::min);
            ((mean * 100.0).round() / 100.0, low, distinct.len())
        };
        assert_eq!(figures(&cuts(1)), (0.81, 0.75, 4));
        assert_eq!(figures(&cuts(10)), (0.75, 0.75, 1));
    }

    /// Labels renumbered in order of first appearance.
    fn first_seen(labels: &[i32]) -> Vec<usize> {
        let mut order: Vec<i32> = vec![];
        labels
            .iter()
            .map(|l| {
                order.iter().position(|o| o == l).unwrap_or_else(|| {
                    order.push(*l);
                    order.len() - 1
                })
            })
            .collect()
    }

    #[test]
    fn trial_counts_are_checked() {
        let (space, _) = set();
        let err = |r: usize| {
            let p = HkMeansParams::new(0).restarts(r);
            HierarchicalKMeans::fit(&space, &space.matrix(), &p)
                .unwrap_err()
                .to_string()
        };
        assert!(err(0).contains("restarts must be at least 1"), "{}", err(0));
        let e = err(MAX_RESTARTS + 1);
        assert!(
            e.contains("restarts = 1001 is more than the limit of 1000 2-means runs per split"),
            "{e}"
        );
        assert!(HkMeansParams::new(0).restarts(MAX_RESTARTS).check().is_ok());
    }
}
