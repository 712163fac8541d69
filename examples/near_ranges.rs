//! Issues 14 and 18, seventh round: the outdoor descriptor's range
//! intervals from 2 m (`outdoor_near`: [2, 5) and [4, 8) in place of the
//! paper's [5, 8), with the Hellinger distance of the sixth round) against
//! the paper's `outdoor` and the sixth round's `outdoor_hellinger`.
//!
//!     cargo run --release --example near_ranges -- --dev   # dev seeds -> docs/near-ranges-dev.json
//!     cargo run --release --example near_ranges            # test seeds, once: docs/near-ranges.{json,md}
//!     ... -- --render   # docs/near-ranges.md again from docs/near-ranges.json
//!
//! Seeds were fixed in docs/seeds.md ("seventh round") before any run.
//! Issue 14's outdoor site (`placecat simulate --scene outdoor --seed S`,
//! 300 scans) on development seeds 1-10 and the seen test seeds 501-505,
//! 601-605 and 701-705, test seeds 801-805; issue 18's families
//! (examples/common/families.rs, every sensor, the presets of rounds 2-3
//! and the two outdoor presets) on seeds 1-6 and 361-365. Each set at its
//! true number of kinds: stride k-means, k-means++ best of 10 (round 4)
//! and hierarchical k-means++ with 10 trial splits (round 5, the page's
//! tree; tree seeds 0-9: mean and lowest). The site also gets the number of
//! categories the default rule chooses on each tree, as the page's first
//! cut does. The test run refuses to overwrite its report.

use placecat::sim::sites::OUTDOOR_KINDS;
use placecat::sim::SceneKind;
use placecat::*;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::path::Path;

#[path = "common/families.rs"]
mod families;
use families::*;
#[path = "common/real.rs"]
mod real;
use real::{real_rows, real_table, RealRow};
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
// This round has no warehouse site and one description per preset: the
// shared `site` and `run` (both sites, the paper's preset) go unused here.
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use site_rounds::*;
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
use preset_rounds::*;

/// Fixed in docs/seeds.md ("issue 18, seventh round", "issue 14, seventh
/// round") before any run; the seen test seeds of the site's earlier
/// rounds were added to its development seeds before the test run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[361, 362, 363, 364, 365];
const SITE_DEV: &[u64] = &[
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 501, 502, 503, 504, 505, 601, 602, 603, 604, 605, 701, 702, 703,
    704, 705,
];
const SITE_TEST: &[u64] = &[801, 802, 803, 804, 805];
/// The site's presets: the paper's, the sixth round's page preset, this
/// round's. The families get the last two beside their own.
const SITE_PRESETS: [&str; 3] = ["outdoor", "outdoor_hellinger", "outdoor_near"];
const DEV_FILE: &str = "near-ranges-dev.json";
const REPORT_FILE: &str = "near-ranges.json";
const FILES: RoundFiles = RoundFiles {
    dev: DEV_FILE,
    report: REPORT_FILE,
    md: MD_FILE,
};
const MD_FILE: &str = "near-ranges.md";

#[derive(Serialize, Deserialize, Clone)]
struct FamilySet {
    family: String,
    sensor: String,
    seed: u64,
    scans: usize,
    presets: Vec<(String, Figures)>,
}

/// A site seed: each preset's figures and the rule's choice on each tree.
#[derive(Serialize, Deserialize, Clone)]
struct SiteSet {
    site: String,
    seed: u64,
    scans: usize,
    presets: Vec<(String, Figures, Vec<Chosen>)>,
}

type Part = site_rounds::Part<FamilySet, SiteSet>;

#[derive(Serialize, Deserialize)]
struct Report {
    presets: Vec<(String, Vec<String>)>,
    dev: Part,
    test: Part,
    #[serde(default)]
    real: Vec<RealRow>,
}

/// Each family's presets of rounds 2-3, then the two outdoor presets.
fn round_presets(docs: &Path) -> Res<Vec<(String, Vec<String>)>> {
    let mut presets = presets_of(docs)?;
    for (_, names) in &mut presets {
        for extra in &SITE_PRESETS[1..] {
            if !names.iter().any(|n| n == extra) {
                names.push(extra.to_string());
            }
        }
    }
    Ok(presets)
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let set = describe_set(f, sensor, seed, presets)?;
    let mut out = vec![];
    for (name, p, ds) in &set.presets {
        out.push((name.clone(), measure(ds, p, &set.truth, set.kinds)?.0));
    }
    Ok(FamilySet {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: set.scans,
        presets: out,
    })
}

