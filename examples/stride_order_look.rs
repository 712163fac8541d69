//! Issue 18, a look at the evaluation after the nineteenth round (it uses
//! seeds already seen, changes no preset, parameter or method and judges
//! no candidate; its plan is in docs/seeds.md, written before its run).
//! Every room set of issue 18's rounds lists its scans kind by kind, 9 of
//! each (`placecat::sim` plans them so), and stride seeding puts k-means'
//! first centres at scans i·n/k: 0, 9, 18, 27 and 36 of 45, one scan of
//! each true kind. The rounds' stride k-means on room rows so started from
//! the answer. This re-runs the eighteenth and nineteenth rounds' room
//! rows and reports stride k-means on the scans as listed (checked against
//! the figures reported in docs/spectral.json and spectral-2.json) and on
//! the same scans in random orders, beside the reported k-means++ best of
//! 10 and spectral clustering, and how many rows meet issue 18's indoor
//! target either way.
//!
//!     cargo run --release --example stride_order_look   # -> docs/stride-order.{md,json}

// dev_look.rs' development seeds and their check go unused: this look
// runs test seeds that were run already.
#![allow(dead_code)]

use placecat::cluster::{KMeans, KMeansParams, Seeding};
use placecat::distance::Space;
use placecat::*;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

include!("common/dev_look.rs");

/// The two samples and the reports that hold their figures.
const SAMPLES: &[(&str, &[u64])] = &[
    ("spectral.json", &[481, 482, 483, 484, 485]),
    ("spectral-2.json", &[491, 492, 493, 494, 495]),
];
const PRESETS: &[&str] = &["indoor", "indoor_searched", "indoor_objects"];
/// Random orders of each set: order seeds 0-9.
const ORDERS: u64 = 10;
/// Issue 18's indoor target (%).
const TARGET: f64 = 85.0;

/// A reported row of the rounds' JSON (the fields read here).
#[derive(Deserialize)]
struct Reported {
    family: String,
    sensor: String,
    preset: String,
    stride: Vec<f64>,
    best_of_10: Vec<f64>,
    spectral: Vec<f64>,
}

#[derive(Deserialize)]
struct ReportedFile {
    seeds: Vec<u64>,
    rows: Vec<Reported>,
}

/// One room row and preset over the ten seeds (per seed, in the samples'
/// order).
#[derive(Serialize, Deserialize, Default)]
struct Row {
    family: String,
    sensor: String,
    preset: String,
    /// Stride k-means on the scans as listed (as reported).
    stride_listed: Vec<f64>,
    /// Stride k-means on the scans in random orders: mean over order seeds 0-9.
    stride_shuffled: Vec<f64>,
    /// The lowest of those orders.
    stride_shuffled_lowest: Vec<f64>,
    /// Whether the listed order's stride seeds were one scan of each kind.
    seeds_one_per_kind: Vec<bool>,
    /// As reported.
    best_of_10: Vec<f64>,
    spectral: Vec<f64>,
}

/// One of the simulator's own indoor sets (docs/experiments.md, section 1b).
#[derive(Serialize, Deserialize)]
struct HeldOut {
    seed: u64,
    stride_listed: f64,
    stride_shuffled: f64,
    stride_shuffled_lowest: f64,
}

#[derive(Serialize, Deserialize)]
struct Report {
    seeds: Vec<u64>,
    orders: u64,
    seconds: f64,
    rows: Vec<Row>,
    /// The simulator's held-out indoor sets, seeds 11-40.
    held_out: Vec<HeldOut>,
}

/// The simulator's held-out indoor seeds of docs/experiments.md (section
/// 1b), 5 kinds of 40 scans, the paper's `indoor`.
const HELD_OUT: std::ops::RangeInclusive<u64> = 11..=40;

#[derive(Deserialize)]
struct ExperimentSeed {
    seed: u64,
    stride: f64,
}

