//! The n x n Delta matrix.

use serde::{Deserialize, Serialize};

/// A symmetric n x n matrix of Delta, row-major, zero diagonal.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DistanceMatrix {
    /// Number of scans.
    pub n: usize,
    /// n * n values, Delta(i, j) at `i * n + j`.
    pub data: Vec<f32>,
}

impl DistanceMatrix {
    #[inline]
    /// Delta between scans i and j.
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
