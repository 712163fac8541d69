//! Issues 14 and 18, fifth round: hierarchical k-means++ whose every split
//! keeps the cheapest of 10 trial 2-means++ runs (`HkMeansParams::restarts`;
//! bisecting k-means with trial splits, Steinbach, Karypis and Kumar 2000),
//! against the paper's one run per split.
//!
//!     cargo run --release --example split_trials -- --dev   # dev seeds -> docs/split-trials-dev.json
//!     cargo run --release --example split_trials            # test seeds, once: docs/split-trials.{json,md}
//!     ... -- --render   # docs/split-trials.md again from docs/split-trials.json
//!
//! Seeds and N = 10 were fixed in docs/seeds.md ("fifth round") before any
//! run. Issue 18's families (examples/common/families.rs, every sensor and
//! the presets of round 4) on seeds 1-6 and 341-345; issue 14's sites
//! (`placecat simulate --scene outdoor|warehouse --seed S`, as
//! examples/sites.rs describes them) on seeds 1-10 and 601-605. Each set at
//! its true number of kinds: stride k-means, k-means++ best of 10 (round
//! 4's option), and hierarchical k-means++ with 1 and with 10 trials per
//! split (tree seeds 0-9: mean and lowest). The sites also get the number
//! of categories the default rule chooses for each tree, as the page's
//! first cut does. The test run refuses to overwrite its report.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::sim::sites::{OUTDOOR_KINDS, WAREHOUSE_KINDS};
use placecat::sim::SceneKind;
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
#[path = "common/site_rounds.rs"]
mod site_rounds;
use site_rounds::*;

/// Fixed in docs/seeds.md ("issue 18, fifth round", "issue 14, fifth
/// round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[341, 342, 343, 344, 345];
const SITE_DEV: &[u64] = &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10];
const SITE_TEST: &[u64] = &[601, 602, 603, 604, 605];
/// Trial splits per node, and k-means++ restarts (round 4's N).
const TRIALS: usize = 10;
const DEV_FILE: &str = "split-trials-dev.json";
const REPORT_FILE: &str = "split-trials.json";
const FILES: RoundFiles = RoundFiles {
    dev: DEV_FILE,
    report: REPORT_FILE,
    md: MD_FILE,
};
const MD_FILE: &str = "split-trials.md";

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
struct Figures {
    stride: Method,
    /// k-means++, best of 10 restarts (round 4).
    best_of_10: Method,
    /// Hierarchical k-means++, one 2-means++ run per split (the paper's).
    hk: Method,
    /// Hierarchical k-means++, the cheapest of 10 trials per split.
    hk_trials: Method,
}

#[derive(Serialize, Deserialize, Clone)]
struct FamilySet {
    family: String,
    sensor: String,
    seed: u64,
    scans: usize,
    presets: Vec<(String, Figures)>,
}

#[derive(Serialize, Deserialize, Clone)]
struct SiteSet {
    site: String,
    seed: u64,
    scans: usize,
    figures: Figures,
    /// Tree seeds 0-9: one trial per split, then ten.
    chosen: Vec<Chosen>,
    chosen_trials: Vec<Chosen>,
}

type Part = site_rounds::Part<FamilySet, SiteSet>;

#[derive(Serialize, Deserialize)]
struct Report {
    presets: Vec<(String, Vec<String>)>,
    dev: Part,
    test: Part,
}

