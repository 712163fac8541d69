//! Writes docs/descriptors.md and docs/descriptors.json (issue 18): every
//! descriptor preset against the paper's, on several scene families and
//! sensors, with seeds fixed beforehand in docs/seeds.md.
//!
//!     cargo run --release --example descriptors -- --dev   # dev seeds -> docs/descriptors-dev.json
//!     cargo run --release --example descriptors            # test seeds: the report
//!     ... -- --only office   # dev seeds of the families whose name holds `office`, to stdout
//!     ... -- --render        # docs/descriptors.md again from docs/descriptors.json
//!     ... -- --check-choices # each family's choice made again from the dev file, against the report's
//!     ... -- --family outdoor  # one family's dev and test seeds again, its rows replaced
//!     ... -- --round 2 --dev   # the second round (docs/seeds.md): dev seeds 1-6
//!     ... -- --round 2         # its test seeds 311-315, run once: docs/descriptors-2.*
//!     ... -- --round 3 --dev   # the third round (M2DP): dev seeds 1-6
//!     ... -- --round 3         # its test seeds 321-325, run once: docs/descriptors-3.*
//!
//! The dev run chooses each family's new preset and is kept in its own
//! file, so that the test run (which reads it) stays near 15 minutes.
//!
//! Every preset of `placecat::descriptor::PRESETS` is run, so a preset
//! added there joins by itself. For each family x sensor x preset x seed:
//! deterministic (stride) k-means and hierarchical k-means++ (clustering
//! seeds 0-9) at the true number of kinds, accuracy and ARI, and 1-NN
//! leave-one-out with no neighbour from the scan's own room (routes: none
//! within the stretch of 25 scans at the default 300 a route). The best
//! new preset of a family is chosen on the development seeds (default
//! sensor, stride k-means; of equals, round 1 kept the later in PRESETS,
//! round 2 the better on dev hk-means++, then room-level 1-NN) and
//! reported on the test seeds, so the choice does not flatter it.
//!
//! The report is computed into plain data ([`Report`]), written as JSON,
//! and the markdown is rendered from that data.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::eval::evaluate;
use placecat::sim::{SceneKind, Simulation};
use placecat::*;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

#[path = "common/families.rs"]
mod families;
#[path = "common/real.rs"]
mod real;

use families::*;

/// The example's error: every failure is reported by `main`, none panics.
type Res<T> = Result<T, Box<dyn std::error::Error>>;

/// A round of the evaluation: its seeds, fixed in docs/seeds.md before
/// any run of it, its files, and how it picks a family's new preset.
struct Round {
    /// 1, 2 or 3.
    number: u32,
    dev_seeds: &'static [u64],
    test_seeds: &'static [u64],
    /// Under docs/: the dev run, the report's data and its markdown.
    dev_file: &'static str,
    report_file: &'static str,
    md_file: &'static str,
    /// Of new presets equal on dev stride k-means, keep the one with the
    /// best dev hk-means++, then room-level 1-NN (round 2, written down
    /// before its test run); round 1 kept the later in PRESETS.
    tie_break: bool,
}

/// Issue 18's first round: test seeds 301-305, run once.
const FIRST: Round = Round {
    number: 1,
    dev_seeds: &[1, 2, 3],
    test_seeds: &[301, 302, 303, 304, 305],
    dev_file: "descriptors-dev.json",
    report_file: "descriptors.json",
    md_file: "descriptors.md",
    tie_break: false,
};

/// The second round (after 301-305 had been seen): new development seeds
/// 4-6 beside 1-3, fresh test seeds 311-315.
const SECOND: Round = Round {
    number: 2,
    dev_seeds: &[1, 2, 3, 4, 5, 6],
    test_seeds: &[311, 312, 313, 314, 315],
    dev_file: "descriptors-dev-2.json",
    report_file: "descriptors-2.json",
    md_file: "descriptors-2.md",
    tie_break: true,
};

/// The third round (M2DP; after 311-315 had been seen): dev seeds 1-6,
/// fresh test seeds 321-325, round 2's tie-break.
const THIRD: Round = Round {
    number: 3,
    dev_seeds: &[1, 2, 3, 4, 5, 6],
    test_seeds: &[321, 322, 323, 324, 325],
    dev_file: "descriptors-dev-3.json",
    report_file: "descriptors-3.json",
    md_file: "descriptors-3.md",
    tie_break: true,
};

impl Round {
    fn seeds_text(&self, seeds: &[u64]) -> String {
        match (seeds.first(), seeds.last()) {
            (Some(a), Some(b)) => format!("{a}-{b}"),
            _ => String::new(),
        }
    }
}
/// The presets of the paper and of placecat before issue 18.
const PAPER_PRESETS: [&str; 4] = ["indoor", "outdoor", "perception_oru", "indoor_bands"];
/// Clustering seeds of hierarchical k-means++.
const HK_SEEDS: u64 = 10;
/// Route neighbours left out of a route scan's 1-NN, at the default
/// density of 300 scans a route; scaled to the same stretch of route when
/// a route has fewer scans.
const ROUTE_WINDOW: usize = 25;

/// One preset's figures on one simulated set.
#[derive(Serialize, Deserialize, Clone, Copy, Default)]
struct Figures {
    stride_accuracy: f64,
    stride_ari: f64,
    /// Means over clustering seeds 0-9.
    hk_accuracy: f64,
    hk_ari: f64,
    /// 1-NN with no neighbour from the scan's room (or route window).
    nn_room: f64,
    /// Plain leave-one-out 1-NN, for comparison with older reports.
    nn_plain: f64,
    /// Describing time per scan (ms, one core).
    describe_ms: f64,
}

#[derive(Serialize, Deserialize, Clone)]
struct SetResult {
    family: String,
    sensor: String,
    seed: u64,
    scans: usize,
    /// (preset, figures), in the order of `placecat::descriptor::PRESETS`;
    /// presets that could not describe every scan (the `outdoor` preset
    /// finds nothing in its far ranges indoors) are in `failed`.
    presets: Vec<(String, Figures)>,
    /// (preset, the first error it gave).
    failed: Vec<(String, String)>,
}

/// A scan's neighbours that 1-NN may not use.
enum Exclusion {
    /// Indoor: the room of each scan.
    Rooms(Vec<usize>),
    /// Routes: scans this close in the sequence.
    Window(usize),
}

impl Exclusion {
    fn allows(&self, i: usize, j: usize) -> bool {
        match self {
            Exclusion::Rooms(r) => r[i] != r[j],
            Exclusion::Window(w) => i.abs_diff(j) > *w,
        }
    }
}

