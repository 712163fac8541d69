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