/// The outdoor site of `seed`, described with each of [`SITE_PRESETS`],
/// clustered into 3, and each tree's choice.
fn site_set(scene: SceneKind, seed: u64) -> Res<SiteSet> {
    assert_eq!(
        scene,
        SceneKind::Outdoor,
        "this round is the outdoor site's"
    );
    let params: Vec<DescriptorParams> = SITE_PRESETS
        .iter()
        .map(|p| DescriptorParams::preset(p))
        .collect::<placecat::Result<_>>()?;
    let (truth, described) = described_site(scene, seed, &params)?;
    let mut presets = vec![];
    for (p, ds) in params.iter().zip(&described) {
        let (figures, space, m, trees) = measure(ds, p, &truth, 3)?;
        let chosen = choices(&space, &m, &trees, &truth)?;
        presets.push((p.preset.clone(), figures, chosen));
    }
    Ok(SiteSet {
        site: "outdoor".into(),
        seed,
        scans: truth.len(),
        presets,
    })
}

fn figures_of<'a>(s: &'a FamilySet, p: &str) -> Option<&'a Figures> {
    s.presets.iter().find(|q| q.0 == p).map(|q| &q.1)
}

fn family_table(
    o: &mut String,
    r: &Report,
    all: &[FamilySet],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | hk-means++, 10 trials | lowest | ARI (hk-means++) | target |\n|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &FamilySet) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        &r.presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let of = |f: fn(&Figures) -> f64| move |s: &FamilySet| figures_of(s, p).map(f);
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} | {:.3} | {} |",
                pct(mean_over(sets, of(|f| f.stride.accuracy))),
                pct(mean_over(sets, of(|f| f.best_of_10.accuracy))),
                pct(mean_over(sets, of(|f| f.hk_trials.accuracy))),
                pct(lowest_over(sets, of(|f| f.hk_trials.lowest))),
                mean_over(sets, of(|f| f.hk_trials.ari)),
                if i == 0 { "-" } else { target(family) },
            )?;
            Ok(())
        },
    )
}

