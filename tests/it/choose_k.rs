//! The rule that chooses the number of categories, on descriptor sets of
//! known structure and on real files of known places.

use crate::common;
use common::*;
use placecat::cluster::choose_k::{
    choose_k, reference_log_w, scores, scores_with_references, ChooseKParams, Clusterer, Rule,
    DEFAULT_RULE,
};
use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::{HierarchicalKMeans, KMeansParams, Space};
use placecat::descriptor::Summary;
use placecat::io::{read_scan_named, ReadLimits};
use placecat::{describe, Descriptor, DescriptorParams, DistanceOptions};
use rand::Rng;

const ROWS: usize = 6;
const COLS: usize = 4;

/// `n` descriptors around `proto` (ROWS x COLS relative weights), each
/// count = proto x 200 x (1 + uniform(-spread, spread)), one candidate.
fn group(r: &mut rand_chacha::ChaCha8Rng, proto: &[f64], spread: f64, n: usize) -> Vec<Descriptor> {
    (0..n)
        .map(|_| Descriptor {
            rows: ROWS,
            cols: COLS,
            matrices: vec![proto
                .iter()
                .map(|&p| (p * 200.0 * (1.0 + r.random_range(-spread..=spread))).round() as u32)
                .collect()],
            summary: Summary::default(),
            parts: Vec::new(),
        })
        .collect()
}

/// A prototype with weight on one row per column, the row shifted by `at`.
fn proto(at: usize) -> Vec<f64> {
    (0..ROWS * COLS)
        .map(|i| {
            if (i / COLS + i % COLS + at) % ROWS == 0 {
                10.0
            } else {
                1.0
            }
        })
        .collect()
}

/// K chosen by the default rule for the tree (seed 0) and for k-means.
fn chosen(descriptors: &[Descriptor], opts: DistanceOptions) -> (usize, usize) {
    let space = Space::new(descriptors, opts).unwrap();
    let matrix = space.matrix();
    let hk = HkMeansParams::new(0);
    let tree = HierarchicalKMeans::fit(&space, &matrix, &hk).unwrap();
    let p = ChooseKParams::default();
    let t = choose_k(
        &space,
        Some(&matrix),
        Clusterer::Tree(&tree, &hk),
        &p,
        DEFAULT_RULE,
    )
    .unwrap();
    let k = choose_k(
        &space,
        None,
        Clusterer::KMeans(&KMeansParams::new(1)),
        &p,
        DEFAULT_RULE,
    )
    .unwrap();
    // The scores cover the Ks tried, and the page can plot them.
    assert!(t
        .scores
        .iter()
        .all(|s| s.0 >= 1 && s.0 <= p.max_k && s.1.is_finite()));
    assert_eq!(t.rule, DEFAULT_RULE);
    (t.k, k.k)
}

#[test]
fn three_separated_groups_give_three() {
    let mut r = rng(1);
    let mut d = group(&mut r, &proto(0), 0.2, 12);
    d.extend(group(&mut r, &proto(2), 0.2, 9));
    d.extend(group(&mut r, &proto(4), 0.2, 15));
    assert_eq!(chosen(&d, DistanceOptions::default()), (3, 3));
}

#[test]
fn one_tight_group_gives_one() {
    let mut r = rng(2);
    let d = group(&mut r, &proto(1), 0.2, 30);
    assert_eq!(chosen(&d, DistanceOptions::default()), (1, 1));
}

#[test]
fn a_tight_and_a_far_wider_group_give_two_for_the_tree() {
    let mut r = rng(3);
    // Eight times the spread. The tree's cut keeps the wide group whole.
    // k-means splits it at K = 3 and the gap statistic's 1-SE rule takes
    // that split (Gap(2) = 2.50 < Gap(3) - s_3 = 2.53): a known weakness
    // of the rule (reported), held here so that a change shows.
    let mut d = group(&mut r, &proto(0), 0.05, 15);
    d.extend(group(&mut r, &proto(3), 0.4, 15));
    assert_eq!(chosen(&d, DistanceOptions::default()), (2, 3));
}

/// The real files, in the repository (tests/data/real).
fn real_dir() -> String {
    REAL.to_string()
}

/// The default rule's K for the tree on these real files.
fn real_k(files: &[&str], params: DescriptorParams) -> usize {
    let d: Vec<Descriptor> = files
        .iter()
        .map(|f| {
            let path = format!("{}/{f}", real_dir());
            let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
            let c = read_scan_named(&bytes, f, &ReadLimits::default()).unwrap();
            describe(&c.points, &params).unwrap()
        })
        .collect();
    chosen(&d, DistanceOptions::from(&params)).0
}

#[test]
fn ten_ouster_scans_of_one_place_give_one() {
    let files: Vec<String> = (0..10)
        .map(|i| format!("ouster_os0_sequence/scan_{i:03}.bin"))
        .collect();
    let files: Vec<&str> = files.iter().map(|s| s.as_str()).collect();
    assert_eq!(real_k(&files, DescriptorParams::indoor()), 1);
}

#[test]
fn four_kitti_scans_of_two_places_give_two() {
    let files = [
        "kitti00/000094.bin",
        "kitti00/000095.bin",
        "kitti00/000198.bin",
        "kitti00/000199.bin",
    ];
    assert_eq!(real_k(&files, DescriptorParams::outdoor()), 2);
}

