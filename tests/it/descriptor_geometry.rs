//! The descriptor on known geometry (docs/design.md#descriptor).

use crate::common;
use common::*;
use placecat::descriptor::directions::{hemisphere, nearest};
use placecat::descriptor::ndt_grid;
use placecat::descriptor::shape::{classify, Shape};
use placecat::descriptor::{Alignment, DescriptorParams};
use placecat::{delta, describe, DistanceOptions};
use rand::Rng;

fn only_cell(points: &[[f32; 3]]) -> ndt_grid::Cell {
    let g = ndt_grid::build(points, 0.4, 5);
    assert_eq!(g.cells.len(), 1, "points should fill exactly one voxel");
    g.cells[0]
}

#[test]
fn plane_is_planar_with_its_normal() {
    let mut r = rng(1);
    // A tilted plane inside the voxel [4.0, 4.4) x [0, 0.4) x [0, 0.4).
    let normal = [0.3f64, 0.2, 0.933];
    let pts: Vec<[f32; 3]> = (0..200)
        .map(|_| {
            let (x, y): (f64, f64) = (r.random_range(0.05..0.35), r.random_range(0.05..0.35));
            let z = 0.2 - (normal[0] * (x - 0.2) + normal[1] * (y - 0.2)) / normal[2];
            [(4.0 + x) as f32, y as f32, z as f32]
        })
        .collect();
    let c = classify(&only_cell(&pts), 0.05).expect("non-degenerate");
    assert_eq!(c.shape, Shape::Planar);
    let n = (normal[0].powi(2) + normal[1].powi(2) + normal[2].powi(2)).sqrt();
    let dot =
        (c.normal[0] * normal[0] + c.normal[1] * normal[1] + c.normal[2] * normal[2]).abs() / n;
    assert!(dot > 0.999, "normal off by acos({dot})");
    // In the histogram (identity alignment) it lands in the class of the
    // planar direction nearest its normal.
    let mut p = DescriptorParams::indoor();
    p.alignment = Alignment::None;
    let d = describe(&pts, &p).unwrap();
    let class = 1 + nearest(&hemisphere(9), &c.normal);
    let f = &d.matrices[0];
    let row_sum: u32 = (0..d.cols).map(|col| f[class * d.cols + col]).sum();
    assert!(row_sum >= 1, "planar voxel not in row {class}: {f:?}");
    assert_eq!(d.summary.planar, 1);
}

#[test]
fn line_is_linear_and_blob_is_spherical() {
    let mut r = rng(2);
    let line: Vec<[f32; 3]> = (0..100)
        .map(|i| {
            let t = 0.02 + 0.36 * i as f32 / 100.0;
            [
                2.0 + t,
                0.2 + 0.001 * r.random::<f32>(),
                0.2 + 0.001 * r.random::<f32>(),
            ]
        })
        .collect();
    let c = classify(&only_cell(&line), 0.05).unwrap();
    assert_eq!(c.shape, Shape::Linear);
    assert!(c.axis[0].abs() > 0.999);

    let blob: Vec<[f32; 3]> = (0..500)
        .map(|_| [0, 1, 2].map(|k| if k == 0 { 2.0 } else { 0.0 } + r.random_range(0.01f32..0.39)))
        .collect();
    let c = classify(&only_cell(&blob), 0.05).unwrap();
    assert_eq!(c.shape, Shape::Spherical);
}

#[test]
fn sparse_voxels_are_skipped() {
    let mut r = rng(3);
    let mut pts: Vec<[f32; 3]> = (0..4)
        .map(|_| {
            [
                2.1 + 0.1 * r.random::<f32>(),
                0.1,
                0.1 + 0.1 * r.random::<f32>(),
            ]
        })
        .collect();
    let g = ndt_grid::build(&pts, 0.4, 5);
    assert_eq!((g.cells.len(), g.sparse_voxels), (0, 1));
    pts.push([2.15, 0.12, 0.15]);
    let g = ndt_grid::build(&pts, 0.4, 5);
    assert_eq!((g.cells.len(), g.sparse_voxels), (1, 0));
}

#[test]
fn voxel_at_five_metres_counts_in_two_overlapping_intervals() {
    let mut r = rng(4);
    // A blob inside the voxel [5.2, 5.6) x [0, 0.4)^2, its mean ~5.4 m from the
    // origin: in both [3,6) and [5,8).
    let blob: Vec<[f32; 3]> = (0..300)
        .map(|_| {
            [
                5.25 + r.random_range(0.0f32..0.3),
                r.random_range(0.05f32..0.35),
                r.random_range(0.05f32..0.35),
            ]
        })
        .collect();
    let d = describe(&blob, &DescriptorParams::indoor()).unwrap();
    let f = &d.matrices[0];
    let col_sums: Vec<u32> = (0..d.cols)
        .map(|c| (0..d.rows).map(|row| f[row * d.cols + c]).sum())
        .collect();
    assert_eq!(col_sums, vec![0, 1, 1, 0, 0, 0, 0]);
    assert_eq!(d.total(), 2);
}

