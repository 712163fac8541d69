//! The room and route rows of issue 18's rounds with the room scans in a
//! random order (the twentieth round on): what a row holds, how a round
//! runs its families on its seeds, and the checks and table they share.
//! Used by `order_free_round.rs` (rounds 20-22) and
//! `fresh_family_round/` (round 23).

use crate::families::*;
use crate::preset_rounds;
use crate::rounds::*;
use placecat::cluster::{KMeans, KMeansParams, Seeding, Spectral, SpectralParams};
use placecat::distance::Space;
use placecat::DistanceMatrix;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

pub const ROOM_PRESETS: &[&str] = &["indoor", "indoor_searched", "indoor_objects"];
/// The twenty-sixth round's family also with its candidate preset.
pub const INSTITUTE_PRESETS: &[&str] = &[
    "indoor",
    "indoor_searched",
    "indoor_objects",
    "indoor_object_types",
];
pub const WAREHOUSE_PRESETS: &[&str] = &["indoor", "indoor_plus"];
pub const OUTDOOR_PRESETS: &[&str] = &["outdoor", "outdoor_near"];
/// Issue 18's targets (%): indoor kinds, warehouse halls.
pub const ROOM_TARGET: f64 = 85.0;
pub const HALL_TARGET: f64 = 95.0;

/// One family, sensor and preset on a round's seeds: each method's figure
/// on each seed (the randomised ones the mean over clustering or tree
/// seeds 0-9).
#[derive(Serialize, Deserialize, Clone)]
pub struct Row {
    pub family: String,
    pub sensor: String,
    pub preset: String,
    pub rooms: bool,
    pub stride: Vec<f64>,
    pub best_of_10: Vec<f64>,
    /// Hierarchical k-means++, ten trial splits a node, cut at k.
    pub tree: Vec<f64>,
    pub spectral: Vec<f64>,
    pub nearest: Vec<f64>,
    /// k-means with spectral seeding (the twenty-first round; empty in
    /// the twentieth's).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub seeded: Vec<f64>,
}

/// How often, on the room sets as simulated, stride seeding's first
/// centres (scans i·n/k) were one scan of each kind.
#[derive(Serialize, Deserialize, Default)]
pub struct StrideStarts {
    pub room_sets: usize,
    pub one_of_each_kind: usize,
}

#[derive(Serialize, Deserialize)]
pub struct Report {
    pub seeds: Vec<u64>,
    pub seconds: f64,
    pub rows: Vec<Row>,
    pub stride_starts: StrideStarts,
}

pub fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

impl Row {
    /// Each method's mean over the seeds, in the table's order.
    pub fn means(&self) -> [f64; 5] {
        [
            &self.stride,
            &self.best_of_10,
            &self.tree,
            &self.spectral,
            &self.nearest,
        ]
        .map(|v| mean(v))
    }

    /// The target column: rooms, stride k-means and best of 10 each at
    /// least 85 %; the warehouse, the tree at least 95 %; outdoor none.
    pub fn target(&self) -> &'static str {
        let [stride, best, tree, ..] = self.means().map(|x| 100.0 * x);
        let met = match (self.rooms, self.family.as_str()) {
            (true, _) => stride >= ROOM_TARGET && best >= ROOM_TARGET,
            (false, "warehouse") => tree >= HALL_TARGET,
            _ => return "",
        };
        if met {
            "met"
        } else {
            "missed"
        }
    }

    pub fn cells(&self) -> Vec<String> {
        let mut figures: Vec<String> = self.means().map(pct).to_vec();
        if !self.seeded.is_empty() {
            figures.insert(2, pct(mean(&self.seeded)));
        }
        ([&self.family, &self.sensor]
            .map(|s| s.to_string())
            .into_iter())
        .chain([format!("`{}`", self.preset)])
        .chain(figures)
        .chain([self.target().to_string()])
        .collect()
    }
}

pub fn presets_of(f: &Family) -> &'static [&'static str] {
    match f.name {
        "warehouse" => WAREHOUSE_PRESETS,
        "outdoor" => OUTDOOR_PRESETS,
        "institute (fresh)" | "gym (fresh)" => INSTITUTE_PRESETS,
        _ => ROOM_PRESETS,
    }
}

