//! Eigen-decomposition of a symmetric 3x3 covariance, specialised for the
//! shape classes: eigenvalues in closed form (the trigonometric solution of
//! the characteristic cubic), e1 and e3 as cross products of rows of
//! A - lambda I. Measured 5x faster than nalgebra's general `SymmetricEigen`
//! (tridiagonalisation + implicit QR), which was ~22 % of describing a scan.
//!
//! The closed form is accurate to a few ulps of lambda3 except where two
//! eigenvalues (nearly) coincide: there the split of the pair, and the
//! eigenvectors of that pair, are ill-conditioned. When a gap that an
//! eigenvector depends on is below [`MIN_GAP`] x lambda3 (or the input is
//! not finite) the caller is told to use the general solver, so those rare
//! voxels keep exactly the old results.

/// Eigenvalues ascending, e1 (smallest eigenvalue's eigenvector), e3
/// (largest's); `None` when the closed form is not trusted for this matrix.
pub(super) struct Eigen {
    pub values: [f64; 3],
    pub e1: [f64; 3],
    pub e3: [f64; 3],
}

/// Relative eigenvalue gap below which the cross-product eigenvectors are
/// not trusted. Their error is about eps * lambda3^2 / gap^2 (the closed
/// form's eigenvalue error near a double root over the gap), ~1e-10 here.
const MIN_GAP: f64 = 1e-3;

/// Closed-form decomposition of the symmetric matrix with diagonal
/// (a00, a11, a22) and off-diagonal (a01, a02, a12).
#[inline]
pub(super) fn closed_form(c: &[[f64; 3]; 3]) -> Option<Eigen> {
    let (a00, a11, a22) = (c[0][0], c[1][1], c[2][2]);
    let (a01, a02, a12) = (c[0][1], c[0][2], c[1][2]);
    let q = (a00 + a11 + a22) / 3.0;
    let (b00, b11, b22) = (a00 - q, a11 - q, a22 - q);
    let off = a01 * a01 + a02 * a02 + a12 * a12;
    let p2 = (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * off) / 6.0;
    // Not finite, or all three eigenvalues equal (eigenvectors arbitrary):
    // the general solver decides.
    if !(p2 > 0.0 && p2.is_finite() && q.is_finite()) {
        return None;
    }
    let p = p2.sqrt();
    // det(B) / 2, then r = det(B / p) / 2 in [-1, 1].
    let det = b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02)
        + a02 * (a01 * a12 - b11 * a02);
    let r = (det / (2.0 * p2 * p)).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let (s, co) = phi.sin_cos();
    // cos(phi), cos(phi + 2pi/3), cos(phi + 4pi/3) without two more cosines.
    const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;
    let l3 = q + 2.0 * p * co;
    let l1 = q + 2.0 * p * (-0.5 * co - HALF_SQRT3 * s);
    let l2 = 3.0 * q - l1 - l3;
    // l1 <= l2 <= l3 holds in exact arithmetic (phi in [0, pi/3]); rounding
    // can swap a near-equal pair, which the gap test below then rejects.
    let scale = l3.abs().max(l1.abs());
    if l2 - l1 < MIN_GAP * scale || l3 - l2 < MIN_GAP * scale {
        return None;
    }
    let e1 = null_vector(c, l1)?;
    let e3 = null_vector(c, l3)?;
    Some(Eigen {
        values: [l1, l2, l3],
        e1,
        e3,
    })
}

