//! k-medoids (alternating, "Voronoi iteration") on the precomputed Delta
//! matrix: centres are scans, so no mean of matrices is needed.

use crate::cluster::lloyd::seeds;
use crate::cluster::Seeding;
use crate::distance::DistanceMatrix;
use crate::distance::Space;
use crate::error::Result;
use crate::rng::rng;

pub struct KMedoids;

impl KMedoids {
    /// Labels and the medoid of each cluster.
    pub fn fit(
        space: &Space,
        matrix: &DistanceMatrix,
        k: usize,
        seed: u64,
        max_iterations: usize,
    ) -> Result<(Vec<i32>, Vec<usize>)> {
        crate::cluster::lloyd::check_k(k, matrix.n)?;
        let n = matrix.n;
        let all: Vec<usize> = (0..n).collect();
        let mut medoids = seeds(space, &all, k, Seeding::PlusPlus, &mut rng(seed));
        let mut labels = vec![0usize; n];
        for _ in 0..max_iterations.max(1) {
            for (i, l) in labels.iter_mut().enumerate() {
                *l = (0..k)
                    .min_by(|&a, &b| {
                        matrix
                            .get(i, medoids[a])
                            .total_cmp(&matrix.get(i, medoids[b]))
                    })
                    .unwrap_or(0);
            }
            let mut changed = false;
            for (c, medoid) in medoids.iter_mut().enumerate() {
                let members: Vec<usize> = (0..n).filter(|&i| labels[i] == c).collect();
                let best = members
                    .iter()
                    .copied()
                    .min_by(|&a, &b| {
                        let ca: f32 = members.iter().map(|&m| matrix.get(a, m)).sum();
                        let cb: f32 = members.iter().map(|&m| matrix.get(b, m)).sum();
                        ca.total_cmp(&cb)
                    })
                    .unwrap_or(*medoid);
                if best != *medoid {
                    *medoid = best;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        Ok((labels.into_iter().map(|l| l as i32).collect(), medoids))
    }
}