#[test]
fn sampled_silhouette_without_a_matrix_chooses_as_the_exact_one() {
    // 3 groups of 40; the silhouette sample (50 scans) is far below n.
    let mut r = rng(4);
    let mut d = group(&mut r, &proto(0), 0.2, 40);
    d.extend(group(&mut r, &proto(2), 0.2, 40));
    d.extend(group(&mut r, &proto(4), 0.2, 40));
    let space = Space::new(&d, DistanceOptions::default()).unwrap();
    let km = KMeansParams::new(1);
    let small = ChooseKParams {
        silhouette_sample: 50,
        ..Default::default()
    };
    let exact = choose_k(
        &space,
        Some(&space.matrix()),
        Clusterer::KMeans(&km),
        &small,
        DEFAULT_RULE,
    )
    .unwrap();
    let sampled = choose_k(&space, None, Clusterer::KMeans(&km), &small, DEFAULT_RULE).unwrap();
    assert_eq!((exact.k, sampled.k), (3, 3));
    // The one-category statistic is the best silhouette, both well above 0.5.
    let (a, b) = (exact.one_category.unwrap(), sampled.one_category.unwrap());
    assert!(a > 0.5 && b > 0.5 && (a - b).abs() < 0.1, "{a} vs {b}");
}

#[test]
fn bad_requests_are_errors() {
    let mut r = rng(5);
    let d = group(&mut r, &proto(0), 0.2, 5);
    let space = Space::new(&d, DistanceOptions::default()).unwrap();
    let km = KMeansParams::new(1);
    let p = ChooseKParams::default();
    let e = choose_k(&space, None, Clusterer::KMeans(&km), &p, Rule::HeightGap).unwrap_err();
    assert!(e.to_string().contains("needs a tree"), "{e}");
    // A tree of other scans.
    let other = Space::new(&d[..4], DistanceOptions::default()).unwrap();
    let hk = HkMeansParams::new(0);
    let tree = HierarchicalKMeans::fit_without_matrix(&other, &hk).unwrap();
    let e = choose_k(&space, None, Clusterer::Tree(&tree, &hk), &p, DEFAULT_RULE).unwrap_err();
    assert!(e.to_string().contains("a tree of 4"), "{e}");
    let zero = ChooseKParams { max_k: 0, ..p };
    assert!(choose_k(&space, None, Clusterer::KMeans(&km), &zero, DEFAULT_RULE).is_err());
}

#[test]
fn reference_sets_computed_in_shares_elsewhere_give_the_same_scores_bit_for_bit() {
    // What the page does: two workers, each with its own set of the same
    // descriptors, compute every other reference set; the main thread
    // scores with them. 3 groups of 25; reference sets of 40 of the 75.
    let mut r = rng(6);
    let mut d = group(&mut r, &proto(0), 0.3, 25);
    d.extend(group(&mut r, &proto(2), 0.3, 25));
    d.extend(group(&mut r, &proto(4), 0.3, 25));
    let space = Space::new(&d, DistanceOptions::default()).unwrap();
    let matrix = space.matrix();
    let hk = HkMeansParams::new(3);
    let tree = HierarchicalKMeans::fit(&space, &matrix, &hk).unwrap();
    let p = ChooseKParams {
        reference_size: 40,
        ..Default::default()
    };
    for clusterer in [
        Clusterer::Tree(&tree, &hk),
        Clusterer::KMeans(&KMeansParams::new(1)),
    ] {
        let whole = scores(&space, Some(&matrix), clusterer, &p).unwrap();
        let worker = |which: &[usize]| {
            let own = Space::new(&d, DistanceOptions::default()).unwrap();
            reference_log_w(&own, clusterer.method(), &p, which).unwrap()
        };
        let (even, odd) = (worker(&[0, 2, 4, 6, 8]), worker(&[1, 3, 5, 7, 9]));
        let sets: Vec<Vec<f64>> = (0..10)
            .map(|b| [&even, &odd][b % 2][b / 2].clone())
            .collect();
        let split = scores_with_references(&space, Some(&matrix), clusterer, &p, &sets).unwrap();
        // Debug prints each f64 exactly (shortest round trip), NaN included.
        assert_eq!(format!("{split:?}"), format!("{whole:?}"));
        // Each set is its own draw: set 3 alone is the whole run's fourth.
        assert_eq!(worker(&[3]), vec![sets[3].clone()]);
        assert_ne!(sets[3], sets[4]);
        assert_eq!(split.choose(DEFAULT_RULE).unwrap().k, 3);
        // A missing set or a short one is refused, naming what was expected.
        let e =
            scores_with_references(&space, Some(&matrix), clusterer, &p, &sets[1..]).unwrap_err();
        assert!(e.to_string().contains("9 reference sets"), "{e}");
        let mut short = sets.clone();
        short[7].pop();
        let e = scores_with_references(&space, Some(&matrix), clusterer, &p, &short).unwrap_err();
        assert!(
            e.to_string()
                .contains("10 reference sets of 9 to 10 values given, 10 of 10 (K = 1 to 10)"),
            "{e}"
        );
    }
    let e = reference_log_w(&space, Clusterer::Tree(&tree, &hk).method(), &p, &[10]).unwrap_err();
    assert!(
        e.to_string().contains("reference set 10 asked for, of 10"),
        "{e}"
    );
}
