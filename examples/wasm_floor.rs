//! The same read + describe stages natively and in wasm, for counting what
//! each build executes per point (docs/wasm-floor.md). Each stage is its own
//! exported, never-inlined function that runs the stage `n` times on inputs
//! prepared once by `floor_load`, so an instruction counter (valgrind) or a
//! sampling profiler sees one function per stage in both builds, and runs
//! with n = 0 measure everything else (start-up, compilation, loading).
//!
//! Native: `cargo run --release --example wasm_floor -- FILE STAGE N`
//! (STAGE one of read, grid, classify, align, hist, describe, total; `time`
//! to print the fastest of N single calls of each stage, 5 in a row; `digest` to print
//! a digest of the grid's and the descriptor's bits).
//! wasm: `cargo build --release --example wasm_floor --target
//! wasm32-unknown-unknown --no-default-features` (the `floor_*` functions
//! are exported from the example's .wasm as they are), run by
//! bench/wasm-floor.mjs; bench/wasm-floor-count.sh counts instructions.
use placecat::descriptor::shape::ShapedCell;
use placecat::descriptor::{alignment, histogram, ndt_grid, shape};
use placecat::io::{read_scan, ReadLimits};
use placecat::{describe, DescriptorParams};
use std::hint::black_box;
use std::sync::Mutex;

/// What `floor_load` prepared: the file's bytes and name, and each stage's
/// input computed once.
struct Prepared {
    bytes: Vec<u8>,
    name: &'static str,
    points: Vec<[f32; 3]>,
    grid: ndt_grid::Grid,
    cells: Vec<ShapedCell>,
    rotations: Vec<alignment::Rotation>,
    params: DescriptorParams,
}

static STATE: Mutex<Option<Prepared>> = Mutex::new(None);

fn with<R>(f: impl FnOnce(&Prepared) -> R) -> R {
    f(STATE.lock().unwrap().as_ref().expect("floor_load first"))
}

/// Room for a file of `len` bytes in this module's memory (leaked: one per run).
#[no_mangle]
pub extern "C" fn floor_alloc(len: usize) -> *mut u8 {
    Vec::leak(vec![0u8; len]).as_mut_ptr()
}

/// Reads the `len` bytes at `ptr` (format 0: PLY, 1: KITTI .bin, 2: PCD)
/// and prepares every stage's input; returns the number of points.
///
/// # Safety
/// `ptr` must come from `floor_alloc(len)`.
#[no_mangle]
pub unsafe extern "C" fn floor_load(ptr: *const u8, len: usize, format: u32) -> u32 {
    let bytes = std::slice::from_raw_parts(ptr, len).to_vec();
    let name = ["a.ply", "a.bin", "a.pcd"][format as usize];
    let params = DescriptorParams::outdoor();
    let points = read_scan(&bytes, name, &ReadLimits::default())
        .unwrap()
        .points;
    let grid = ndt_grid::build(&points, params.voxel_size, params.min_points_per_voxel);
    let cells: Vec<ShapedCell> = grid
        .cells
        .iter()
        .filter_map(|c| shape::classify(c, params.eigen_threshold))
        .collect();
    let rotations = alignment::candidates(&cells, &params);
    let n = points.len() as u32;
    *STATE.lock().unwrap() = Some(Prepared {
        bytes,
        name,
        points,
        grid,
        cells,
        rotations,
        params,
    });
    n
}

/// Reading the file's bytes into points.
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_read(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| read_scan(black_box(&s.bytes), s.name, &ReadLimits::default()).unwrap())
            .map(|c| c.points.len() as u32)
            .sum()
    })
}

/// The NDT grid (voxel sums, means and covariances).
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_grid(n: u32) -> u32 {
    with(|s| {
        let p = &s.params;
        (0..n)
            .map(|_| ndt_grid::build(black_box(&s.points), p.voxel_size, p.min_points_per_voxel))
            .map(|g| g.cells.len() as u32)
            .sum()
    })
}

/// Classifying the grid's cells (the eigen decomposition).
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_classify(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| {
                black_box(&s.grid)
                    .cells
                    .iter()
                    .filter_map(|c| shape::classify(c, s.params.eigen_threshold))
                    .count() as u32
            })
            .sum()
    })
}

/// The candidate alignments.
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_align(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| alignment::candidates(black_box(&s.cells), &s.params).len() as u32)
            .sum()
    })
}