/// `m`: the space's Delta matrix (the caller's, so it is computed once).
fn measure(
    space: &Space,
    m: &DistanceMatrix,
    truth: &[String],
    k: usize,
) -> Res<(Figures, [Trees; 2])> {
    let stride = KMeans::fit(space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels;
    let one = trees(space, m, 1)?;
    let ten = trees(space, m, TRIALS)?;
    let cut =
        |t: &[(HkMeansParams, Tree)]| over_seeds(truth, |s| Ok(t[s as usize].1.cut_k(k)?.labels));
    let figures = Figures {
        stride: once(truth, &stride)?,
        best_of_10: over_seeds(truth, |s| {
            Ok(KMeans::fit(space, &KMeansParams::new(k).seed(s).restarts(TRIALS))?.labels)
        })?,
        hk: cut(&one)?,
        hk_trials: cut(&ten)?,
    };
    Ok((figures, [one, ten]))
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let set = describe_set(f, sensor, seed, presets)?;
    let mut out = vec![];
    for (name, p, ds) in &set.presets {
        let space = Space::new(ds, DistanceOptions::from(p))?;
        out.push((
            name.clone(),
            measure(&space, &space.matrix(), &set.truth, set.kinds)?.0,
        ));
    }
    Ok(FamilySet {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: set.scans,
        presets: out,
    })
}

/// `placecat simulate --scene S --seed N` with the site's preset (as
/// examples/common/sites.rs), clustered into 3, and each tree's choice.
fn site_set(scene: SceneKind, seed: u64) -> Res<SiteSet> {
    let site = site(scene, seed)?;
    let space = Space::new(&site.descriptors, DistanceOptions::from(&site.params))?;
    let m = space.matrix();
    let (figures, [one, ten]) = measure(&space, &m, &site.truth, 3)?;
    Ok(SiteSet {
        site: site.name.into(),
        seed,
        scans: site.truth.len(),
        figures,
        chosen: choices(&space, &m, &one, &site.truth)?,
        chosen_trials: choices(&space, &m, &ten, &site.truth)?,
    })
}

fn family_table(
    o: &mut String,
    r: &Report,
    all: &[FamilySet],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | hk-means++, 1 trial: mean | lowest | hk-means++, 10 trials: mean | lowest | ARI | target |\n|---|---|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &FamilySet) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        &r.presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let of = |f: fn(&Figures) -> f64| {
                move |s: &FamilySet| s.presets.iter().find(|q| q.0 == p).map(|q| f(&q.1))
            };
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} | {} | {} | {:.3} | {} |",
                pct(mean_over(sets, of(|f| f.stride.accuracy))),
                pct(mean_over(sets, of(|f| f.best_of_10.accuracy))),
                pct(mean_over(sets, of(|f| f.hk.accuracy))),
                pct(lowest_over(sets, of(|f| f.hk.lowest))),
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
    writeln!(o, "| site | seed | stride k-means | ARI | k-means++ best of 10 | hk-means++, 1 trial: mean (lowest) | ARI | hk-means++, 10 trials: mean (lowest) | ARI | K chosen, 1 trial | K chosen, 10 trials | accuracy at K chosen, 1 / 10 trials |\n|---|---|---|---|---|---|---|---|---|---|---|---|")?;
    for s in sites {
        let f = &s.figures;
        let at = |c: &[Chosen]| c.iter().map(|c| c.accuracy).sum::<f64>() / c.len() as f64;
        writeln!(
            o,
            "| {} | {} | {} | {:.3} | {} | {} ({}) | {:.3} | {} ({}) | {:.3} | {} | {} | {} / {} |",
            s.site,
            s.seed,
            pct(f.stride.accuracy),
            f.stride.ari,
            pct(f.best_of_10.accuracy),
            pct(f.hk.accuracy),
            pct(f.hk.lowest),
            f.hk.ari,
            pct(f.hk_trials.accuracy),
            pct(f.hk_trials.lowest),
            f.hk_trials.ari,
            ks(&s.chosen),
            ks(&s.chosen_trials),
            pct(at(&s.chosen)),
            pct(at(&s.chosen_trials)),
        )?;
    }
    for site in ["outdoor", "warehouse"] {
        let v: Vec<&SiteSet> = sites.iter().filter(|s| s.site == site).collect();
        let m = |f: fn(&Figures) -> f64| pct(mean_over(&v, |s| Some(f(&s.figures))));
        writeln!(
            o,
            "| {site} | mean | {} | | {} | {} | | {} | | | | |",
            m(|f| f.stride.accuracy),
            m(|f| f.best_of_10.accuracy),
            m(|f| f.hk.accuracy),
            m(|f| f.hk_trials.accuracy),
        )?;
    }
    Ok(())
}

/// What the round showed, written after its one test run (nothing was
/// changed or run again after it).
const NOTES: &str = "Written after the one test run (seeds 341-345 and 601-605, commit 3f3a73e's code; N = 10, the seeds and the page's decision fixed beforehand in seeds.md). Only the tree changed in this round: stride k-means and k-means++ best of 10 are the fourth round's methods, rerun on the new seeds as references. Their figures here are a new sample of unchanged methods, not a new verdict on them.

