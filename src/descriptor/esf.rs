//! Shape-function histograms in the manner of the Ensemble of Shape
//! Functions (ESF) of Wohlkinger and Vincze, "Ensemble of shape functions
//! for 3D object classification" (ROBIO 2011), built on the shape
//! distributions of Osada et al. (ACM TOG 2002): random triples of points
//! give the distance of a pair (D2), the angle at one point (A3) and the
//! triangle's area (D3), and, as ESF adds, how much of the line between
//! two points runs through occupied voxels (ESF's in/out ratio).
//!
//! Unlike ESF, which scales objects to the unit sphere, distances stay in
//! metres: the size of a place is what tells a hall from a room. Points are
//! thinned to one per 0.25 m voxel first (surfaces count by area), and the
//! triples come from a fixed seed, so the same scan gives the same
//! histograms natively and in wasm. Every channel is invariant to rotation.
//!
//! Channels: D2 on a square-root scale to 64 m (24 bins), A3 from 0 to pi
//! (16), sqrt of D3 on a square-root scale to 32 m (24), occupied share of
//! the D2 line (16).

use super::parts::{soft_bin, unit_sum};
use crate::cloud::is_finite;
use rand::Rng;
use rustc_hash::FxHashSet;

/// Bins of each channel: D2, A3, D3, line ratio.
pub const CHANNELS: [usize; 4] = [24, 16, 24, 16];

/// Voxel edge of the thinning and of the occupancy the lines are traced in (m).
const VOXEL: f32 = 0.25;
/// Random triples per scan: 2,000 keep each histogram's noise a few
/// per cent of its mass at a few milliseconds a scan.
const TRIPLES: usize = 2000;
/// Seed of the triples (any fixed value).
const SEED: u64 = 0x00E5_F201;

type Key = [i32; 3];

fn key(p: &[f32; 3]) -> Key {
    p.map(|v| (v / VOXEL).floor() as i32)
}

fn sub(a: &[f32; 3], b: &[f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn norm(a: &[f32; 3]) -> f32 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// Most samples along one line: 4,096 voxel edges are 1 km, beyond any
/// lidar's reach, so real scans are sampled every voxel edge; a wild point
/// (the readers accept any finite value, e.g. 1e30) must not make one
/// line cost billions of lookups or, at infinity, never end.
const MAX_STEPS: usize = 4096;

/// Share of the voxels along a to b (sampled every voxel edge, at most
/// [`MAX_STEPS`]) that are occupied.
fn occupied_share(a: &[f32; 3], b: &[f32; 3], occupied: &FxHashSet<Key>) -> f64 {
    let d = sub(b, a);
    let length = norm(&d) / VOXEL;
    let steps = if length.is_finite() {
        (length.ceil() as usize).clamp(1, MAX_STEPS)
    } else {
        MAX_STEPS
    };
    let hits = (0..=steps)
        .filter(|&s| {
            let t = s as f32 / steps as f32;
            occupied.contains(&key(&[a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]]))
        })
        .count();
    hits as f64 / (steps + 1) as f64
}

/// The four histograms, each of unit sum (all mass in bin 0 for fewer than
/// three distinct voxels).
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    let mut occupied = FxHashSet::default();
    let sample: Vec<[f32; 3]> = points
        .iter()
        .filter(|p| is_finite(p) && occupied.insert(key(p)))
        .copied()
        .collect();
    let mut h: Vec<Vec<f32>> = CHANNELS.iter().map(|&b| vec![0f32; b]).collect();
    if sample.len() >= 3 {
        let mut r = crate::rng::rng(SEED);
        let n = sample.len();
        for _ in 0..TRIPLES {
            let (p, q, s) = (
                &sample[r.random_range(0..n)],
                &sample[r.random_range(0..n)],
                &sample[r.random_range(0..n)],
            );
            let (u, v) = (sub(q, p), sub(s, p));
            let (lu, lv) = (norm(&u) as f64, norm(&v) as f64);
            let bins = |c: usize| (CHANNELS[c] - 1) as f64;
            soft_bin(&mut h[0], (lu / 64.0).sqrt() * bins(0), 1.0);
            if lu > 0.0 && lv > 0.0 {
                let cos = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) as f64 / (lu * lv);
                soft_bin(
                    &mut h[1],
                    cos.clamp(-1.0, 1.0).acos() / std::f64::consts::PI * bins(1),
                    1.0,
                );
            }
            let c = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let area = norm(&c) as f64 / 2.0;
            soft_bin(&mut h[2], (area.sqrt() / 32.0).sqrt() * bins(2), 1.0);
            soft_bin(&mut h[3], occupied_share(p, q, &occupied) * bins(3), 1.0);
        }
    }
    h.iter_mut().for_each(|c| unit_sum(c));
    h.concat()
}