/// Share of scans whose nearest allowed neighbour has their label.
fn nearest_neighbour(
    m: &DistanceMatrix,
    truth: &[String],
    ok: impl Fn(usize, usize) -> bool,
) -> f64 {
    let hits = (0..m.n)
        .filter(|&i| {
            (0..m.n)
                .filter(|&j| j != i && ok(i, j))
                .min_by(|&a, &b| m.get(i, a).total_cmp(&m.get(i, b)))
                .is_some_and(|j| truth[i] == truth[j])
        })
        .count();
    hits as f64 / m.n as f64
}

fn measure(
    descriptors: &[Descriptor],
    params: &DescriptorParams,
    truth: &[String],
    ex: &Exclusion,
    k: usize,
) -> Res<Figures> {
    let space = Space::new(descriptors, DistanceOptions::from(params))?;
    let m = space.matrix();
    let stride = evaluate(
        truth,
        &KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels,
    )?;
    let (mut acc, mut ari) = (0.0, 0.0);
    for seed in 0..HK_SEEDS {
        let tree = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(seed))?;
        let e = evaluate(truth, &tree.cut_k(k)?.labels)?;
        acc += e.accuracy / HK_SEEDS as f64;
        ari += e.ari / HK_SEEDS as f64;
    }
    Ok(Figures {
        stride_accuracy: stride.accuracy,
        stride_ari: stride.ari,
        hk_accuracy: acc,
        hk_ari: ari,
        nn_room: nearest_neighbour(&m, truth, |i, j| ex.allows(i, j)),
        nn_plain: nearest_neighbour(&m, truth, |_, _| true),
        describe_ms: 0.0,
    })
}

/// Simulate one set and measure every preset on it.
fn run_set(f: &Family, sensor: Sensor, seed: u64, presets: &[DescriptorParams]) -> Res<SetResult> {
    let sim = Simulation::new(&sim_params(f, sensor, seed)?)?;
    // Each scan has its own RNG stream, so casting in parallel changes no
    // figure; every preset describes the scan while its points are here.
    let per_scan: Vec<Vec<(placecat::Result<Descriptor>, f64)>> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let points = sim.scan(i).points;
            presets
                .iter()
                .map(|p| {
                    let t = std::time::Instant::now();
                    let d = describe(&points, p);
                    (d, t.elapsed().as_secs_f64() * 1e3)
                })
                .collect()
        })
        .collect();
    let truth: Vec<String> = (0..sim.len()).map(|i| sim.label(i).to_string()).collect();
    let mut kinds = truth.clone();
    kinds.sort();
    kinds.dedup();
    let ex = if f.scene == SceneKind::Warehouse || f.scene == SceneKind::Outdoor {
        Exclusion::Window(
            (ROUTE_WINDOW * sim.len()).div_ceil(placecat::sim::DEFAULT_SEQUENCE_SCANS),
        )
    } else {
        Exclusion::Rooms((0..sim.len()).map(|i| sim.room(i)).collect())
    };
    let (mut out, mut failed) = (vec![], vec![]);
    for (k, p) in presets.iter().enumerate() {
        // Error is not Clone: keep the first message, clone the descriptors.
        let ds: Result<Vec<Descriptor>, String> = per_scan
            .iter()
            .map(|s| s[k].0.as_ref().cloned().map_err(|e| e.to_string()))
            .collect();
        let ds = match ds {
            Ok(ds) => ds,
            Err(e) => {
                failed.push((p.preset.to_string(), e));
                continue;
            }
        };
        let mut fig = measure(&ds, p, &truth, &ex, kinds.len())?;
        fig.describe_ms = per_scan.iter().map(|s| s[k].1).sum::<f64>() / per_scan.len() as f64;
        out.push((p.preset.to_string(), fig));
    }
    Ok(SetResult {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: sim.len(),
        presets: out,
        failed,
    })
}

/// Real-scan retrieval: for each preset, the scans of tests/data/real
/// whose nearest other scan is from another place.
#[derive(Serialize, Deserialize)]
struct RealRow {
    preset: String,
    scans: usize,
    same_place: usize,
    wrong: Vec<String>,
}

fn real_rows(presets: &[DescriptorParams]) -> Res<Vec<RealRow>> {
    let scans = real::real_scans();
    let mut rows = vec![];
    for p in presets {
        let (same_place, wrong) = match real::wrong_places(&scans, p)? {
            Ok(wrong) => (scans.len() - wrong.len(), wrong),
            Err(e) => (0, vec![format!("cannot describe every scan: {e}")]),
        };
        rows.push(RealRow {
            preset: p.preset.to_string(),
            scans: scans.len(),
            same_place,
            wrong,
        });
    }
    Ok(rows)
}

#[derive(Serialize, Deserialize)]
struct Report {
    presets: Vec<String>,
    new_presets: Vec<String>,
    /// Per family: the paper preset and the new preset chosen on dev seeds.
    choices: Vec<Choice>,
    dev: Vec<SetResult>,
    test: Vec<SetResult>,
    real: Vec<RealRow>,
    seconds: f64,
}

#[derive(Serialize, Deserialize)]
struct Choice {
    family: String,
    paper: String,
    /// None when there is no new preset yet.
    best_new: Option<String>,
}

fn mean_of(sets: &[&SetResult], preset: &str, f: impl Fn(&Figures) -> f64) -> f64 {
    // NaN (shown n/a) unless the preset described every set.
    let v: Vec<f64> = sets
        .iter()
        .filter_map(|s| s.presets.iter().find(|p| p.0 == preset).map(|p| f(&p.1)))
        .collect();
    if v.is_empty() || v.len() < sets.len() {
        return f64::NAN;
    }
    v.iter().sum::<f64>() / v.len() as f64
}

/// Scans labelled right by `preset` over `sets`, from accuracies (shares
/// of a set's scans, or means over `runs` clusterings of it); None unless
/// the preset described every set.
fn correct_of(
    sets: &[&SetResult],
    preset: &str,
    runs: u64,
    f: impl Fn(&Figures) -> f64,
) -> Option<u64> {
    sets.iter()
        .map(|s| {
            let x = &s.presets.iter().find(|p| p.0 == preset)?.1;
            Some((f(x) * (s.scans as u64 * runs) as f64).round() as u64)
        })
        .sum()
}

fn sets_of<'a>(all: &'a [SetResult], family: &str, sensor: &str) -> Vec<&'a SetResult> {
    all.iter()
        .filter(|s| s.family == family && s.sensor == sensor)
        .collect()
}

/// The development run: the presets it ran and its sets.
#[derive(Serialize, Deserialize)]
struct DevRun {
    presets: Vec<String>,
    sets: Vec<SetResult>,
    seconds: f64,
}

