//! Issues 14 and 18, sixth round: the Hellinger distance between the
//! normalised NDT histograms (`Metric::Hellinger`, an option of
//! docs/design.md#variants) in place of the paper's sum of column norms
//! (Eq. 2), with everything else as it was: the same descriptors, the size
//! factor, the minimum over alignments, the presets' parts and weights.
//!
//!     cargo run --release --example hellinger -- --dev   # dev seeds -> docs/hellinger-dev.json
//!     cargo run --release --example hellinger            # test seeds, once: docs/hellinger.{json,md}
//!     ... -- --render   # docs/hellinger.md again from docs/hellinger.json
//!
//! Seeds were fixed in docs/seeds.md ("sixth round") before any run. Issue
//! 18's families (examples/common/families.rs, every sensor and the presets
//! of rounds 2-3) on seeds 1-6 and 351-355; issue 14's sites (`placecat
//! simulate --scene outdoor|warehouse --seed S`, the scene's paper preset)
//! on seeds 1-10 and 701-705. Each set at its true number of kinds, with
//! each preset's own metric and with Hellinger: stride k-means, k-means++
//! best of 10 (round 4), and hierarchical k-means++ with 10 trial splits
//! (round 5, the page's tree; tree seeds 0-9: mean and lowest). The sites
//! also get the number of categories the default rule chooses on each
//! tree, as the page's first cut does. The test run refuses to overwrite
//! its report.

use placecat::descriptor::Metric;
use placecat::sim::sites::{OUTDOOR_KINDS, WAREHOUSE_KINDS};
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
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
#[path = "common/site_rounds.rs"]
mod site_rounds;
use site_rounds::*;
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
use preset_rounds::*;

/// Fixed in docs/seeds.md ("issue 18, sixth round", "issue 14, sixth
/// round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[351, 352, 353, 354, 355];
const SITE_DEV: &[u64] = &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10];
const SITE_TEST: &[u64] = &[701, 702, 703, 704, 705];
const DEV_FILE: &str = "hellinger-dev.json";
const REPORT_FILE: &str = "hellinger.json";
const FILES: RoundFiles = RoundFiles {
    dev: DEV_FILE,
    report: REPORT_FILE,
    md: MD_FILE,
};
const MD_FILE: &str = "hellinger.md";

/// A preset's figures with its own metric and with Hellinger.
#[derive(Serialize, Deserialize, Clone, Copy, Default)]
struct Pair {
    own: Figures,
    hellinger: Figures,
}

#[derive(Serialize, Deserialize, Clone)]
struct FamilySet {
    family: String,
    sensor: String,
    seed: u64,
    scans: usize,
    presets: Vec<(String, Pair)>,
}

#[derive(Serialize, Deserialize, Clone)]
struct SiteSet {
    site: String,
    seed: u64,
    scans: usize,
    figures: Pair,
    /// Tree seeds 0-9: the preset's own metric, then Hellinger.
    chosen: Vec<Chosen>,
    chosen_hellinger: Vec<Chosen>,
}

type Part = site_rounds::Part<FamilySet, SiteSet>;

/// Same-place retrieval on the real scans (tests/data/real/groups.csv):
/// how many find a scan of their own place as their nearest other scan.
#[derive(Serialize, Deserialize, Clone)]
struct RealRow {
    preset: String,
    hellinger: bool,
    scans: usize,
    same_place: usize,
    /// Scans whose nearest other scan is of another place (or the reason
    /// none could be described).
    wrong: Vec<String>,
}

#[derive(Serialize, Deserialize)]
struct Report {
    presets: Vec<(String, Vec<String>)>,
    dev: Part,
    test: Part,
    /// Run with the test seeds (the real files were looked at before).
    #[serde(default)]
    real: Vec<RealRow>,
}

/// Real-scan retrieval for every preset of the rounds, with its own metric
/// and with Hellinger.
fn real_rows(presets: &[(String, Vec<String>)]) -> Res<Vec<RealRow>> {
    let scans = real::real_scans();
    let mut names: Vec<&String> = presets.iter().flat_map(|p| &p.1).collect();
    names.sort();
    names.dedup();
    let mut rows = vec![];
    for name in names {
        let own = DescriptorParams::preset(name)?;
        for (hellinger, p) in [(false, own.clone()), (true, with_hellinger(&own))] {
            let (same_place, wrong) = match real::wrong_places(&scans, &p)? {
                Ok(wrong) => (scans.len() - wrong.len(), wrong),
                Err(e) => (0, vec![format!("cannot describe every scan: {e}")]),
            };
            rows.push(RealRow {
                preset: name.clone(),
                hellinger,
                scans: scans.len(),
                same_place,
                wrong,
            });
        }
    }
    Ok(rows)
}