- **Ten trial splits made hierarchical k-means++ better on the whole.** On the test seeds its mean rose in 27 of the 34 family rows, fell in 6 and moved less than 0.1 point in 1 (the same counts as on the development seeds, mostly in other rows: many buildings `indoor_clutter` and the warehouse's `indoor` fell on both). Its lowest single run rose in 29 rows and fell in 2. On single sets (160 of 170 differ) it was better in 112 and worse in 48.
  - Falls: many buildings `indoor_clutter` 77.2 -> 71.5 %, one building `indoor_plus` 84.9 -> 83.5, office floor at 0.3 m 77.6 -> 75.9, and three rows of the paper's `indoor` preset by 1.6-2.4 points.
  - The cheapest split is not always the one that parts the kinds (the integration test `trial_splits_find_the_same_cheapest_tree_from_every_seed` shows one such set). What trials buy most is a tree far less dependent on its seed: the gap between a set's mean over tree seeds and its lowest falls from 10.0 to 3.1 points on average (test sets; development 9.2 -> 2.9), and all ten tree seeds give the same accuracy in 61 of 170 test sets instead of 6.
- **Warehouse halls, at least 95 % (issue 18): met with the own sensor, missed with 32 beams.** `indoor_plus` gives 97.6 % with ten trials (lowest 96.0 %; one trial 93.0 %, lowest 59 %) and 92.0 % with 32 beams (one trial 90.3 %). k-means++ best of 10 (unchanged) gives 87.0 and 76.7 %.
- **Indoor kinds and outdoor (issue 18): no new verdict.** Those targets are read on k-means, which this round did not change. On these seeds the office floor's `indoor_clutter` gives 82.9 % with k-means++ best of 10 (331-335: 84.7) and 86.7 % with stride k-means (84.9). Outdoor `outdoor_plus` best of 10 gives 95.6 % against the paper preset's 95.2 % (331-335: 94.0 against 95.6). Those differences are the spread between seed sets.
- **The outdoor site (issue 14): trials change little; 95 % on every seed is missed.** Hierarchical k-means++ with ten trials gives 95.3 / 94.7 / 93.8 / 97.3 / 93.3 % on 601-605 (mean 94.9 %; one trial: mean 94.8 %). That is at least 95 % on 2 of 5 seeds. Stride k-means (unchanged) gives 95.7 / 95.0 / 92.7 / 97.0 / 95.3 % (mean 95.1 %), at least 95 % on 4 of 5. These test seeds are harder than 501-505 (stride mean 96.2 %). The rule chose 3 categories on all 100 trees.
- **The warehouse site:** under `indoor` at 3 categories, ten trials give a mean of 65.8 % against 58.7 % (3 seeds up, 2 down: 602 53.4 -> 53.1 %, 603 69.9 -> 57.9 %). The rule still finds one category on every tree.
- **Development seeds** (sections 4 and 5) were looked at before the test run and the page's decision. There, ten trials mended the outdoor site's seed 7 (82.6 -> 96.7 %) and seed 5 (94.7 -> 96.3 %), but not seed 10 (65.3 -> 61.0 %: the cheapest top split is there a wrong one). Seed 1, the page's demo, went from 96.8 % (tree seed 0: 96.7 %) to 97.0 % on every tree seed.
- **Cost:** in Node's wasm (`node bench/tree_trials.mjs`), 1000 outdoor scans take 0.81 s for the tree instead of 0.09 s (about nine times), and 1.5 s for the reference trees instead of 0.5 s (three times). So the page uses ten trials up to 500 scans only (docs/seeds.md), and the CLI, npm and Python keep the paper's single run unless asked.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Trial splits for hierarchical k-means++ (issues 14 and 18, fifth round)\n"
    )?;
    writeln!(o, "**A clustering option, not a descriptor change.** `HkMeansParams::restarts` (`placecat cluster --method hkmeans --restarts 10`): at every node of the tree, 2-means++ is run N times and the split of lowest cost is kept (the sum over the node's scans of Delta to their centre, the cost k-means' restarts compare). This is bisecting k-means with trial splits (Steinbach, Karypis and Kumar 2000, \"ITER\"). The default stays one run per split, the paper's tree.\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example split_trials -- --dev` (`{DEV_FILE}`, {:.0} s) then `cargo run --release --example split_trials` (test seeds, this file and `{REPORT_FILE}`, {:.0} s; it refuses to run again once `{REPORT_FILE}` exists; `-- --render` renders this file from it). Seeds and N = {TRIALS} were fixed in [seeds.md](seeds.md) (\"fifth round\") before any run. Families: issue 18's, with round 4's sensors, scan counts and presets, development seeds 1-6, test seeds 341-345. Sites: issue 14's outdoor and warehouse sites as `placecat simulate` makes them (300 scans), development seeds 1-10, test seeds 601-605. Every method but stride k-means runs with clustering seeds 0-9 (mean over seeds and sets; lowest: any single seed on any set).\n", r.dev.seconds, r.test.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(
        o,
        "## 1. Sites, test seeds 601-605 (accuracy in %, at 3 categories unless said)\n"
    )?;
    site_table(&mut o, &r.test.sites)?;
    writeln!(
        o,
        "\n## 2. Families, test seeds 341-345, each family's own sensor\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s == "own")?;
    writeln!(
        o,
        "\n## 3. Families, test seeds 341-345, the other sensors\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s != "own")?;
    writeln!(
        o,
        "\n## 4. Sites, development seeds 1-10 (looked at before the test run)\n"
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
    let presets = presets_of(&docs)?;
    // The kinds the sites are read against (a change of the simulator's
    // names would show here, not as a silent 0 %).
    assert_eq!((OUTDOOR_KINDS.len(), WAREHOUSE_KINDS.len()), (3, 3));
    round_main(
        &FILES,
        || {
            Ok(Report {
                presets: presets.clone(),
                dev: site_rounds::run(&presets, FAMILY_DEV, SITE_DEV, "dev", site_set, family_set)?,
                test: Part::default(),
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
                test: site_rounds::run(
                    &presets,
                    FAMILY_TEST,
                    SITE_TEST,
                    "test",
                    site_set,
                    family_set,
                )?,
            })
        },
        render,
    )
}