/// Round 3's trials: M2DP alone and beside the paper's and the best
/// existing presets, at the weights its dev grid scored best (docs/parts.md,
/// third round). They are no presets (the rule made none): run beside the
/// presets so that M2DP's test figures are reported, never chosen.
const TRIALS_3: [(&str, &str, f64, f64); 4] = [
    ("m2dp_alone", "indoor", 0.0, 20.0),
    ("indoor+m2dp", "indoor", 1.0, 20.0),
    ("indoor_clutter+m2dp", "indoor_clutter", 1.0, 10.0),
    ("warehouse+m2dp", "warehouse", 1.0, 10.0),
];

/// The trials of a round (names and parameters): none before round 3.
fn trials(round: &Round) -> Res<Vec<(&'static str, DescriptorParams)>> {
    if round.number < 3 {
        return Ok(vec![]);
    }
    TRIALS_3
        .iter()
        .map(|&(name, base, ndt, m2dp)| {
            let mut p = DescriptorParams::preset(base)?;
            p.preset = name.into();
            p.ndt_weight = ndt;
            if ndt == 0.0 {
                p.parts.clear();
            }
            p.parts.push(placecat::descriptor::Part {
                kind: placecat::descriptor::PartKind::M2dp,
                weight: m2dp,
            });
            p.validate()?;
            Ok((name, p))
        })
        .collect()
}

/// Every preset of PRESETS, then the round's trials: names and parameters.
fn all_presets(round: &Round) -> Res<(Vec<&'static str>, Vec<DescriptorParams>)> {
    let mut names = placecat::descriptor::preset_names();
    let mut presets: Vec<DescriptorParams> = names
        .iter()
        .map(|n| DescriptorParams::preset(n))
        .collect::<placecat::Result<_>>()?;
    for (name, p) in trials(round)? {
        names.push(name);
        presets.push(p);
    }
    Ok((names, presets))
}

