//! Descriptors and parameters arrive as JSON written by anyone (the page's
//! advanced parameters, `--params`, `cluster DESCRIPTORS.json`, `addJson`):
//! a shape or class count that lies is an error with a message, never a
//! panic or a wrapped-round size.

use placecat::cluster::Space;
use placecat::{Descriptor, DescriptorParams, DistanceOptions};

fn descriptor(rows: usize, cols: usize, matrix: Vec<u32>) -> Descriptor {
    Descriptor {
        rows,
        cols,
        matrices: vec![matrix],
        summary: Default::default(),
        parts: Vec::new(),
    }
}

#[test]
fn a_shape_whose_product_wraps_round_is_refused() {
    // (2^63 + 1) x 2 wraps round to 2 cells in 64 bits (2^31 + 1 in 32):
    // the 2 counts given would pass an unchecked product.
    let d = descriptor(usize::MAX / 2 + 2, 2, vec![1, 1]);
    let err = d.validate().unwrap_err().to_string();
    assert!(err.contains("rows x cols"), "{err}");
    let err = Space::new(&[d.clone(), d], DistanceOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("descriptor 0"), "{err}");
}

#[test]
fn an_empty_shape_is_refused_and_a_true_one_accepted() {
    assert!(descriptor(0, 7, vec![]).validate().is_err());
    assert!(descriptor(11, 0, vec![]).validate().is_err());
    assert!(descriptor(2, 2, vec![1, 2, 3]).validate().is_err());
    assert!(descriptor(2, 2, vec![1, 2, 3, 4]).validate().is_ok());
}

#[test]
fn class_counts_whose_sum_wraps_round_are_refused() {
    let mut p = DescriptorParams::indoor();
    p.spherical_classes = usize::MAX;
    p.planar_classes = 2;
    p.linear_classes = 1; // usize::MAX + 3 wraps round to 2
    let err = p.validate().unwrap_err().to_string();
    assert!(err.contains("too many classes"), "{err}");
}

#[test]
fn parameters_whose_matrix_would_be_huge_are_refused() {
    let mut p = DescriptorParams::indoor();
    // 11 classes x 100,001 bands x 7 ranges = 7.7 million cells.
    p.height_bands = (0..100_000).map(|i| i as f64 * 0.01).collect();
    let err = p.validate().unwrap_err().to_string();
    assert!(err.contains("7700077 cells"), "{err}");
    p.height_bands.truncate(1000); // 11 x 1001 x 7 = 77,077: allowed
    p.validate().unwrap();
}

#[test]
fn a_candidate_cap_beyond_256_is_refused() {
    let mut p = DescriptorParams::indoor();
    p.max_alignments = 1_000_000;
    let err = p.validate().unwrap_err().to_string();
    assert!(
        err.contains("max_alignments must be in 1..=256, got 1000000"),
        "{err}"
    );
    p.max_alignments = 256;
    p.validate().unwrap();
}