/// Unit vector spanning the null space of A - l I (l a simple eigenvalue):
/// the largest of the three cross products of its rows.
#[inline]
fn null_vector(c: &[[f64; 3]; 3], l: f64) -> Option<[f64; 3]> {
    let r0 = [c[0][0] - l, c[0][1], c[0][2]];
    let r1 = [c[0][1], c[1][1] - l, c[1][2]];
    let r2 = [c[0][2], c[1][2], c[2][2] - l];
    let cross = |a: &[f64; 3], b: &[f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let norm2 = |v: &[f64; 3]| v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    let (x, y, z) = (cross(&r0, &r1), cross(&r0, &r2), cross(&r1, &r2));
    let (nx, ny, nz) = (norm2(&x), norm2(&y), norm2(&z));
    let (v, n) = if nx >= ny && nx >= nz {
        (x, nx)
    } else if ny >= nz {
        (y, ny)
    } else {
        (z, nz)
    };
    if !(n > 0.0 && n.is_finite()) {
        return None;
    }
    let inv = 1.0 / n.sqrt();
    Some([v[0] * inv, v[1] * inv, v[2] * inv])
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix3, Rotation3, SymmetricEigen, Vector3};
    use rand::{Rng, SeedableRng};

    /// nalgebra's decomposition, sorted ascending: (values, e1, e3).
    fn reference(c: &[[f64; 3]; 3]) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let eig = SymmetricEigen::new(Matrix3::from_fn(|i, j| c[i][j]));
        let mut o = [0usize, 1, 2];
        o.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
        let col = |k: usize| {
            let v = eig.eigenvectors.column(o[k]);
            [v[0], v[1], v[2]]
        };
        (o.map(|k| eig.eigenvalues[k]), col(0), col(2))
    }

    fn from_eigen(values: [f64; 3], rot: &Rotation3<f64>) -> [[f64; 3]; 3] {
        let m = rot.matrix()
            * Matrix3::from_diagonal(&Vector3::from(values))
            * rot.matrix().transpose();
        // Symmetric exactly, as the grid's covariances are.
        [0, 1, 2].map(|i| [0, 1, 2].map(|j| if i <= j { m[(i, j)] } else { m[(j, i)] }))
    }

    /// Sine of the angle between two unit vectors (as lines).
    fn sin_angle(a: &[f64; 3], b: &[f64; 3]) -> f64 {
        let c = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
    }

    /// Agrees with nalgebra wherever it answers: eigenvalues within 1e-12
    /// of lambda3, eigenvectors within 1e-9 rad; and it answers for all
    /// but near-degenerate spectra.
    #[test]
    fn agrees_with_nalgebra_on_random_and_degenerate_covariances() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let (mut answered, mut total) = (0, 0);
        for k in 0..200_000 {
            let rot = Rotation3::new(Vector3::new(
                r.random_range(-3.0..3.0),
                r.random_range(-3.0..3.0),
                r.random_range(-3.0..3.0),
            ));
            let scale = 10f64.powf(r.random_range(-12.0..6.0));
            let mut v = [0, 1, 2].map(|_| scale * 10f64.powf(r.random_range(-6.0..0.0)));
            match k % 8 {
                // Equal pairs, all equal, rank 1 and 2, a tiny spread.
                0 => v[1] = v[0],
                1 => v[2] = v[1],
                2 => v = [v[0]; 3],
                3 => v[0] = 0.0,
                4 => (v[0], v[1]) = (0.0, 0.0),
                5 => v[1] = v[0] * (1.0 + 1e-9),
                _ => {}
            }
            let c = from_eigen(v, &rot);
            let (want, w1, w3) = reference(&c);
            total += 1;
            let Some(got) = closed_form(&c) else {
                continue;
            };
            answered += 1;
            let l3 = want[2].abs();
            for i in 0..3 {
                assert!(
                    (got.values[i] - want[i]).abs() <= 1e-12 * l3,
                    "{k}: {:?} vs {want:?}",
                    got.values
                );
            }
            assert!(sin_angle(&got.e1, &w1) < 1e-9, "{k} e1 {:?} {w1:?}", got.e1);
            assert!(sin_angle(&got.e3, &w3) < 1e-9, "{k} e3 {:?} {w3:?}", got.e3);
        }
        // Degenerate kinds 0-5 are 6/8 of the cases; most distinct
        // spectra must be answered.
        assert!(
            answered as f64 > 0.2 * total as f64,
            "{answered} of {total}"
        );
    }

    #[test]
    fn refuses_equal_eigenvalues_and_non_finite_input() {
        let id = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]];
        assert!(closed_form(&id).is_none());
        let zero = [[0.0; 3]; 3];
        assert!(closed_form(&zero).is_none());
        let nan = [[f64::NAN, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]];
        assert!(closed_form(&nan).is_none());
        let inf = [[f64::INFINITY, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]];
        assert!(closed_form(&inf).is_none());
        let diag = [[3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]];
        let e = closed_form(&diag).unwrap();
        assert_eq!(e.values.map(|v| (v * 1e12).round() / 1e12), [1.0, 2.0, 3.0]);
        assert!((e.e1[1].abs() - 1.0).abs() < 1e-12 && (e.e3[0].abs() - 1.0).abs() < 1e-12);
    }
}