fn dev_run(round: &Round, keep: impl Fn(&Family) -> bool) -> Res<DevRun> {
    let t0 = std::time::Instant::now();
    let (names, presets) = all_presets(round)?;
    let mut sets = vec![];
    for f in families().iter().filter(|f| keep(f)) {
        for &seed in round.dev_seeds {
            eprintln!(
                "dev {} seed {seed} ({:.0} s)",
                f.name,
                t0.elapsed().as_secs_f64()
            );
            sets.push(run_set(f, Sensor::Own, seed, &presets)?);
        }
    }
    Ok(DevRun {
        presets: names.iter().map(|n| n.to_string()).collect(),
        sets,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// `with_real`: also the real-scan rows (not needed when one family is run
/// again).
fn compute(round: &Round, dev_run: DevRun, dev_only: bool, with_real: bool) -> Res<Report> {
    let t0 = std::time::Instant::now();
    let (names, presets) = all_presets(round)?;
    let trial_names: Vec<&str> = TRIALS_3.iter().map(|t| t.0).collect();
    let new_presets: Vec<String> = names
        .iter()
        .filter(|n| !PAPER_PRESETS.contains(n) && !trial_names.contains(n))
        .map(|n| n.to_string())
        .collect();
    if dev_run.presets != names {
        return Err(format!(
            "docs/{} holds presets {:?}, there are {names:?}: run with --dev first",
            round.dev_file, dev_run.presets
        )
        .into());
    }
    let dev = dev_run.sets;
    let fams: Vec<Family> = families()
        .into_iter()
        .filter(|f| dev.iter().any(|s| s.family == f.name))
        .collect();
    let choices = fams
        .iter()
        .map(|f| {
            let sets = sets_of(&dev, f.name, "own");
            // Compared as whole numbers of correctly labelled scans over
            // the family's dev sets (equal means of float accuracies read
            // back from JSON need not be equal to the last bit); a preset
            // that failed on a dev set (None) is never chosen.
            let score = |p: &str| correct_of(&sets, p, 1, |x| x.stride_accuracy);
            // Round 2's tie-break: dev hk-means++ (scans right summed
            // over the clustering seeds), then room-level 1-NN.
            let then = |p: &str| {
                if round.tie_break {
                    (
                        correct_of(&sets, p, HK_SEEDS, |x| x.hk_accuracy),
                        correct_of(&sets, p, 1, |x| x.nn_room),
                    )
                } else {
                    (Some(0), Some(0))
                }
            };
            let best_new = new_presets
                .iter()
                .filter(|p| score(p).is_some())
                .max_by_key(|p| (score(p), then(p)))
                .cloned();
            Choice {
                family: f.name.into(),
                paper: f.paper.into(),
                best_new,
            }
        })
        .collect();
    let mut test = vec![];
    if !dev_only {
        for f in &fams {
            for sensor in std::iter::once(Sensor::Own).chain(f.sensors.iter().copied()) {
                for &seed in round.test_seeds {
                    eprintln!(
                        "test {} {} seed {seed} ({:.0} s)",
                        f.name,
                        sensor.name(),
                        t0.elapsed().as_secs_f64()
                    );
                    test.push(run_set(f, sensor, seed, &presets)?);
                }
            }
        }
    }
    Ok(Report {
        presets: names.iter().map(|n| n.to_string()).collect(),
        new_presets,
        choices,
        dev,
        test,
        real: if with_real {
            real_rows(&presets)?
        } else {
            vec![]
        },
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// The families' sensors in the order they were run.
fn sensors_of(all: &[SetResult], family: &str) -> Vec<String> {
    let mut out: Vec<String> = vec![];
    for s in all.iter().filter(|s| s.family == family) {
        if !out.contains(&s.sensor) {
            out.push(s.sensor.clone());
        }
    }
    out
}

/// The target of a family on stride k-means, as issue 18 sets it.
fn target(family: &str, paper: f64) -> (String, f64) {
    if family == "warehouse" {
        ("at least 95 %".into(), 0.95)
    } else if family == "outdoor" {
        (
            format!("not worse than the paper's {} %", pct(paper)),
            paper,
        )
    } else {
        ("at least 85 %".into(), 0.85)
    }
}

fn render(round: &Round, r: &Report, notes: &str) -> Res<String> {
    let mut o = String::new();
    let (title, dev_cmd, test_cmd) = match round.number {
        1 => ("", "-- --dev".to_string(), String::new()),
        n => (
            if n == 2 {
                ", second round"
            } else {
                ", third round"
            },
            format!("-- --round {n} --dev"),
            format!(" -- --round {n}"),
        ),
    };
    // Only round 1's outdoor rows were run again (the site changed in
    // 9df133b, after its test run); round 2 ran every family once.
    let family_note = if round.number == 1 {
        ", as was done for the outdoor site after commit 9df133b"
    } else {
        ""
    };
    let dev_list = round
        .dev_seeds
        .iter()
        .map(u64::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let tests = round.seeds_text(round.test_seeds);
    let (t0, t1) = (
        round.test_seeds[0],
        round.test_seeds[round.test_seeds.len() - 1],
    );
    writeln!(
        o,
        "# Place descriptors beyond the paper (issue 18){title}\n"
    )?;
    writeln!(o, "Regenerate with `cargo run --release --example descriptors {dev_cmd}` (the development seeds, `{}`) then `cargo run --release --example descriptors{test_cmd}` (the test seeds: this file and `{}`; {:.0} s for the test run on a two-core machine shared with five other builds; `-- --render` renders this file again from `{}`; `-- --family NAME` runs one family's dev and test seeds again and replaces only its rows{family_note}). Seeds fixed in [seeds.md](seeds.md) before any run: development {dev_list}; test {t0} to {t1}. Every figure below is on the test seeds, each run once, whatever it showed, unless it says dev.\n", round.dev_file, round.report_file, r.seconds, round.report_file)?;
    writeln!(
        o,
        "Presets run: {}. The paper's (and placecat's before this issue): {}. New: {}.\n",
        r.presets
            .iter()
            .map(|p| format!("`{p}`"))
            .collect::<Vec<_>>()
            .join(", "),
        PAPER_PRESETS.map(|p| format!("`{p}`")).join(", "),
        if r.new_presets.is_empty() {
            "none yet".to_string()
        } else {
            r.new_presets
                .iter()
                .map(|p| format!("`{p}`"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    )?;
    let developed = if round.number == 1 {
        "No descriptor or preset was developed on the office or school floors."
    } else if round.number == 3 {
        "In this round the `m2dp` part (M2DP, He, Wang and Zhang, IROS 2016) was tried on the development seeds of every family, alone and beside the existing presets, under a rule written before its grid was looked at (docs/parts.md, third round); the test seeds were run once, after. The rule made no preset with M2DP; four trials are run beside the presets so that its test figures are reported, never chosen: `m2dp_alone` (M2DP alone), `indoor+m2dp` (the paper's indoor NDT plus M2DP at weight 20), `indoor_clutter+m2dp` (plus M2DP at 10) and `warehouse+m2dp` (plus M2DP at 10), the best weights of its dev grid for each."
    } else {
        "In this round the `clutter` part and `indoor_clutter` were developed on the development seeds of every family, the office and school floors included (docs/parts.md); the test seeds were run once, after."
    };
    writeln!(o, "**Method.** Families: indoor rooms of one building, of many buildings (`--buildings many`), of varied plans (`--buildings varied`: mirrored layouts, L-shaped rooms), an office floor (`--scene office-floor`: corridor, private office, meeting room, open plan, restroom; doors open into the corridor; written while the descriptors were being built, by another hand), school floors written after the descriptors were committed (`--scene school`: corridor with lockers, classroom, library, cafeteria, staff room), the warehouse and the outdoor site. {developed} Indoor families: {KIND_SCANS} scans a kind, {ROOM_SCANS} per room at free spots anywhere in it ({} scans a set); routes: {ROUTE_SCANS} scans (a third of `placecat simulate`'s default). Sensors: each scene's own (128-beam OS0 indoors and in the warehouse at 1.0 to 1.4 m, 64-beam KITTI-like outdoors at 1.6 to 1.95 m); the school (the family written last) also with `--beams 16/32/64` and `--sensor-height 0.3/1.8`; rooms of many buildings and outdoors also with 16 beams; the office floor at 0.3 m; the warehouse with 32 beams; rooms of one building and of varied plans only with their own sensor. **Subsampled** (fewer scans, not every family with every sensor) so that the whole run stays near 15 minutes on a two-core machine shared by six builds; the sets are small, so a figure moves by 1/45 (indoor) or 1/100 (routes) per scan. Measures at the true number of kinds: deterministic (stride) k-means, hierarchical k-means++ (mean of clustering seeds 0-9), accuracy and ARI; 1-NN leave-one-out with no neighbour from the scan's room (routes: none within {ROUTE_WINDOW} scans at the default density of 300 a route, i.e. within {} of the {ROUTE_SCANS} scans here). The new preset reported for a family is the one with the best stride k-means on the dev seeds with the scene's own sensor (table in section 5).\n", 5 * KIND_SCANS, (ROUTE_WINDOW * ROUTE_SCANS).div_ceil(placecat::sim::DEFAULT_SEQUENCE_SCANS))?;
    writeln!(o, "## 1. The best new preset against the paper's, per family (own sensor, mean of test seeds {tests})\n")?;
    render_best(&mut o, r)?;
    writeln!(o, "\n## 2. Every preset, every family and sensor (mean of test seeds {tests})\n\nEach cell: stride k-means / hk-means++ / room-level 1-NN, in %.\n")?;
    for c in &r.choices {
        writeln!(o, "### {}\n", c.family)?;
        let sensors = sensors_of(&r.test, &c.family);
        writeln!(
            o,
            "| preset | {} |\n|---|{}",
            sensors.join(" | "),
            "---|".repeat(sensors.len())
        )?;
        for p in &r.presets {
            let cells: Vec<String> = sensors
                .iter()
                .map(|s| {
                    let sets = sets_of(&r.test, &c.family, s);
                    format!(
                        "{} / {} / {}",
                        pct(mean_of(&sets, p, |x| x.stride_accuracy)),
                        pct(mean_of(&sets, p, |x| x.hk_accuracy)),
                        pct(mean_of(&sets, p, |x| x.nn_room))
                    )
                })
                .collect();
            let mark = if *p == c.paper {
                " (paper)"
            } else if Some(p) == c.best_new.as_ref() {
                " (new, chosen)"
            } else {
                ""
            };
            writeln!(o, "| `{p}`{mark} | {} |", cells.join(" | "))?;
        }
        writeln!(o)?;
    }
    render_failures(&mut o, r)?;
    writeln!(o, "## 3. Real scans: same-place retrieval (tests/data/real, 18 scans at 5 places)\n\nA scan counts when its nearest other scan under the preset's distance is from the same place (`groups.csv`); no preset was tuned on these files.\n\n| preset | same place | nearest from another place |\n|---|---|---|")?;
    for row in &r.real {
        writeln!(
            o,
            "| `{}` | {} of {} | {} |",
            row.preset,
            row.same_place,
            row.scans,
            if row.wrong.is_empty() {
                "none".to_string()
            } else {
                row.wrong.join(", ")
            }
        )?;
    }
    writeln!(o, "\n## 4. What did not work\n")?;
    writeln!(o, "{notes}")?;
    writeln!(o, "Sets where the chosen new preset does worse than the paper's (test-seed means, stride k-means or room-level 1-NN, by more than 1 point):\n")?;
    let mut any = false;
    for c in &r.choices {
        let Some(b) = &c.best_new else { continue };
        for s in sensors_of(&r.test, &c.family) {
            let sets = sets_of(&r.test, &c.family, &s);
            for (what, f) in [
                (
                    "stride k-means",
                    (|x: &Figures| x.stride_accuracy) as fn(&Figures) -> f64,
                ),
                ("room-level 1-NN", |x: &Figures| x.nn_room),
            ] {
                let (new, old) = (mean_of(&sets, b, f), mean_of(&sets, &c.paper, f));
                if new < old - 0.01 {
                    any = true;
                    writeln!(
                        o,
                        "- {}, sensor {s}: {what} `{b}` {} % vs `{}` {} %",
                        c.family,
                        pct(new),
                        c.paper,
                        pct(old)
                    )?;
                }
            }
        }
    }
    if !any {
        writeln!(o, "- none")?;
    }
    writeln!(o, "\n## 5. Development seeds ({}, own sensor): the choice of the new preset\n\n| family | preset | stride k-means | hk-means++ | room-level 1-NN | describe ms a scan (wall time in a worker on the busy machine: a rough guide, not a benchmark) |\n|---|---|---|---|---|---|", round.seeds_text(round.dev_seeds))?;
    for c in &r.choices {
        let sets = sets_of(&r.dev, &c.family, "own");
        for p in &r.presets {
            let mark = if Some(p) == c.best_new.as_ref() {
                " (chosen)"
            } else {
                ""
            };
            writeln!(
                o,
                "| {} | `{p}`{mark} | {} | {} | {} | {} |",
                c.family,
                pct(mean_of(&sets, p, |x| x.stride_accuracy)),
                pct(mean_of(&sets, p, |x| x.hk_accuracy)),
                pct(mean_of(&sets, p, |x| x.nn_room)),
                pct(mean_of(&sets, p, |x| x.describe_ms / 100.0))
            )?;
        }
    }
    writeln!(o, "\n## 6. Every test-seed figure\n\nEach cell: stride k-means / hk-means++ / room-level 1-NN, in %; ARI and plain 1-NN are in `{}`.\n\n| family | sensor | preset | {} |\n|---|---|---|{}", round.report_file, round.test_seeds.iter().map(u64::to_string).collect::<Vec<_>>().join(" | "), "---|".repeat(round.test_seeds.len()))?;
    for c in &r.choices {
        for s in sensors_of(&r.test, &c.family) {
            let sets = sets_of(&r.test, &c.family, &s);
            for p in &r.presets {
                let cells: Vec<String> = sets
                    .iter()
                    .map(|set| {
                        set.presets
                            .iter()
                            .find(|x| x.0 == *p)
                            .map_or("-".into(), |(_, x)| {
                                format!(
                                    "{} / {} / {}",
                                    pct(x.stride_accuracy),
                                    pct(x.hk_accuracy),
                                    pct(x.nn_room)
                                )
                            })
                    })
                    .collect();
                writeln!(o, "| {} | {s} | `{p}` | {} |", c.family, cells.join(" | "))?;
            }
        }
    }
    Ok(o)
}

/// Section 1's table: per family, the paper's preset and the new one
/// chosen on the dev seeds, on the test seeds with the scene's own sensor.
fn render_best(o: &mut String, r: &Report) -> Res<()> {
    writeln!(o, "| family | preset | stride k-means | ARI | hk-means++ | ARI | room-level 1-NN | target (stride k-means) | met |\n|---|---|---|---|---|---|---|---|---|")?;
    for c in &r.choices {
        let sets = sets_of(&r.test, &c.family, "own");
        let paper = mean_of(&sets, &c.paper, |x| x.stride_accuracy);
        let (text, bar) = target(&c.family, paper);
        let mut rows = vec![(format!("`{}` (paper)", c.paper), c.paper.clone())];
        if let Some(b) = &c.best_new {
            rows.push((format!("`{b}` (new)"), b.clone()));
        }
        for (label, p) in rows {
            let acc = mean_of(&sets, &p, |x| x.stride_accuracy);
            let met = if p == c.paper {
                "-".to_string()
            } else if acc + 1e-9 >= bar {
                "yes".into()
            } else {
                "**no**".into()
            };
            writeln!(
                o,
                "| {} | {label} | {} | {:.3} | {} | {:.3} | {} | {text} | {met} |",
                c.family,
                pct(acc),
                mean_of(&sets, &p, |x| x.stride_ari),
                pct(mean_of(&sets, &p, |x| x.hk_accuracy)),
                mean_of(&sets, &p, |x| x.hk_ari),
                pct(mean_of(&sets, &p, |x| x.nn_room))
            )?;
        }
    }
    Ok(())
}

/// The presets that could not describe every scan of a set (n/a above):
/// on how many test sets of which family, and the first error.
fn render_failures(o: &mut String, r: &Report) -> std::fmt::Result {
    let mut seen: Vec<(String, String, usize, String)> = vec![];
    for set in &r.test {
        for (preset, error) in &set.failed {
            match seen
                .iter_mut()
                .find(|x| x.0 == set.family && x.1 == *preset)
            {
                Some(x) => x.2 += 1,
                None => seen.push((set.family.clone(), preset.clone(), 1, error.clone())),
            }
        }
    }
    if seen.is_empty() {
        return Ok(());
    }
    writeln!(o, "Presets shown n/a could not describe every scan of a set (the error stops a run on such a set, so no figure):\n")?;
    for (family, preset, n, error) in seen {
        writeln!(
            o,
            "- {family}, `{preset}`: {n} test sets; first error: {error}"
        )?;
    }
    writeln!(o)
}

/// What did not work, in words, written after the test run (the figures
/// behind it are in the tables; the list after it is computed).
const NOTES: &str = "Written after the one test run (presets of the `desc` branch at commit 2eca927, merged here; the figures are in the tables above).

- **The indoor target is not met on the floors written for this evaluation.** Office floor: the chosen `indoor_plus` gives stride k-means 74.2 % (the paper's `indoor` 68.0 %), at 0.3 m 66.7 % (55.1 %). School, the family written after the descriptors were committed: 74.2 % (63.6 %); over its six sensors `indoor_plus` gives 74 to 83 %, the paper's 64 to 74 %. Better than the paper's everywhere there, and still 2 to 11 points short of 85 %. On the three room families the new presets were built on (one building, many buildings, varied plans) they reach 91 to 97 %, and the paper's 85 to 93 % on these smaller sets: the gap between those families and the floors is the honest measure of how far the new parts generalise.
- **Warehouse halls: stride k-means stays at 65 to 72 % for every preset but `indoor_bands` (78.4 %)** (chosen new 71.0 %, paper 68.0 %; 32 beams 71.4 % against 60.0 %), far from 95 %. Hierarchical k-means++ with the new presets reaches 91 to 98 % on the same Delta (`indoor_plus` 96.5 %, 32 beams 97.5 %; paper 63.7 %; only `free_space` at 32 beams falls to 71.4 %): the new parts do separate the halls, but deterministic k-means' stride seeding does not find that split. The target, stated for stride k-means, is missed.
- **Room-level 1-NN got worse in two places**: warehouse 95.8 % against 98.6 % (`indoor_plus` vs `indoor`), rooms of many buildings 90.7 % against 92.0 %. On the office floor it stays where the paper's is (66.2 % against 65.8 %), on the school 77.8 % against 76.4 %.
- **The choice on the development seeds cost some points once**: for rooms of one building the dev seeds chose `free_space` (94.2 % on test), while `indoor_plus` gave 97.3 % on the test seeds. The chosen one is what section 1 reports.
- **`free_space` alone** (the free-space slice without the NDT histogram's full weight) is never the best on the floors: 63.1 % on the school, as the paper's preset, 69.8 % on the office floor.
- **`outdoor` and `outdoor_plus` cannot describe most indoor scans** (no voxel in their far range intervals): n/a on every set of the three room families and on 9 of the 10 office-floor sets; on the school's larger rooms they describe 27 of 30 sets and rank below `indoor_plus` there.
- **Outdoor, run again on the site of commit 9df133b** (spruce crowns down to the ground, scans labelled by the place the vehicle stands; `--family outdoor`, the first run of these seeds on that site, nothing tuned; the other families' rows are those of the full run). On the dev seeds the four new presets tie at 95.0 % stride k-means (285 of 300 scans each), below the paper's `outdoor` and `indoor` (97.0 %); the argmax keeps the last of the tie in preset order, `free_space`. On the test seeds it gives 95.2 % against the paper's 96.6 % (hk-means++ 85.4 % against 91.3 %, room-level 1-NN 94.8 % against 95.8 %): **the outdoor target (not worse than the paper's) is now missed.** No new preset beats the paper's with the site's own sensor (`indoor_plus` 95.6 %, `warehouse` 96.2 %, `outdoor_plus` 96.4 %); with 16 beams all four do (95.6 to 96.8 % against 87.0 %). On the site before 9df133b `indoor_plus` was chosen and met it (93.8 % against 92.8 %).
- **Small sets**: 45 scans a set indoors (one scan moves a figure by 2.2 points), 100 along a route; means over five test seeds. Differences of two or three points between presets are within that noise.
";

/// Replaces the sets of `family` in `all` by `new`, where the old ones
/// stood (at the end when there were none), so the other families' rows and
/// their order stay as they were.
fn splice_family(all: &mut Vec<SetResult>, family: &str, new: Vec<SetResult>) {
    let at = all
        .iter()
        .position(|s| s.family == family)
        .unwrap_or(all.len());
    all.retain(|s| s.family != family);
    let tail = all.split_off(at.min(all.len()));
    all.extend(new);
    all.extend(tail);
}

/// What did not work in round 2, in words, written after its one test run.
const NOTES_2: &str = "Written after the one test run of seeds 311-315 (presets of commit 4f279e5; the later sharing of polar coordinates between parts changes no value, tests/it/parts.rs checks it bit for bit). **After this run the clutter part's voxel sample changed** from the first point seen in each 0.1 m voxel (which made the part depend on the points' order) to the voxel's lowest point; every figure here was computed with the old sample, and the test seeds were not run again. On the development seeds 1-6 (`examples/parts_dev.rs`, office and school floors, 9 scans a kind; old and new code in the same session) `indoor_clutter` moved by at most 0.7 points: office floor 86.3/74.8/83.7 -> 86.7/75.1/83.0 % (stride k-means / hk-means++ / room-level 1-NN), school 85.5/72.9/94.8 -> 85.5/73.4/94.8 % (docs/parts.md). The new part is `clutter` (docs/parts.md), the new preset `indoor_clutter`; the other presets are those of round 1.

- **The school, the family written after the first descriptors, still misses 85 % with stride k-means**: `indoor_clutter` 79.1 % (paper 71.6 %); over its six sensors 76.0 to 86.2 % (paper 69.8 to 77.3 %), only at 1.8 m above it. Its room-level 1-NN rose from 76.4 % to 94.2 % (85.3 to 96.4 % over the sensors), so the descriptor now holds the kinds; deterministic k-means does not find them as clusters (hk-means++ 68.7 %).
- **Office floor at 0.3 m**: 84.9 % (paper 61.8 %), just under the target that the own sensor meets (94.2 %, paper 60.9 %).
- **Warehouse halls: stride k-means stays at 64 to 69 % for every new preset** (chosen `indoor_plus` 66.6 %, paper 64.6 %; 32 beams 64.8 % against 61.2 %); the target is missed as in round 1, for the same reason (stride seeds in the large hall). hk-means++ reaches 92 to 98 % with the slice and ring presets (`free_space` at 32 beams 84.7 %). `indoor_clutter` is no hall preset: hk-means++ 66.4 % (dev 67.2 %; the racks are clutter in every hall). Room-level 1-NN of the chosen `indoor_plus`: 96.2 % against the paper's 99.4 %.
- **Outdoor: the target (not worse than the paper's) is missed again, by more than in round 1.** The dev seeds chose `indoor_clutter` outright (95.3 % stride k-means against `indoor_plus` 94.8 %; no tie, so the new tie rule did not act); on the test seeds it gives 91.4 % against the paper's 95.6 % (hk-means++ 91.6 % against 82.5 %, room-level 1-NN 96.6 % against 97.4 %). No new preset reaches the paper's stride k-means with the site's own sensor (best `indoor_plus` 94.0 %); with 16 beams every new one beats it (90.8 to 95.4 % against 85.4 %). A half-point lead on six dev seeds chose a preset whose new part (what stands above the floor indoors) means nothing on a forest road.
- **hk-means++ fell with the clutter part where the rooms are plain boxes**: rooms of one building `indoor_clutter` 86.2 % against `indoor_plus` 89.2 % (dev: 79.0 % against 85.1 %); the dev seeds chose `indoor_plus` there.
- **Without the NDT histogram the clutter part is weaker** (dev, clutter alone at weight 10: office 80.0 %, school 69.6 % stride k-means, against 86.3 % and 85.5 % for `indoor_clutter`); it was not made a preset.
- **Rounds are not comparable figure by figure**: `indoor_plus` on the office floor gives 79.6 % here and gave 74.2 % on seeds 301-305, the paper's `indoor` 60.9 % and 68.0 %. Compare presets within a round.
- **Small sets**: 45 scans a set indoors (one scan moves a figure by 2.2 points), 100 along a route; means over five test seeds.
";

/// What did not work in round 3, in words, written after its one test run.
const NOTES_3: &str = "Written after the one test run of seeds 321-325 (commit d7476e6's presets, unchanged from round 2; the four `+m2dp` and `m2dp_alone` rows are trials, never chosen). The family `school (fresh)` keeps the name it got when it was written after the first descriptors (the name is its key in the JSON of every round); it is not fresh here: its dev seeds were used in rounds 2 and 3, only its test seeds 321-325 are new.

- **M2DP made no preset.** On the dev seeds (docs/parts.md, third round) no weighting with M2DP passed the rule written before the grid: rooms, `indoor_clutter` + M2DP 10 gave 89.4 % mean stride k-means against `indoor_clutter`'s 89.6 % (1.0 point more was needed); halls, `warehouse` + M2DP 10 gave 73.9 % against `indoor_plus`'s 75.6 %. The test seeds agree: beside `indoor_clutter` it costs the floors (office 84.9 against 86.7 %, room-level 1-NN 89.8 against 92.4 %; school 81.8 against 84.0 %, 1-NN 92.4 against 94.2 %) and changes placecat's rooms by at most a scan (one building 99.1 against 98.7 %, many 97.3 against 97.3 %, varied plans 98.7 against 98.2 %); beside `warehouse` it changes nothing (own sensor 64.6 / 95.9 % against 64.8 / 95.6 %, 32 beams 63.8 / 97.6 % against 64.4 / 97.8 %).
- **M2DP alone is the weakest descriptor run**: stride k-means 62.2 % on the school, 60.4 % on the office floor, 75.6 to 87.6 % on placecat's rooms, 79.2 % outdoors (paper 95.6 %); hk-means++ 50 to 66 %; and the only one to miss real-scan retrieval (15 of 18; two scans of the Velodyne pair and one of the OS0 sequence find another place). It is scale-free (its rings are shares of the farthest point's distance, as in the paper), so rooms of one shape and different sizes look alike, and indoors its noise is near its spread (a box room turned by 1.1 rad moves 0.0028, a 16 x 12 m hall of nearly the same proportions is at 0.0036; tests/it/parts.rs). Only in the warehouse with 32 beams did it give the best stride k-means of the run (77.2 %, hk-means++ 77.1 %), far from the target.
- **Beside the paper's NDT histogram alone it helps some families**: `indoor+m2dp` against `indoor`: varied plans 96.0 against 90.2 %, office floor 69.8 against 63.6 %, school 77.3 against 76.0 %, outdoors 96.2 against 96.8 % (`indoor`) and 95.6 % (`outdoor`); many buildings 95.6 against 96.9 %, warehouse 67.6 against 69.8 %. Everywhere below the existing new presets on the floors.
- **The school still misses 85 % with stride k-means** (`indoor_clutter` 84.0 %, paper 76.0 %; 80.0 to 87.6 % over its six sensors), by one scan in 45 on average; room-level 1-NN 94.2 %. The office floor meets it (86.7 %, at 0.3 m 83.1 %).
- **Outdoor misses again**: the dev seeds chose `outdoor_plus` (96.8 %, tied with `indoor_plus` and broken by dev hk-means++ 97.3 against 93.5 %); on the test seeds it gives 91.6 % against the paper's 95.6 % (hk-means++ 93.1 against 95.3 %, room-level 1-NN 96.4 against 95.0 %). With 16 beams every new preset beats the paper's (94.2 to 97.0 % against 81.4 %).
- **Warehouse halls: stride k-means 64.6 to 69.2 % for every new preset** (chosen `indoor_plus` 69.2 %, paper 69.8 %), while hk-means++ reaches 96.1 % (32 beams 97.9 %). Why, measured on the dev seeds 1-6 (`examples/warehouse_stride.rs`, 150 scans a route, own sensor; means of the six seeds; the run's output, seed by seed, is [warehouse-stride-dev-3.txt](warehouse-stride-dev-3.txt)):

| preset | stride k-means | stride, scans shuffled (10 orders) | k-means++ (seeds 0-9) | random seeds | k-means++ run of least cost of the ten | hk-means++ | Lloyd started at the true kinds | true grouping's cost < stride's own |
|---|---|---|---|---|---|---|---|---|
| `indoor` (paper) | 68.3 | 65.0 | 68.4 | 69.2 | 71.0 | 62.6 | 78.1 | 0 of 6 (37.5 against 40.5) |
| `indoor_plus` | 70.8 | 75.7 | 83.9 | 82.3 | 98.5 | 96.8 | 99.4 | 6 of 6 (137.2 against 142.8) |
| `warehouse` | 67.8 | 75.2 | 83.5 | 81.5 | 98.7 | 97.0 | 99.4 | 6 of 6 (123.3 against 127.5) |
| `free_space` | 59.9 | 66.9 | 81.8 | 79.7 | 89.3 | 98.5 | 99.4 | 6 of 6 (165.5 against 169.8) |

  The route runs small hall (20-21 scans), airlock (7-8), large hall (108-111), airlock (7-8), small hall (5): 72-74 % of the scans are in the large hall and 10 % in the airlock. On all six seeds the stride seeds (scans 0, 50, 100) fall in the small hall, the large hall and the large hall again, so no centre starts in the airlock and Lloyd's iterations split the large hall and merge the airlock into a hall. **With the slice and ring parts this is the seeding, not the descriptor**: the true grouping has a lower k-means cost than the grouping stride k-means ends in on 6 of 6 seeds, Lloyd started at the true kinds stays there (99.4 %), and the cheapest of ten k-means++ runs finds the kinds (98.5 % and 98.7 %; hk-means++, which splits the large hall from the rest first, 96.8 % and 97.0 %). It is not the seeds' order along the sequence as such: stride seeds on shuffled scans (seeds at random scans) do no better than 67-76 %, and single random or k-means++ starts reach 80-84 %, because any start whose three seeds miss the small airlock (10 % of the scans) ends in the same wrong minimum; the kinds' unbalanced sizes are the cause, and picking the run of least cost is the remedy the objective supports. **With the paper's NDT histogram alone it is the descriptor**: the true grouping costs more than stride k-means' own on 6 of 6 seeds (40.5 against 37.5), Lloyd started at the truth drifts away (78.1 %), and no seeding finds the halls (hk-means++ 62.6 %). Stride k-means is the paper's deterministic choice and the target is stated for it; placecat's default clustering was not changed here.
- **Rounds are not comparable figure by figure** (office floor `indoor_clutter` 94.2 % on 311-315, 86.7 % here); compare presets within a round. Small sets: 45 scans a set indoors (one scan moves a figure by 2.2 points), 100 along a route.
";

fn notes_of(round: &Round) -> &'static str {
    match round.number {
        1 => NOTES,
        2 => NOTES_2,
        _ => NOTES_3,
    }
}

/// The pointer to round 4 (examples/kmeans_restarts.rs), which changed
/// the clustering, not the descriptors.
const ROUND_4: &str = "## 8. Fourth round: k-means++ with 10 restarts (a clustering option, not a descriptor change)

Rounds 1-3 changed the descriptor; round 4 changed only the clustering: k-means with k-means++ seeding run 10 times, keeping the run of lowest k-means cost (`--restarts 10`; scikit-learn's `n_init`), on the presets rounds 2 and 3 chose, with test seeds 331-335 run once. The descriptors, their presets and the paper's methods are unchanged, and one run stays the default. Every figure is in [descriptors-4.md](descriptors-4.md). In short: on rooms the best of 10 meets 85 % in four of five families (office floor 84.7 %), about as stride k-means does and above one k-means++ run in 32 of 34 rows; the warehouse halls are **not** found (77.2 % own sensor, 71.1 % with 32 beams, against 99.4 % and 84.4 % on the dev seeds), since there the cheapest of the 10 runs is mostly another grouping; hk-means++ stays the halls' method (94.3 and 97.8 %). Outdoors the new presets stay under the paper's with the own sensor (94.0 against 95.6 %).";

/// A round's markdown. Round 1's keeps its six sections as they were and,
/// once round 2 has run, ends with round 2's summary table.
fn markdown(docs: &std::path::Path, round: &Round, report: &Report) -> Res<String> {
    let mut md = render(round, report, notes_of(round))?;
    let second = docs.join(SECOND.report_file);
    if round.number == 1 && second.exists() {
        let r2: Report = read_json(&second)?;
        writeln!(md, "\n## 7. Second round: the best new preset against the paper's (own sensor, mean of test seeds {})\n\nPresets chosen on the dev seeds {} (ties broken by dev hk-means++, then room-level 1-NN); every figure of that round, per sensor and seed, and what did not work, are in [descriptors-2.md](descriptors-2.md).\n", SECOND.seeds_text(SECOND.test_seeds), SECOND.seeds_text(SECOND.dev_seeds))?;
        render_best(&mut md, &r2)?;
        writeln!(md, "\nWhat did not work in the second round:\n\n{NOTES_2}")?;
    }
    if round.number == 1 && docs.join("descriptors-4.md").exists() {
        writeln!(md, "\n{ROUND_4}")?;
    }
    Ok(md)
}

/// Writes a round's report data and markdown; after round 2, round 1's
/// markdown again (its section 7).
fn write_report(docs: &std::path::Path, round: &Round, report: &Report) -> Res<()> {
    std::fs::write(
        docs.join(round.report_file),
        serde_json::to_string_pretty(report)?,
    )?;
    std::fs::write(docs.join(round.md_file), markdown(docs, round, report)?)?;
    if round.number != 1 {
        let first: Report = read_json(&docs.join(FIRST.report_file))?;
        std::fs::write(docs.join(FIRST.md_file), markdown(docs, &FIRST, &first)?)?;
    }
    Ok(())
}

/// `--family NAME`: the dev seeds, the choice and the test seeds of one
/// family (its name exactly) again, e.g. after its scene changed; only that
/// family's rows of the round's dev and report data are replaced, and its
/// markdown is rendered again. The real-scan rows and the recorded run
/// time are kept from the full run.
fn rerun_family(docs: &std::path::Path, round: &Round, name: &str) -> Res<()> {
    if !families().iter().any(|f| f.name == name) {
        let names: Vec<_> = families().iter().map(|f| f.name).collect();
        return Err(format!("--family {name:?}: no such family; there are {names:?}").into());
    }
    let dev_path = docs.join(round.dev_file);
    let mut dev_all: DevRun = read_json(&dev_path)?;
    let mut report: Report = read_json(&docs.join(round.report_file))?;
    let dev = dev_run(round, |f| f.name == name)?;
    splice_family(&mut dev_all.sets, name, dev.sets.clone());
    let dev_seconds = dev.seconds;
    let fresh = compute(round, dev, false, false)?;
    splice_family(&mut report.dev, name, fresh.dev);
    splice_family(&mut report.test, name, fresh.test);
    for c in fresh.choices {
        match report.choices.iter_mut().find(|x| x.family == c.family) {
            Some(old) => *old = c,
            None => report.choices.push(c),
        }
    }
    std::fs::write(&dev_path, serde_json::to_string_pretty(&dev_all)?)?;
    write_report(docs, round, &report)?;
    eprintln!(
        "replaced {name} in docs/{} and docs/{}, rendered docs/{} ({:.0} s dev, {:.0} s test)",
        round.dev_file, round.report_file, round.md_file, dev_seconds, fresh.seconds
    );
    Ok(())
}

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
    };
    let dev_only = args.iter().any(|a| a == "--dev");
    let only = value("--only");
    let family = value("--family");
    let round = match value("--round").map(String::as_str) {
        None | Some("1") => &FIRST,
        Some("2") => &SECOND,
        Some("3") => &THIRD,
        Some(other) => return Err(format!("--round {other}: there are rounds 1, 2 and 3").into()),
    };
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let dev_path = docs.join(round.dev_file);
    if dev_only || only.is_some() {
        let dev = dev_run(round, |f| only.is_none_or(|o| f.name.contains(o.as_str())))?;
        if only.is_none() {
            std::fs::write(&dev_path, serde_json::to_string_pretty(&dev)?)?;
            eprintln!("wrote docs/{} ({:.0} s)", round.dev_file, dev.seconds);
        }
        println!(
            "{}",
            render(round, &compute(round, dev, true, true)?, notes_of(round))?
        );
        return Ok(());
    }
    if let Some(name) = family {
        return rerun_family(&docs, round, name);
    }
    if args.iter().any(|a| a == "--check-choices") {
        // The choices the report holds, made again from the dev file by
        // today's rule (no seed is run).
        let report: Report = read_json(&docs.join(round.report_file))?;
        let dev: DevRun = read_json(&dev_path)?;
        let now = compute(round, dev, true, false)?;
        let mut differ = 0;
        for c in &now.choices {
            let was = report.choices.iter().find(|x| x.family == c.family);
            let was = was.and_then(|x| x.best_new.clone());
            println!("{}: {:?} (report: {:?})", c.family, c.best_new, was);
            differ += usize::from(was != c.best_new);
        }
        if differ > 0 {
            return Err(format!("{differ} choices differ from docs/{}", round.report_file).into());
        }
        return Ok(());
    }
    if args.iter().any(|a| a == "--render") {
        let report: Report = read_json(&docs.join(round.report_file))?;
        std::fs::write(docs.join(round.md_file), markdown(&docs, round, &report)?)?;
        eprintln!(
            "rendered docs/{} from docs/{}",
            round.md_file, round.report_file
        );
        return Ok(());
    }
    let dev: DevRun = read_json(&dev_path).map_err(|e| format!("{e} (run with --dev first)"))?;
    let report = compute(round, dev, false, true)?;
    write_report(&docs, round, &report)?;
    eprintln!(
        "wrote docs/{} and docs/{} ({:.0} s)",
        round.md_file, round.report_file, report.seconds
    );
    Ok(())
}
