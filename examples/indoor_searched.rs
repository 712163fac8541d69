//! Issue 18, fourteenth round: the preset `indoor_searched` (the
//! thirteenth round's searched weights, unchanged) on fresh test seeds,
//! beside each family's presets of the earlier rounds and `indoor_columns`.
//!
//!     cargo run --release --example indoor_searched -- --dev   # dev seeds -> docs/indoor-searched-dev.json
//!     cargo run --release --example indoor_searched            # test seeds, once: docs/indoor-searched.{json,md}
//!     ... -- --render   # docs/indoor-searched.md again from its .json
//!
//! The preset and the rule that withdraws it were fixed in docs/seeds.md
//! ("issue 18, fourteenth round") before any run: it is withdrawn if on
//! the test seeds its mean over the 14 room rows of (stride k-means +
//! k-means++ best of 10) / 2 is below `indoor_columns`'. The report
//! computes that verdict. Issue 18's families (examples/common/families.rs,
//! every sensor) and the hospital floors, on seeds 1-6 and 441-445; the
//! preset runs on the room families. Each set at its true number of kinds:
//! stride k-means, k-means++ best of 10, hierarchical k-means++ with 10
//! trial splits (tree seeds 0-9: mean and lowest), and room-level 1-NN.
//! The test run refuses to overwrite its report.

use std::fmt::Write;
use std::path::Path;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, fourteenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[441, 442, 443, 444, 445];
const FILES: RoundFiles = RoundFiles {
    dev: "indoor-searched-dev.json",
    report: "indoor-searched.json",
    md: "indoor-searched.md",
};
const TEXT: RoundText = RoundText {
    example: "indoor_searched",
    test_seeds: "441-445",
    candidates_on: "; `indoor_searched` on the room families",
};
const PRESET: &str = "indoor_searched";

/// Every preset is a real one: all are described.
fn described(names: &[String]) -> Vec<String> {
    names.to_vec()
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[])
}

/// The rule's figure for `preset` on the room rows of `sets`: the mean
/// over rows (family and sensor) of the mean over seeds of (stride k-means
/// + k-means++ best of 10) / 2, and the rows counted.
fn room_mean(sets: &[FamilySet], preset: &str) -> (f64, usize) {
    let mut rows: Vec<(&str, &str)> = (sets.iter())
        .filter(|s| of_rooms(&s.family))
        .map(|s| (s.family.as_str(), s.sensor.as_str()))
        .collect();
    rows.sort();
    rows.dedup();
    let row_mean = |&(family, sensor): &(&str, &str)| {
        let row: Vec<&FamilySet> = (sets.iter())
            .filter(|s| (s.family.as_str(), s.sensor.as_str()) == (family, sensor))
            .collect();
        mean_over(&row, |s| {
            entry(s, preset).map(|e| (e.1.stride.accuracy + e.1.best_of_10.accuracy) / 2.0)
        })
    };
    let total: f64 = rows.iter().map(row_mean).sum();
    (total / rows.len() as f64, rows.len())
}

/// What the round showed, written after its one test run.
const NOTES: &str = "";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The preset `indoor_searched` on fresh seeds (issue 18, fourteenth round)\n"
    )?;
    let (searched, rows) = room_mean(&r.test.families, PRESET);
    let (columns, _) = room_mean(&r.test.families, BASE);
    writeln!(o, "**Preset.** `indoor_searched`: `indoor_columns`' parts and `iron`, weighted as the thirteenth round's search found on development seeds 1-3 (the NDT histogram 1, slice 4, ESF 32, ring 1, clutter 10, columns 5, iron 10; docs/weights-dev.md), unchanged. It was made a preset after that round's test seeds (431-435, docs/searched.md) were seen, so these fresh seeds judge it. The rule, fixed in docs/seeds.md before any run: withdrawn if on the test seeds its mean over the room rows of (stride k-means + k-means++ best of 10) / 2 is below `indoor_columns`'.\n")?;
    writeln!(
        o,
        "**The rule, computed:** over the {rows} room rows of the test seeds, `indoor_searched` {} % against `indoor_columns` {} %: {}.\n",
        pct(searched),
        pct(columns),
        if searched >= columns {
            "the preset stays"
        } else {
            "the preset is withdrawn"
        }
    )?;
    round_body(&mut o, r, &FILES, &TEXT, NOTES)?;
    Ok(o)
}

fn main() -> Res<()> {
    seeds::check_round_seeds(FAMILY_DEV, FAMILY_TEST)?;
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = round_presets(&docs, &[PRESET])?;
    every_family_round(
        &FILES,
        &presets,
        (FAMILY_DEV, FAMILY_TEST),
        family_set,
        described,
        render,
    )
}
