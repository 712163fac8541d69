//! Issue 18, eighth round: the `columns` part (what stands in each
//! direction, from the floor up) in the preset `indoor_columns`
//! (`indoor_clutter` plus columns at weight 5), against each family's
//! presets of the earlier rounds.
//!
//!     cargo run --release --example columns -- --dev   # dev seeds -> docs/columns-dev.json
//!     cargo run --release --example columns            # test seeds, once: docs/columns.{json,md}
//!     ... -- --render   # docs/columns.md again from docs/columns.json
//!
//! Seeds were fixed in docs/seeds.md ("issue 18, eighth round") before any
//! run: issue 18's families (examples/common/families.rs, every sensor) on
//! seeds 1-6 and 371-375, and on the test seeds only the hospital floors
//! (`--scene hospital`, written in this round by another hand, never
//! described before the test run). Each set at its true number of kinds:
//! stride k-means, k-means++ best of 10, hierarchical k-means++ with 10
//! trial splits (tree seeds 0-9: mean and lowest), and room-level 1-NN.
//! The test run refuses to overwrite its report.

use placecat::sim::SceneKind;
use std::fmt::Write;
use std::path::Path;

#[path = "common/families.rs"]
mod families;
use families::*;
#[path = "common/real.rs"]
mod real;
use real::{real_rows, real_table};
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
// This round has no site: the shared site code goes unused here.
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use site_rounds::*;
#[path = "common/family_sets.rs"]
mod family_sets;
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
use family_sets::*;

/// Fixed in docs/seeds.md ("issue 18, eighth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[371, 372, 373, 374, 375];
/// The round's preset, given to every family beside its own.
const NEW: &str = "indoor_columns";
/// The presets the fresh family is described with: the paper's, the
/// floors' preset of rounds 2-7, this round's.
const FRESH_PRESETS: [&str; 3] = ["indoor", "indoor_clutter", NEW];
const FILES: RoundFiles = RoundFiles {
    dev: "columns-dev.json",
    report: "columns.json",
    md: "columns.md",
};

/// Each family's presets of rounds 2-3, then this round's; the fresh
/// family's after them.
fn round_presets(docs: &Path) -> Res<Vec<(String, Vec<String>)>> {
    let mut presets = presets_of(docs)?;
    for (_, names) in &mut presets {
        if !names.iter().any(|n| n == NEW) {
            names.push(NEW.to_string());
        }
    }
    Ok(presets)
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let set = describe_set(f, sensor, seed, presets)?;
    measured_set(f, sensor, seed, &set)
}

/// The fresh family on the test seeds, each of its sensors.
fn fresh_sets() -> Res<Vec<FamilySet>> {
    let f = hospital_family();
    let presets: Vec<String> = FRESH_PRESETS.iter().map(|p| p.to_string()).collect();
    let mut sets = vec![];
    for sensor in std::iter::once(Sensor::Own).chain(f.sensors.iter().copied()) {
        for &seed in FAMILY_TEST {
            eprintln!("test {} {} seed {seed}", f.name, sensor.name());
            sets.push(family_set(&f, sensor, seed, &presets)?);
        }
    }
    Ok(sets)
}

/// Every set's stride k-means / best of 10 with the round's preset and the
/// family's best earlier one, one row per family, sensor and seed.
fn seed_table(o: &mut String, presets: &[(String, Vec<String>)], all: &[FamilySet]) -> Res<()> {
    writeln!(o, "| family | sensor | seed | `{NEW}`: stride / best of 10 / tree / 1-NN | the family's other presets, the same four |\n|---|---|---|---|---|")?;
    for s in all {
        let four = |p: &str| {
            entry(s, p).map_or("n/a".to_string(), |e| {
                format!(
                    "{} / {} / {} / {}",
                    pct(e.1.stride.accuracy),
                    pct(e.1.best_of_10.accuracy),
                    pct(e.1.hk_trials.accuracy),
                    pct(e.2)
                )
            })
        };
        let others: Vec<String> = presets
            .iter()
            .find(|p| p.0 == s.family)
            .map(|p| p.1.clone())
            .unwrap_or_else(|| FRESH_PRESETS.iter().map(|p| p.to_string()).collect())
            .iter()
            .filter(|p| *p != NEW)
            .map(|p| format!("`{p}` {}", four(p)))
            .collect();
        writeln!(
            o,
            "| {} | {} | {} | {} | {} |",
            s.family,
            s.sensor,
            s.seed,
            four(NEW),
            others.join("; ")
        )?;
    }
    Ok(())
}

