//! Per-stage benchmarks (criterion), with peers measured in the same run:
//! ply-rs for PLY reading, and a fixed-stride copy of x, y, z (the memory
//! floor). `cargo bench --bench stages`; `node scripts/bench-table.mjs`
//! turns the results into docs/benchmarks.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::descriptor::polar::PolarScan;
use placecat::descriptor::{alignment, histogram, ndt_grid, shape, PartKind, PartValues};
use placecat::io::write::{self, PlyEncoding};
use placecat::io::{read_scan, ReadLimits};
use placecat::sim::{LidarParams, SceneKind, SimParams, Simulation};
use placecat::*;
use std::hint::black_box;
use std::time::Duration;

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real");

/// A simulated outdoor scan of about `beams` x `azimuth` rays.
fn sim_scan(beams: usize, azimuth: usize) -> Vec<[f32; 3]> {
    sim_scan_of(SceneKind::Outdoor, beams, azimuth)
}

fn sim_scan_of(scene: SceneKind, beams: usize, azimuth: usize) -> Vec<[f32; 3]> {
    let mut p = SimParams::new(scene, 1);
    p.scans = 3;
    let base = match scene {
        SceneKind::Indoor => LidarParams::indoor(),
        _ => LidarParams::outdoor(),
    };
    p.lidar = Some(LidarParams {
        beams,
        azimuth_steps: azimuth,
        dropout: 0.0,
        ..base
    });
    Simulation::new(&p).unwrap().scan(1).points
}

/// The memory floor: copy x, y, z out of fixed-stride float32 records.
/// (Benchmarks black_box its input and output: returning only the length
/// let the compiler delete the copy.)
fn stride_copy(body: &[u8], stride: usize) -> Vec<[f32; 3]> {
    body.chunks_exact(stride)
        .map(|r| {
            let f = |o: usize| f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]]);
            [f(0), f(4), f(8)]
        })
        .collect()
}

fn ply_rs_read(bytes: &[u8]) -> usize {
    let parser = ply_rs::parser::Parser::<ply_rs::ply::DefaultElement>::new();
    let mut r = std::io::Cursor::new(bytes);
    let ply = parser.read_ply(&mut r).unwrap();
    ply.payload["vertex"].len()
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(500))
}

fn read(c: &mut Criterion) {
    let limits = ReadLimits::default();
    let mut g = c.benchmark_group("read");
    for (label, pts) in [("100k", sim_scan(64, 1800)), ("1M", sim_scan(128, 8192))] {
        let n = pts.len() as u64;
        let bin = write::ply(&pts, PlyEncoding::BinaryLittleEndian, false);
        let ascii = write::ply(&pts, PlyEncoding::Ascii, false);
        let header = bin.len() - pts.len() * 12;
        g.throughput(Throughput::Elements(n));
        g.bench_with_input(
            BenchmarkId::new("ply_binary/placecat", label),
            &bin,
            |b, x| b.iter(|| black_box(read_scan(black_box(x), "a.ply", &limits).unwrap().points)),
        );
        g.bench_with_input(
            BenchmarkId::new("ply_binary/ply-rs", label),
            &bin,
            |b, x| b.iter(|| ply_rs_read(black_box(x))),
        );
        g.bench_with_input(
            BenchmarkId::new("ply_binary/stride_copy_floor", label),
            &bin,
            |b, x| b.iter(|| black_box(stride_copy(black_box(&x[header..]), 12))),
        );
        g.bench_with_input(
            BenchmarkId::new("ply_ascii/placecat", label),
            &ascii,
            |b, x| b.iter(|| black_box(read_scan(black_box(x), "a.ply", &limits).unwrap().points)),
        );
        if label == "100k" {
            g.bench_with_input(
                BenchmarkId::new("ply_ascii/ply-rs", label),
                &ascii,
                |b, x| b.iter(|| ply_rs_read(black_box(x))),
            );
        }
    }
    for (label, rel) in [
        ("kitti_bin/real_000094", "kitti00/000094.bin"),
        (
            "pcd_binary_compressed/real_room_scan1",
            "pcl_room/room_scan1.pcd",
        ),
        ("pcd_binary/real_velodyne", "velodyne_pair/251370668.pcd"),
    ] {
        let bytes = std::fs::read(format!("{REAL}/{rel}")).unwrap();
        let n = read_scan(&bytes, rel, &limits).unwrap().points.len() as u64;
        g.throughput(Throughput::Elements(n));
        g.bench_with_input(BenchmarkId::new(label, n), &bytes, |b, x| {
            b.iter(|| black_box(read_scan(black_box(x), rel, &limits).unwrap().points))
        });
    }
    g.finish();
}