/// The histograms, one per candidate alignment.
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_hist(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| histogram::histograms(black_box(&s.cells), &s.rotations, &s.params).1 as u32)
            .sum()
    })
}

/// describe() from points: every stage above but reading, and the rest.
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_describe(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| {
                describe(black_box(&s.points), &s.params)
                    .unwrap()
                    .summary
                    .voxels as u32
            })
            .sum()
    })
}

/// Read + describe, as the page does per scan.
#[no_mangle]
#[inline(never)]
pub extern "C" fn floor_total(n: u32) -> u32 {
    with(|s| {
        (0..n)
            .map(|_| {
                let c = read_scan(black_box(&s.bytes), s.name, &ReadLimits::default()).unwrap();
                describe(&c.points, &s.params).unwrap().summary.voxels as u32
            })
            .sum()
    })
}

/// FNV-1a of every bit of the grid's cells and of the descriptor (its
/// matrices and summary counts): equal digests from the native and the
/// wasm build, or from two versions, mean bit-identical results.
#[no_mangle]
pub extern "C" fn floor_digest() -> u64 {
    with(|s| {
        let mut h = 0xcbf2_9ce4_8422_2325u64;
        let mut eat = |bits: u64| {
            for b in bits.to_le_bytes() {
                h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
            }
        };
        for c in &s.grid.cells {
            eat(c.count as u64);
            c.mean
                .iter()
                .chain(c.cov.iter().flatten())
                .for_each(|v| eat(v.to_bits()));
        }
        let d = describe(&s.points, &s.params).unwrap();
        d.matrices.iter().flatten().for_each(|&v| eat(v as u64));
        let m = &d.summary;
        [
            m.points,
            m.dropped,
            m.voxels,
            m.sparse_voxels,
            m.spherical,
            m.planar,
            m.linear,
            m.in_range,
        ]
        .into_iter()
        .for_each(|v| eat(v as u64));
        h
    })
}

/// The stages by name, in the order of the table.
#[cfg(not(target_arch = "wasm32"))]
const STAGES: [(&str, extern "C" fn(u32) -> u32); 7] = [
    ("read", floor_read),
    ("grid", floor_grid),
    ("classify", floor_classify),
    ("align", floor_align),
    ("hist", floor_hist),
    ("describe", floor_describe),
    ("total", floor_total),
];

/// Calls of one stage in a row in `time` mode.
#[cfg(not(target_arch = "wasm32"))]
const REPEAT: u32 = 5;

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [file, stage, n] = &args[..] else {
        panic!("usage: wasm_floor FILE STAGE|time N");
    };
    let bytes = std::fs::read(file).unwrap();
    let ptr = floor_alloc(bytes.len());
    // SAFETY: ptr has room for bytes.len() bytes (floor_alloc).
    let points = unsafe {
        std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr, bytes.len());
        let format = ["ply", "bin", "pcd"].iter().position(|e| file.ends_with(e));
        floor_load(
            ptr,
            bytes.len(),
            format.expect("a .ply, .bin or .pcd file") as u32,
        )
    };
    let n: u32 = n.parse().unwrap();
    if stage == "digest" {
        println!("{:016x}", floor_digest());
    } else if stage == "time" {
        // Fastest single call of each stage: the stages take turns, REPEAT
        // calls at a time (one call after another of a different stage
        // finds the allocator and caches in that stage's state, not its
        // own), so that a load on the machine touches them alike.
        let mut best = [f64::INFINITY; STAGES.len()];
        for _ in 0..n.div_ceil(REPEAT) {
            for (b, (_, f)) in best.iter_mut().zip(STAGES) {
                for _ in 0..REPEAT {
                    let t = std::time::Instant::now();
                    black_box(f(1));
                    *b = b.min(t.elapsed().as_secs_f64());
                }
            }
        }
        let out: serde_json::Map<_, _> = STAGES
            .iter()
            .zip(best)
            .map(|((name, _), b)| (name.to_string(), serde_json::json!(b)))
            .collect();
        println!("{}", serde_json::json!({"points": points, "seconds": out}));
    } else {
        let f = STAGES
            .iter()
            .find(|(name, _)| name == stage)
            .expect("stage")
            .1;
        println!("{}", f(n));
    }
}

/// The wasm build is driven from JS through the exported functions.
#[cfg(target_arch = "wasm32")]
fn main() {}