fn real_table(o: &mut String, rows: &[RealRow]) -> Res<()> {
    writeln!(o, "| preset | own metric: same place | Hellinger: same place | wrong (own / Hellinger) |\n|---|---|---|---|")?;
    for pair in rows.chunks(2) {
        let [own, hel] = pair else { continue };
        writeln!(
            o,
            "| `{}` | {} of {} | {} of {} | {} / {} |",
            own.preset,
            own.same_place,
            own.scans,
            hel.same_place,
            hel.scans,
            if own.wrong.is_empty() {
                "-".into()
            } else {
                own.wrong.join(", ")
            },
            if hel.wrong.is_empty() {
                "-".into()
            } else {
                hel.wrong.join(", ")
            },
        )?;
    }
    Ok(())
}

/// The preset with the Hellinger distance in place of its own.
fn with_hellinger(p: &DescriptorParams) -> DescriptorParams {
    DescriptorParams {
        metric: Metric::Hellinger,
        ..p.clone()
    }
}

fn pair(ds: &[Descriptor], p: &DescriptorParams, truth: &[String], k: usize) -> Res<Pair> {
    Ok(Pair {
        own: measure(ds, p, truth, k)?.0,
        hellinger: measure(ds, &with_hellinger(p), truth, k)?.0,
    })
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let set = describe_set(f, sensor, seed, presets)?;
    let mut out = vec![];
    for (name, p, ds) in &set.presets {
        out.push((name.clone(), pair(ds, p, &set.truth, set.kinds)?));
    }
    Ok(FamilySet {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: set.scans,
        presets: out,
    })
}

/// `placecat simulate --scene S --seed N` with the scene's paper preset
/// (as examples/common/sites.rs), clustered into 3, and each tree's choice.
fn site_set(scene: SceneKind, seed: u64) -> Res<SiteSet> {
    let site = site(scene, seed)?;
    let (ds, truth) = (&site.descriptors, &site.truth);
    let (own, space, m, own_trees) = measure(ds, &site.params, truth, 3)?;
    let chosen = choices(&space, &m, &own_trees, truth)?;
    let (hellinger, space, m, h_trees) = measure(ds, &with_hellinger(&site.params), truth, 3)?;
    let chosen_hellinger = choices(&space, &m, &h_trees, truth)?;
    Ok(SiteSet {
        site: site.name.into(),
        seed,
        scans: truth.len(),
        figures: Pair { own, hellinger },
        chosen,
        chosen_hellinger,
    })
}

fn family_table(
    o: &mut String,
    r: &Report,
    all: &[FamilySet],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means: own / Hellinger | k-means++ best of 10: own / Hellinger | hk-means++, 10 trials: own / Hellinger | lowest: own / Hellinger | ARI (hk-means++): own / Hellinger | target |\n|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &FamilySet) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        &r.presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let of = |f: fn(&Pair) -> f64| {
                move |s: &FamilySet| s.presets.iter().find(|q| q.0 == p).map(|q| f(&q.1))
            };
            let both = |own: fn(&Pair) -> f64, hel: fn(&Pair) -> f64| {
                format!(
                    "{} / {}",
                    pct(mean_over(sets, of(own))),
                    pct(mean_over(sets, of(hel)))
                )
            };
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} / {} | {:.3} / {:.3} | {} |",
                both(|f| f.own.stride.accuracy, |f| f.hellinger.stride.accuracy),
                both(
                    |f| f.own.best_of_10.accuracy,
                    |f| f.hellinger.best_of_10.accuracy
                ),
                both(
                    |f| f.own.hk_trials.accuracy,
                    |f| f.hellinger.hk_trials.accuracy
                ),
                pct(lowest_over(sets, of(|f| f.own.hk_trials.lowest))),
                pct(lowest_over(sets, of(|f| f.hellinger.hk_trials.lowest))),
                mean_over(sets, of(|f| f.own.hk_trials.ari)),
                mean_over(sets, of(|f| f.hellinger.hk_trials.ari)),
                if i == 0 { "-" } else { target(family) },
            )?;
            Ok(())
        },
    )
}