#[test]
fn non_finite_points_are_dropped_and_counted() {
    let mut pts = office(5);
    let n = pts.len();
    pts.push([f32::NAN, 0.0, 0.0]);
    pts.push([1.0, f32::INFINITY, 0.0]);
    let d = describe(&pts, &DescriptorParams::indoor()).unwrap();
    assert_eq!(d.summary.dropped, 2);
    assert_eq!(d.summary.points, n);
}

#[test]
fn empty_scan_has_no_descriptor() {
    let err = describe(&[], &DescriptorParams::indoor()).unwrap_err();
    assert!(err.to_string().contains("no descriptor"), "{err}");
    let nan = vec![[f32::NAN; 3]; 100];
    let err = describe(&nan, &DescriptorParams::indoor()).unwrap_err();
    assert!(err.to_string().contains("100 dropped"), "{err}");
}

#[test]
fn delta_is_zero_to_itself_and_symmetric() {
    let p = DescriptorParams::indoor();
    let a = describe(&office(6), &p).unwrap();
    let b = describe(&corridor(7), &p).unwrap();
    let o = DistanceOptions::from(&p);
    assert_eq!(delta(&a, &a, o).unwrap(), 0.0);
    let ab = delta(&a, &b, o).unwrap();
    assert!(ab > 0.0);
    assert_eq!(ab, delta(&b, &a, o).unwrap());
}

fn check_rotation_invariance(r: [[f64; 3]; 3], alignment: Alignment) {
    let mut p = DescriptorParams::indoor();
    p.alignment = alignment;
    let o = DistanceOptions::from(&p);
    let scene = office(8);
    let a = describe(&scene, &p).unwrap();
    let rotated = describe(&rotate_points(&scene, &r), &p).unwrap();
    let other = describe(&corridor(9), &p).unwrap();
    let same = delta(&a, &rotated, o).unwrap();
    let diff = delta(&a, &other, o).unwrap();
    assert!(
        same < 0.25 * diff,
        "{alignment:?}: Delta to the rotated scan {same} is not much smaller than to another scene {diff}"
    );
}

#[test]
fn rotation_about_z_keeps_delta_small() {
    for angle in [0.3, 1.1, 2.5, -2.0] {
        check_rotation_invariance(rotation([0.0, 0.0, 1.0], angle), Alignment::Paper);
        check_rotation_invariance(rotation([0.0, 0.0, 1.0], angle), Alignment::Yaw);
    }
}

#[test]
fn rotation_about_any_axis_keeps_delta_small() {
    let mut r = rng(10);
    for _ in 0..4 {
        let axis = [
            r.random_range(-1.0..1.0),
            r.random_range(-1.0..1.0),
            r.random_range(-1.0..1.0),
        ];
        let angle = r.random_range(-3.1..3.1);
        check_rotation_invariance(rotation(axis, angle), Alignment::Paper);
    }
}

#[test]
fn without_alignment_a_rotation_changes_the_descriptor() {
    // The control for the two tests above: with alignment "none", rotating
    // the office by 40 degrees about x moves its normals between classes.
    let mut p = DescriptorParams::indoor();
    p.alignment = Alignment::None;
    let o = DistanceOptions::from(&p);
    let scene = office(8);
    let a = describe(&scene, &p).unwrap();
    let b = describe(&rotate_points(&scene, &rotation([1.0, 0.0, 0.0], 0.7)), &p).unwrap();
    assert!(delta(&a, &b, o).unwrap() > 0.3);
}

#[test]
fn height_bands_multiply_rows_and_one_band_is_the_paper() {
    let mut p = DescriptorParams::indoor();
    let scene = office(11);
    let plain = describe(&scene, &p).unwrap();
    assert_eq!(plain.rows, 11);
    p.height_bands = vec![-0.8, 0.3, 1.5];
    let banded = describe(&scene, &p).unwrap();
    assert_eq!(banded.rows, 44);
    assert_eq!(banded.total(), plain.total());
}

#[test]
fn invalid_parameters_are_named() {
    let mut p = DescriptorParams::indoor();
    p.voxel_size = -1.0;
    assert!(describe(&office(1), &p)
        .unwrap_err()
        .to_string()
        .contains("voxel_size"));
    // A subnormal B would make 1/B infinite; too small a B is refused too.
    for tiny in [5e-324, 1e-310, 1e-9, 9.99e-4] {
        let mut p = DescriptorParams::indoor();
        p.voxel_size = tiny;
        let e = describe(&office(1), &p).unwrap_err().to_string();
        assert!(
            e.contains("voxel_size must be at least 0.001"),
            "{tiny}: {e}"
        );
    }
    let mut p = DescriptorParams::indoor();
    p.voxel_size = 1e-3;
    assert!(p.validate().is_ok());
    let mut p = DescriptorParams::indoor();
    p.min_points_per_voxel = 2;
    assert!(describe(&office(1), &p)
        .unwrap_err()
        .to_string()
        .contains("min_points_per_voxel"));
    assert!(DescriptorParams::preset("attic")
        .unwrap_err()
        .to_string()
        .contains("attic"));
}
