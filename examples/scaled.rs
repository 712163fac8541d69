//! Issue 18, ninth round: each term of the combined distance (Delta and
//! every part) divided by its median over the collection's pairs of scans
//! before it is weighted (`distance::scale`, `Scale::Median`), against each
//! family's presets of the earlier rounds and the eighth round's
//! `indoor_columns`.
//!
//!     cargo run --release --example scaled -- --medians  # dev seeds: each term's median
//!     cargo run --release --example scaled -- --dev      # dev seeds -> docs/scaled-dev.json
//!     cargo run --release --example scaled               # test seeds, once: docs/scaled.{json,md}
//!     ... -- --render   # docs/scaled.md again from docs/scaled.json
//!
//! Seeds were fixed in docs/seeds.md ("issue 18, ninth round") before any
//! run: issue 18's families (examples/common/families.rs, every sensor)
//! and the hospital floors, on seeds 1-6 and 381-385. Each set at its true
//! number of kinds: stride k-means, k-means++ best of 10, hierarchical
//! k-means++ with 10 trial splits (tree seeds 0-9: mean and lowest), and
//! room-level 1-NN. The test run refuses to overwrite its report.

use placecat::descriptor::{DescriptorParams, Part, PartKind, Scale};
use placecat::distance::scale::resolve;
use placecat::DistanceOptions;
use std::fmt::Write;
use std::path::Path;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, ninth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[381, 382, 383, 384, 385];
/// The eighth round's preset, which every candidate scales.
const BASE: &str = "indoor_columns";
/// The seventh round's outdoor preset, on which the outdoor target is read.
const OUTDOOR_NEAR: &str = "outdoor_near";
const FILES: RoundFiles = RoundFiles {
    dev: "scaled-dev.json",
    report: "scaled.json",
    md: "scaled.md",
};
const TEXT: RoundText = RoundText {
    example: "scaled",
    test_seeds: "381-385",
    candidates_on: "",
};

/// A candidate: a name, and its parameters made from [`BASE`]'s (the
/// descriptors are [`BASE`]'s: weights and scale change no descriptor).
struct Candidate {
    name: &'static str,
    params: fn() -> DescriptorParams,
}

/// `indoor_columns`' parts, every term at weight 1, each scaled by its median.
fn equal_shares() -> DescriptorParams {
    let mut p = DescriptorParams::indoor_columns();
    p.preset = "median, equal shares".into();
    p.ndt_weight = 1.0;
    for part in &mut p.parts {
        part.weight = 1.0;
    }
    p.scale = Scale::Median;
    p
}

/// `indoor_columns`' weights times each term's median on the office and
/// school floors' own sensors (development seeds 1-6, `--medians`, the mean
/// of the two floors), over Delta's: each term keeps the share of a
/// typical distance it has there, with every sensor.
fn floor_shares() -> DescriptorParams {
    let mut p = DescriptorParams::indoor_columns();
    p.preset = "median, floors' shares".into();
    let share = |k: PartKind| match k {
        PartKind::Slice => 0.586,
        PartKind::Esf => 0.172,
        PartKind::Ring => 0.127,
        PartKind::Clutter => 1.523,
        PartKind::Columns => 1.973,
        _ => 0.0,
    };
    p.ndt_weight = 1.0;
    for part in &mut p.parts {
        part.weight = share(part.kind);
    }
    p.scale = Scale::Median;
    p
}

const CANDIDATES: &[Candidate] = &[
    Candidate {
        name: "median, equal shares",
        params: equal_shares,
    },
    Candidate {
        name: "median, floors' shares",
        params: floor_shares,
    },
];

/// Each family's presets of rounds 2-3, `indoor_columns`, the outdoor
/// family's `outdoor_near`, then the candidates; the hospital floors with
/// the paper's, `indoor_clutter`, `indoor_columns` and the candidates.
fn scaled_presets(docs: &Path) -> Res<Vec<(String, Vec<String>)>> {
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
        names.extend(CANDIDATES.iter().map(|c| c.name.to_string()));
    }
    Ok(presets)
}