/// Whether stride seeding's first centres on `truth` are one scan of each
/// of its `k` kinds.
pub fn stride_starts_one_of_each(truth: &[String], k: usize) -> bool {
    let n = truth.len();
    let mut kinds: Vec<&String> = (0..k).map(|i| &truth[i * n / k]).collect();
    kinds.sort();
    kinds.dedup();
    kinds.len() == k
}

/// Refuse a room set whose scans are still listed kind by kind (the round
/// is about the order; a harness that lost `shuffle` must not report).
pub fn check_shuffled(f: &Family, truth: &[String], kinds: usize) -> Res<()> {
    let changes = truth.windows(2).filter(|w| w[0] != w[1]).count();
    if changes < 2 * kinds {
        return Err(format!(
            "{}: only {changes} changes of kind along {} scans: not shuffled",
            f.name,
            truth.len()
        )
        .into());
    }
    Ok(())
}

/// k-means with spectral seeding for clustering seeds 0-9 (mean) on
/// `space` and its Delta `matrix`, each run checked against k-means from
/// the groups of a spectral clustering run here (the development look's
/// way, docs/spectral-seeding-dev.md).
pub fn spectral_seeding(
    space: &Space,
    matrix: &DistanceMatrix,
    truth: &[String],
    k: usize,
) -> Res<f64> {
    let mut sum = 0.0;
    for s in 0..CLUSTER_SEEDS {
        let params = KMeansParams::new(k).seeding(Seeding::Spectral).seed(s);
        let fit = KMeans::fit_with_matrix(space, Some(matrix), &params)?;
        let groups = Spectral::fit(matrix, &SpectralParams::new(k).seed(s))?;
        let look = KMeans::fit_from_groups(space, &groups.labels, k, 100)?;
        if look.labels != fit.labels {
            return Err(
                "spectral seeding differs from k-means from the spectral groups' means".into(),
            );
        }
        sum += placecat::eval::evaluate(truth, &fit.labels)?.accuracy;
    }
    Ok(sum / CLUSTER_SEEDS as f64)
}

