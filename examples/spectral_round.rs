//! Issue 18, eighteenth round: spectral clustering (`cluster::spectral`)
//! of the presets' distance, beside k-means, on every family and sensor of
//! the seventeenth round.
//!
//!     cargo run --release --example spectral_round -- --dev   # seeds 1-6: docs/spectral-dev.json
//!     cargo run --release --example spectral_round            # test seeds, once: docs/spectral.{json,md}
//!     ... -- --render   # docs/spectral.md again from the two .json
//!     ... -- --second   # nineteenth round, test seeds 491-495, once: docs/spectral-2.{json,md}
//!     ... -- --second --render
//!
//! The method, the presets and the rule were fixed in docs/seeds.md
//! ("issue 18, eighteenth round") before any run: spectral clustering
//! becomes an option whatever the figures; the docs recommend it for room
//! kinds if on the test seeds, with `indoor_objects`, its mean over the 14
//! room rows is above k-means++ best of 10's and it is lower than best of
//! 10 in at most 4 of them. The test run refuses to overwrite its report.
//! The nineteenth round ("issue 18, nineteenth round" in docs/seeds.md)
//! runs the same on fresh seeds and reads that rule on both samples pooled.

use placecat::cluster::{KMeans, KMeansParams, Seeding};
use placecat::distance::Space;
use placecat::*;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::path::{Path, PathBuf};

#[path = "common/families.rs"]
mod families;
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
#[path = "common/seeds.rs"]
mod seeds;
use families::*;
use rounds::*;

/// Fixed in docs/seeds.md ("issue 18, eighteenth round") before any run.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];
const TEST_SEEDS: &[u64] = &[481, 482, 483, 484, 485];
/// The nineteenth round's, fixed in docs/seeds.md before any run.
const SECOND_SEEDS: &[u64] = &[491, 492, 493, 494, 495];
const ROOM_PRESETS: &[&str] = &["indoor", "indoor_searched", "indoor_objects"];
const WAREHOUSE_PRESETS: &[&str] = &["indoor", "indoor_plus"];
const OUTDOOR_PRESETS: &[&str] = &["outdoor", "outdoor_near"];
/// The preset and the bounds of the rule.
const PRESET: &str = "indoor_objects";
const MOST_ROWS_LOWER: usize = 4;
/// Issue 18's indoor target (%).
const TARGET: f64 = 85.0;

/// One family, sensor and preset on a round's seeds: each method's figure
/// on each seed (the randomised ones the mean over clustering seeds 0-9).
#[derive(Serialize, Deserialize, Clone)]
struct Row {
    family: String,
    sensor: String,
    preset: String,
    rooms: bool,
    stride: Vec<f64>,
    best_of_10: Vec<f64>,
    spectral: Vec<f64>,
    /// The lowest spectral clustering of any clustering seed on each set.
    spectral_lowest: Vec<f64>,
    nearest: Vec<f64>,
}

#[derive(Serialize, Deserialize)]
struct Report {
    seeds: Vec<u64>,
    seconds: f64,
    rows: Vec<Row>,
}

impl Row {
    /// The row's table cells: names, then each method's mean over the seeds.
    fn cells(&self) -> Vec<String> {
        let lowest = (self.spectral_lowest.iter().copied()).fold(f64::INFINITY, f64::min);
        let figures = [&self.stride, &self.best_of_10, &self.spectral];
        (([&self.family, &self.sensor].map(|s| s.to_string())).into_iter())
            .chain([format!("`{}`", self.preset)])
            .chain(figures.map(|v| pct(mean(v))))
            .chain([pct(lowest), pct(mean(&self.nearest))])
            .collect()
    }
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

fn presets_of(f: &Family) -> &'static [&'static str] {
    match f.name {
        "warehouse" => WAREHOUSE_PRESETS,
        "outdoor" => OUTDOOR_PRESETS,
        _ => ROOM_PRESETS,
    }
}