/// The candidates' names: no presets, so described by the round itself.
fn candidate_names() -> Vec<&'static str> {
    CANDIDATES.iter().map(|c| c.name).collect()
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let set = describe_set(f, sensor, seed, &without(presets, &candidate_names()))?;
    let mut out = vec![];
    let mut measured = |name: &str, p: &DescriptorParams, ds: &[placecat::Descriptor]| -> Res<()> {
        let (figures, _, m, _) = measure(ds, p, &set.truth, set.kinds)?;
        out.push((
            name.to_string(),
            figures,
            room_level_nn(&m, &set.truth, &set.apart),
        ));
        Ok(())
    };
    for (name, p, ds) in &set.presets {
        measured(name, p, ds)?;
    }
    let base = set.presets.iter().find(|p| p.0 == BASE);
    for c in CANDIDATES
        .iter()
        .filter(|c| presets.iter().any(|p| p == c.name))
    {
        let (_, _, ds) = base.ok_or_else(|| format!("{} did not describe {}", BASE, f.name))?;
        measured(c.name, &(c.params)(), ds)?;
    }
    Ok(FamilySet {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        scans: set.scans,
        presets: out,
    })
}

/// Each term's median over the pairs of `indoor_columns`' descriptors of
/// every room family and sensor on the development seeds (mean over the
/// seeds): what `Scale::Median` divides by.
fn medians() -> Res<()> {
    seeds::check_round_seeds(FAMILY_DEV, FAMILY_TEST)?;
    let mut unit = DescriptorParams::indoor_columns();
    for part in &mut unit.parts {
        part.weight = 1.0;
    }
    unit.scale = Scale::Median;
    let kinds: Vec<PartKind> = unit.parts.iter().map(|p: &Part| p.kind).collect();
    println!("family | sensor | ndt | {kinds:?}");
    for f in all_families() {
        if target(f.name) != target("rooms") {
            continue;
        }
        for sensor in std::iter::once(Sensor::Own).chain(f.sensors.iter().copied()) {
            let mut sums = vec![0f64; 1 + kinds.len()];
            for &seed in FAMILY_DEV {
                let set = describe_set(&f, sensor, seed, &[BASE.to_string()])?;
                let w = resolve(&set.presets[0].2, DistanceOptions::from(&unit))?;
                sums[0] += 1.0 / w.ndt_weight as f64;
                for (s, k) in sums[1..].iter_mut().zip(&kinds) {
                    *s += 1.0 / w.part_weights[k.index()] as f64;
                }
            }
            let n = FAMILY_DEV.len() as f64;
            let cells: Vec<String> = sums.iter().map(|s| format!("{:.4}", s / n)).collect();
            println!("{} | {} | {}", f.name, sensor.name(), cells.join(" | "));
        }
    }
    Ok(())
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 381-385, commit 55f448a's code; the seeds, the hypothesis and the decision were fixed beforehand in seeds.md). The decision, from the development seeds alone: no preset, since neither candidate beat `indoor_columns` on the rows it was aimed at taken together (row by row each was higher on a few, seeds.md's corrections) and neither brought any of them to the target. The presets' rows are new samples of unchanged presets and methods.

