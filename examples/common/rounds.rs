//! What issue 18's clustering rounds share (round 4, `kmeans_restarts.rs`:
//! k-means++ restarts; round 5, `split_trials.rs`: trial splits of
//! hierarchical k-means++): the presets the earlier rounds chose, each set
//! described once per preset, and a method's figures over clustering seeds.
//! Include after `families.rs` (`#[path] mod families;` then this).

use crate::families::{sim_params, Family, Sensor};
use placecat::eval::evaluate;
use placecat::sim::{SceneKind, SimScan, Simulation};
use placecat::*;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::Path;

pub type Res<T> = Result<T, Box<dyn std::error::Error>>;

/// Clustering seeds 0-9 of every randomised method.
pub const CLUSTER_SEEDS: u64 = 10;

/// Accuracy and ARI of one method on one set: the mean over clustering
/// seeds and the lowest accuracy (a deterministic method: one run, all
/// three from it).
#[derive(Serialize, Deserialize, Clone, Copy, Default)]
pub struct Method {
    pub accuracy: f64,
    pub lowest: f64,
    pub ari: f64,
}

/// `labels(seed)` for clustering seeds 0-9, scored against `truth`.
pub fn over_seeds(truth: &[String], mut labels: impl FnMut(u64) -> Res<Vec<i32>>) -> Res<Method> {
    let mut m = Method {
        lowest: f64::INFINITY,
        ..Method::default()
    };
    for seed in 0..CLUSTER_SEEDS {
        let e = evaluate(truth, &labels(seed)?)?;
        m.accuracy += e.accuracy / CLUSTER_SEEDS as f64;
        m.ari += e.ari / CLUSTER_SEEDS as f64;
        m.lowest = m.lowest.min(e.accuracy);
    }
    Ok(m)
}

/// k-means++ best of 10 runs at `k`, for clustering seeds 0-9.
#[allow(dead_code)] // the rounds and looks that report it
pub fn best_of_10(space: &placecat::distance::Space, truth: &[String], k: usize) -> Res<Method> {
    use placecat::cluster::{KMeans, KMeansParams};
    over_seeds(truth, |s| {
        Ok(KMeans::fit(space, &KMeansParams::new(k).seed(s).restarts(10))?.labels)
    })
}

/// Spectral clustering (`SpectralParams` defaults) at `k`, for clustering seeds 0-9.
#[allow(dead_code)] // spectral_round and spectral_routes_dev
pub fn spectral_over_seeds(matrix: &DistanceMatrix, truth: &[String], k: usize) -> Res<Method> {
    use placecat::cluster::{Spectral, SpectralParams};
    over_seeds(truth, |s| {
        Ok(Spectral::fit(matrix, &SpectralParams::new(k).seed(s))?.labels)
    })
}

/// One deterministic clustering, as a [`Method`].
pub fn once(truth: &[String], labels: &[i32]) -> Res<Method> {
    let e = evaluate(truth, labels)?;
    Ok(Method {
        accuracy: e.accuracy,
        lowest: e.accuracy,
        ari: e.ari,
    })
}

/// A simulated set described with each preset that could describe every
/// scan (the `outdoor` preset finds nothing to describe indoors).
pub struct DescribedSet {
    pub truth: Vec<String>,
    /// The number of true kinds (the k every method is given).
    pub kinds: usize,
    pub scans: usize,
    pub presets: Vec<(String, DescriptorParams, Vec<Descriptor>)>,
    /// The neighbours a scan's room-level 1-NN may not use: indoors its own
    /// room's scans; along a route those within [`ROUTE_WINDOW`] scans at
    /// the default density of 300 a route.
    #[allow(dead_code)] // read by the rounds that report 1-NN (columns.rs)
    pub apart: Apart,
}

/// Neighbours 25 scans (of 300 a route) either side are of the same
/// stretch of route (issue 18's "no neighbour within 25 scans").
pub const ROUTE_WINDOW: usize = 25;

/// What room-level 1-NN leaves out of a scan's neighbours.
#[allow(dead_code)]
pub enum Apart {
    /// The scans of the same room (its room id).
    Rooms(Vec<usize>),
    /// The scans within this many along the route.
    Window(usize),
}

#[allow(dead_code)]
impl Apart {
    /// Whether scan `j` may be scan `i`'s neighbour.
    pub fn allows(&self, i: usize, j: usize) -> bool {
        match self {
            Apart::Rooms(r) => r[i] != r[j],
            Apart::Window(w) => i.abs_diff(j) > *w,
        }
    }
}

/// The share of scans whose nearest allowed neighbour is of their kind.
#[allow(dead_code)]
pub fn room_level_nn(m: &DistanceMatrix, truth: &[String], apart: &Apart) -> f64 {
    let hits = (0..m.n)
        .filter(|&i| {
            (0..m.n)
                .filter(|&j| j != i && apart.allows(i, j))
                .min_by(|&a, &b| m.get(i, a).total_cmp(&m.get(i, b)))
                .is_some_and(|j| truth[i] == truth[j])
        })
        .count();
    hits as f64 / m.n as f64
}

