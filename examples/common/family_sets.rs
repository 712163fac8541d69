//! What the rounds that add a preset or a candidate to every family share
//! (round 8, `columns.rs`; round 9, `scaled.rs`; rounds 10-16, through
//! `family_round.rs`): a set's figures for each preset, the table of their
//! means by family and sensor, the report, the run over every family, and
//! the candidates (made by a round, not named presets).
//! Include after `families.rs`, `real.rs`, `rounds.rs`, `site_rounds.rs`
//! and `preset_rounds.rs`.

use crate::families::{families, hospital_family, pct, Family, Sensor};
use crate::preset_rounds::{measure, Figures};
use crate::real::{real_rows, real_table, RealRow};
use crate::rounds::{
    describe_set_with, each_row, every_set_of, lowest_over, mean_over, presets_of, room_level_nn,
    target, DescribedSet, Res,
};
use crate::site_rounds::{round_main, RoundFiles};
use placecat::descriptor::DescriptorParams;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::path::Path;

/// A round's sets on one kind of seeds.
pub type FamilyPart = crate::site_rounds::Part<FamilySet, ()>;

/// A round's report: the presets of each family, the development and test
/// sets, and the real scans' same-place retrieval (test run only).
#[derive(Serialize, Deserialize)]
pub struct Report {
    pub presets: Vec<(String, Vec<String>)>,
    pub dev: FamilyPart,
    pub test: FamilyPart,
    #[serde(default)]
    pub real: Vec<RealRow>,
}

/// The eighth round's preset, on which rounds 10 and 11 build candidates.
#[allow(dead_code)]
pub const BASE: &str = "indoor_columns";
/// The seventh round's outdoor preset, on which the outdoor target is read.
#[allow(dead_code)]
const OUTDOOR_NEAR: &str = "outdoor_near";

/// Whether a family is one of rooms (the candidates run on those).
#[allow(dead_code)]
pub fn of_rooms(family: &str) -> bool {
    target(family) == target("rooms")
}

/// Each family's presets of rounds 2-3, [`BASE`], the outdoor family's
/// `outdoor_near`; the room families' then `candidates`; the hospital
/// floors with the paper's, `indoor_clutter`, [`BASE`] and the candidates
/// (rounds 10 and 11).
#[allow(dead_code)]
pub fn round_presets(docs: &Path, candidates: &[&str]) -> Res<Vec<(String, Vec<String>)>> {
    let mut presets = presets_of(docs)?;
    presets.push((
        hospital_family().name.to_string(),
        vec!["indoor".into(), "indoor_clutter".into()],
    ));
    for (family, names) in &mut presets {
        if family == "outdoor" {
            names.push(OUTDOOR_NEAR.into());
        }
        if !names.iter().any(|n| n == BASE) {
            names.push(BASE.into());
        }
        if of_rooms(family) {
            names.extend(candidates.iter().map(|c| c.to_string()));
        }
    }
    Ok(presets)
}

/// Every family, the hospital floors after them.
#[allow(dead_code)] // rounds 9 and 10; round 8 added the hospital itself
pub fn all_families() -> Vec<Family> {
    let mut f = families();
    f.push(hospital_family());
    f
}

/// Every family and the hospital floors on `seeds`, each set by `each`.
#[allow(dead_code)] // rounds 9 and 10
fn run_families(
    presets: &[(String, Vec<String>)],
    seeds: &[u64],
    what: &str,
    each: fn(&Family, Sensor, u64, &[String]) -> Res<FamilySet>,
) -> Res<FamilyPart> {
    let (families, seconds) = every_set_of(all_families(), presets, seeds, what, each)?;
    Ok(FamilyPart {
        families,
        seconds,
        ..FamilyPart::default()
    })
}

