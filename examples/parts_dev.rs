//! Development run for the extra descriptor parts (issue 18): describes
//! simulator scenes on the development seeds (1, 2, 3; docs/seeds.md) once
//! with every part, then scores weightings of the parts by stride k-means,
//! hierarchical k-means++ (mean over clustering seeds 0..9) and 1-NN
//! (sequences: no neighbour within 25 scans), and prints the median
//! distance of the NDT histogram and of each part.
//!
//!     cargo run --release --example parts_dev -- [--seeds 1,2,3] [--scans N] [--only NAME] [WEIGHTS...]
//!
//! WEIGHTS: `ndt,height_range,slice,esf,ring,clutter,m2dp,columns,iron,objects`
//! (e.g. `1,0,5,5,5,0,0,0,0,0`); without any, a fixed list. The office and school floors
//! (9 scans a kind, 3 a room, as in `examples/descriptors.rs`) score 1-NN
//! with no neighbour from the scan's own room. Never run on test seeds:
//! every seed of the test column of docs/seeds.md is refused.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::descriptor::{Part, PartKind};
use placecat::eval::evaluate;
use placecat::sim::{Buildings, LidarParams, SceneKind, SimParams, Simulation};
use placecat::*;
use rayon::prelude::*;

type Res<T> = Result<T, Box<dyn std::error::Error>>;

#[path = "common/seeds.rs"]
mod seeds;
use seeds::test_seeds;

/// The NDT histogram's weight, then one per part kind.
const WEIGHTS: usize = 1 + placecat::descriptor::parts::MAX_PARTS;

/// Neighbours 1-NN may not use: along a route, the 25 nearest scans; on
/// the floors, the scan's own room; else none.
enum Exclusion {
    None,
    Window(usize),
    Rooms(Vec<usize>),
}

struct Set {
    name: String,
    exclusion: Exclusion,
    truth: Vec<String>,
    descriptors: Vec<Descriptor>,
    params: DescriptorParams,
}

fn all_parts(mut p: DescriptorParams) -> DescriptorParams {
    p.parts = PartKind::ALL
        .iter()
        .map(|&kind| Part { kind, weight: 1.0 })
        .collect();
    p
}

fn lidar32() -> LidarParams {
    LidarParams {
        beams: 32,
        fov_down: -25.0,
        fov_up: 15.0,
        azimuth_steps: 1024,
        ..LidarParams::indoor()
    }
}

fn simulate(name: &str, sp: SimParams, params: DescriptorParams) -> Res<Set> {
    let sim = Simulation::new(&sp)?;
    let params = all_parts(params);
    let described: Vec<(Descriptor, String)> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let s = sim.scan(i);
            describe(&s.points, &params).map(|d| (d, s.label))
        })
        .collect::<Result<_, _>>()?;
    let (descriptors, truth) = described.into_iter().unzip();
    let exclusion = match sp.scene {
        SceneKind::Indoor => Exclusion::None,
        SceneKind::OfficeFloor | SceneKind::School => {
            Exclusion::Rooms((0..sim.len()).map(|i| sim.room(i)).collect())
        }
        _ => Exclusion::Window(25),
    };
    Ok(Set {
        name: name.into(),
        exclusion,
        truth,
        descriptors,
        params,
    })
}

fn kinds(truth: &[String]) -> usize {
    let mut t: Vec<&String> = truth.iter().collect();
    t.sort();
    t.dedup();
    t.len()
}

/// (stride, hk mean, 1-NN) for the weights.
fn score(set: &Set, w: &[f32; WEIGHTS]) -> Res<(f64, f64, f64)> {
    let mut opts = DistanceOptions::from(&set.params);
    opts.ndt_weight = w[0];
    opts.part_weights.copy_from_slice(&w[1..]);
    let space = Space::new(&set.descriptors, opts)?;
    let m = space.matrix();
    let k = kinds(&set.truth);
    let stride = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?;
    let mut hk = 0.0;
    for seed in 0..10 {
        let tree = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(seed))?;
        hk += evaluate(&set.truth, &tree.cut_k(k)?.labels)?.accuracy / 10.0;
    }
    let allowed = |i: usize, j: usize| match &set.exclusion {
        Exclusion::None => true,
        Exclusion::Window(w) => j.abs_diff(i) > *w,
        Exclusion::Rooms(r) => r[i] != r[j],
    };
    let nn = (0..m.n)
        .filter(|&i| {
            (0..m.n)
                .filter(|&j| j != i && allowed(i, j))
                .min_by(|&a, &b| m.get(i, a).total_cmp(&m.get(i, b)))
                .is_some_and(|j| set.truth[i] == set.truth[j])
        })
        .count() as f64
        / m.n as f64;
    Ok((evaluate(&set.truth, &stride.labels)?.accuracy, hk, nn))
}