fn site_table(o: &mut String, sites: &[SiteSet]) -> Res<()> {
    let names = SITE_PRESETS.map(|p| format!("`{p}`")).join(" / ");
    writeln!(o, "| seed | stride k-means: {names} | k-means++ best of 10 | hk-means++, 10 trials: mean (lowest) | ARI of the tree | K chosen | accuracy at K chosen |\n|---|---|---|---|---|---|---|")?;
    let cells = |s: &SiteSet, f: &dyn Fn(&Figures, &[Chosen]) -> String| {
        s.presets
            .iter()
            .map(|(_, fig, c)| f(fig, c))
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let at = |c: &[Chosen]| c.iter().map(|c| c.accuracy).sum::<f64>() / c.len() as f64;
    for s in sites {
        writeln!(
            o,
            "| {} | {} | {} | {} | {} | {} | {} |",
            s.seed,
            cells(s, &|f, _| pct(f.stride.accuracy)),
            cells(s, &|f, _| pct(f.best_of_10.accuracy)),
            cells(s, &|f, _| format!(
                "{} ({})",
                pct(f.hk_trials.accuracy),
                pct(f.hk_trials.lowest)
            )),
            cells(s, &|f, _| format!("{:.3}", f.hk_trials.ari)),
            cells(s, &|_, c| ks(c)),
            cells(s, &|_, c| pct(at(c))),
        )?;
    }
    let v: Vec<&SiteSet> = sites.iter().collect();
    let mean = |f: fn(&Figures) -> f64| {
        (0..SITE_PRESETS.len())
            .map(|j| pct(mean_over(&v, |s| Some(f(&s.presets[j].1)))))
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let low = |f: fn(&Figures) -> f64| {
        (0..SITE_PRESETS.len())
            .map(|j| pct(lowest_over(&v, |s| Some(f(&s.presets[j].1)))))
            .collect::<Vec<_>>()
            .join(" / ")
    };
    writeln!(
        o,
        "| mean | {} | {} | {} | | | |",
        mean(|f| f.stride.accuracy),
        mean(|f| f.best_of_10.accuracy),
        mean(|f| f.hk_trials.accuracy),
    )?;
    writeln!(
        o,
        "| lowest seed | {} | {} | {} (lowest tree: {}) | | | |",
        low(|f| f.stride.accuracy),
        low(|f| f.best_of_10.lowest),
        low(|f| f.hk_trials.accuracy),
        low(|f| f.hk_trials.lowest),
    )?;
    Ok(())
}

/// What the round showed, written after its one test run (the decision
/// was not changed after it).
const NOTES: &str = "Written after the one test run (seeds 361-365 and 801-805, commit a05882f's code; the seeds, the preset and the page's decision were fixed beforehand in seeds.md). Only the range intervals change against the sixth round's `outdoor_hellinger`; the other presets' rows are new samples of unchanged presets and methods, not a new verdict on them.

- **The outdoor site (issue 14): 95 % on every seed, met with both methods.** With `outdoor_near` stride k-means gives 96.7 / 97.3 / 98.0 / 98.7 / 98.3 % on 801-805 (mean 97.8 %) and hierarchical k-means++ with ten trial splits 98.0 / 97.0 / 98.4 / 99.0 / 98.7 % (mean 98.2 %; its lowest single tree 96.7 %, on 802). On the same seeds `outdoor_hellinger` gives 95.3 / 94.0 / 96.7 / 97.7 / 97.0 % and 96.7 / 93.7 / 96.8 / 98.0 / 97.2 % (802 missed by both methods), the paper's `outdoor` 96.0 / 91.0 / 97.3 / 96.7 / 96.3 % and 96.3 / 91.0 / 98.3 / 97.7 / 97.0 % (802 missed by both). Against `outdoor_hellinger`, `outdoor_near` is higher on every seed with both methods; against the paper's `outdoor` on every seed with both (the closest: 803's tree, 98.4 against 98.3 %). The rule chose 3 categories on all 50 trees of each preset. With the 25 development seeds (among them 502, 603 and 703, the seeds that failed the earlier rounds), `outdoor_near` is at least 95 % on 30 of 30 seeds with stride k-means and with every tree. Checked once after the run through the CLI (`placecat describe --preset outdoor_near`, `placecat cluster --method hkmeans --categories 3 --seed T` for T = 0-9), the paper's own tree, one 2-means++ run a split, gives 97.2 / 96.6 / 98.4 / 98.6 / 98.5 % on 801-805 (lowest single tree 95.3 %, on 802), and stride k-means and the tree of ten trials on 802 give the CLI 97.3 and 97.0 %, as above.
- **Outdoor (issue 18), not worse than the paper's preset: met with both sensors.** On the outdoor family's test seeds, `outdoor_near` gives with the own sensor 97.0 % with k-means++ best of 10 against the paper's 96.6 % (stride 97.2 against 96.8 %, the tree 97.8 against 96.6 %), and with 16 beams 97.5 against 88.7 % (stride 97.4 against 86.4 %, the tree 97.6 against 86.8 %; its lowest tree 89 against 50 %). `outdoor_plus` and `indoor_clutter`, the earlier rounds' outdoor presets, are as good here with 16 beams (97.0-97.8 % with the three methods).
- **Indoors it is no preset**: on the 14 rows of room families and sensors it is below each family's own preset in 13 with each method (office floor 66.2 % with stride k-means against `indoor_clutter`'s 84.9 %) and above it in one with each (one building: best of 10 91.3 against `indoor_plus`'s 86.4 %, the tree 86.7 against 75.3 %; many buildings with 16 beams: stride 92.0 against `indoor_clutter`'s 88.0 %). The page suggests the outdoor presets only for scans with many far points.
- **Real scans:** every preset of the round, `outdoor_near` among them, finds a scan of the same place for 18 of 18 real scans.
- **The other targets of issue 18 get no new verdict** (their presets and methods did not change). As new samples on 361-365: the office floor's `indoor_clutter` 84.9 % with stride k-means and 85.8 % best of 10 (with the sensor at 0.3 m 84.0 and 80.6 %), the school's with 16 beams 85.8 and 83.0 %; every other room row at least 85 % with both; the warehouse halls' `indoor_plus` with the tree of ten trials 98.0 % (own sensor) and 99.2 % (32 beams).
- **The page** keeps suggesting `outdoor_hellinger` and keeps its outdoor demo on it, as decided before this run, because on the development seeds the rule's first cut chose 3 categories less often with `outdoor_near` (21 of 25 seeds against 24; on the demo's seed 1 it chose 4). On the test seeds it chose 3 on every tree with both; that is no ground to change the page now, as it would be a choice made on test seeds. `outdoor_near` is in the page's menu.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Range intervals from 2 m for the outdoor descriptor (issues 14 and 18, seventh round)\n"
    )?;
    writeln!(o, "**A preset, not a new descriptor.** `outdoor_near` is the sixth round's `outdoor_hellinger` (the paper's outdoor parameters, Tab. II, with the Hellinger distance between the normalised histograms) with the range intervals [2, 5) [4, 8) [7, 10) [9, 12) [11, 15) [14, 20) m in place of the paper's [5, 8) [7, 10) [9, 12) [11, 15) [14, 20): two near intervals where the paper's first one was. The reason, written in docs/seeds.md before any run: a scan is labelled with the place the vehicle stands in, most of the errors lay within 20 m of a change of place (docs/experiments.md, \"where the errors are\"), where the paper's 5-20 m disc holds both places, and what stands within 5 m of the vehicle (a path's trees, a road's verges, nothing on a field) is the place it is in.\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example near_ranges -- --dev` (`{DEV_FILE}`, {:.0} s) then `cargo run --release --example near_ranges` (test seeds, this file and `{REPORT_FILE}`, {:.0} s; it refuses to run again once `{REPORT_FILE}` exists; `-- --render` renders this file from it). Seeds were fixed in [seeds.md](seeds.md) (\"seventh round\") before any run. Site: issue 14's outdoor site as `placecat simulate --scene outdoor` makes it (300 scans), development seeds 1-10 and the seen test seeds 501-505, 601-605 and 701-705, test seeds 801-805. Families: issue 18's, with the sensors, scan counts and presets of rounds 4-6 and the two outdoor presets, development seeds 1-6, test seeds 361-365. Every method but stride k-means runs with clustering seeds 0-9 (mean over seeds and sets; lowest: any single seed on any set).\n", r.dev.seconds, r.test.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(
        o,
        "## 1. The outdoor site, test seeds 801-805 (accuracy in %, at 3 categories unless said; {})\n",
        SITE_PRESETS.map(|p| format!("`{p}`")).join(" / ")
    )?;
    site_table(&mut o, &r.test.sites)?;
    writeln!(
        o,
        "\n## 2. Families, test seeds 361-365, each family's own sensor\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s == "own")?;
    writeln!(
        o,
        "\n## 3. Families, test seeds 361-365, the other sensors\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s != "own")?;
    writeln!(
        o,
        "\n## 3b. Real scans: same-place retrieval (every preset of the round)\n"
    )?;
    real_table(&mut o, &r.real)?;
    writeln!(
        o,
        "\n## 4. The outdoor site, development seeds (looked at before the test run)\n"
    )?;
    site_table(&mut o, &r.dev.sites)?;
    writeln!(
        o,
        "\n## 5. Families, development seeds 1-6, every sensor (looked at before the test run)\n"
    )?;
    family_table(&mut o, r, &r.dev.families, |_| true)?;
    Ok(o)
}

fn main() -> Res<()> {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = round_presets(&docs)?;
    // The kinds the site is read against (a change of the simulator's
    // names would show here, not as a silent 0 %).
    assert_eq!(OUTDOOR_KINDS.len(), 3);
    let scenes = [SceneKind::Outdoor];
    round_main(
        &FILES,
        || {
            Ok(Report {
                presets: presets.clone(),
                dev: run_on(
                    &scenes, &presets, FAMILY_DEV, SITE_DEV, "dev", site_set, family_set,
                )?,
                test: Part::default(),
                real: vec![],
            })
        },
        |r| {
            let mut o = String::new();
            site_table(&mut o, &r.dev.sites)?;
            o.push('\n');
            family_table(&mut o, r, &r.dev.families, |_| true)?;
            Ok(o)
        },
        |dev| {
            Ok(Report {
                presets: presets.clone(),
                dev: dev.dev,
                test: run_on(
                    &scenes,
                    &presets,
                    FAMILY_TEST,
                    SITE_TEST,
                    "test",
                    site_set,
                    family_set,
                )?,
                real: real_rows(&presets)?,
            })
        },
        render,
    )
}
