//! The NDT grid: voxels of edge B on a lattice anchored at the origin
//! (index = floor(p / B)), so the grid does not depend on the data. Per voxel
//! the count, mean and sample covariance of its points.

use crate::cloud::is_finite;
use rustc_hash::FxHashMap;

/// Running sums of one voxel, relative to the voxel's corner so that the
/// one-pass covariance does not lose precision far from the origin.
#[derive(Clone, Copy, Default)]
struct Sums {
    n: u32,
    s: [f64; 3],
    // xx, xy, xz, yy, yz, zz
    ss: [f64; 6],
}

/// A voxel with enough points: its mean and covariance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub count: u32,
    pub mean: [f64; 3],
    /// Sample covariance, row-major 3x3.
    pub cov: [[f64; 3]; 3],
}

/// The result of gridding one scan.
#[derive(Debug, Clone)]
pub struct Grid {
    pub cells: Vec<Cell>,
    /// Finite points used.
    pub points: usize,
    /// Non-finite points dropped.
    pub dropped: usize,
    /// Occupied voxels skipped for having too few points.
    pub sparse_voxels: usize,
}

/// Build the grid; voxels with fewer than `min_points` points are skipped.
/// Cells come out sorted by voxel index, so the result does not depend on
/// hash order.
pub fn build(points: &[[f32; 3]], voxel_size: f64, min_points: usize) -> Grid {
    let inv = 1.0 / voxel_size;
    let mut map: FxHashMap<(i32, i32, i32), Sums> = FxHashMap::default();
    map.reserve(points.len() / 8);
    let mut dropped = 0;
    for p in points {
        if !is_finite(p) {
            dropped += 1;
            continue;
        }
        let q = [p[0] as f64, p[1] as f64, p[2] as f64];
        // `as i32` saturates, so absurd coordinates cannot overflow.
        let idx = [0, 1, 2].map(|k| (q[k] * inv).floor() as i32);
        let local = [0, 1, 2].map(|k| q[k] - idx[k] as f64 * voxel_size);
        let e = map.entry((idx[0], idx[1], idx[2])).or_default();
        e.n += 1;
        for (s, l) in e.s.iter_mut().zip(local) {
            *s += l;
        }
        e.ss[0] += local[0] * local[0];
        e.ss[1] += local[0] * local[1];
        e.ss[2] += local[0] * local[2];
        e.ss[3] += local[1] * local[1];
        e.ss[4] += local[1] * local[2];
        e.ss[5] += local[2] * local[2];
    }
    let mut keyed: Vec<((i32, i32, i32), Sums)> = map.into_iter().collect();
    keyed.sort_unstable_by_key(|(k, _)| *k);
    let mut sparse = 0;
    let mut cells = Vec::with_capacity(keyed.len());
    for (key, s) in keyed {
        if (s.n as usize) < min_points {
            sparse += 1;
            continue;
        }
        let n = s.n as f64;
        let m = [s.s[0] / n, s.s[1] / n, s.s[2] / n];
        let c = |a: usize, i: usize, j: usize| (s.ss[a] - n * m[i] * m[j]) / (n - 1.0);
        let (xx, xy, xz, yy, yz, zz) = (
            c(0, 0, 0),
            c(1, 0, 1),
            c(2, 0, 2),
            c(3, 1, 1),
            c(4, 1, 2),
            c(5, 2, 2),
        );
        let corner = [key.0, key.1, key.2].map(|i| i as f64 * voxel_size);
        cells.push(Cell {
            count: s.n,
            mean: [corner[0] + m[0], corner[1] + m[1], corner[2] + m[2]],
            cov: [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]],
        });
    }
    Grid {
        cells,
        points: points.len() - dropped,
        dropped,
        sparse_voxels: sparse,
    }
}
