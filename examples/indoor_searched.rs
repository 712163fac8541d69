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
/// Issue 18's indoor target (%).
const TARGET: f64 = 85.0;

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[])
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 441-445, commit 1a008de's code; the preset and the rule that would withdraw it were fixed beforehand in seeds.md, the preset's weights in the thirteenth round). The rule, computed above: the preset stays. Every other preset's rows are new samples of unchanged presets and methods.

- **On fresh seeds the searched weights hold up, by less than on the seeds that chose them.** Over the 14 room rows `indoor_searched` averages 87.6 % against `indoor_columns`' 85.1 % (the mean of stride k-means and best of 10; on 431-435 the same weights gave 88.5 against 85.2 %). The nine rows that missed on 421-425 rose by +1.4 / +3.8 points (stride k-means / best of 10; on 431-435 +2.4 / +2.7), the other five by +1.2 / +3.1 (on 431-435 +1.6 / +7.8). Row by row, `indoor_columns` then `indoor_searched`: the one building 93.3 / 90.4 against 96.4 / 97.7 %, the many buildings 93.8 / 88.4 against 95.6 / 88.0 %, with 16 beams 88.9 / 85.9 against 94.2 / 90.5 %, the varied plans 91.1 / 83.3 against 89.3 / 85.6 %, the office floor 90.7 / 83.4 against 88.4 / 84.9 %, at 0.3 m 90.2 / 84.4 against 82.2 / 84.3 %, the school 84.9 / 84.6 against 95.6 / 94.3 %, with 16 beams 80.9 / 81.7 against 82.2 / 85.8 %, 32 beams 86.2 / 78.9 against 87.6 / 86.9 %, 64 beams 86.2 / 83.8 against 86.2 / 87.6 %, at 0.3 m 86.2 / 82.8 against 89.3 / 83.1 %, at 1.8 m 92.4 / 86.2 against 94.7 / 92.0 %, the hospital floors 82.7 / 78.5 against 83.6 / 80.7 % and with 16 beams 72.0 / 70.9 against 72.9 / 71.6 %.
- **Where it is worse: the office floor, as on 431-435.** At 0.3 m stride k-means fell by 8.0 points (90.2 against 82.2 %), with the own sensor by 2.2; room-level 1-NN fell on both office rows (87.1 against 84.4 %, at 0.3 m 90.2 against 83.6 %) and on the hospital floors (81.3 against 77.3 %, with 16 beams 69.8 against 66.2 %), and rose or held on the school rows. Stride k-means also fell on the varied plans (-1.8) and best of 10 on the many buildings (-0.4). Hierarchical k-means++ rose on 10 of the 14 rows (the school at 1.8 m +12.3 points) and fell on 4 (the hospital -4.8, the school at 0.3 m -3.0, the hospital with 16 beams -1.4, the varied plans -0.3). The docs say so in the preset's note: for office floors `indoor_columns` stays the better choice on this evidence.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10).** Read on the presets as in the thirteenth round (`indoor_columns` on the office, school and hospital floors, the family's earlier preset on the other room families): met in 5 of 14 room rows (one building `indoor_plus` 94.2 / 96.6 %, many buildings `indoor_clutter` 95.1 / 90.8 %, with 16 beams 86.7 / 86.0 %, varied plans `indoor_clutter` 91.1 / 87.7 %, the school at 1.8 m `indoor_columns` 92.4 / 86.2 %), missed in 9. Read on `indoor_searched`, now a preset of every room family: met in 8 of 14 (the four other room families, the school with its own sensor, 32 and 64 beams and at 1.8 m), missed in 6: the office floor 88.4 / 84.9 %, at 0.3 m 82.2 / 84.3 %, the school with 16 beams 82.2 / 85.8 %, at 0.3 m 89.3 / 83.1 %, the hospital floors 83.6 / 80.7 % and with 16 beams 72.9 / 71.6 %. Some new preset meets it in 9 of 14 (`indoor_clutter` on the school at 0.3 m, 90.2 / 86.6 %). The hospital floors, the family written by another hand, miss with every preset; with 16 beams by 12 to 14 points.
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.7 % (own sensor, lowest tree 96.0 %) and 99.0 % (32 beams, lowest 98.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 98.0 against 96.4 %, best of 10 97.8 against 96.2 %, the tree 98.3 against 96.5 %; 16 beams: 95.4 / 95.6 / 95.8 against 84.4 / 87.1 / 86.0 %.
- **Real scans:** every preset of the round, `indoor_searched` included, finds a scan of the same place for 18 of 18 real scans.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The preset `indoor_searched` on fresh seeds (issue 18, fourteenth round)\n"
    )?;
    // This round's rule reads only the means, not the rows meeting the
    // indoor target.
    let (_, searched, rows) = room_rows_against_target(&r.test.families, PRESET, TARGET);
    let (_, columns, _) = room_rows_against_target(&r.test.families, BASE, TARGET);
    writeln!(o, "**Preset.** `indoor_searched`: `indoor_columns`' parts and `iron`, weighted as the thirteenth round's search found on development seeds 1-3 (the NDT histogram 1, slice 4, ESF 32, ring 1, clutter 10, columns 5, iron 10; docs/weights-dev.md), unchanged. It was made a preset after that round's test seeds (431-435, docs/searched.md) were seen, so these fresh seeds judge it. The rule, fixed in docs/seeds.md before any run: withdrawn if on the test seeds its mean over the room rows of (stride k-means + k-means++ best of 10) / 2 is below `indoor_columns`'.\n")?;
    writeln!(
        o,
        "**The rule, computed:** over the {rows} room rows of the test seeds, `indoor_searched` {} % against `indoor_columns` {} %: {}.\n",
        pct(searched / 100.0),
        pct(columns / 100.0),
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
    family_round(
        &FILES,
        (FAMILY_DEV, FAMILY_TEST),
        &[PRESET],
        &[],
        family_set,
        render,
    )
}