/// Room-level 1-NN as a table: for each scan, by its true kind (`kind`,
/// 0..k), the kind of its nearest allowed neighbour (column k: none).
#[allow(dead_code)] // the kind diagnostics (kinds_dev.rs, hotel_kinds_look.rs)
pub fn nearest_kinds(
    m: &DistanceMatrix,
    kind: &[usize],
    k: usize,
    apart: &Apart,
) -> Vec<Vec<usize>> {
    let mut c = vec![vec![0; k + 1]; k];
    for i in 0..m.n {
        let nearest = (0..m.n)
            .filter(|&j| j != i && apart.allows(i, j))
            .min_by(|&a, &b| m.get(i, a).total_cmp(&m.get(i, b)));
        c[kind[i]][nearest.map_or(k, |j| kind[j])] += 1;
    }
    c
}

#[allow(dead_code)] // the tenth round (floor.rs) calls describe_set_with alone
pub fn describe_set(
    f: &Family,
    sensor: Sensor,
    seed: u64,
    presets: &[String],
) -> Res<DescribedSet> {
    describe_set_with(f, sensor, seed, presets, |_| Ok(vec![]))
}

/// Parameters made for one simulated scan from a set's (round 11: its true
/// floor).
pub type PerScan = fn(&DescriptorParams, &SimScan) -> DescriptorParams;

/// [`describe_set`], then each of the parameters `extra` makes from the
/// simulation (named as it names them; round 10: a floor found from the
/// set's scans).
pub fn describe_set_with(
    f: &Family,
    sensor: Sensor,
    seed: u64,
    presets: &[String],
    extra: impl FnOnce(&Simulation) -> Res<Vec<(String, DescriptorParams)>>,
) -> Res<DescribedSet> {
    let sim = Simulation::new(&sim_params(f, sensor, seed)?)?;
    let extra = extra(&sim)?;
    let extra = extra.into_iter().map(|(n, p)| (n, p, None)).collect();
    describe_simulated(f, &sim, presets, extra)
}

/// [`describe_set`], then each of `per_scan`'s parameters as its function
/// makes them for each scan (named by the first; the set keeps the
/// parameters given, which every scan's fit in shape).
#[allow(dead_code)] // the eleventh round (true_floor.rs)
pub fn describe_set_per_scan(
    f: &Family,
    sensor: Sensor,
    seed: u64,
    presets: &[String],
    per_scan: &[(String, DescriptorParams, PerScan)],
) -> Res<DescribedSet> {
    let sim = Simulation::new(&sim_params(f, sensor, seed)?)?;
    let extra = (per_scan.iter())
        .map(|(n, p, make)| (n.clone(), p.clone(), Some(*make)))
        .collect();
    describe_simulated(f, &sim, presets, extra)
}

fn describe_simulated(
    f: &Family,
    sim: &Simulation,
    presets: &[String],
    extra: Vec<(String, DescriptorParams, Option<PerScan>)>,
) -> Res<DescribedSet> {
    let mut params: Vec<(DescriptorParams, Option<PerScan>)> = presets
        .iter()
        .map(|p| DescriptorParams::preset(p).map(|p| (p, None)))
        .collect::<placecat::Result<_>>()?;
    let names: Vec<String> = (presets.iter().cloned())
        .chain(extra.iter().map(|e| e.0.clone()))
        .collect();
    params.extend(extra.into_iter().map(|e| (e.1, e.2)));
    // Each scan has its own RNG stream, so describing in parallel changes
    // no figure.
    let per_scan: Vec<Vec<placecat::Result<Descriptor>>> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let scan = sim.scan(i);
            (params.iter())
                .map(|(p, make)| match make {
                    Some(make) => describe(&scan.points, &make(p, &scan)),
                    None => describe(&scan.points, p),
                })
                .collect()
        })
        .collect();
    let truth: Vec<String> = (0..sim.len()).map(|i| sim.label(i).to_string()).collect();
    let mut kinds = truth.clone();
    kinds.sort();
    kinds.dedup();
    let mut described = vec![];
    for (j, (p, _)) in params.into_iter().enumerate() {
        let ds: Option<Vec<Descriptor>> = per_scan
            .iter()
            .map(|s| s[j].as_ref().ok().cloned())
            .collect();
        if let Some(ds) = ds {
            described.push((names[j].clone(), p, ds));
        }
    }
    let apart = if f.scene == SceneKind::Warehouse || f.scene == SceneKind::Outdoor {
        Apart::Window((ROUTE_WINDOW * sim.len()).div_ceil(placecat::sim::DEFAULT_SEQUENCE_SCANS))
    } else {
        Apart::Rooms((0..sim.len()).map(|i| sim.room(i)).collect())
    };
    Ok(DescribedSet {
        apart,
        truth,
        kinds: kinds.len(),
        scans: sim.len(),
        presets: described,
    })
}