fn median_distances(set: &Set) -> Res<Vec<f32>> {
    let mut out = Vec::new();
    for c in 0..WEIGHTS {
        let mut w = [0f32; WEIGHTS];
        w[c] = 1.0;
        let mut opts = DistanceOptions::from(&set.params);
        opts.ndt_weight = w[0];
        opts.part_weights.copy_from_slice(&w[1..]);
        let space = Space::new(&set.descriptors, opts)?;
        let n = space.len();
        let mut v: Vec<f32> = (0..n)
            .flat_map(|i| ((i + 1)..n).step_by(7).map(move |j| (i, j)))
            .map(|(i, j)| space.delta(i, j))
            .collect();
        v.sort_by(f32::total_cmp);
        out.push(v[v.len() / 2]);
    }
    Ok(out)
}

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut seeds = vec![1u64, 2, 3];
    let mut scans = 150usize;
    let mut weights: Vec<[f32; WEIGHTS]> = Vec::new();
    let mut only: Option<String> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--seeds" => {
                seeds = it
                    .next()
                    .ok_or("--seeds N,N")?
                    .split(',')
                    .map(str::parse)
                    .collect::<Result<_, _>>()?;
            }
            "--scans" => scans = it.next().ok_or("--scans N")?.parse()?,
            "--only" => only = it.next().cloned(),
            w => {
                let v: Vec<f32> = w.split(',').map(str::parse).collect::<Result<_, _>>()?;
                if v.len() < 10 || v.len() > WEIGHTS {
                    return Err("ten to twelve weights: ndt,height_range,slice,esf,ring,clutter,m2dp,columns,iron,objects[,object_types,object_layout] (the last two 0 if left out)".into());
                }
                weights.push(padded(&v));
            }
        }
    }
    let blocked = test_seeds()?;
    if let Some(s) = seeds.iter().find(|s| blocked.contains(s)) {
        return Err(format!("seed {s} is a test seed, not for development (docs/seeds.md)").into());
    }
    if weights.is_empty() {
        weights = [
            [1., 0., 0., 0., 0., 0., 0., 0., 0., 0.],
            [1., 0., 5., 5., 5., 0., 0., 0., 0., 0.],
            [1., 0., 0., 0., 0., 5., 0., 0., 0., 0.],
            [1., 0., 5., 5., 5., 5., 0., 0., 0., 0.],
            [1., 0., 5., 0., 5., 5., 0., 0., 0., 0.],
            [0., 0., 0., 0., 0., 10., 0., 0., 0., 0.],
        ]
        .iter()
        .map(|w| padded(w))
        .collect();
    }
    for &seed in &seeds {
        let mut sets = Vec::new();
        let mut add = |name: &str, sp: SimParams, p: DescriptorParams| -> Res<()> {
            if only.as_ref().is_none_or(|o| name.starts_with(o.as_str())) {
                sets.push(simulate(name, sp, p)?);
            }
            Ok(())
        };
        let indoor = |b: Buildings, lidar: Option<LidarParams>| SimParams {
            scans: 20,
            buildings: b,
            lidar,
            ..SimParams::new(SceneKind::Indoor, seed)
        };
        let floor = |scene: SceneKind| SimParams {
            scans: 9,
            scans_per_room: 3,
            ..SimParams::new(scene, seed)
        };
        let site = |scene: SceneKind, lidar: Option<LidarParams>| SimParams {
            scans,
            lidar,
            ..SimParams::new(scene, seed)
        };
        add(
            "indoor",
            indoor(Buildings::One, None),
            DescriptorParams::indoor(),
        )?;
        add(
            "indoor_many",
            indoor(Buildings::Many, None),
            DescriptorParams::indoor(),
        )?;
        add(
            "indoor_many_32",
            indoor(Buildings::Many, Some(lidar32())),
            DescriptorParams::indoor(),
        )?;
        add(
            "warehouse",
            site(SceneKind::Warehouse, None),
            DescriptorParams::indoor(),
        )?;
        add(
            "warehouse_32",
            site(SceneKind::Warehouse, Some(lidar32())),
            DescriptorParams::indoor(),
        )?;
        add(
            "outdoor",
            site(SceneKind::Outdoor, None),
            DescriptorParams::outdoor(),
        )?;
        add(
            "office",
            floor(SceneKind::OfficeFloor),
            DescriptorParams::indoor(),
        )?;
        add(
            "school",
            floor(SceneKind::School),
            DescriptorParams::indoor(),
        )?;
        for set in &sets {
            let med = median_distances(set)?;
            let mut counts: Vec<(String, usize)> = Vec::new();
            for t in &set.truth {
                match counts.iter_mut().find(|(n, _)| n == t) {
                    Some(c) => c.1 += 1,
                    None => counts.push((t.clone(), 1)),
                }
            }
            println!("{counts:?}");
            println!(
                "seed {seed} {:<16} n={} medians ndt {:.3} hr {:.3} slice {:.3} esf {:.3} ring {:.3} clutter {:.3} m2dp {:.4}",
                set.name, set.descriptors.len(), med[0], med[1], med[2], med[3], med[4], med[5], med[6]
            );
            for w in &weights {
                let (s, h, n) = score(set, w)?;
                println!(
                    "  w={:?}  stride {:5.1}  hk {:5.1}  1nn {:5.1}",
                    w,
                    100.0 * s,
                    100.0 * h,
                    100.0 * n
                );
            }
        }
    }
    Ok(())
}

/// Weights given for the first kinds, the later kinds at 0.
fn padded(given: &[f32]) -> [f32; WEIGHTS] {
    let mut w = [0f32; WEIGHTS];
    w[..given.len()].copy_from_slice(given);
    w
}
