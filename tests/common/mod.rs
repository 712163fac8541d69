//! Helpers shared by the integration tests: known geometry and rotations.
#![allow(dead_code)]

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real");

pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// Points uniformly on the rectangle `origin + s*u + t*v`, s, t in [0, 1].
pub fn rect(
    rng: &mut ChaCha8Rng,
    origin: [f32; 3],
    u: [f32; 3],
    v: [f32; 3],
    n: usize,
) -> Vec<[f32; 3]> {
    (0..n)
        .map(|_| {
            let (s, t): (f32, f32) = (rng.random(), rng.random());
            [0, 1, 2].map(|k| origin[k] + s * u[k] + t * v[k])
        })
        .collect()
}

/// Surfaces of an axis-aligned box room (floor, ceiling, 4 walls) around the
/// sensor, plus boxes of furniture, sampled with a density per square metre.
pub fn room(
    seed: u64,
    size: [f32; 3],
    floor_z: f32,
    furniture: &[([f32; 3], [f32; 3])],
    density: f32,
) -> Vec<[f32; 3]> {
    let mut r = rng(seed);
    let mut pts = Vec::new();
    let [sx, sy, sz] = size;
    let (x0, y0) = (-sx * 0.4, -sy * 0.55);
    let mut face = |r: &mut ChaCha8Rng, o: [f32; 3], u: [f32; 3], v: [f32; 3]| {
        let area =
            (u.iter().map(|a| a * a).sum::<f32>() * v.iter().map(|a| a * a).sum::<f32>()).sqrt();
        pts.extend(rect(r, o, u, v, (area * density) as usize));
    };
    face(&mut r, [x0, y0, floor_z], [sx, 0.0, 0.0], [0.0, sy, 0.0]);
    face(
        &mut r,
        [x0, y0, floor_z + sz],
        [sx, 0.0, 0.0],
        [0.0, sy, 0.0],
    );
    face(&mut r, [x0, y0, floor_z], [sx, 0.0, 0.0], [0.0, 0.0, sz]);
    face(
        &mut r,
        [x0, y0 + sy, floor_z],
        [sx, 0.0, 0.0],
        [0.0, 0.0, sz],
    );
    face(&mut r, [x0, y0, floor_z], [0.0, sy, 0.0], [0.0, 0.0, sz]);
    face(
        &mut r,
        [x0 + sx, y0, floor_z],
        [0.0, sy, 0.0],
        [0.0, 0.0, sz],
    );
    for (o, d) in furniture {
        face(
            &mut r,
            [o[0], o[1], o[2] + d[2]],
            [d[0], 0.0, 0.0],
            [0.0, d[1], 0.0],
        );
        face(&mut r, *o, [d[0], 0.0, 0.0], [0.0, 0.0, d[2]]);
        face(&mut r, *o, [0.0, d[1], 0.0], [0.0, 0.0, d[2]]);
    }
    pts
}

/// A room-like office (desks) and a long corridor: two different scenes.
pub fn office(seed: u64) -> Vec<[f32; 3]> {
    room(
        seed,
        [7.0, 5.0, 2.7],
        -1.2,
        &[
            ([1.0, 1.0, -1.2], [1.6, 0.8, 0.75]),
            ([-1.5, -2.0, -1.2], [1.6, 0.8, 0.75]),
            ([3.5, -2.5, -1.2], [0.5, 2.0, 2.0]),
        ],
        400.0,
    )
}

pub fn corridor(seed: u64) -> Vec<[f32; 3]> {
    room(seed, [30.0, 2.2, 2.7], -1.2, &[], 400.0)
}

/// Rotation matrix (rows) about a unit axis by an angle.
pub fn rotation(axis: [f64; 3], angle: f64) -> [[f64; 3]; 3] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let [x, y, z] = axis.map(|a| a / n);
    let (s, c) = angle.sin_cos();
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

pub fn rotate_points(points: &[[f32; 3]], r: &[[f64; 3]; 3]) -> Vec<[f32; 3]> {
    points
        .iter()
        .map(|p| {
            let q = p.map(|v| v as f64);
            [0, 1, 2].map(|i| (r[i][0] * q[0] + r[i][1] * q[1] + r[i][2] * q[2]) as f32)
        })
        .collect()
}

/// Read a real file by its path under tests/data/real.
pub fn real(rel: &str) -> Vec<u8> {
    std::fs::read(format!("{REAL}/{rel}")).unwrap_or_else(|e| panic!("{REAL}/{rel}: {e}"))
}