fn site_table(o: &mut String, sites: &[SiteSet]) -> Res<()> {
    writeln!(o, "| site | seed | stride k-means: own / Hellinger | ARI | k-means++ best of 10 | hk-means++, 10 trials: mean (lowest), own | Hellinger | ARI: own / Hellinger | K chosen: own | Hellinger | accuracy at K chosen: own / Hellinger |\n|---|---|---|---|---|---|---|---|---|---|---|")?;
    for s in sites {
        let (a, b) = (&s.figures.own, &s.figures.hellinger);
        let at = |c: &[Chosen]| c.iter().map(|c| c.accuracy).sum::<f64>() / c.len() as f64;
        writeln!(
            o,
            "| {} | {} | {} / {} | {:.3} / {:.3} | {} / {} | {} ({}) | {} ({}) | {:.3} / {:.3} | {} | {} | {} / {} |",
            s.site,
            s.seed,
            pct(a.stride.accuracy),
            pct(b.stride.accuracy),
            a.stride.ari,
            b.stride.ari,
            pct(a.best_of_10.accuracy),
            pct(b.best_of_10.accuracy),
            pct(a.hk_trials.accuracy),
            pct(a.hk_trials.lowest),
            pct(b.hk_trials.accuracy),
            pct(b.hk_trials.lowest),
            a.hk_trials.ari,
            b.hk_trials.ari,
            ks(&s.chosen),
            ks(&s.chosen_hellinger),
            pct(at(&s.chosen)),
            pct(at(&s.chosen_hellinger)),
        )?;
    }
    for site in ["outdoor", "warehouse"] {
        let v: Vec<&SiteSet> = sites.iter().filter(|s| s.site == site).collect();
        let m = |f: fn(&Pair) -> f64| pct(mean_over(&v, |s| Some(f(&s.figures))));
        writeln!(
            o,
            "| {site} | mean | {} / {} | | {} / {} | {} | {} | | | | |",
            m(|f| f.own.stride.accuracy),
            m(|f| f.hellinger.stride.accuracy),
            m(|f| f.own.best_of_10.accuracy),
            m(|f| f.hellinger.best_of_10.accuracy),
            m(|f| f.own.hk_trials.accuracy),
            m(|f| f.hellinger.hk_trials.accuracy),
        )?;
    }
    Ok(())
}

/// What the round showed, written after its one test run (the decision was
/// not changed after it; the test seeds were run once more with the faster
/// kernel only to check that every figure stayed the same).
const NOTES: &str = "Written after the one test run (seeds 351-355 and 701-705, commit d16afcd's code; the seeds, the change and the page's decision were fixed beforehand in seeds.md). The descriptors and the clusterings are those of rounds 4 and 5; only the distance between histograms changes. The presets' own columns are a new sample of unchanged methods, not a new verdict on them.