fn run(seeds: &[u64]) -> Res<Report> {
    let t0 = std::time::Instant::now();
    let mut rows = vec![];
    for f in families().into_iter().chain([hospital_family()]) {
        let sensors = std::iter::once(Sensor::Own).chain(f.sensors.iter().copied());
        for sensor in sensors.collect::<Vec<_>>() {
            let presets: Vec<String> = presets_of(&f).iter().map(|p| p.to_string()).collect();
            let mut out: Vec<Row> = (presets.iter())
                .map(|p| Row {
                    family: f.name.into(),
                    sensor: sensor.name(),
                    preset: p.clone(),
                    rooms: f.scans_per_room > 1,
                    stride: vec![],
                    best_of_10: vec![],
                    spectral: vec![],
                    spectral_lowest: vec![],
                    nearest: vec![],
                })
                .collect();
            for &seed in seeds {
                let set = describe_set(&f, sensor, seed, &presets)?;
                for (name, params, descriptors) in &set.presets {
                    let row = (out.iter_mut())
                        .find(|r| &r.preset == name)
                        .ok_or("a preset described that was not asked for")?;
                    let space = Space::new(descriptors, DistanceOptions::from(params))?;
                    let k = set.kinds;
                    let stride =
                        KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?;
                    let best = best_of_10(&space, &set.truth, k)?;
                    let matrix = space.matrix();
                    let spectral = spectral_over_seeds(&matrix, &set.truth, k)?;
                    row.stride.push(once(&set.truth, &stride.labels)?.accuracy);
                    row.best_of_10.push(best.accuracy);
                    row.spectral.push(spectral.accuracy);
                    row.spectral_lowest.push(spectral.lowest);
                    row.nearest
                        .push(room_level_nn(&matrix, &set.truth, &set.apart));
                }
            }
            for r in &out {
                eprintln!(
                    "{} ({:.0} s)",
                    r.cells().join(" | "),
                    t0.elapsed().as_secs_f64()
                );
            }
            rows.extend(out.into_iter().filter(|r| !r.stride.is_empty()));
        }
    }
    Ok(Report {
        seeds: seeds.to_vec(),
        seconds: t0.elapsed().as_secs_f64(),
        rows,
    })
}

/// A run of seeds as the reports name it: "481-485".
fn span(seeds: &[u64]) -> String {
    format!("{}-{}", seeds[0], seeds[seeds.len() - 1])
}

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs")
}

fn write(name: &str, text: &str) -> Res<()> {
    let path = docs().join(name);
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    eprintln!("wrote docs/{name}");
    Ok(())
}

/// The rule of the round, computed on a report's room rows of [`PRESET`].
struct Rule {
    rows: usize,
    spectral: f64,
    best_of_10: f64,
    lower: usize,
}

impl Rule {
    fn of(r: &Report) -> Rule {
        let rows: Vec<&Row> = (r.rows.iter())
            .filter(|x| x.rooms && x.preset == PRESET)
            .collect();
        let n = rows.len() as f64;
        Rule {
            rows: rows.len(),
            spectral: rows.iter().map(|x| mean(&x.spectral)).sum::<f64>() / n,
            best_of_10: rows.iter().map(|x| mean(&x.best_of_10)).sum::<f64>() / n,
            lower: (rows.iter())
                .filter(|x| mean(&x.spectral) < mean(&x.best_of_10))
                .count(),
        }
    }
    fn recommends(&self) -> bool {
        self.spectral > self.best_of_10 && self.lower <= MOST_ROWS_LOWER
    }
    /// The report's line on the rule: `scope`, what it was computed on;
    /// `yes` and `no`, the verdicts.
    fn computed(&self, scope: &str, yes: &str, no: &str) -> String {
        format!(
            "**The rule, computed** ({scope}, `{PRESET}`, {} room rows): spectral clustering averages {:.1} % against k-means++ best of 10's {:.1} %, and is lower in {} rows: {}.\n",
            self.rows,
            100.0 * self.spectral,
            100.0 * self.best_of_10,
            self.lower,
            if self.recommends() { yes } else { no }
        )
    }
}

/// Two reports' rows as one: each row's seeds of both, in order.
fn pooled(a: &Report, b: &Report) -> Res<Report> {
    let mut rows = a.rows.clone();
    for (x, y) in rows.iter_mut().zip(&b.rows) {
        if (&x.family, &x.sensor, &x.preset) != (&y.family, &y.sensor, &y.preset) {
            return Err(format!("rows differ: {} {} {}", y.family, y.sensor, y.preset).into());
        }
        x.stride.extend(&y.stride);
        x.best_of_10.extend(&y.best_of_10);
        x.spectral.extend(&y.spectral);
        x.spectral_lowest.extend(&y.spectral_lowest);
        x.nearest.extend(&y.nearest);
    }
    Ok(Report {
        seeds: a.seeds.iter().chain(&b.seeds).copied().collect(),
        seconds: a.seconds + b.seconds,
        rows,
    })
}

/// Room rows (of `preset`) where a method's mean reaches the target.
fn rows_at_target(r: &Report, preset: &str, met: impl Fn(&Row) -> bool) -> usize {
    (r.rows.iter())
        .filter(|x| x.rooms && x.preset == preset && met(x))
        .count()
}