/// Stride k-means on one held-out set as listed (checked against
/// docs/experiments.json) and in random orders.
fn held_out(seed: u64, reported: &[ExperimentSeed]) -> Res<HeldOut> {
    // `placecat simulate --scene indoor`'s defaults (SimParams::new) as a
    // family, so that the rounds' describe_set describes it.
    let family = Family {
        name: "indoor (held out)",
        scene: placecat::sim::SceneKind::Indoor,
        buildings: placecat::sim::Buildings::One,
        scans: 40,
        scans_per_room: 5,
        paper: "indoor",
        sensors: &[],
        shuffle: false,
    };
    let set = describe_set(&family, Sensor::Own, seed, &["indoor".to_string()])?;
    let (_, params, ds) = set
        .presets
        .first()
        .ok_or("the indoor preset described nothing")?;
    let listed: Vec<usize> = (0..ds.len()).collect();
    let as_listed = stride_in(&listed, ds, &set.truth, params, set.kinds)?;
    let rep = (reported.iter().find(|r| r.seed == seed))
        .ok_or_else(|| format!("docs/experiments.json: no seed {seed}"))?;
    same_as_reported(as_listed, rep.stride, || {
        format!("held-out seed {seed}: docs/experiments.json")
    })?;
    let shuffled = shuffled_strides(seed, ds, &set.truth, params, set.kinds)?;
    Ok(HeldOut {
        seed,
        stride_listed: as_listed,
        stride_shuffled: mean(&shuffled),
        stride_shuffled_lowest: shuffled.iter().copied().fold(f64::INFINITY, f64::min),
    })
}

/// A recomputed figure must be the reported one (same code, same scans).
fn same_as_reported(got: f64, reported: f64, what: impl Fn() -> String) -> Res<()> {
    if (got - reported).abs() > 1e-9 {
        return Err(format!("{}: stride k-means {got}, reported {reported}", what()).into());
    }
    Ok(())
}

/// Stride k-means on the scans in order seeds 0-9's random orders.
fn shuffled_strides(
    seed: u64,
    ds: &[Descriptor],
    truth: &[String],
    params: &DescriptorParams,
    k: usize,
) -> Res<Vec<f64>> {
    (0..ORDERS)
        .map(|o| {
            let mut order: Vec<usize> = (0..ds.len()).collect();
            order.shuffle(&mut ChaCha8Rng::seed_from_u64(seed * 1000 + o));
            stride_in(&order, ds, truth, params, k)
        })
        .collect()
}

/// Stride k-means' accuracy on `descriptors` in the order `order`.
fn stride_in(
    order: &[usize],
    descriptors: &[Descriptor],
    truth: &[String],
    params: &DescriptorParams,
    k: usize,
) -> Res<f64> {
    let ds: Vec<Descriptor> = order.iter().map(|&i| descriptors[i].clone()).collect();
    let t: Vec<String> = order.iter().map(|&i| truth[i].clone()).collect();
    let space = Space::new(&ds, DistanceOptions::from(params))?;
    let labels = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels;
    Ok(placecat::eval::evaluate(&t, &labels)?.accuracy)
}

/// Written after the run.
const SHOWS: &str = "Stride k-means' room figures were in large part figures of the order: on every one of the 140 sets (14 rows, ten seeds) its first centres were one scan of each kind. On the same scans in random orders it falls by 2.7 to 22.7 points a row (with `indoor_objects` by 9.2 to 18.6; its mean over the 14 rows from 88.4 to 75.5 %), and it is below k-means++ best of 10 in every row with the two room presets (by 3.2 to 22.8 points) and in all but one with `indoor` (the many buildings with 16 beams, 75.9 against 76.3 %). The order counts least with `indoor` (2.7 to 14.9 points; random orders did as well as the listed one or better on 24 of its 140 sets, against 7 with `indoor_searched` and 5 with `indoor_objects`). In a random order stride seeding is one k-means run from k scans drawn at random, and best of 10 keeps the cheapest of ten k-means++ runs. Issue 18's indoor target read as the rounds read it (stride k-means and best of 10 each at least 85 %) is met in 8 of the 14 room rows with `indoor_objects` as reported and in none with stride k-means in random orders; the reported 8 are the rows where best of 10 alone reaches 85 %, which does not start from the order (7 with `indoor_searched`, 3 with `indoor`). The simulator's own thirty held-out indoor sets, whose deterministic k-means the README set beside the paper's 93.3 %: 94.5 % as listed, 81.8 % in random orders (lower on 29 of 30 sets). What it changes: the stride k-means figures of room sets in issue 18's reports and the README measure the listing order as much as the method, and the thirteenth and fifteenth rounds' weight searches had stride k-means in their objective, so `indoor_searched`'s weights (and so `indoor_objects'`) were chosen in part on a figure that started from the answer. Best of 10, spectral clustering and the tree draw their first centres at random, so they do not start from the order (a single clustering changes with it, what to expect of it does not), and room-level 1-NN does not use it. Along a route the order is the recording's own, and stride seeding along it is the paper's design; this look does not touch routes.";