- **The outdoor site (issue 14): 95 % on every seed is missed again, on one seed of five.** With `outdoor_hellinger` (the paper's outdoor parameters, Hellinger distance) stride k-means gives 97.3 / 98.0 / 91.0 / 95.7 / 97.0 % on 701-705 (mean 95.8 %) and hierarchical k-means++ with ten trial splits 98.5 / 98.3 / 90.9 / 95.9 / 97.0 % (mean 96.1 %; lowest tree 90.3 % on 703). Both reach 95 % on 4 of 5 seeds; 703 misses for both. The paper's `outdoor` gives 97.7 / 97.0 / 92.0 / 96.0 / 96.0 % (mean 95.7 %) and 98.0 / 97.3 / 93.0 / 95.7 / 96.0 % (mean 96.0 %): also 4 of 5, and on 703 Hellinger is worse by 1.0 and 2.0 points. Against the paper's, Hellinger raised stride k-means on 2 seeds and lowered it on 3, and raised the tree on 4 and lowered it on 1. The rule chose 3 categories on all 100 trees. The development run's gain (stride 96.6 -> 97.3 %, tree 93.2 -> 97.6 %, most of it seed 10's tree) did not carry over: on the test seeds the means moved by 0.15 point at most (stride +0.1, best of 10 -0.1, the tree +0.15).
- **Outdoor (issue 18), not worse than the paper's preset: met with the site's own sensor.** On the outdoor family's test seeds, `outdoor` with Hellinger gives 96.2 % with k-means++ best of 10 against the paper's 94.9 %, stride k-means 96.2 against 95.2 %, and the tree 95.8 against 94.3 %. With 16 beams it is mixed: stride 88.4 against 85.6 %, best of 10 81.5 against 83.6 %, the tree 80.8 against 83.5 % (its lowest run 53 against 79 %).
- **Indoors Hellinger is no better, as on the development seeds.** With the paper's `indoor` preset it lowered stride k-means in 9 of 14 rows (one building 92.9 -> 86.2 %, many buildings 89.8 -> 85.8 %) and best of 10 in 10 of 14. Over all 34 rows it raised stride k-means in 14 and lowered it in 17 (3 within 0.05 point), best of 10 in 13 and 20, and the tree in 20 and 12. The warehouse site fell (stride 65.2 -> 64.4 %, best of 10 71.0 -> 65.4 %, tree 54.7 -> 53.6 %). No indoor preset uses it.
- **Real scans:** every preset finds a scan of the same place for 18 of 18 real scans, with its own distance and with Hellinger.
- **The other targets of issue 18 get no new verdict**: their presets and methods did not change. As new samples: office floor `indoor_clutter` stride 92.9 %, best of 10 87.6 % (341-345: 86.7 and 82.9; 331-335: 84.9 and 84.7); warehouse halls `indoor_plus`, tree with ten trials, 97.4 % with the own sensor and 97.4 % with 32 beams (341-345: 97.6 and 92.0).
- **The page** suggests `outdoor_hellinger` where it suggested `outdoor` and shows the outdoor demo with it, as decided before this run. On the demo (seed 1, a development seed) that gives 98.3 %, ARI 0.952, where the paper's preset gave 97.0 %. On the test seeds it is about as good as the paper's preset on the site and better on the family with the own sensor (with 16 beams worse with two of three methods). The paper's `outdoor` stays in the menu.
- **Cost, and a kernel changed after the run.** The Hellinger kernel summed the whole matrix in order and took both square roots for every entry and pair: the Delta matrix of 1,000 simulated outdoor scans (`placecat distances`, 2 cores) took 3.7 s of CPU against 0.5 s for the paper's distance. After this run it sums column by column in four lanes, stops once the pair cannot be the nearest, and takes each entry's root once when the descriptor is prepared: 0.6 s of CPU. In wasm, in one thread (`node bench/metrics.mjs`, the same 1,000 scans, alternated, under a load average of 2.5): 1.50 s against the paper's 1.38 s (1.09x). The values change in the last bits, so the test seeds were run again with the new kernel: every figure above is the same (the JSON, timings aside, is equal). The development seeds were not run again.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The Hellinger distance between NDT histograms (issues 14 and 18, sixth round)\n"
    )?;
    writeln!(o, "**A distance option, not a new descriptor.** `metric: \"hellinger\"` in a preset's parameters: the distance between two normalised histograms F/|F| and G/|G| becomes sqrt(1/2 sum (sqrt(f) - sqrt(g))^2) over all their entries, in place of the paper's sum over range intervals of the columns' L2 norms (Eq. 2). The size factor max(|F|,|G|)/min(|F|,|G|), the minimum over candidate alignments and the presets' extra parts and weights stay as they are. The square root weighs a bin by its relative change rather than its absolute one, so the few linear and rough voxels of tree trunks and crowns count beside the many planar ones of the ground (Hellinger distance of histograms: e.g. Arandjelovic and Zisserman 2012, RootSIFT).\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example hellinger -- --dev` (`{DEV_FILE}`, {:.0} s) then `cargo run --release --example hellinger` (test seeds, this file and `{REPORT_FILE}`, {:.0} s; it refuses to run again once `{REPORT_FILE}` exists; `-- --render` renders this file from it). Seeds were fixed in [seeds.md](seeds.md) (\"sixth round\") before any run. The test run used the paper's outdoor preset with `metric` set to Hellinger; the preset `outdoor_hellinger`, named after the run, is exactly that. Families: issue 18's, with the sensors, scan counts and presets of rounds 4 and 5, development seeds 1-6, test seeds 351-355. Sites: issue 14's outdoor and warehouse sites as `placecat simulate` makes them (300 scans) with the scene's paper preset, development seeds 1-10, test seeds 701-705. Every method but stride k-means runs with clustering seeds 0-9 (mean over seeds and sets; lowest: any single seed on any set).\n", r.dev.seconds, r.test.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    writeln!(
        o,
        "## 1. Sites, test seeds 701-705 (accuracy in %, at 3 categories unless said)\n"
    )?;
    site_table(&mut o, &r.test.sites)?;
    writeln!(
        o,
        "\n## 2. Families, test seeds 351-355, each family's own sensor\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s == "own")?;
    writeln!(
        o,
        "\n## 3. Families, test seeds 351-355, the other sensors\n"
    )?;
    family_table(&mut o, r, &r.test.families, |s| s != "own")?;
    writeln!(
        o,
        "\n## 3b. Real scans: same-place retrieval (every preset of the rounds, its own metric and Hellinger)\n"
    )?;
    real_table(&mut o, &r.real)?;
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
                test: site_rounds::run(
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