/// The RNG stream of a room row's own listing order (the twenty-second
/// round): FNV-1a of its family and sensor, so every row of a seed draws
/// apart, and the presets of a row share one order.
pub fn row_stream(family: &str, sensor: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in family.bytes().chain([b'/']).chain(sensor.bytes()) {
        h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// `set` listed again in the order drawn for its row and `seed` (the
/// twenty-second round): the simulator's shuffled order depends on the
/// seed and the scan count alone, the same for every row of a seed.
pub fn relisted(set: DescribedSet, family: &str, sensor: &str, seed: u64) -> Res<DescribedSet> {
    use rand::seq::SliceRandom;
    let mut order: Vec<usize> = (0..set.truth.len()).collect();
    order.shuffle(&mut placecat::rng::rng_stream(
        seed,
        row_stream(family, sensor),
    ));
    let pick = |v: &[String]| order.iter().map(|&i| v[i].clone()).collect::<Vec<_>>();
    let Apart::Rooms(rooms) = &set.apart else {
        return Err(format!("{family}: only room sets are listed again").into());
    };
    let rooms = order.iter().map(|&i| rooms[i]).collect();
    let presets = (set.presets.into_iter())
        .map(|(name, params, d)| {
            let d = order.iter().map(|&i| d[i].clone()).collect();
            (name, params, d)
        })
        .collect();
    Ok(DescribedSet {
        truth: pick(&set.truth),
        kinds: set.kinds,
        scans: set.scans,
        presets,
        apart: Apart::Rooms(rooms),
    })
}

/// How a round lists the room sets: as the simulator shuffles them (the
/// twentieth and twenty-first rounds), or each row in its own order too.
#[derive(Clone, Copy, PartialEq)]
pub enum Listing {
    Simulated,
    PerRow,
}

/// Every family of `families`, with its own sensor and each of its
/// others, on `seeds`: room sets shuffled (and, with [`Listing::PerRow`],
/// listed again in their row's order), routes as recorded.
pub fn run(families: Vec<Family>, seeds: &[u64], seeded: bool, listing: Listing) -> Res<Report> {
    let t0 = std::time::Instant::now();
    let mut rows = vec![];
    let mut starts = StrideStarts::default();
    for f in families {
        let rooms = f.scans_per_room > 1;
        let f = Family {
            shuffle: rooms,
            ..f
        };
        let sensors: Vec<Sensor> = std::iter::once(Sensor::Own)
            .chain(f.sensors.iter().copied())
            .collect();
        for sensor in sensors {
            let presets: Vec<String> = presets_of(&f).iter().map(|p| p.to_string()).collect();
            let mut out: Vec<Row> = (presets.iter())
                .map(|p| Row {
                    family: f.name.into(),
                    sensor: sensor.name(),
                    preset: p.clone(),
                    rooms,
                    stride: vec![],
                    best_of_10: vec![],
                    tree: vec![],
                    spectral: vec![],
                    nearest: vec![],
                    seeded: vec![],
                })
                .collect();
            for &seed in seeds {
                let mut set = describe_set(&f, sensor, seed, &presets)?;
                if rooms && listing == Listing::PerRow {
                    set = relisted(set, f.name, &sensor.name(), seed)?;
                }
                let k = set.kinds;
                if rooms {
                    check_shuffled(&f, &set.truth, k)?;
                    starts.room_sets += 1;
                    starts.one_of_each_kind += stride_starts_one_of_each(&set.truth, k) as usize;
                }
                for (name, params, descriptors) in &set.presets {
                    let row = (out.iter_mut())
                        .find(|r| &r.preset == name)
                        .ok_or("a preset described that was not asked for")?;
                    let (figures, space, matrix, _) =
                        preset_rounds::measure(descriptors, params, &set.truth, k)?;
                    let spectral = spectral_over_seeds(&matrix, &set.truth, k)?;
                    row.stride.push(figures.stride.accuracy);
                    row.best_of_10.push(figures.best_of_10.accuracy);
                    row.tree.push(figures.hk_trials.accuracy);
                    row.spectral.push(spectral.accuracy);
                    row.nearest
                        .push(room_level_nn(&matrix, &set.truth, &set.apart));
                    if seeded {
                        row.seeded
                            .push(spectral_seeding(&space, &matrix, &set.truth, k)?);
                    }
                }
            }
            for r in &out {
                eprintln!(
                    "{} ({:.0} s)",
                    r.cells().join(" | "),
                    t0.elapsed().as_secs_f64()
                );
            }
            // A preset that could not describe a set (none here, but the
            // rounds allow it) leaves its row out.
            rows.extend(out.into_iter().filter(|r| r.stride.len() == seeds.len()));
        }
    }
    Ok(Report {
        seeds: seeds.to_vec(),
        seconds: t0.elapsed().as_secs_f64(),
        rows,
        stride_starts: starts,
    })
}

/// Refuse figures of `row` that differ from the same figures in `source`
/// (pairs of ours and theirs); returns how many were compared.
pub fn equal_figures(row: &Row, source: &str, pairs: &[(&Vec<f64>, &Vec<f64>)]) -> Res<usize> {
    let mut compared = 0;
    for (ours, theirs) in pairs {
        if ours.len() != theirs.len()
            || ours
                .iter()
                .zip(theirs.iter())
                .any(|(a, b)| (a - b).abs() > 1e-12)
        {
            return Err(format!(
                "{} {} {}: differs from {source}",
                row.family, row.sensor, row.preset
            )
            .into());
        }
        compared += ours.len();
    }
    Ok(compared)
}

/// The table of a round with k-means of spectral seeding, every row of
/// `r` with its means.
pub fn seeding_table(o: &mut String, r: &Report) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | k-means, spectral seeding | hk-means++, 10 trials | spectral | room-level 1-NN | target |")?;
    writeln!(o, "|---|---|---|---|---|---|---|---|---|---|")?;
    for x in &r.rows {
        writeln!(o, "| {} |", x.cells().join(" | "))?;
    }
    Ok(())
}
