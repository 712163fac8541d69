//! Issue 18, sixteenth round: the preset `indoor_objects` (`indoor_searched`
//! and the objects part at the weight chosen on development seeds 1-6,
//! made a preset on seeds 7-9; docs/objects-round-dev.md) on fresh test
//! seeds, beside each family's presets of the earlier rounds,
//! `indoor_columns` and `indoor_searched`.
//!
//!     cargo run --release --example room_objects -- --dev   # dev seeds -> docs/room-objects-dev.json
//!     cargo run --release --example room_objects            # test seeds, once: docs/room-objects.{json,md}
//!     ... -- --render   # docs/room-objects.md again from its .json
//!
//! The preset and the rule that withdraws it were fixed in docs/seeds.md
//! ("issue 18, sixteenth round") before any run: it is withdrawn if on the
//! test seeds it meets issue 18's indoor target in fewer of the 14 room
//! rows than `indoor_searched`, or its mean over those rows of (stride
//! k-means + k-means++ best of 10) / 2 is below `indoor_searched`'s. The
//! report computes that verdict. Issue 18's families
//! (examples/common/families.rs, every sensor) and the hospital floors, on
//! seeds 1-6 and 461-465; the preset runs on the room families. Each set
//! at its true number of kinds: stride k-means, k-means++ best of 10,
//! hierarchical k-means++ with 10 trial splits (tree seeds 0-9: mean and
//! lowest), and room-level 1-NN. The test run refuses to overwrite its
//! report.

use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, sixteenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[461, 462, 463, 464, 465];
const FILES: RoundFiles = RoundFiles {
    dev: "room-objects-dev.json",
    report: "room-objects.json",
    md: "room-objects.md",
};
const TEXT: RoundText = RoundText {
    example: "room_objects",
    test_seeds: "461-465",
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
const NOTES: &str = "Written after the one test run (seeds 461-465, commit f948e7b's code; the part's constants, the weights tried, the seeds and both rules were fixed beforehand in seeds.md, commit c1486b3 at 11:58; the preset was made by the development rule in 518e73f and f948e7b before this run). The rule, computed above: the preset stays. Every other preset's rows are new samples of unchanged presets and methods. Differences below are computed from the JSON, `indoor_objects` minus `indoor_searched`, stride k-means / best of 10.

- **The objects part held up on fresh seeds, by a small margin.** Over the 14 room rows `indoor_objects` averages 87.8 % against `indoor_searched`'s 87.3 % and `indoor_columns`' 83.1 % (the mean of stride k-means and best of 10), and meets the target in 8 rows against 8 and 2: not in the same rows. +0.5 points on the mean is within a row's noise (the median standard error of a room row's five-seed mean is 3.4 points here; on seeds 7-9 the difference was +0.9); per seed, a row's difference of (stride k-means + best of 10) / 2 runs from -15.6 to +20.1 points.
- **Where it gained: the rooms whose furniture differs, seen with the sensor's own beams.** The school with its own sensor +4.9 / +6.9 (93.3 / 93.1 %) and at 0.3 m +4.0 / +4.0 (94.7 / 88.4 %, meeting it), the hospital with its own sensor +5.8 / +3.6 (80.9 / 83.6 %, still short) and the office floor at 0.3 m +5.8 / +1.5, as on seeds 7-9; the office floor with its own sensor +4.9 / +4.4 (90.2 / 88.5 %, meeting the target, which no other preset does there), which on seeds 7-9 had lost with stride k-means (-5.2 / +2.7); the school at 1.8 m with best of 10 (+5.6; stride k-means -1.8).
- **Where it lost: the school with 16, 32 and 64 beams** (-4.4 / -1.5, -3.6 / -2.1, -3.6 / -1.7; the 64-beam row still meets the target, 87.1 / 85.9 %), and why is not known: alone, the objects told those rows' kinds apart about as well on the development seeds as on the school rows where they gained (room-level 1-NN 65.6-77.0 against 69.3-77.4 %, docs/objects-dev.md); best of 10 on the many buildings (-6.3, with 16 beams -5.3; the own-sensor row falls below the target, 94.2 / 84.4 %); the varied plans (-1.8 / -1.1); the hospital with 16 beams on stride k-means (-5.8; +1.3 with best of 10). Hierarchical k-means++ rose on 6 rows and fell on 8 (-6.3 to +5.1 points); room-level 1-NN rose on 7, fell on 5 and held on 2.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets: met in 11 of 14 room rows by some preset**: `indoor_objects` on 8 (alone on the office floor and on the school at 0.3 m), `indoor_searched` on 8 (alone on the school with 16 beams, 86.7 / 86.4 %; on the many buildings with its own sensor with the paper's `indoor`), `indoor_clutter` alone on the school with 32 beams (85.3 / 86.8 %). **Missed in 3 with every preset:** the office floor at 0.3 m (`indoor_objects` 91.1 / 82.5 %, `indoor_searched` 85.3 / 81.0 %) and both hospital rows (best: `indoor_objects` 80.9 / 83.6 % with its own sensor; 16 beams `indoor_searched` 79.1 / 68.4 %, `indoor_objects` 73.3 / 69.7 %). No one preset meets it on more than 8.
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.5 % (own sensor, lowest tree 96.0 %) and 99.1 % (32 beams, lowest 98.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 98.4 against 96.2 %, best of 10 98.6 against 96.1 %, the tree 97.8 against 95.6 %; 16 beams: 94.8 / 95.2 / 95.2 against 78.6 / 82.2 / 74.2 %.
- **Real scans:** every preset of the round, `indoor_objects` included, finds a scan of the same place for 18 of 18 real scans.";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The preset `indoor_objects` on fresh seeds (issue 18, sixteenth round)\n"
    )?;
    let standing = Standing::of(&r.test.families, (PRESET, AGAINST), TARGET);
    writeln!(o, "**Preset.** `indoor_objects`: `indoor_searched` (the NDT histogram 1, slice 4, ESF 32, ring 1, clutter 10, columns 5, iron 10) and the objects part (what stands in the room cut into connected 0.1 m cells: histograms of the objects' footprints, tops and roundness, and their number per m² seen; `src/descriptor/objects.rs`) at weight 10. The weight was chosen among 2, 5, 10 and 20 on development seeds 1-6, and on seeds 7-9 the candidate met the indoor target in 7 of 14 room rows against 4 for `indoor_searched`, its mean 86.3 against 85.4 % (docs/objects-round-dev.md, `cargo run --release --example objects_round`), so by the rule fixed in docs/seeds.md before any run it became a preset, and these fresh seeds judge it. The rule: withdrawn if on the test seeds it meets the target in fewer room rows than `indoor_searched`, or its mean over the room rows of (stride k-means + k-means++ best of 10) / 2 is below `indoor_searched`'s.\n")?;
    writeln!(
        o,
        "**The rule, computed:** over the {} room rows of the test seeds, {standing}.\n",
        standing.rows
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
