//! The NDT grid: voxels of edge B on a lattice anchored at the origin
//! (index = floor(p / B)), so the grid does not depend on the data. Per voxel
//! the count, mean and sample covariance of its points.

use crate::cloud::is_finite;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

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
    /// Points in the voxel.
    pub count: u32,
    /// Mean of its points in the sensor frame (m).
    pub mean: [f64; 3],
    /// Sample covariance, row-major 3x3.
    pub cov: [[f64; 3]; 3],
}

/// The result of gridding one scan.
#[derive(Debug, Clone)]
pub struct Grid {
    /// The voxels with at least `min_points_per_voxel` points.
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
    // Sums live in a Vec; the map gives each voxel key its slot. Lidar
    // points come in ring order, so consecutive points often share a voxel:
    // the last slot is remembered and the hash lookup skipped. (Reserving
    // more than points / 8 was measured slower on 1M-point scans: a
    // sparser table misses the cache more.)
    let mut slots: HashMap<u64, u32, BuildHasherDefault<KeyHasher>> = HashMap::default();
    slots.reserve(points.len() / 8);
    let mut sums: Vec<(u64, Sums)> = Vec::with_capacity(points.len() / 8);
    let (mut last_key, mut last_slot) = (NO_RUN, 0usize);
    // The sums of the voxel of the current run of points, kept in
    // registers and stored when the run ends: the same additions in the
    // same order as adding into the table, without a store and reload per
    // point (dense indoor scans have runs of dozens of points).
    let mut run = Sums::default();
    let mut dropped = 0;
    // Keys and in-voxel offsets a block at a time, in a branch-free loop
    // the compiler vectorises; then the sums, point by point in file order
    // (the order of the additions, hence every bit of the sums, unchanged).
    const BLOCK: usize = 128;
    let mut keys = [0u64; BLOCK];
    let mut offsets = [[0f64; 3]; BLOCK];
    for block in points.chunks(BLOCK) {
        for ((p, key), local) in block.iter().zip(&mut keys).zip(&mut offsets) {
            let q = [p[0] as f64, p[1] as f64, p[2] as f64];
            let idx = [0, 1, 2].map(|k| voxel_floor(q[k] * inv));
            *local = [0, 1, 2].map(|k| q[k] - idx[k].1 * voxel_size);
            *key = if is_finite(p) {
                pack(idx.map(|(i, _)| i))
            } else {
                NO_KEY
            };
        }
        for (&key, local) in keys[..block.len()].iter().zip(&offsets) {
            if key != last_key {
                if key == NO_KEY {
                    dropped += 1;
                    continue;
                }
                if last_key != NO_RUN {
                    sums[last_slot].1 = run;
                }
                let next = sums.len() as u32;
                last_slot = *slots.entry(key).or_insert(next) as usize;
                if last_slot == sums.len() {
                    sums.push((key, Sums::default()));
                }
                last_key = key;
                run = sums[last_slot].1;
            }
            run.n += 1;
            for (s, l) in run.s.iter_mut().zip(local) {
                *s += l;
            }
            run.ss[0] += local[0] * local[0];
            run.ss[1] += local[0] * local[1];
            run.ss[2] += local[0] * local[2];
            run.ss[3] += local[1] * local[1];
            run.ss[4] += local[1] * local[2];
            run.ss[5] += local[2] * local[2];
        }
    }
    if last_key != NO_RUN {
        sums[last_slot].1 = run;
    }
    // Sorted by voxel key, so the result does not depend on hash or
    // insertion order. Only voxels with enough points are sorted (outdoor
    // scans have twice as many sparse voxels as dense ones), as small
    // (key, slot) pairs rather than the sums.
    let mut order: Vec<(u64, u32)> = sums
        .iter()
        .enumerate()
        .filter(|(_, (_, s))| s.n as usize >= min_points)
        .map(|(i, (k, _))| (*k, i as u32))
        .collect();
    let sparse = sums.len() - order.len();
    order.sort_unstable();
    let mut cells = Vec::with_capacity(order.len());
    for (key, slot) in order {
        let s = &sums[slot as usize].1;
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
        let corner = unpack(key).map(|i| i as f64 * voxel_size);
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

/// Voxel indices are kept within +-2^20 (+-420 km at B = 0.4 m), so three
/// fit in one u64 key: hashing and sorting one integer instead of a tuple
/// (the profile of a KITTI scan showed both). Farther points share the
/// outermost voxels.
const INDEX_LIMIT: i64 = (1 << 20) - 1;

/// floor(x) clamped to the index range, without a libm call (the profile
/// showed `floor` at 14% of describing a scan; on x86-64 without SSE4.1
/// `floor` is a function call). wasm builds use `voxel_floor_wasm`.
#[cfg(any(not(target_arch = "wasm32"), test))]
#[inline(always)]
fn voxel_index(x: f64) -> i32 {
    let x = x.clamp(-(INDEX_LIMIT as f64), INDEX_LIMIT as f64);
    // Through i32, not i64: the clamped value fits, and f64 -> i32 has a
    // vector instruction on every x86-64 (SSE2) and in wasm simd128.
    let t = x as i32;
    if (t as f64) > x {
        t - 1
    } else {
        t
    }
}

/// The voxel index of `x` (in voxels), as an integer and as an f64.
#[cfg(not(target_arch = "wasm32"))]
#[inline(always)]
fn voxel_floor(x: f64) -> (i32, f64) {
    let i = voxel_index(x);
    (i, i as f64)
}

/// The same on wasm, where `floor` is one instruction (f64.floor) but a
/// float-to-int conversion is several with its range checks (V8's code
/// for the function above was 114 x86 instructions per point in the key
/// loop, docs/wasm-floor.md): the index is the clamped floor, an
/// integer-valued f64, read out of the bits of `f + 1.5 * 2^52` (exact for
/// |f| < 2^31; the clamp keeps |f| < 2^20), and the f64 is used directly
/// for the offset. The `+ 0.0` makes a -0.0 index 0.0, as `0i32 as f64`
/// is, so the offsets are the same bits as the native path's. The two
/// paths differ only for a NaN `x` (native: index 0 and a finite offset;
/// here: a NaN offset). `x` is NaN only for a non-finite point, whose key
/// is NO_KEY and whose offset is never summed: params' validate() keeps
/// `voxel_size >= MIN_VOXEL_SIZE`, so 1/B is finite and a finite
/// coordinate times it is never NaN (a subnormal B, 1/B = inf, made a 0.0
/// coordinate NaN).
#[cfg(any(target_arch = "wasm32", test))]
#[inline(always)]
fn voxel_floor_wasm(x: f64) -> (i32, f64) {
    const MAGIC: f64 = 6_755_399_441_055_744.0; // 1.5 * 2^52
    let f = x.floor().clamp(-(INDEX_LIMIT as f64), INDEX_LIMIT as f64) + 0.0;
    ((f + MAGIC).to_bits() as u32 as i32, f)
}

#[cfg(target_arch = "wasm32")]
use voxel_floor_wasm as voxel_floor;

/// Key of a non-finite point (packed keys are below 2^63).
const NO_KEY: u64 = u64::MAX;
/// `last_key` before the first finite point: neither a key nor NO_KEY, so
/// a non-finite first point is still dropped.
const NO_RUN: u64 = u64::MAX - 1;

/// Order-preserving packing: sorting keys sorts by (x, y, z) index.
#[inline(always)]
fn pack(i: [i32; 3]) -> u64 {
    let b = |v: i32| (v as i64 + (1 << 20)) as u64;
    (b(i[0]) << 42) | (b(i[1]) << 21) | b(i[2])
}

fn unpack(k: u64) -> [i32; 3] {
    let m = (1u64 << 21) - 1;
    [(k >> 42) & m, (k >> 21) & m, k & m].map(|v| (v as i64 - (1 << 20)) as i32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_points_are_dropped_wherever_they_are() {
        let (nan, inf) = (f32::NAN, f32::INFINITY);
        let p = [
            [nan, 0.0, 0.0],
            [0.1, 0.1, 0.1],
            [0.1, inf, 0.1],
            [0.2, 0.1, 0.3],
        ];
        let g = build(&p, 0.4, 2);
        assert_eq!((g.points, g.dropped, g.cells.len()), (2, 2, 1));
        assert_eq!(g.cells[0].count, 2);
        let only_bad = build(&[[nan; 3]; 300], 0.4, 1);
        assert_eq!((only_bad.dropped, only_bad.cells.len()), (300, 0));
    }

    #[test]
    fn index_is_floor_and_packing_round_trips_in_order() {
        for x in [-3.5f64, -3.0, -0.2, -0.0, 0.0, 0.2, 2.999, 3.0, 1e7, -1e7] {
            let want = x.floor().clamp(-(INDEX_LIMIT as f64), INDEX_LIMIT as f64) as i32;
            assert_eq!(voxel_index(x), want, "{x}");
        }
        let keys = [[-5, 3, 2], [-5, 3, 3], [-5, 4, -100], [0, 0, 0], [7, -1, 1]];
        for w in keys.windows(2) {
            assert!(pack(w[0]) < pack(w[1]));
        }
        for k in keys {
            assert_eq!(unpack(pack(k)), k);
        }
    }

    /// The wasm voxel index gives the native one's integer and f64 bits for
    /// every non-NaN input. Runs natively (`cargo test --lib ndt_grid`) and
    /// compiled to wasm, where `voxel_index` is the portable code compiled
    /// by the same backend as `voxel_floor_wasm` (`wasm-pack test --node --
    /// --no-default-features --lib ndt_grid`, scripts/test-1-wasm.sh).
    #[cfg_attr(not(target_arch = "wasm32"), test)]
    #[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
    fn wasm_voxel_index_equals_the_portable_one() {
        let l = INDEX_LIMIT as f64;
        let mut edges = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0 - f64::EPSILON / 2.0,
            -(1.0 - f64::EPSILON / 2.0),
            -2.5,
            2.999,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN,
        ];
        // Subnormals and the smallest normals, both signs.
        for v in [5e-324, 1e-310, f64::MIN_POSITIVE] {
            edges.extend([v, -v]);
        }
        // Around the clamp: +-L exactly, inside (L, L+1), L+1, and beyond.
        for v in [l, l + 0.5, l + 1.0, l + 2.0, 1e7] {
            for w in [v, v.next_up(), v.next_down()] {
                edges.extend([w, -w]);
            }
        }
        // Past i32 and the magic constant's exact range.
        for k in [31, 32, 51, 52, 53, 63, 64] {
            let v = 2f64.powi(k);
            edges.extend([v, -v, 1.5 * v, -1.5 * v, v.next_up(), -v.next_down()]);
        }
        // Powers of two and their neighbours from 2^-60 to 2^59.
        for k in -60..60 {
            let v = 2f64.powi(k);
            edges.extend([
                v,
                -v,
                v.next_up(),
                v.next_down(),
                -v.next_up(),
                -v.next_down(),
            ]);
        }
        // Random values: within the index range, small ones, and ones
        // reaching past the clamp (about a third beyond +-L).
        let mut r = crate::rng::rng(3);
        let random = (0..60_000).map(|k| {
            let w = [3e6, 3e5, 50.0][k % 3];
            rand::Rng::random_range(&mut r, -w..w)
        });
        let mut beyond = 0;
        for x in edges.into_iter().chain(random) {
            beyond += (x.abs() > l) as usize;
            let (i, f) = voxel_floor_wasm(x);
            let want = voxel_index(x);
            assert_eq!(i, want, "{x:e}");
            assert_eq!(f.to_bits(), (want as f64).to_bits(), "{x:e}");
        }
        assert!(beyond > 10_000, "{beyond} values past the clamp");
    }
}

/// Hashes one packed voxel key with a 64-bit multiply and folds the high
/// half into the low one. Written here, not taken from a crate, because it
/// was measured: FxHash (rustc-hash 2) hashes a u64 as two 32-bit words on
/// wasm32, and this hasher made wasm read + describe 4-5 % faster in Node
/// (KITTI 000094: 3.39-3.42 -> 3.24-3.25 ms; a simulated 111k-point PLY:
/// 4.32-4.33 -> 4.19-4.20 ms, fastest of 40, alternated builds), with
/// native unchanged (2.52-2.54 ms and 2.95-2.98 ms, fastest of 100).
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn write(&mut self, bytes: &[u8]) {
        // Not used for u64 keys; kept correct for any other input.
        for &b in bytes {
            self.write_u64(self.0 ^ u64::from(b));
        }
    }
    #[inline(always)]
    fn write_u64(&mut self, key: u64) {
        let h = key.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        self.0 = h ^ (h >> 32);
    }
    #[inline(always)]
    fn finish(&self) -> u64 {
        self.0
    }
}