/// The fresh family's presets, for the tables.
fn fresh_presets() -> Vec<(String, Vec<String>)> {
    vec![(
        hospital_family().name.to_string(),
        FRESH_PRESETS.iter().map(|p| p.to_string()).collect(),
    )]
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 371-375, commit fc306fb's code; the seeds, the part, the preset and how the targets are read were fixed beforehand in seeds.md). The other presets' rows are new samples of unchanged presets and methods.

- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10) is still missed, in 8 of 14 room rows: 6 of the 12 earlier ones, all on the office and school floors, and both of the hospital floors.** With `indoor_columns`, as decided, on the floors: the office floor 84.4 / 83.9 % (stride / best of 10; `indoor_clutter` 86.7 / 79.9 %), at 0.3 m 86.7 / 81.6 % (84.9 / 77.3 %); the school with its own sensor 86.7 / 88.2 % (met; `indoor_clutter` 83.6 / 84.7 %), at 1.8 m 88.0 / 86.4 % (met; 89.3 / 89.7 %), at 0.3 m 86.7 / 83.1 % (84.4 / 86.0 %), with 16 beams 77.3 / 82.8 % (78.7 / 81.4 %), 32 beams 80.9 / 82.4 % (82.2 / 83.9 %), 64 beams 78.2 / 84.8 % (83.6 / 83.2 %). The other room families with their earlier presets meet it: one building `indoor_plus` 94.7 / 96.1 %, many buildings `indoor_clutter` 95.1 / 90.9 % (16 beams 89.8 / 87.4 %), varied plans 92.0 / 90.0 %.
- **What the part did on the test seeds, against `indoor_clutter`** (the preset it extends) over the 8 floor rows: best of 10 higher in 5 (office +4.0, school +3.5 with their own sensors), lower in 3 (school with 32 beams -1.5, at 0.3 m -2.9, at 1.8 m -3.4); stride k-means higher in 3, lower in 5 (office own -2.2, school 64 beams -5.3). The tree of ten trials is higher in 5 of 8, and room-level 1-NN, which measures the descriptor without the clustering, higher or equal in 6 of 8 (office 89.8 against 88.9 %, school 32 beams 92.9 against 88.0 %). The development seeds promised more (office floor stride +6.3 points); on the test seeds the gain is in the k-means++ runs and the neighbours, not in the deterministic stride seeding.
- **The fresh family, the hospital floors (described for the first time in this run): missed, well above the paper's.** Own sensor: `indoor_columns` 77.8 / 79.5 % (room-level 1-NN 84.0 %), `indoor_clutter` 76.9 / 73.8 % (79.1 %), the paper's `indoor` 55.6 / 55.2 % (49.3 %); 16 beams 73.8 / 64.4 % against 66.2 / 62.0 % and 51.1 / 53.0 %. The new part helped most on the family it was not built on, and the gap to 85 % there is the honest measure of how far these descriptors generalise.
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.8 % (own sensor, lowest tree 97.0 %) and 98.4 % (32 beams, lowest 97.0 %). `indoor_columns` is no warehouse preset (64.8 %).
- **Outdoor: no new verdict.** This round's families ran each family's presets of rounds 2-3 and `indoor_columns`, not the seventh round's `outdoor_near`, so the outdoor target rests on the seventh round (361-365, met with both sensors). Here the paper's `outdoor` gives 96.2 / 96.0 % with its own sensor and 86.0 / 87.3 % with 16 beams; `outdoor_plus` 95.6 / 96.0 % (below the paper's with both k-means: best of 10 95.98 against 96.02 % before rounding) and 95.6 / 95.6 %; `indoor_columns` is no outdoor preset (the tree 63.1 %).
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans, `indoor_columns` among them.
- **Cost:** the part reads every point once more (no voxel sample); its describe time is in docs/parts.md (\"Eighth round\": 2.7 times the NDT histogram on a real room scan, 1.1 times on a simulated outdoor scan).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# What stands in each direction: the columns part (issue 18, eighth round)\n"
    )?;
    writeln!(o, "**A new part and a preset.** The `columns` part (src/descriptor/columns.rs) takes, in each of 180 azimuth sectors, what stands inside the room (as the `clutter` part finds it: nearer than the sector's wall, above the floor, below the ceiling) and counts over the sectors the highest point's height above the floor, how many of 8 layers of 0.25 m it fills and the lowest layer it fills, and the share of sectors that hold anything. `indoor_columns` is `indoor_clutter` with it at weight 5. The hypothesis, written in docs/seeds.md before any run: the kinds k-means confused on the office floor's development seeds, a private office and a restroom of one size, hold about as much at each height, but a desk top stands alone at 0.75 m where stall partitions reach 2 m across a side.\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example columns -- --dev` (`{}`, {:.0} s) then `cargo run --release --example columns` (test seeds, this file and `{}`, {:.0} s; it refuses to run again once `{}` exists; `-- --render` renders this file from it). Families: issue 18's, with the sensors and scan counts of rounds 4-7, the presets of rounds 2-3 and `{NEW}` for each, development seeds 1-6, test seeds 371-375; and on the test seeds only the hospital ward floors (`--scene hospital`: corridor, patient room, nurse station, treatment room, day room), written in this round by a helper told to run no descriptor on them, never described before the test run. Every method but stride k-means runs with clustering seeds 0-9 (mean; lowest tree: any single tree on any set). Room-level 1-NN: no neighbour from the scan's own room (routes: none within 25 of 300 scans).\n", FILES.dev, r.dev.seconds, FILES.report, r.test.seconds, FILES.report)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(
        o,
        "## 1. Families, test seeds 371-375, each family's own sensor\n"
    )?;
    family_table(&mut o, &r.presets, &r.test.families, |s| s == "own")?;
    writeln!(
        o,
        "\n## 2. Families, test seeds 371-375, the other sensors\n"
    )?;
    family_table(&mut o, &r.presets, &r.test.families, |s| s != "own")?;
    writeln!(
        o,
        "\n## 3. The fresh family (hospital floors), test seeds 371-375, first description\n"
    )?;
    family_table(&mut o, &fresh_presets(), &r.test.families, |_| true)?;
    writeln!(
        o,
        "\n## 4. Real scans: same-place retrieval (every preset of the round)\n"
    )?;
    real_table(&mut o, &r.real)?;
    writeln!(o, "\n## 5. Every test set of the room families\n")?;
    let rooms: Vec<FamilySet> = r
        .test
        .families
        .iter()
        .filter(|s| target(&s.family) == target("rooms"))
        .cloned()
        .collect();
    seed_table(&mut o, &r.presets, &rooms)?;
    writeln!(
        o,
        "\n## 6. Families, development seeds 1-6, every sensor (looked at before the test run)\n"
    )?;
    family_table(&mut o, &r.presets, &r.dev.families, |_| true)?;
    Ok(o)
}

fn main() -> Res<()> {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = round_presets(&docs)?;
    let no_sites: [SceneKind; 0] = [];
    let no_site = |_: SceneKind, _: u64| -> Res<()> { Ok(()) };
    round_main(
        &FILES,
        || {
            Ok(Report {
                presets: presets.clone(),
                dev: run_on(
                    &no_sites,
                    &presets,
                    FAMILY_DEV,
                    &[],
                    "dev",
                    no_site,
                    family_set,
                )?,
                test: FamilyPart::default(),
                real: vec![],
            })
        },
        |r| {
            let mut o = String::new();
            family_table(&mut o, &r.presets, &r.dev.families, |_| true)?;
            Ok(o)
        },
        |dev| {
            let mut test = run_on(
                &no_sites,
                &presets,
                FAMILY_TEST,
                &[],
                "test",
                no_site,
                family_set,
            )?;
            let t0 = std::time::Instant::now();
            test.families.extend(fresh_sets()?);
            test.seconds += t0.elapsed().as_secs_f64();
            let mut all = presets.clone();
            all.extend(fresh_presets());
            Ok(Report {
                presets: presets.clone(),
                dev: dev.dev,
                test,
                real: real_rows(&all)?,
            })
        },
        render,
    )
}
