//! Issue 18, seventeenth round: a second fresh sample for the preset
//! `indoor_objects`, no change. Every family's presets as in the sixteenth
//! round (`room_objects.rs`), on fresh test seeds, and the rule that
//! withdraws the preset read on both samples pooled.
//!
//!     cargo run --release --example room_objects_again            # test seeds, once: docs/room-objects-2.{json,md}
//!     ... -- --render   # docs/room-objects-2.md again from its .json
//!
//! The rule was fixed in docs/seeds.md ("issue 18, seventeenth round")
//! before any run: pooled over 461-465 (docs/room-objects.json) and
//! 471-475, ten seeds a row, `indoor_objects` is withdrawn if it meets
//! issue 18's indoor target in fewer of the 14 room rows than
//! `indoor_searched`, or its mean over those rows of (stride k-means +
//! k-means++ best of 10) / 2 is below `indoor_searched`'s. The presets and
//! the development seeds are the sixteenth round's, so its development
//! report (docs/room-objects-dev.json) is this round's too; no `--dev`
//! run. The test run refuses to overwrite its report.

use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, seventeenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[471, 472, 473, 474, 475];
const FILES: RoundFiles = RoundFiles {
    // The sixteenth round's: the same presets on the same seeds.
    dev: "room-objects-dev.json",
    report: "room-objects-2.json",
    md: "room-objects-2.md",
};
/// The first sample's report, pooled with this one for the rule.
const FIRST: &str = "room-objects.json";
const TEXT: RoundText = RoundText {
    example: "room_objects_again",
    test_seeds: "471-475",
    candidates_on: "; `indoor_searched` and `indoor_objects` on the room families",
};
const PRESET: &str = "indoor_objects";
const AGAINST: &str = "indoor_searched";
/// Issue 18's indoor target (%), each of stride k-means and best of 10.
const TARGET: f64 = 85.0;

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[])
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 471-475, commit 49da27d's code; the rule was fixed beforehand in seeds.md, commit 5fd9540 at 13:00). The development seeds' table below is the sixteenth round's (docs/room-objects-dev.json: the same presets on the same seeds), so the \"-- --dev\" step above is that round's and was not run again. The rule, computed above: the preset stays. Every preset's rows are new samples of unchanged presets and methods. Differences below are computed from the JSON, `indoor_objects` minus `indoor_searched`, stride k-means / best of 10; on these seeds the median standard error of a room row's five-seed mean is 2.2 points (0.0 to 6.9).

- **The lead held, again by little.** On 471-475 `indoor_objects` averages 87.6 % over the 14 room rows against `indoor_searched`'s 87.2 % and `indoor_columns`' 85.4 %, and meets the target in 8 rows against 7 and 5. Pooled with 461-465 (ten seeds a row): 8 rows against 7, 87.7 against 87.2 %.
- **Four rows moved as on 461-465, the others did not repeat.** As before: the office floor +5.3 / +3.8 (96.4 / 93.3 %) and at 0.3 m +4.4 / +2.2 (84.0 / 80.7 %, still short), the school at 0.3 m +8.4 / +5.7 (94.2 / 89.6 %, the only preset meeting the target there), and the school with 32 beams -4.9 / -2.5. Not as before: the hospital with its own sensor +0.9 / -1.8 (on 461-465 +5.8 / +3.6), the school with 16 and 64 beams -0.4 / -0.2 and -0.4 / -0.1 (there -4.4 / -1.5 and -3.6 / -1.7), the school with its own sensor -3.1 / +4.9 (there +4.9 / +6.9), the many buildings with 16 beams +0.4 / +0.1 (there +1.8 / -5.3). The rest: the one building -4.9 / +2.8 (still 95.1 / 96.8 %), the many buildings +0.9 / -4.7 (still 92.7 % with best of 10), the varied plans -2.7 / +1.9, the school at 1.8 m -1.8 / +0.3, the hospital with 16 beams -2.7 / +0.2. Hierarchical k-means++ rose on 7 rows and fell on 7 (-9.2 to +11.7 points); room-level 1-NN rose on 11 and fell on 3.
- **Pooled over both samples, row by row** (`indoor_objects`, stride k-means / best of 10): the target is met on the one building (96.4 / 97.8 %), the many buildings (96.2 / 88.5 %, with 16 beams 92.7 / 90.6 %), the varied plans (91.6 / 89.3 %), the office floor (93.3 / 90.9 %), the school with its own sensor (92.9 / 91.5 %), at 0.3 m (94.4 / 89.0 %) and at 1.8 m (96.2 / 96.8 %); missed on the office floor at 0.3 m (87.6 / 81.6 %), the school with 16, 32 and 64 beams (82.4 / 81.4, 81.3 / 80.1, 86.2 / 83.8 %; `indoor_searched` 84.9 / 82.2, 85.6 / 82.4, 88.2 / 84.7 %) and the hospital floors (83.8 / 80.9 %, with 16 beams 70.9 / 67.9 %).
- **Issue 18's indoor target on these seeds, read on the presets: met in 8 of 14 room rows by some preset, missed in 6 with every preset**: the office floor at 0.3 m, the school with 16, 32 and 64 beams (the nearest, with 32 beams, `indoor_clutter` 84.4 / 84.4 %) and both hospital rows (with its own sensor `indoor_objects` 86.7 / 78.3 %, `indoor_columns` 84.0 / 82.5 %; with 16 beams no preset above 72.0 % with stride k-means).
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.8 % (own sensor, lowest tree 97.0 %) and 99.1 % (32 beams, lowest 98.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 97.8 against 95.4 %, best of 10 97.8 against 95.4 %, the tree 98.1 against 95.5 %; 16 beams: 95.8 / 95.9 / 96.4 against 80.6 / 83.0 / 80.6 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The preset `indoor_objects` on a second fresh sample (issue 18, seventeenth round)\n"
    )?;
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let first: Report = read_json(&docs.join(FIRST))?;
    let pooled: Vec<FamilySet> = (first.test.families.iter())
        .chain(&r.test.families)
        .cloned()
        .collect();
    writeln!(o, "**Preset.** `indoor_objects` (`indoor_searched` and the objects part at weight 10), unchanged since the sixteenth round, where it stayed on 461-465 (docs/room-objects.md) by +0.5 points on the room rows' mean, the target met in 8 of 14 rows as with `indoor_searched`. No part, weight, preset or method changes here. The rule, fixed in docs/seeds.md before any run: pooled over 461-465 and 471-475 (ten seeds a row), withdrawn if it meets the target in fewer room rows than `indoor_searched`, or its mean over the room rows of (stride k-means + k-means++ best of 10) / 2 is below `indoor_searched`'s.\n")?;
    let standing = Standing::of(&pooled, (PRESET, AGAINST), TARGET);
    writeln!(
        o,
        "**The rule, computed** (pooled, ten seeds a row): over the {} room rows {standing}.\n",
        standing.rows
    )?;
    let alone = Standing::of(&r.test.families, (PRESET, AGAINST), TARGET);
    writeln!(
        o,
        "On 471-475 alone: `indoor_objects` {} rows, {:.1} %; `indoor_searched` {} rows, {:.1} %.\n",
        alone.met[0], alone.mean[0], alone.met[1], alone.mean[1]
    )?;
    round_body(&mut o, r, &FILES, &TEXT, NOTES)?;
    Ok(o)
}

fn main() -> Res<()> {
    family_round(
        &FILES,
        (FAMILY_DEV, FAMILY_TEST),
        &[AGAINST, PRESET],
        &[],
        family_set,
        render,
    )
}
