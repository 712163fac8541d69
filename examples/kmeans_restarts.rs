//! Issue 18, fourth round: k-means++ restarted 10 times, keeping the run of
//! lowest cost, on the presets the earlier rounds chose. A clustering
//! option, not a descriptor change: the descriptors are those of round 3.
//!
//!     cargo run --release --example kmeans_restarts -- --dev   # dev seeds 1-6 -> docs/descriptors-dev-4.json
//!     cargo run --release --example kmeans_restarts            # test seeds 331-335, once: docs/descriptors-4.{json,md}
//!     ... -- --render   # docs/descriptors-4.md again from docs/descriptors-4.json
//!
//! Seeds and N = 10 were fixed in docs/seeds.md before any run. For each
//! family x sensor of rounds 1-3 (examples/common/families.rs) x preset
//! (the family's paper preset and every new preset rounds 2 and 3 chose
//! for it, read from docs/descriptors-2.json and -3.json) x seed, at the
//! true number of kinds: stride k-means and hierarchical k-means++ (mean of
//! clustering seeds 0-9) as in rounds 1-3, k-means++ as one run and as the
//! best of 10 restarts, each over clustering seeds 0-9 (mean and lowest).
//! The test run refuses to overwrite its report: the test seeds run once.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::*;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::path::Path;

#[path = "common/families.rs"]
mod families;
use families::*;
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;

/// Fixed in docs/seeds.md ("issue 18, fourth round") before any run.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];
const TEST_SEEDS: &[u64] = &[331, 332, 333, 334, 335];
/// k-means runs a clustering keeps the cheapest of (scikit-learn's n_init).
const RESTARTS: usize = 10;
const DEV_FILE: &str = "descriptors-dev-4.json";
const REPORT_FILE: &str = "descriptors-4.json";
const MD_FILE: &str = "descriptors-4.md";

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
struct Figures {
    stride: Method,
    hk: Method,
    /// k-means++, one run per clustering seed (the default before restarts).
    plusplus: Method,
    /// k-means++, best of RESTARTS runs per clustering seed.
    best_of_10: Method,
}

#[derive(Serialize, Deserialize, Clone)]
struct SetResult {
    family: String,
    sensor: String,
    seed: u64,
    scans: usize,
    /// (preset, figures); a preset that cannot describe every scan (the
    /// `outdoor` preset indoors) is left out.
    presets: Vec<(String, Figures)>,
}

#[derive(Serialize, Deserialize)]
struct Report {
    /// Per family: the presets run, the paper's first.
    presets: Vec<(String, Vec<String>)>,
    dev: Vec<SetResult>,
    test: Vec<SetResult>,
    dev_seconds: f64,
    test_seconds: f64,
}

fn measure(ds: &[Descriptor], p: &DescriptorParams, truth: &[String], k: usize) -> Res<Figures> {
    let space = Space::new(ds, DistanceOptions::from(p))?;
    let m = space.matrix();
    let stride = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels;
    let kmeans = |restarts: usize| {
        over_seeds(truth, |s| {
            let params = KMeansParams::new(k).seed(s).restarts(restarts);
            Ok(KMeans::fit(&space, &params)?.labels)
        })
    };
    Ok(Figures {
        stride: once(truth, &stride)?,
        hk: over_seeds(truth, |s| {
            let tree = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(s))?;
            Ok(tree.cut_k(k)?.labels)
        })?,
        plusplus: kmeans(1)?,
        best_of_10: kmeans(RESTARTS)?,
    })
}

fn run_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<SetResult> {
    let set = describe_set(f, sensor, seed, presets)?;
    let mut out = vec![];
    for (name, p, ds) in &set.presets {
        out.push((name.clone(), measure(ds, p, &set.truth, set.kinds)?));
    }
    Ok(SetResult {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: set.scans,
        presets: out,
    })
}

fn run(presets: &[(String, Vec<String>)], seeds: &[u64], what: &str) -> Res<(Vec<SetResult>, f64)> {
    every_set(presets, seeds, what, run_set)
}

/// A figure of `preset` in a set, if it described the set.
fn of(s: &SetResult, preset: &str, f: &impl Fn(&Figures) -> f64) -> Option<f64> {
    s.presets.iter().find(|p| p.0 == preset).map(|p| f(&p.1))
}

/// Mean over `sets` of a figure of `preset`; NaN unless it described them all.
fn mean(sets: &[&SetResult], preset: &str, f: impl Fn(&Figures) -> f64) -> f64 {
    mean_over(sets, |s| of(s, preset, &f))
}

/// The lowest accuracy over `sets` of any clustering seed's run.
fn lowest(sets: &[&SetResult], preset: &str, f: impl Fn(&Figures) -> f64) -> f64 {
    lowest_over(sets, |s| of(s, preset, &f))
}