/// Each family's paper preset, then the new presets rounds 2 and 3 chose.
pub fn presets_of(docs: &Path) -> Res<Vec<(String, Vec<String>)>> {
    #[derive(Deserialize)]
    struct Choice {
        family: String,
        paper: String,
        best_new: Option<String>,
    }
    #[derive(Deserialize)]
    struct Round {
        choices: Vec<Choice>,
    }
    let mut out: Vec<(String, Vec<String>)> = vec![];
    for file in ["descriptors-2.json", "descriptors-3.json"] {
        let round: Round = crate::families::read_json(&docs.join(file))?;
        for c in round.choices {
            let i = match out.iter().position(|o| o.0 == c.family) {
                Some(i) => i,
                None => {
                    out.push((c.family.clone(), vec![c.paper.clone()]));
                    out.len() - 1
                }
            };
            if let Some(new) = c.best_new {
                if !out[i].1.contains(&new) {
                    out[i].1.push(new);
                }
            }
        }
    }
    Ok(out)
}

/// `each(family, sensor, seed, presets)` for every family, its own sensor
/// then its others, and every seed, in that order; the results and the
/// seconds taken.
pub fn every_set<T>(
    presets: &[(String, Vec<String>)],
    seeds: &[u64],
    what: &str,
    each: impl FnMut(&Family, Sensor, u64, &[String]) -> Res<T>,
) -> Res<(Vec<T>, f64)> {
    every_set_of(crate::families::families(), presets, seeds, what, each)
}

/// [`every_set`] over `families`.
pub fn every_set_of<T>(
    families: Vec<Family>,
    presets: &[(String, Vec<String>)],
    seeds: &[u64],
    what: &str,
    mut each: impl FnMut(&Family, Sensor, u64, &[String]) -> Res<T>,
) -> Res<(Vec<T>, f64)> {
    let t0 = std::time::Instant::now();
    let mut sets = vec![];
    for f in families {
        let chosen = presets
            .iter()
            .find(|p| p.0 == f.name)
            .ok_or_else(|| format!("no presets chosen for family {:?}", f.name))?;
        if chosen.1.first().map(String::as_str) != Some(f.paper) {
            return Err(format!(
                "{}: rounds 2-3 name another paper preset than {}",
                f.name, f.paper
            )
            .into());
        }
        for sensor in std::iter::once(Sensor::Own).chain(f.sensors.iter().copied()) {
            for &seed in seeds {
                eprintln!(
                    "{what} {} {} seed {seed} ({:.0} s)",
                    f.name,
                    sensor.name(),
                    t0.elapsed().as_secs_f64()
                );
                sets.push(each(&f, sensor, seed, &chosen.1)?);
            }
        }
    }
    Ok((sets, t0.elapsed().as_secs_f64()))
}

/// The mean of `figure` over `sets`; NaN unless every set has it (a
/// preset that could not describe one of them).
pub fn mean_over<S>(sets: &[&S], figure: impl Fn(&S) -> Option<f64>) -> f64 {
    let v: Vec<f64> = sets.iter().filter_map(|s| figure(s)).collect();
    if v.is_empty() || v.len() < sets.len() {
        return f64::NAN;
    }
    v.iter().sum::<f64>() / v.len() as f64
}

/// The lowest of `figure` over `sets` (NaN if none has it).
pub fn lowest_over<S>(sets: &[&S], figure: impl Fn(&S) -> Option<f64>) -> f64 {
    sets.iter()
        .filter_map(|s| figure(s))
        .fold(f64::NAN, f64::min)
}

/// Issue 18's target for a family's new presets.
pub fn target(family: &str) -> &'static str {
    match family {
        "warehouse" => "at least 95 %",
        "outdoor" => "not worse than the paper's preset",
        _ => "at least 85 %",
    }
}

/// A table's rows, grouped as every round's tables are: for each family
/// (in `presets`' order) and each of its sensors that `sensor_filter`
/// keeps, the sets of that family and sensor, then `row(family, sensor,
/// sets, index, preset)` for each of the family's presets (index 0: the
/// paper's). `key` gives a set's (family, sensor).
pub fn each_row<S>(
    presets: &[(String, Vec<String>)],
    all: &[S],
    key: impl Fn(&S) -> (&str, &str),
    sensor_filter: impl Fn(&str) -> bool,
    mut row: impl FnMut(&str, &str, &[&S], usize, &str) -> Res<()>,
) -> Res<()> {
    for (family, names) in presets {
        let mut sensors: Vec<&str> = all
            .iter()
            .map(&key)
            .filter(|(f, s)| f == family && sensor_filter(s))
            .map(|(_, s)| s)
            .collect();
        sensors.dedup();
        for sensor in sensors {
            let sets: Vec<&S> = all
                .iter()
                .filter(|s| key(s) == (family.as_str(), sensor))
                .collect();
            for (i, p) in names.iter().enumerate() {
                row(family, sensor, &sets, i, p)?;
            }
        }
    }
    Ok(())
}

/// The repository's docs folder.
#[allow(dead_code)]
pub fn docs() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs")
}

/// Write docs/`name` and say so.
#[allow(dead_code)]
pub fn write(name: &str, text: &str) -> Res<()> {
    let path = docs().join(name);
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    eprintln!("wrote docs/{name}");
    Ok(())
}