- **The hypothesis did not hold.** The terms' medians do move with the sensor (with 16 beams Delta's median rises by 35-39 % on the school and hospital floors and the many buildings, and on the two floors the `clutter` and `columns` medians fall by 15-18 % and 10-23 %; `--medians` on the development seeds, docs/scaled-medians.txt), but sizing each term by its median brought none of the rows it was aimed at to the target and lifted few of them. On the test seeds, against `indoor_columns` on the seven rows aimed at (the school with 16, 32 and 64 beams and at 0.3 m, the office floor at 0.3 m, the hospital floors with both sensors), \"floors' shares\" (`indoor_columns`' shares on the floors' own sensors, kept on every sensor) was higher with stride k-means in 2 (office at 0.3 m 85.8 against 84.9 %, school 16 beams 84.9 against 84.4 %), equal in 2 (64 beams, the hospital with 16) and lower in 3 (school 32 beams 86.2 against 87.6 %, at 0.3 m 82.7 against 85.3 %, hospital 84.4 against 86.7 %); with best of 10 higher in 3, equal in 1 and lower in 3, none by more than 1.7 points (with stride k-means the largest fall is 2.7, the school at 0.3 m). \"Equal shares\" (every term at weight 1) was lower than `indoor_columns` on most of those rows (office at 0.3 m 80.4 / 73.9 against 84.9 / 83.2 %, the hospital 76.9 / 74.0 against 86.7 / 82.4 %), as on the development seeds, and higher on the hospital with 16 beams (69.8 / 71.6 against 67.6 / 69.2 %, still far short) and with best of 10 at 64 beams (85.7 against 85.5 %).
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets as decided: met in 7 of 14 room rows, missed in 7.** Met: one building `indoor_plus` 92.4 / 95.4 %, many buildings with 16 beams `indoor_clutter` 92.4 / 89.0 %, varied plans `indoor_clutter` 88.0 / 88.9 %, the office floor `indoor_columns` 91.1 / 90.8 %, the school 86.7 / 86.2 %, with 64 beams 88.0 / 85.5 %, at 1.8 m 85.3 / 85.1 %. Missed: many buildings with its own sensor `indoor_clutter` 94.2 / 81.9 % (best of 10; it was 90.9 % on 371-375), the office floor at 0.3 m 84.9 / 83.2 %, the school with 16 beams 84.4 / 83.8 %, 32 beams 87.6 / 82.8 %, at 0.3 m 85.3 / 83.1 %, the hospital floors 86.7 / 82.4 % and with 16 beams 67.6 / 69.2 %. Five misses are within 2.6 points, one or two scans of a 45-scan set; many buildings with best of 10 is 3.1 points short, and the hospital with 16 beams 17.4 (stride k-means) and 15.8 (best of 10).
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.6 % (own sensor, lowest tree 97.0 %) and 98.2 % (32 beams, lowest 97.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 97.6 against 95.8 %, best of 10 98.0 against 95.9 %, the tree 98.5 against 95.9 %; 16 beams: 95.0 / 95.1 / 94.9 against 85.8 / 86.5 / 86.2 %. \"Equal shares\" is higher still with k-means (own 97.2 / 97.6 %, 16 beams 97.6 / 97.7 %) and lower with the tree (96.2 and 85.0 %), as on the development seeds; it is no preset.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidates are no presets and were not run on them).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Each term sized by its median: the scaled distance (issue 18, ninth round)\n"
    )?;
    writeln!(o, "**An option, no preset.** With `\"scale\": \"median\"` (src/distance/scale.rs) Delta and each part's distance are divided by their median over the collection's pairs of scans before the weights apply, so a weight is the term's share of a typical distance whatever the sensor; a model keeps the weights its scans gave. Two candidates on `indoor_columns`' descriptors: every term at weight 1 (equal shares), and `indoor_columns`' weights times each term's median on the office and school floors' own sensors (floors' shares: Delta 1, slice 0.586, ESF 0.172, ring 0.127, clutter 1.523, columns 1.973). The hypothesis, written in docs/seeds.md before any run: fewer beams change how far apart scans are in each term, so fixed weights give the parts other shares on other sensors.\n")?;
    round_body(&mut o, r, &FILES, &TEXT, NOTES)?;
    Ok(o)
}

fn main() -> Res<()> {
    if std::env::args().any(|a| a == "--medians") {
        return medians();
    }
    seeds::check_round_seeds(FAMILY_DEV, FAMILY_TEST)?;
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = scaled_presets(&docs)?;
    every_family_round(
        &FILES,
        &presets,
        (FAMILY_DEV, FAMILY_TEST),
        family_set,
        &candidate_names(),
        render,
    )
}
