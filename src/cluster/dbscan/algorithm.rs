use super::hyperparams::DbscanValidParams;
use crate::cluster::ParamGuard;
use crate::distance::DistanceMatrix;
use crate::error::Result;

/// DBSCAN over a precomputed Delta matrix.
pub struct Dbscan;

impl Dbscan {
    /// Labels 0.. in order of discovery (scan order), -1 for noise.
    /// `params` is checked first (a [`DbscanParams`](super::DbscanParams)
    /// or its validated form).
    pub fn fit(
        matrix: &DistanceMatrix,
        params: &impl ParamGuard<Checked = DbscanValidParams>,
    ) -> Result<Vec<i32>> {
        let params = params.check()?;
        let n = matrix.n;
        let neighbours = |i: usize| -> Vec<usize> {
            (0..n)
                .filter(|&j| matrix.get(i, j) <= params.epsilon)
                .collect()
        };
        let mut labels = vec![-2i32; n]; // -2: not visited yet
        let mut cluster = 0i32;
        for i in 0..n {
            if labels[i] != -2 {
                continue;
            }
            let nb = neighbours(i);
            if nb.len() < params.min_points {
                labels[i] = -1;
                continue;
            }
            labels[i] = cluster;
            let mut queue = nb;
            let mut q = 0;
            while q < queue.len() {
                let j = queue[q];
                q += 1;
                if labels[j] == -1 {
                    labels[j] = cluster; // border scan, first reached
                }
                if labels[j] != -2 {
                    continue;
                }
                labels[j] = cluster;
                let nj = neighbours(j);
                if nj.len() >= params.min_points {
                    queue.extend(nj);
                }
            }
            cluster += 1;
        }
        Ok(labels)
    }
}
