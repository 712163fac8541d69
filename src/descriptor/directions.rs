//! Directions on the upper hemisphere (z >= 0), spread by the golden-angle
//! (Fibonacci) spiral; lines through the origin are matched by |dot|, so a
//! direction and its opposite fall in the same bin.

/// `n` unit vectors on the upper hemisphere, the first pointing nearly up.
pub fn hemisphere(n: usize) -> Vec<[f64; 3]> {
    if n == 1 {
        return vec![[0.0, 0.0, 1.0]];
    }
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            // z evenly spaced in (0, 1]: equal areas on the hemisphere.
            let z = 1.0 - (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = golden * i as f64;
            [r * phi.cos(), r * phi.sin(), z]
        })
        .collect()
}

/// Index of the direction nearest to the line through `v` (largest |dot|).
#[inline]
pub fn nearest(dirs: &[[f64; 3]], v: &[f64; 3]) -> usize {
    let mut best = 0;
    let mut best_dot = -1.0;
    for (i, d) in dirs.iter().enumerate() {
        let dot = (d[0] * v[0] + d[1] * v[1] + d[2] * v[2]).abs();
        if dot > best_dot {
            best_dot = dot;
            best = i;
        }
    }
    best
}

/// [`nearest`] over a number of directions known when compiling, so that the
/// loop is unrolled: the same comparisons in the same order, the same answer.
/// The histogram looks up every planar voxel's normal among 9 directions once
/// per candidate orientation; unrolled, that took 39.3 -> 31.2 instructions per
/// point of a simulated outdoor scan with 12 orientations.
#[inline]
pub fn nearest_of<const N: usize>(dirs: &[[f64; 3]; N], v: &[f64; 3]) -> usize {
    nearest(dirs, v)
}

/// Exact nearest-direction lookup for large direction sets (the alignment's
/// fine histogram): a grid over the hemisphere in (z, azimuth), each cell
/// listing the only directions that can be nearest to a vector in it. A
/// direction d can be nearest to v in cell C (centre c, angular radius r)
/// only if angle(d, c) <= min over d' of angle(d', c) + 2r (triangle
/// inequality of the angle between lines), so the answer, ties included,
/// equals the brute-force [`nearest`]. The profile of a KITTI scan had 14%
/// of describing in brute-force lookups over 400 directions.
pub struct DirectionIndex {
    dirs: Vec<[f64; 3]>,
    cells: Vec<Vec<u16>>,
}

const Z_BINS: usize = 24;
const PHI_BINS: usize = 48;