fn describe_stages(c: &mut Criterion) {
    let mut g = c.benchmark_group("describe");
    let kitti = read_scan(
        &std::fs::read(format!("{REAL}/kitti00/000094.bin")).unwrap(),
        "a.bin",
        &ReadLimits::default(),
    )
    .unwrap()
    .points;
    // Sparse outdoor (~100k), dense outdoor and indoor (~1M), an 8-beam
    // sensor (~6k), and a real KITTI scan.
    for (label, pts, p) in [
        ("real_kitti_121k", kitti, DescriptorParams::outdoor()),
        ("sim_100k", sim_scan(64, 1800), DescriptorParams::outdoor()),
        ("sim_1M", sim_scan(128, 8192), DescriptorParams::outdoor()),
        (
            "sim_indoor_1M",
            sim_scan_of(SceneKind::Indoor, 128, 8192),
            DescriptorParams::indoor(),
        ),
        (
            "sim_8beam_6k",
            sim_scan(8, 900),
            DescriptorParams::outdoor(),
        ),
    ] {
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_with_input(BenchmarkId::new("ndt_grid", label), &pts, |b, x| {
            b.iter(|| {
                ndt_grid::build(x, p.voxel_size, p.min_points_per_voxel)
                    .cells
                    .len()
            })
        });
        let grid = ndt_grid::build(&pts, p.voxel_size, p.min_points_per_voxel);
        g.bench_with_input(BenchmarkId::new("classify", label), &grid, |b, x| {
            b.iter(|| {
                x.cells
                    .iter()
                    .filter_map(|c| shape::classify(c, p.eigen_threshold))
                    .count()
            })
        });
        let cells: Vec<_> = grid
            .cells
            .iter()
            .filter_map(|c| shape::classify(c, p.eigen_threshold))
            .collect();
        g.bench_with_input(BenchmarkId::new("alignment", label), &cells, |b, x| {
            b.iter(|| alignment::candidates(x, &p).len())
        });
        let rotations = alignment::candidates(&cells, &p);
        g.bench_with_input(BenchmarkId::new("histogram", label), &cells, |b, x| {
            b.iter(|| histogram::histograms(x, &rotations, &p).0.len())
        });
        g.bench_with_input(BenchmarkId::new("describe_total", label), &pts, |b, x| {
            b.iter(|| describe(x, &p).unwrap().total())
        });
    }
    g.finish();
}