fn table(
    o: &mut String,
    r: &Report,
    all: &[SetResult],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | hk-means++ | k-means++ (1 run) | k-means++ best of 10: mean | lowest | ARI | target |\n|---|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &SetResult) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        &r.presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} | {} | {:.3} | {} |",
                pct(mean(sets, p, |f| f.stride.accuracy)),
                pct(mean(sets, p, |f| f.hk.accuracy)),
                pct(mean(sets, p, |f| f.plusplus.accuracy)),
                pct(mean(sets, p, |f| f.best_of_10.accuracy)),
                pct(lowest(sets, p, |f| f.best_of_10.lowest)),
                mean(sets, p, |f| f.best_of_10.ari),
                if i == 0 { "-" } else { target(family) },
            )?;
            Ok(())
        },
    )
}

/// What the round showed, written after its one test run (nothing was
/// changed or run again after it).
const NOTES: &str = "Written after the one test run of seeds 331-335 (commit dacaaf2's code; N = 10 and the seeds fixed beforehand). Targets read on the k-means++ best-of-10 mean, each family's own sensor unless said:

- **Indoor kinds, at least 85 %: met by four of the five families.** Rooms of one building `indoor_plus` 98.1 % (stride k-means 93.3, hk-means++ 85.0, one k-means++ run 88.1); of many buildings `indoor_clutter` 93.5 % (stride 93.3; 16 beams 89.6); of varied plans `indoor_clutter` 96.0 % (stride 91.1); the school `indoor_clutter` 87.8 % (stride 88.0). **The office floor misses it**: `indoor_clutter` 84.7 % (stride 84.9), and at 0.3 m 79.2 % (stride 86.7). The school's other sensors: 16 beams 82.9 % (missed), 32 beams 85.9, 64 beams 87.4, 0.3 m 85.8, 1.8 m 95.1 %.
- **Warehouse halls, at least 95 %: missed, and far from the development seeds.** `indoor_plus` gives 77.2 % (lowest 56 %) with the own sensor and 71.1 % with 32 beams, against 99.4 % and 84.4 % on dev seeds 1-6. Per test seed (section 4) the best of 10 finds the halls on seed 333 only (99 %); on 332 every clustering seed keeps the same 70 % grouping. There the cheapest of 10 runs is another grouping than the halls (whether the true grouping costs more than it was not measured: that would take another look at the test seeds); with the halls' preset the best of 10 is *worse* than a single k-means++ run (own sensor 77.2 against 79.3 %, 32 beams 71.1 against 81.3 %), the only two rows of 34 where restarts lowered the mean. hk-means++ stays the halls' method (94.3 % and 97.8 %). Stride k-means: 67.0 and 67.2 %.
- **Outdoor, not worse than the paper's preset: missed with the own sensor, met with 16 beams.** The paper's `outdoor` preset gives 95.6 % with best of 10 (stride 95.2); the new presets 94.0 % (`outdoor_plus`, round 3's choice) and 92.0 % (`indoor_clutter`, round 2's: one seed, 331, at 69 %). With 16 beams the new ones beat it: `indoor_clutter` 96.2 and `outdoor_plus` 94.5 % against 82.5 %.
- **Against one k-means++ run, the best of 10 raised the mean in 32 of 34 rows** (dev: 33 of 34), and it raised the lowest figure most: e.g. rooms of one building `indoor_plus` 88.1 -> 98.1 % mean, lowest 93.3 %. **Against stride k-means it is better in 19 rows and worse in 15**; the paper's `indoor` preset on rooms of one building loses (90.3 against 94.7 %). It is an option beside the paper's methods, not a replacement for them.
- **The paper's presets gain little**: `indoor` on the office floor 63.0 % and the school 74.4 %, as with stride k-means; the descriptor, not the clustering, limits them (issue 18's finding stands).
- Small sets: 45 scans a set indoors (one scan moves a figure by 2.2 points), 100 along a route; five test seeds. Rounds are not comparable figure by figure (the test seeds differ).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Place descriptors beyond the paper (issue 18), fourth round: k-means++ with restarts\n"
    )?;
    writeln!(o, "**A clustering option, not a descriptor change.** The descriptors and presets are those of round 3 ([descriptors-3.md](descriptors-3.md)); what is new is `KMeansParams::restarts` (`placecat cluster --method kmeans --seeding plusplus --restarts 10`, `kmeans(k, seeding, seed, restarts)` in wasm and npm, `restarts=` in Python): k-means++ run N times, each run from RNG stream r of the seed, keeping the run of lowest k-means cost (the sum over scans of the distance to their centre, which `KMeansResult.cost` reports), the earliest of equal costs; scikit-learn's `n_init`, and Arthur and Vassilvitskii (2007) recommend restarting k-means++. The default stays one run, the paper's.\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example kmeans_restarts -- --dev` (dev seeds, `{DEV_FILE}`, {:.0} s) then `cargo run --release --example kmeans_restarts` (test seeds, this file and `{REPORT_FILE}`, {:.0} s; it refuses to run again once `{REPORT_FILE}` exists; `-- --render` renders this file from it). Seeds and N = {RESTARTS} fixed in [seeds.md](seeds.md) (\"issue 18, fourth round\") before any run: development 1-6, test 331-335. Families, sensors, scan counts and presets as in round 3 (the paper's preset of each family and every new preset rounds 2 and 3 chose for it; no preset was chosen in this round). Every randomised method is run with clustering seeds 0-9: the tables give the mean over seeds and sets, and the lowest accuracy of any single clustering seed on any set. Stride k-means is deterministic (one run a set). Targets (issue 18) are read on the k-means++ best-of-10 mean.\n", r.dev_seconds, r.test_seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(
        o,
        "## 1. Test seeds 331-335, each family's own sensor (accuracy in %)\n"
    )?;
    table(&mut o, r, &r.test, |s| s == "own")?;
    writeln!(o, "\n## 2. Test seeds 331-335, the other sensors\n")?;
    table(&mut o, r, &r.test, |s| s != "own")?;
    writeln!(
        o,
        "\n## 3. Development seeds 1-6, every sensor (looked at before the test run)\n"
    )?;
    table(&mut o, r, &r.dev, |_| true)?;
    writeln!(o, "\n## 4. Every test-seed set: best of 10, mean / lowest over clustering seeds (stride k-means in brackets)\n\n| family | sensor | preset | {} |\n|---|---|---|{}", TEST_SEEDS.iter().map(u64::to_string).collect::<Vec<_>>().join(" | "), "---|".repeat(TEST_SEEDS.len()))?;
    for (family, presets) in &r.presets {
        let mut sensors: Vec<&str> = r
            .test
            .iter()
            .filter(|s| &s.family == family)
            .map(|s| s.sensor.as_str())
            .collect();
        sensors.dedup();
        for sensor in sensors {
            for p in presets {
                let cells: Vec<String> = TEST_SEEDS
                    .iter()
                    .map(|&seed| {
                        r.test
                            .iter()
                            .find(|s| &s.family == family && s.sensor == sensor && s.seed == seed)
                            .and_then(|s| s.presets.iter().find(|q| &q.0 == p))
                            .map_or("n/a".into(), |(_, f)| {
                                format!(
                                    "{} / {} ({})",
                                    pct(f.best_of_10.accuracy),
                                    pct(f.best_of_10.lowest),
                                    pct(f.stride.accuracy)
                                )
                            })
                    })
                    .collect();
                writeln!(o, "| {family} | {sensor} | `{p}` | {} |", cells.join(" | "))?;
            }
        }
    }
    Ok(o)
}

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let has = |a: &str| args.iter().any(|x| x == a);
    if has("--render") {
        let r: Report = read_json(&docs.join(REPORT_FILE))?;
        std::fs::write(docs.join(MD_FILE), render(&r)?)?;
        return Ok(());
    }
    let presets = presets_of(&docs)?;
    if has("--dev") {
        let (dev, seconds) = run(&presets, DEV_SEEDS, "dev")?;
        let r = Report {
            presets,
            dev,
            test: vec![],
            dev_seconds: seconds,
            test_seconds: 0.0,
        };
        std::fs::write(docs.join(DEV_FILE), serde_json::to_string_pretty(&r)?)?;
        let mut o = String::new();
        table(&mut o, &r, &r.dev, |_| true)?;
        println!("{o}");
        return Ok(());
    }
    if docs.join(REPORT_FILE).exists() {
        return Err(format!(
            "docs/{REPORT_FILE} exists: the test seeds run once (--render renders it again)"
        )
        .into());
    }
    let dev: Report =
        read_json(&docs.join(DEV_FILE)).map_err(|e| format!("{e} (run with --dev first)"))?;
    let (test, seconds) = run(&presets, TEST_SEEDS, "test")?;
    let r = Report {
        presets,
        dev: dev.dev,
        test,
        dev_seconds: dev.dev_seconds,
        test_seconds: seconds,
    };
    std::fs::write(docs.join(REPORT_FILE), serde_json::to_string_pretty(&r)?)?;
    std::fs::write(docs.join(MD_FILE), render(&r)?)?;
    eprintln!("wrote docs/{REPORT_FILE} and docs/{MD_FILE} ({seconds:.0} s)");
    Ok(())
}