fn main() -> Res<()> {
    let t0 = std::time::Instant::now();
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let mut reported = vec![];
    let mut seeds = vec![];
    for (file, sample) in SAMPLES {
        seeds::check_round_seeds(&[], sample)?;
        let r: ReportedFile = read_json(&docs.join(file))?;
        if r.seeds != *sample {
            return Err(format!("docs/{file} holds seeds {:?}, not {sample:?}", r.seeds).into());
        }
        reported.push(r);
        seeds.extend_from_slice(sample);
    }
    let mut rows = vec![];
    for (f, sensor) in room_rows() {
        let mut of_preset: Vec<Row> = (PRESETS.iter())
            .map(|p| Row {
                family: f.name.into(),
                sensor: sensor.name(),
                preset: p.to_string(),
                ..Row::default()
            })
            .collect();
        let presets: Vec<String> = PRESETS.iter().map(|p| p.to_string()).collect();
        for (sample, file) in reported.iter().zip(SAMPLES) {
            for (s, &seed) in sample.seeds.iter().enumerate() {
                let set = describe_set(&f, sensor, seed, &presets)?;
                let (truth, k) = (&set.truth, set.kinds);
                let listed: Vec<usize> = (0..set.scans).collect();
                for (row, (name, params, ds)) in of_preset.iter_mut().zip(&set.presets) {
                    let rep = (sample.rows.iter())
                        .find(|r| {
                            r.family == row.family && r.sensor == row.sensor && r.preset == *name
                        })
                        .ok_or_else(|| {
                            format!(
                                "docs/{}: no row {} {} {name}",
                                file.0, row.family, row.sensor
                            )
                        })?;
                    let as_listed = stride_in(&listed, ds, truth, params, k)?;
                    // The reported figure, recomputed: the same code and scans.
                    same_as_reported(as_listed, rep.stride[s], || {
                        format!(
                            "{} {} {name} seed {seed}: docs/{}",
                            row.family, row.sensor, file.0
                        )
                    })?;
                    let shuffled = shuffled_strides(seed, ds, truth, params, k)?;
                    let mut kinds: Vec<&String> =
                        (0..k).map(|i| &truth[i * set.scans / k]).collect();
                    kinds.sort();
                    kinds.dedup();
                    row.stride_listed.push(as_listed);
                    row.stride_shuffled
                        .push(shuffled.iter().sum::<f64>() / ORDERS as f64);
                    row.stride_shuffled_lowest
                        .push(shuffled.iter().copied().fold(f64::INFINITY, f64::min));
                    row.seeds_one_per_kind.push(kinds.len() == k);
                    row.best_of_10.push(rep.best_of_10[s]);
                    row.spectral.push(rep.spectral[s]);
                }
            }
        }
        for row in &of_preset {
            eprintln!(
                "{} {} {}: listed {} shuffled {} ({:.0} s)",
                row.family,
                row.sensor,
                row.preset,
                pct(mean(&row.stride_listed)),
                pct(mean(&row.stride_shuffled)),
                t0.elapsed().as_secs_f64()
            );
        }
        rows.extend(of_preset);
    }
    #[derive(Deserialize)]
    struct Experiments {
        seeds: ExperimentSeeds,
    }
    #[derive(Deserialize)]
    struct ExperimentSeeds {
        rows: Vec<ExperimentSeed>,
    }
    let experiments: Experiments = read_json(&docs.join("experiments.json"))?;
    let held_out =
        (HELD_OUT.map(|seed| held_out(seed, &experiments.seeds.rows))).collect::<Res<Vec<_>>>()?;
    eprintln!("held-out indoor sets ({:.0} s)", t0.elapsed().as_secs_f64());
    let report = Report {
        seeds,
        orders: ORDERS,
        seconds: t0.elapsed().as_secs_f64(),
        rows,
        held_out,
    };
    let json = serde_json::to_string_pretty(&report)?;
    write_doc("stride-order.json", &format!("{json}\n"))?;
    write_doc("stride-order.md", &render(&report)?)
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

/// The report: the counts, then one row per room row and preset.
fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(o, "# Stride k-means and the order of the room sets (issue 18, a look after the nineteenth round)\n")?;
    writeln!(o, "A look at the evaluation, on seeds already seen (the eighteenth and nineteenth rounds' test seeds {:?}, ten sets a row); it changes no preset, parameter or method and judges no candidate. Its plan was written in docs/seeds.md before its run. Regenerate with `cargo run --release --example stride_order_look` ({:.0} s).\n", r.seeds, r.seconds)?;
    writeln!(o, "**Why.** Every room set of issue 18's rounds lists its scans kind by kind, 9 of each (45 scans, 5 kinds), as `placecat::sim` plans them, and stride seeding starts k-means from scans i·n/k: 0, 9, 18, 27 and 36, the first scan of each kind. The rounds' stride k-means on room rows so started from one scan of each true kind, which no user's data promises. Here stride k-means runs on each set as listed (its figures recomputed and checked equal to the reported ones, docs/spectral.json and spectral-2.json) and on the same scans in {} random orders (order seeds 0-{}, mean and lowest), beside the reported k-means++ best of 10 and spectral clustering (means over clustering seeds 0-9; their seeding draws scans at random, so an order changes a single clustering but not what to expect of it; not measured in other orders here).\n", r.orders, r.orders - 1)?;
    writeln!(o, "**What it shows** (written after the run): {SHOWS}\n")?;
    writeln!(
        o,
        "## Issue 18's indoor target, pooled over the ten seeds\n"
    )?;
    writeln!(o, "A room row meets it when stride k-means and k-means++ best of 10 are each at least {TARGET:.0} % (the rounds' reading).\n")?;
    writeln!(o, "| preset | rows met, stride as listed (reported) | rows met, stride in random orders | stride alone at least 85 %: as listed | in random orders | best of 10 alone | spectral clustering alone | mean stride as listed | mean stride in random orders | mean best of 10 | mean spectral |")?;
    writeln!(o, "|---|---|---|---|---|---|---|---|---|---|---|")?;
    for p in PRESETS {
        let of: Vec<&Row> = r.rows.iter().filter(|x| x.preset == *p).collect();
        let count = |f: &dyn Fn(&Row) -> bool| of.iter().filter(|x| f(x)).count();
        let at = |v: &[f64]| 100.0 * mean(v) >= TARGET;
        let avg = |f: &dyn Fn(&Row) -> &Vec<f64>| {
            pct(of.iter().map(|x| mean(f(x))).sum::<f64>() / of.len() as f64)
        };
        writeln!(
            o,
            "| `{p}` | {} of {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            count(&|x| at(&x.stride_listed) && at(&x.best_of_10)),
            of.len(),
            count(&|x| at(&x.stride_shuffled) && at(&x.best_of_10)),
            count(&|x| at(&x.stride_listed)),
            count(&|x| at(&x.stride_shuffled)),
            count(&|x| at(&x.best_of_10)),
            count(&|x| at(&x.spectral)),
            avg(&|x| &x.stride_listed),
            avg(&|x| &x.stride_shuffled),
            avg(&|x| &x.best_of_10),
            avg(&|x| &x.spectral),
        )?;
    }
    let h = &r.held_out;
    let of = |f: &dyn Fn(&HeldOut) -> f64| pct(h.iter().map(f).sum::<f64>() / h.len() as f64);
    writeln!(o, "\n## The simulator's own indoor sets\n")?;
    writeln!(o, "The thirty held-out sets of docs/experiments.md section 1b (simulator seeds {}-{}, 5 kinds of 40 scans listed kind by kind, the paper's `indoor`, k = 5), whose deterministic k-means the README compares with the paper's 93.3 %: stride k-means as listed (reported; recomputed and checked equal to docs/experiments.json) {} %, in random orders {} % (lowest set-and-order {} %; lowest set's mean over orders {} %).\n", HELD_OUT.start(), HELD_OUT.end(), of(&|x| x.stride_listed), of(&|x| x.stride_shuffled), pct(h.iter().map(|x| x.stride_shuffled_lowest).fold(f64::INFINITY, f64::min)), pct(h.iter().map(|x| x.stride_shuffled).fold(f64::INFINITY, f64::min)))?;
    writeln!(o, "\n## Every room row, pooled over the ten seeds\n")?;
    writeln!(o, "| family | sensor | preset | stride as listed (reported) | stride in random orders | lowest order | k-means++ best of 10 (reported) | spectral (reported) | sets whose stride seeds were one scan of each kind |")?;
    writeln!(o, "|---|---|---|---|---|---|---|---|---|")?;
    for x in &r.rows {
        let lowest = x
            .stride_shuffled_lowest
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        writeln!(
            o,
            "| {} | {} | `{}` | {} | {} | {} | {} | {} | {} of {} |",
            x.family,
            x.sensor,
            x.preset,
            pct(mean(&x.stride_listed)),
            pct(mean(&x.stride_shuffled)),
            pct(lowest),
            pct(mean(&x.best_of_10)),
            pct(mean(&x.spectral)),
            x.seeds_one_per_kind.iter().filter(|&&b| b).count(),
            x.seeds_one_per_kind.len()
        )?;
    }
    Ok(o)
}