/// The extra descriptor parts (issue 18) beside the NDT histogram, on the
/// same scans in the same run: `ndt_histogram` is `describe` with the
/// paper's indoor parameters, each part its own `PartKind::describe`.
fn describe_parts(c: &mut Criterion) {
    let p = DescriptorParams::indoor();
    let mut g = c.benchmark_group("parts");
    let room = read_scan(
        &std::fs::read(format!("{REAL}/pcl_room/room_scan1.pcd")).unwrap(),
        "a.pcd",
        &ReadLimits::default(),
    )
    .unwrap()
    .points;
    for (label, pts) in [("real_room_112k", room), ("sim_100k", sim_scan(64, 1800))] {
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_with_input(BenchmarkId::new("ndt_histogram", label), &pts, |b, x| {
            b.iter(|| describe(x, &p).unwrap().total())
        });
        for kind in PartKind::ALL {
            let id = kind.name();
            g.bench_with_input(BenchmarkId::new(id, label), &pts, |b, x| {
                b.iter(|| kind.describe(black_box(x)).len())
            });
        }
        // Whole descriptors of the presets issue 18's last rounds read
        // (the NDT histogram and every part, as `describe` makes them).
        for preset in [
            "indoor_columns",
            "indoor_searched",
            "indoor_objects",
            "indoor_object_types",
        ] {
            let params = DescriptorParams::preset(preset).unwrap();
            g.bench_with_input(
                BenchmarkId::new(format!("preset_{preset}"), label),
                &pts,
                |b, x| b.iter(|| describe(black_box(x), &params).unwrap().total()),
            );
        }
        // indoor_clutter's four parts: each on its own (slice, ring and
        // clutter each build their own PolarScan and polygon; esf none),
        // and sharing one (as `describe` does). The code before the
        // sharing (20288a1) is measured by its own bench; docs/parts.md.
        let kinds: Vec<PartKind> = DescriptorParams::indoor_clutter()
            .parts
            .iter()
            .map(|p| p.kind)
            .collect();
        g.bench_with_input(
            BenchmarkId::new("indoor_clutter_parts_separate", label),
            &pts,
            |b, x| {
                b.iter(|| {
                    kinds
                        .iter()
                        .map(|k| k.describe(black_box(x)).len())
                        .sum::<usize>()
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("indoor_clutter_parts_shared", label),
            &pts,
            |b, x| {
                b.iter(|| {
                    let scan = PolarScan::new(black_box(x));
                    kinds
                        .iter()
                        .map(|k| k.describe_scan(&scan).len())
                        .sum::<usize>()
                })
            },
        );
    }
    g.finish();
    // The distance: the paper's Delta matrix against the combined one of
    // indoor_plus (the NDT plus every part) on the same scans.
    let mut g = c.benchmark_group("parts_distance");
    let n = 500;
    let plus = DescriptorParams::indoor_plus();
    let mut ds = many_descriptors(n);
    let mut r = placecat::rng::rng(7);
    for d in &mut ds {
        d.parts = plus
            .parts
            .iter()
            .map(|part| PartValues {
                kind: part.kind,
                values: random_channels(part.kind, &mut r),
            })
            .collect();
    }
    g.throughput(Throughput::Elements((n * (n - 1) / 2) as u64));
    // The same NDT histograms without the parts.
    let plain: Vec<Descriptor> = ds
        .iter()
        .cloned()
        .map(|mut d| {
            d.parts.clear();
            d
        })
        .collect();
    g.bench_with_input(BenchmarkId::new("delta_matrix_paper", n), &plain, |b, x| {
        let o = DistanceOptions::from(&p);
        b.iter(|| delta_matrix(x, o).unwrap().n)
    });
    g.bench_with_input(
        BenchmarkId::new("delta_matrix_indoor_plus", n),
        &ds,
        |b, x| b.iter(|| delta_matrix(x, DistanceOptions::from(&plus)).unwrap().n),
    );
    // The Hellinger distance (outdoor_hellinger's metric) on the same NDT
    // histograms, with the roots taken once per descriptor.
    let hellinger = DistanceOptions {
        metric: placecat::descriptor::Metric::Hellinger,
        ..DistanceOptions::from(&p)
    };
    g.bench_with_input(
        BenchmarkId::new("delta_matrix_hellinger", n),
        &plain,
        |b, x| b.iter(|| delta_matrix(x, hellinger).unwrap().n),
    );
    g.finish();
}

/// A part's channels filled with random unit-sum histograms.
fn random_channels(kind: PartKind, r: &mut impl rand::Rng) -> Vec<f32> {
    kind.channels()
        .iter()
        .flat_map(|&bins| {
            let h: Vec<f32> = (0..bins).map(|_| r.random::<f32>()).collect();
            let s: f32 = h.iter().sum();
            h.into_iter().map(move |v| v / s)
        })
        .collect()
}

fn many_descriptors(n: usize) -> Vec<Descriptor> {
    placecat::sim::reused_descriptors(n, &DescriptorParams::indoor(), 5).unwrap()
}

fn distances_and_clustering(c: &mut Criterion) {
    let mut g = c.benchmark_group("cluster");
    let o = DistanceOptions::default();
    for n in [500usize, 2000] {
        let ds = many_descriptors(n);
        let pairs = (n * (n - 1) / 2) as u64;
        g.throughput(Throughput::Elements(pairs));
        g.bench_with_input(BenchmarkId::new("delta_matrix", n), &ds, |b, x| {
            b.iter(|| delta_matrix(x, o).unwrap().n)
        });
        g.throughput(Throughput::Elements(n as u64));
        let space = Space::new(&ds, o).unwrap();
        g.bench_with_input(BenchmarkId::new("kmeans_pp_k5", n), &space, |b, s| {
            b.iter(|| KMeans::fit(s, &KMeansParams::new(5)).unwrap().iterations)
        });
        let m = delta_matrix(&ds, o).unwrap();
        g.bench_with_input(BenchmarkId::new("hkmeans_tree", n), &m, |b, m| {
            b.iter(|| {
                HierarchicalKMeans::fit(&space, m, &HkMeansParams::new(0))
                    .unwrap()
                    .nodes
                    .len()
            })
        });
        g.bench_with_input(BenchmarkId::new("dbscan", n), &m, |b, m| {
            b.iter(|| Dbscan::fit(m, &DbscanParams::new(0.3, 4)).unwrap().len())
        });
        // Its dense eigen-decomposition grows with n³: spectral::MAX_SCANS.
        g.bench_with_input(BenchmarkId::new("spectral_k5", n), &m, |b, m| {
            b.iter(|| {
                Spectral::fit(m, &SpectralParams::new(5))
                    .unwrap()
                    .labels
                    .len()
            })
        });
    }
    g.finish();
}

criterion_group! { name = benches; config = config(); targets = read, describe_stages, describe_parts, distances_and_clustering }
criterion_main!(benches);