impl DirectionIndex {
    /// Index `dirs` (unit vectors on the upper hemisphere); lookups then give
    /// the same answer as [`nearest`] over them.
    pub fn new(dirs: Vec<[f64; 3]>) -> DirectionIndex {
        let line_cos =
            |a: &[f64; 3], b: &[f64; 3]| (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]).abs().min(1.0);
        let line_angle = |a: &[f64; 3], b: &[f64; 3]| line_cos(a, b).acos();
        let point = |z: f64, phi: f64| {
            let r = (1.0 - z * z).max(0.0).sqrt();
            [r * phi.cos(), r * phi.sin(), z]
        };
        let mut cells = Vec::with_capacity(Z_BINS * PHI_BINS);
        for zi in 0..Z_BINS {
            for pi in 0..PHI_BINS {
                let (z0, z1) = (zi as f64 / Z_BINS as f64, (zi + 1) as f64 / Z_BINS as f64);
                let w = std::f64::consts::TAU / PHI_BINS as f64;
                let (p0, p1) = (pi as f64 * w, (pi + 1) as f64 * w);
                let c = point((z0 + z1) / 2.0, (p0 + p1) / 2.0);
                // The farthest point of the cell from its centre is a corner;
                // the edge midpoints and a margin make the bound safe.
                let r = [
                    (z0, p0),
                    (z0, p1),
                    (z1, p0),
                    (z1, p1),
                    (z0, (p0 + p1) / 2.0),
                    (z1, (p0 + p1) / 2.0),
                ]
                .iter()
                .map(|&(z, p)| line_angle(&point(z, p), &c))
                .fold(0.0, f64::max)
                    * 1.25
                    + 1e-9;
                // angle <= min + 2r, compared as cosines (acos is monotonic):
                // one acos per cell instead of one per direction, which made
                // building the index a visible share of a 40-file run. The
                // bound's margin absorbs the rounding of either form.
                let cosines: Vec<f64> = dirs.iter().map(|d| line_cos(d, &c)).collect();
                let nearest = cosines.iter().copied().fold(0.0, f64::max);
                let bound = nearest.acos() + 2.0 * r;
                let limit = if bound >= std::f64::consts::FRAC_PI_2 {
                    -1.0
                } else {
                    bound.cos()
                };
                cells.push(
                    (0..dirs.len())
                        .filter(|&i| cosines[i] >= limit)
                        .map(|i| i as u16)
                        .collect(),
                );
            }
        }
        DirectionIndex { dirs, cells }
    }

    /// Same answer as `nearest(dirs, v)`.
    #[inline]
    pub fn nearest(&self, v: &[f64; 3]) -> usize {
        // The line through v, taken on the upper hemisphere.
        let u = if v[2] < 0.0 {
            [-v[0], -v[1], -v[2]]
        } else {
            *v
        };
        let n = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
        if n.is_nan() || n <= 0.0 || !n.is_finite() {
            return nearest(&self.dirs, v);
        }
        let z = (u[2] / n).clamp(0.0, 1.0);
        let phi = u[1].atan2(u[0]).rem_euclid(std::f64::consts::TAU);
        let zi = ((z * Z_BINS as f64) as usize).min(Z_BINS - 1);
        let pi = ((phi / std::f64::consts::TAU * PHI_BINS as f64) as usize).min(PHI_BINS - 1);
        let mut best = usize::MAX;
        let mut best_dot = -1.0;
        for &i in &self.cells[zi * PHI_BINS + pi] {
            let d = &self.dirs[i as usize];
            let dot = (d[0] * v[0] + d[1] * v[1] + d[2] * v[2]).abs();
            if dot > best_dot {
                best_dot = dot;
                best = i as usize;
            }
        }
        best
    }

    /// The index of `hemisphere(n)`, built once per n and shared.
    pub fn hemisphere(n: usize) -> std::sync::Arc<DirectionIndex> {
        use std::sync::{Arc, Mutex, OnceLock};
        type Cache = Mutex<Vec<(usize, Arc<DirectionIndex>)>>;
        static CACHE: OnceLock<Cache> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        let mut guard = cache.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, idx)) = guard.iter().find(|(k, _)| *k == n) {
            return idx.clone();
        }
        let idx = Arc::new(DirectionIndex::new(hemisphere(n)));
        guard.push((n, idx.clone()));
        idx
    }

    /// The indexed directions, in the order lookups number them.
    pub fn directions(&self) -> &[[f64; 3]] {
        &self.dirs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn index_agrees_with_brute_force() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        for n in [9usize, 40, 400, 1000] {
            let idx = DirectionIndex::new(hemisphere(n));
            let dirs = hemisphere(n);
            for k in 0..20_000 {
                let mut v: [f64; 3] = [
                    r.random_range(-1.0..1.0),
                    r.random_range(-1.0..1.0),
                    r.random_range(-1.0..1.0),
                ];
                // Also the equator, the pole and the cell edges.
                match k % 5 {
                    0 => v[2] = 0.0,
                    1 => v = [1e-9 * v[0], 1e-9 * v[1], 1.0],
                    2 => {
                        v[2] = (r.random_range(0..Z_BINS) as f64 / Z_BINS as f64)
                            * (v[0] * v[0] + v[1] * v[1] + 1.0).sqrt()
                    }
                    _ => {}
                }
                assert_eq!(idx.nearest(&v), nearest(&dirs, &v), "n {n} v {v:?}");
            }
        }
    }
}