/// The main of a round over every family ([`round_main`]): `--dev` on
/// `dev_seeds`; else `test_seeds`, once, and the real scans with the
/// presets of each family but `candidates` (the candidates are no
/// presets).
#[allow(dead_code)] // rounds 9-14
pub fn every_family_round(
    files: &RoundFiles,
    presets: &[(String, Vec<String>)],
    (dev_seeds, test_seeds): (&[u64], &[u64]),
    each: fn(&Family, Sensor, u64, &[String]) -> Res<FamilySet>,
    candidates: &[&str],
    render: fn(&Report) -> Res<String>,
) -> Res<()> {
    round_main(
        files,
        || {
            Ok(Report {
                presets: presets.to_vec(),
                dev: run_families(presets, dev_seeds, "dev", each)?,
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
            let test = run_families(presets, test_seeds, "test", each)?;
            let kept: Vec<(String, Vec<String>)> = presets
                .iter()
                .map(|(f, n)| (f.clone(), without(n, candidates)))
                .collect();
            Ok(Report {
                presets: presets.to_vec(),
                dev: dev.dev,
                test,
                real: real_rows(&kept)?,
            })
        },
        render,
    )
}

/// What a round over every family says of itself in its report (rounds
/// 9-12).
#[allow(dead_code)]
pub struct RoundText {
    /// The example that runs it (`cargo run --example NAME`).
    pub example: &'static str,
    /// Its test seeds, as the headings name them ("421-425").
    pub test_seeds: &'static str,
    /// Where its candidates run, after the families ("; the candidate on
    /// the room families"), or nothing.
    pub candidates_on: &'static str,
}

/// A round's report after its title and the words on its candidates: how
/// to regenerate it, `notes`, the test seeds' tables (each family's own
/// sensor, then the others), the real scans and the development seeds'
/// table.
#[allow(dead_code)]
pub fn round_body(
    o: &mut String,
    r: &Report,
    files: &RoundFiles,
    t: &RoundText,
    notes: &str,
) -> Res<()> {
    let (ex, seeds) = (t.example, t.test_seeds);
    writeln!(o, "Regenerate with `cargo run --release --example {ex} -- --dev` (`{}`, {:.0} s) then `cargo run --release --example {ex}` (test seeds, this file and `{}`, {:.0} s; it refuses to run again once `{}` exists; `-- --render` renders this file from it). Families: issue 18's (examples/common/families.rs, every sensor) and the hospital floors, development seeds 1-6, test seeds {seeds}{}. Every method but stride k-means runs with clustering seeds 0-9 (mean; lowest tree: any single tree on any set). Room-level 1-NN: no neighbour from the scan's own room (routes: none within 25 of 300 scans).\n", files.dev, r.dev.seconds, files.report, r.test.seconds, files.report, t.candidates_on)?;
    writeln!(o, "## What it shows\n\n{notes}\n")?;
    writeln!(o, "## 1. Test seeds {seeds}, each family's own sensor\n")?;
    family_table(o, &r.presets, &r.test.families, |s| s == "own")?;
    writeln!(o, "\n## 2. Test seeds {seeds}, the other sensors\n")?;
    family_table(o, &r.presets, &r.test.families, |s| s != "own")?;
    writeln!(
        o,
        "\n## 3. Real scans: same-place retrieval (every preset of the round)\n"
    )?;
    real_table(o, &r.real)?;
    writeln!(
        o,
        "\n## 4. Development seeds 1-6, every sensor (looked at before the test run)\n"
    )?;
    family_table(o, &r.presets, &r.dev.families, |_| true)
}

#[derive(Serialize, Deserialize, Clone)]
pub struct FamilySet {
    pub family: String,
    pub sensor: String,
    pub seed: u64,
    pub scans: usize,
    /// Each preset's clusterings and its room-level 1-NN.
    pub presets: Vec<(String, Figures, f64)>,
}

/// `names` but the `candidates` among them: the presets a round describes
/// as they are (a candidate is made by the round, not by its name).
#[allow(dead_code)] // rounds 9-14
pub fn without(names: &[String], candidates: &[&str]) -> Vec<String> {
    (names.iter())
        .filter(|n| !candidates.contains(&n.as_str()))
        .cloned()
        .collect()
}

/// A round's candidate: its name and how its parameters are made.
#[allow(dead_code)] // rounds 12, 13 and 15
pub type Candidate = (&'static str, fn() -> Res<DescriptorParams>);

/// A candidate made of searched weights (rounds 13 and 15): `base`'s
/// parameters named `name`, with the weights docs/`file` found (its
/// `found_weights`: the NDT histogram's, then one per part kind in
/// `PartKind::ALL`'s order; a kind of weight 0 is left out). They must be
/// `tested`, the weights the round's test run was made with, so that a
/// search run again with other results cannot change a report's candidate.
#[allow(dead_code)] // rounds 13 and 15
pub fn searched_weights(
    name: &str,
    file: &str,
    base: &str,
    tested: &[f32],
) -> Res<DescriptorParams> {
    use placecat::descriptor::{Part, PartKind};
    #[derive(Deserialize)]
    struct Search {
        found_weights: Vec<f32>,
    }
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let mut w = crate::families::read_json::<Search>(&docs.join(file))?.found_weights;
    // A search written before a part kind was added weighs it 0.
    if w.len() > 1 + PartKind::ALL.len() {
        return Err(format!(
            "docs/{file}: {} weights, more than {}",
            w.len(),
            1 + PartKind::ALL.len()
        )
        .into());
    }
    w.resize(1 + PartKind::ALL.len(), 0.0);
    if w != tested {
        return Err(format!(
            "docs/{file}: found weights {w:?}, not the {tested:?} this round was tested with"
        )
        .into());
    }
    let mut p = DescriptorParams {
        preset: name.into(),
        ndt_weight: f64::from(w[0]),
        ..DescriptorParams::preset(base)?
    };
    p.parts = (PartKind::ALL.iter().zip(&w[1..]))
        .filter(|(_, &weight)| weight > 0.0)
        .map(|(&kind, &weight)| Part {
            kind,
            weight: f64::from(weight),
        })
        .collect();
    p.validate()?;
    Ok(p)
}

/// A descriptor's weights in words: "the NDT histogram 1, slice 4, ...".
#[allow(dead_code)] // rounds 13 and 15
pub fn weights_text(p: &DescriptorParams) -> String {
    let ndt = std::iter::once(format!("the NDT histogram {}", p.ndt_weight));
    ndt.chain((p.parts.iter()).map(|part| format!("{} {}", part.kind.name(), part.weight)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A set of a round with candidates (rounds 12, 13 and 15): the set described
/// with `presets` (the candidates among them made by `candidates`), and
/// each one's figures and room-level 1-NN. A candidate that cannot describe
/// every scan is an error naming the set.
#[allow(dead_code)] // rounds 12 and 13
pub fn candidate_set(
    f: &Family,
    sensor: Sensor,
    seed: u64,
    presets: &[String],
    candidates: &[Candidate],
) -> Res<FamilySet> {
    let wanted: Vec<&Candidate> = (candidates.iter())
        .filter(|c| presets.iter().any(|p| p == c.0))
        .collect();
    let names: Vec<&str> = candidates.iter().map(|c| c.0).collect();
    let others = without(presets, &names);
    let set = describe_set_with(f, sensor, seed, &others, |_| {
        wanted
            .iter()
            .map(|c| Ok((c.0.to_string(), (c.1)()?)))
            .collect()
    })?;
    if let Some(c) = wanted
        .iter()
        .find(|c| !set.presets.iter().any(|p| p.0 == c.0))
    {
        return Err(format!(
            "{} {} seed {seed}: a scan could not be described with {}",
            f.name,
            sensor.name(),
            c.0
        )
        .into());
    }
    measured_set(f, sensor, seed, &set)
}

/// A described set's figures for each of its presets: the harness's
/// clusterings and room-level 1-NN (rounds 8-13).
pub fn measured_set(f: &Family, sensor: Sensor, seed: u64, set: &DescribedSet) -> Res<FamilySet> {
    let mut out = vec![];
    for (name, p, ds) in &set.presets {
        let (figures, _, m, _) = measure(ds, p, &set.truth, set.kinds)?;
        out.push((
            name.to_string(),
            figures,
            room_level_nn(&m, &set.truth, &set.apart),
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

/// A set's figures for preset `p`.
pub fn entry<'a>(s: &'a FamilySet, p: &str) -> Option<&'a (String, Figures, f64)> {
    s.presets.iter().find(|q| q.0 == p)
}

/// The means over each family and sensor that `sensor_filter` keeps of
/// every preset's figures, one row a preset.
pub fn family_table(
    o: &mut String,
    presets: &[(String, Vec<String>)],
    all: &[FamilySet],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | hk-means++, 10 trials | lowest tree | room-level 1-NN | target |\n|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &FamilySet) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let of = |f: fn(&Figures) -> f64| move |s: &FamilySet| entry(s, p).map(|e| f(&e.1));
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} | {} | {} |",
                pct(mean_over(sets, of(|f| f.stride.accuracy))),
                pct(mean_over(sets, of(|f| f.best_of_10.accuracy))),
                pct(mean_over(sets, of(|f| f.hk_trials.accuracy))),
                pct(lowest_over(sets, of(|f| f.hk_trials.lowest))),
                pct(mean_over(sets, |s: &FamilySet| entry(s, p).map(|e| e.2))),
                if i == 0 { "-" } else { target(family) },
            )?;
            Ok(())
        },
    )
}

/// The rule's figures for `preset` on the room rows of `sets`: the rows
/// (family and sensor) whose means over the seeds of stride k-means and of
/// k-means++ best of 10 both reach `target` (%), the mean over the rows of
/// (stride k-means + best of 10) / 2 (%), and the rows counted.
#[allow(dead_code)] // the rounds that judge a preset against another
pub fn room_rows_against_target(
    sets: &[FamilySet],
    preset: &str,
    target: f64,
) -> (usize, f64, usize) {
    let mut rows: Vec<(&str, &str)> = (sets.iter())
        .filter(|s| of_rooms(&s.family))
        .map(|s| (s.family.as_str(), s.sensor.as_str()))
        .collect();
    rows.sort();
    rows.dedup();
    let figures = |&(family, sensor): &(&str, &str)| {
        let row: Vec<&FamilySet> = (sets.iter())
            .filter(|s| (s.family.as_str(), s.sensor.as_str()) == (family, sensor))
            .collect();
        let stride = mean_over(&row, |s| entry(s, preset).map(|e| e.1.stride.accuracy));
        let best = mean_over(&row, |s| entry(s, preset).map(|e| e.1.best_of_10.accuracy));
        (100.0 * stride, 100.0 * best)
    };
    let all: Vec<(f64, f64)> = rows.iter().map(figures).collect();
    let met = (all.iter())
        .filter(|(s, b)| *s >= target && *b >= target)
        .count();
    let mean = all.iter().map(|(s, b)| (s + b) / 2.0).sum::<f64>() / all.len() as f64;
    (met, mean, rows.len())
}

/// A preset against another on the room rows of `sets`
/// ([`room_rows_against_target`]): rows meeting the target and the mean,
/// the preset's then the other's, and the rows counted.
#[allow(dead_code)] // rounds 16 and 17
pub struct Standing<'a> {
    pub names: [&'a str; 2],
    pub met: [usize; 2],
    pub mean: [f64; 2],
    pub rows: usize,
}

#[allow(dead_code)] // rounds 16 and 17
impl<'a> Standing<'a> {
    pub fn of(sets: &[FamilySet], (preset, against): (&'a str, &'a str), target: f64) -> Self {
        let (met, mean, rows) = room_rows_against_target(sets, preset, target);
        let (met_against, mean_against, _) = room_rows_against_target(sets, against, target);
        Standing {
            names: [preset, against],
            met: [met, met_against],
            mean: [mean, mean_against],
            rows,
        }
    }

    /// The withdrawal rule of rounds 16 and 17: the preset stays unless it
    /// meets the target in fewer rows than the other or its mean is lower.
    pub fn stays(&self) -> bool {
        self.met[0] >= self.met[1] && self.mean[0] >= self.mean[1]
    }
}

/// "`P` meets the target in N rows with a mean of M %, `Q` in ...: the
/// preset stays."
impl std::fmt::Display for Standing<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let [p, q] = self.names;
        write!(
            f,
            "`{p}` meets the target in {} rows with a mean of {:.1} %, `{q}` in {} with {:.1} %: {}",
            self.met[0],
            self.mean[0],
            self.met[1],
            self.mean[1],
            if self.stays() {
                "the preset stays"
            } else {
                "the preset is withdrawn"
            }
        )
    }
}