fn table(o: &mut String, r: &Report) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | spectral | lowest spectral | room-level 1-NN |")?;
    writeln!(o, "|---|---|---|---|---|---|---|---|")?;
    for x in &r.rows {
        writeln!(o, "| {} |", x.cells().join(" | "))?;
    }
    Ok(())
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 481-485, commit a1b8428's code; the method, the presets and the rule were fixed beforehand in seeds.md, commit 7ac8360, 14:51). Differences are computed from the JSON, spectral clustering minus k-means++ best of 10, each the mean over clustering seeds 0-9; the median standard error of a room row's five-seed mean difference is 2.9 points with `indoor_objects`.

- **On room kinds, spectral clustering groups the scans better than k-means on average with every preset of the round.** With `indoor_objects` it is above best of 10 in all 14 room rows (by +0.2 to +11.7 points, several of them within a standard error; mean 91.2 against 86.1 %) and above stride k-means in 11 (88.7 % on average). With `indoor_searched` 89.9 against 85.6 % (lower in 1 row, the hospital with 16 beams, 64.4 against 65.3 %); with the paper's `indoor` 74.0 against 70.9 % (lower in 2 rows, by a point or less). With `indoor_objects` its mean is that of room-level 1-NN (91.3 %). The development seeds had shown the same (92.0 against 87.5 %, higher in 14 of 14 rows).
- **The rows that missed with k-means** (`indoor_objects`, both k-means at least 85 % in 8 rows; spectral against best of 10): the school with 16 beams 90.2 against 84.5 %, 32 beams 88.0 against 80.5 %, 64 beams 92.9 against 81.2 % (there room-level 1-NN is 9 to 13 points above best of 10: the scans' neighbours were of their kind, the grouping lost them); the office floor at 0.3 m 87.0 against 84.98 % (shown as 85.0); the hospital 83.1 against 75.5 % and with 16 beams 67.2 against 64.2 %. The hospital rows stay short with every preset and method; there room-level 1-NN itself is 76.9 % and 71.6 %, so their loss is in the descriptors as much as in the grouping.
- **At least 85 % in a room row** (means over the five seeds): with spectral clustering 12 of 14 rows with `indoor_objects` or `indoor_searched` (all but the two hospital rows), 4 with `indoor`; with both k-means (issue 18's target as written) 8, 7 and 3. Issue 18's target names k-means, so the spectral rows do not meet it as written.
- **Not for routes.** Along the warehouse and outdoor routes it is lower than best of 10 in 5 of the 8 rows, by much in two: the warehouse with `indoor_plus` 66.0 against 84.2 % (own sensor; the halls' target is read on the tree, which was 97.8 % on 471-475), outdoors with the paper's `outdoor` 80.4 against 95.2 % (two of the five sets at 58 and 54 % with every clustering seed); `outdoor_near` 97.2 against 97.8 %. It is higher in 3 (the warehouse with 32 beams and `indoor_plus` 72.5 against 67.9 %, outdoors with 16 beams 83.7 against 83.2 % and with `outdoor_near` 94.4 against 93.6 %). A likely cause, not examined: consecutive scans of a route are each other's nearest neighbours, so neighbourhoods chain one stretch to the next. (Added after a later development look, docs/spectral-routes-dev.md: that guess does not fit the development routes; where spectral clustering fell furthest there, the warehouse with `indoor_plus`, it left the airlock, a tenth of the scans, in with a hall and split a hall instead.) So the docs recommend it for sets of room scans only, with the presets made for them.
- **No preset, weight or descriptor changed**, and the defaults stay the paper's: spectral clustering is an option (`placecat cluster --method spectral`, `DescriptorSet.spectral`, `Collection.spectral`).";

fn render(dev: &Report, test: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Spectral clustering beside k-means (issue 18, eighteenth round)\n"
    )?;
    writeln!(o, "**Method.** Spectral clustering of each preset's distance (`placecat cluster --method spectral`; `cluster::spectral`): Ng, Jordan and Weiss (NIPS 2001) with the local scale of Zelnik-Manor and Perona (NIPS 2004), the affinity exp(-D(i,j)² / (s_i s_j)) over every pair with s_i the distance of scan i to its 7th nearest other scan, the k leading eigenvectors of the degree-normalised affinity with each scan's row scaled to unit length, then Euclidean k-means with k-means++ seeding, the cheapest of 10 runs. Nothing in it was tuned; no descriptor, weight or preset changes. The rule, fixed in docs/seeds.md before any run: spectral clustering is an option whatever the figures (the defaults stay the paper's); the docs recommend it for room kinds if on the test seeds, with `{PRESET}`, its mean over the 14 room rows is above k-means++ best of 10's and it is lower than best of 10 in at most {MOST_ROWS_LOWER} of them. Issue 18's indoor target names k-means, so rows that reach 85 % with spectral clustering only are reported as such, not as meeting the target.\n")?;
    let rule = Rule::of(test).computed(
        "test seeds",
        "the docs recommend it for room kinds",
        "it stays an option the docs do not recommend",
    );
    writeln!(o, "{rule}")?;
    at_target_lines(&mut o, test)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example spectral_round -- --dev` (`spectral-dev.json`, {:.0} s) then `cargo run --release --example spectral_round` (test seeds, this file and `spectral.json`, {:.0} s; it refuses to run again once `spectral.json` exists; `-- --render` renders this file from them). Families: issue 18's (examples/common/families.rs, every sensor) and the hospital floors, 45 scans a room set (5 kinds, rooms of 3 scans), 100 a route; k the true number of kinds. Stride k-means runs once; k-means++ best of 10 and spectral clustering with clustering seeds 0-9 (mean; lowest: any single clustering on any set). Room-level 1-NN: no neighbour from the scan's own room (routes: none within 25 of 300 scans).\n", dev.seconds, test.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(o, "## 1. Test seeds {}\n", span(TEST_SEEDS))?;
    table(&mut o, test)?;
    writeln!(
        o,
        "\n## 2. Development seeds 1-6 (looked at before the test run)\n"
    )?;
    let dev_rule = Rule::of(dev);
    writeln!(
        o,
        "On these seeds, `{PRESET}` over the {} room rows: spectral {:.1} % against best of 10's {:.1} %, lower in {} rows.\n",
        dev_rule.rows,
        100.0 * dev_rule.spectral,
        100.0 * dev_rule.best_of_10,
        dev_rule.lower
    )?;
    table(&mut o, dev)?;
    Ok(o)
}

/// What the second sample showed, written after its one test run.
const NOTES_2: &str = "Written after the one test run (seeds 491-495, commit 5967190's code, the eighteenth round's but for this report; the rule was fixed beforehand in seeds.md, commit f8928c4 at 15:49). Differences are spectral clustering minus k-means++ best of 10 (means over clustering seeds 0-9) unless said; the median standard error of a room row's five-seed difference is 2.4 points with `indoor_objects`.

- **The recommendation holds.** With `indoor_objects` spectral clustering is again above best of 10 in all 14 room rows (+0.6 to +13.5 points), 91.3 against 86.3 % over them; pooled with 481-485, 91.2 against 86.2 %, above in all 14. With `indoor_searched` 90.7 against 85.7 % (pooled 90.3 against 85.7 %, above in all 14).
- **Which gains repeated.** The school with 32 and 64 beams (+11.3 and +13.5 after +7.4 and +11.7) and the varied plans (+9.9 after +9.8) again; the hospital with its own sensor did not (+0.6 after +7.6), nor the school at 0.3 m (+2.0 after +7.6); the hospital with 16 beams rose more (+8.7 after +3.0).
- **Against stride k-means** spectral clustering is above in 12 of 14 room rows with `indoor_objects`; lower on the office floor (81.5 against 84.9 %) and the varied plans (90.2 against 90.7 %). Pooled: 91.2 against 88.4 %, lower in 2 other rows (the many buildings with the own sensor, 94.9 against 95.3 %; the hospital with 16 beams, 73.2 against 74.0 %).
- **At least 85 % in a room row.** On these seeds with `indoor_objects`: 11 rows with spectral clustering (missed: the office floor with its own sensor, 81.5 %, as k-means missed it, 84.9 / 80.2 %; the hospital 83.6 %; the hospital with 16 beams 79.2 %), 7 with both k-means. Pooled (ten seeds a row): 12 against 8, the two hospital rows missed (83.4 and 73.2 %). The office floor with its own sensor is the weakest of the others: 90.5 % on 481-485, 81.5 % here, 86.0 % pooled.
- **With the paper's `indoor`** spectral clustering is above best of 10 on average (73.5 against 71.8 %; pooled 73.7 against 71.4 %) and about level with stride k-means: below it here (74.5 %, lower in 11 of 14 rows), above it on 481-485 (72.1 %) and pooled (73.3 %, lower in 5). The gain is on the presets made for rooms.
- **Routes: lower than best of 10 in 7 of 8 rows here** (all four warehouse rows; with `indoor_plus` 68.2 against 95.8 % with the own sensor; outdoors with the paper's `outdoor` 79.4 against 95.4 %, two sets at 55 and 54 % again), higher in 1 (`outdoor_near` with 16 beams, 97.4 against 95.4 %). The advice stands: not along a route.";

/// One line per preset: the room rows at 85 % with both k-means and with
/// spectral clustering.
fn at_target_lines(o: &mut String, r: &Report) -> Res<()> {
    for preset in ROOM_PRESETS {
        let k = rows_at_target(r, preset, |x| {
            mean(&x.stride) >= TARGET / 100.0 && mean(&x.best_of_10) >= TARGET / 100.0
        });
        let s = rows_at_target(r, preset, |x| mean(&x.spectral) >= TARGET / 100.0);
        writeln!(o, "- `{preset}`: at least 85 % with both k-means in {k} room rows; with spectral clustering in {s}.")?;
    }
    Ok(())
}

fn render_second(first: &Report, second: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Spectral clustering on a second fresh sample (issue 18, nineteenth round)\n"
    )?;
    writeln!(o, "**No change.** The eighteenth round's families, sensors, presets and methods (docs/spectral.md), on fresh test seeds {}. The rule, fixed in docs/seeds.md before any run: pooled over 481-485 and these seeds (ten seeds a row), the docs keep recommending spectral clustering for sets of room scans if, with `{PRESET}`, its mean over the 14 room rows is above k-means++ best of 10's and it is lower than best of 10 in at most {MOST_ROWS_LOWER} of them; otherwise the recommendation is withdrawn.\n", span(SECOND_SEEDS))?;
    let both = pooled(first, second)?;
    let rule = Rule::of(&both).computed(
        "pooled, ten seeds a row",
        "the recommendation stays",
        "the recommendation is withdrawn",
    );
    writeln!(o, "{rule}")?;
    let alone = Rule::of(second);
    writeln!(
        o,
        "On {} alone: spectral {:.1} % against best of 10's {:.1} %, lower in {} rows.\n",
        span(SECOND_SEEDS),
        100.0 * alone.spectral,
        100.0 * alone.best_of_10,
        alone.lower
    )?;
    writeln!(o, "On these seeds:\n")?;
    at_target_lines(&mut o, second)?;
    writeln!(o, "\nPooled (ten seeds a row):\n")?;
    at_target_lines(&mut o, &both)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example spectral_round -- --second` (test seeds, this file and `spectral-2.json`, {:.0} s; it refuses to run again once `spectral-2.json` exists; `-- --second --render` renders this file from it and docs/spectral.json). The development figures are the eighteenth round's (docs/spectral.md). Methods and columns as there.\n", second.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES_2}\n")?;
    writeln!(o, "## 1. Test seeds {}\n", span(SECOND_SEEDS))?;
    table(&mut o, second)?;
    writeln!(
        o,
        "\n## 2. Pooled over 481-485 and {} (ten seeds a row)\n",
        span(SECOND_SEEDS)
    )?;
    table(&mut o, &both)?;
    Ok(o)
}

/// A round's test seeds, checked against docs/seeds.md and run once: an
/// error if docs/`json` exists (`render` says how to render it instead).
fn run_test_once(test: &[u64], json: &str, render: &str) -> Res<()> {
    seeds::check_round_seeds(DEV_SEEDS, test)?;
    if docs().join(json).exists() {
        return Err(format!(
            "docs/{json} exists: the test seeds were run once already (use {render})"
        )
        .into());
    }
    write(json, &serde_json::to_string_pretty(&run(test)?)?)
}

/// The nineteenth round: the second sample, once, then its report.
fn second_sample(args: &[String]) -> Res<()> {
    let (first_json, second_json) = (docs().join("spectral.json"), docs().join("spectral-2.json"));
    if !args.iter().any(|a| a == "--render") {
        run_test_once(SECOND_SEEDS, "spectral-2.json", "--second --render")?;
    }
    let first: Report = read_json(&first_json)?;
    let second: Report = read_json(&second_json)?;
    write("spectral-2.md", &render_second(&first, &second)?)
}

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--second") {
        return second_sample(&args);
    }
    let (dev_json, test_json) = (
        docs().join("spectral-dev.json"),
        docs().join("spectral.json"),
    );
    if args.iter().any(|a| a == "--dev") {
        seeds::check_round_seeds(DEV_SEEDS, &[])?;
        let r = run(DEV_SEEDS)?;
        return write("spectral-dev.json", &serde_json::to_string_pretty(&r)?);
    }
    if !args.iter().any(|a| a == "--render") {
        if !dev_json.exists() {
            return Err("run the development seeds first (--dev)".into());
        }
        run_test_once(TEST_SEEDS, "spectral.json", "--render")?;
    }
    let dev: Report = read_json(&dev_json)?;
    let test: Report = read_json(&test_json)?;
    write("spectral.md", &render(&dev, &test)?)
}
