//! Issue 18, twelfth round: IRON as a global part (`iron`: how a scan's
//! planar NDT cells stand to each other, src/descriptor/iron.rs) added to
//! `indoor_columns`, against each family's presets of the earlier rounds
//! and `indoor_columns` itself.
//!
//!     cargo run --release --example iron -- --dev   # dev seeds -> docs/iron-dev.json
//!     cargo run --release --example iron            # test seeds, once: docs/iron.{json,md}
//!     ... -- --render   # docs/iron.md again from docs/iron.json
//!
//! Seeds, hypothesis, candidate and decision rule were fixed in
//! docs/seeds.md ("issue 18, twelfth round") before any run: issue 18's
//! families (examples/common/families.rs, every sensor) and the hospital
//! floors, on seeds 1-6 and 421-425. The candidate runs on the room
//! families only; the warehouse and outdoor rows are the presets'. Each set
//! at its true number of kinds: stride k-means, k-means++ best of 10,
//! hierarchical k-means++ with 10 trial splits (tree seeds 0-9: mean and
//! lowest), and room-level 1-NN. The test run refuses to overwrite its
//! report.

use placecat::descriptor::{DescriptorParams, Part, PartKind};
use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, twelfth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[421, 422, 423, 424, 425];
const FILES: RoundFiles = RoundFiles {
    dev: "iron-dev.json",
    report: "iron.json",
    md: "iron.md",
};
const TEXT: RoundText = RoundText {
    example: "iron",
    test_seeds: "421-425",
    candidates_on: "; the candidate on the room families",
};
/// The one candidate.
const WITH_IRON: &str = "columns + iron";
const CANDIDATES: [&str; 1] = [WITH_IRON];
/// The part's weight, fixed in the plan: the weight `columns` has in
/// `indoor_columns`.
const IRON_WEIGHT: f64 = 5.0;

/// `indoor_columns` with the `iron` part added.
fn with_iron() -> Res<DescriptorParams> {
    let mut p = DescriptorParams {
        preset: WITH_IRON.into(),
        ..DescriptorParams::preset(BASE)?
    };
    p.parts.push(Part {
        kind: PartKind::Iron,
        weight: IRON_WEIGHT,
    });
    p.validate()?;
    Ok(p)
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[(WITH_IRON, with_iron)])
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 421-425, commit e381ccc's code; the seeds, the hypothesis, the candidate and the decision rule were fixed beforehand in seeds.md). The decision, from the development seeds alone: the rule (a mean lift of at least 3 points with both stride k-means and best of 10 on the five rows docs/kinds-dev.md names) was not met, +0.7 / +0.9 points; the `iron` part becomes no preset. The presets' rows are new samples of unchanged presets and methods.

- **The iron part does not make the confused kinds compact.** On the test seeds, the five named rows (stride k-means / best of 10, `indoor_columns` then the candidate): the school with 16 beams 80.0 / 76.1 against 81.8 / 75.8 % (+1.8 / -0.3 points), with 32 beams 79.1 / 73.6 against 82.7 / 74.3 % (+3.6 / +0.7), the hospital floors 84.4 / 78.3 against 84.0 / 79.9 % (-0.4 / +1.6), with 16 beams 66.7 / 64.6 against 71.1 / 67.1 % (+4.4 / +2.5), the many buildings with 16 beams 90.2 / 87.4 against 88.4 / 86.5 % (-1.8 / -0.8). Mean lift +1.5 / +0.7 points, against +0.7 / +0.9 on the development seeds: on both seed sets a point or so, short of the 3 the rule asked. The other nine room rows gained +1.2 / +1.2 on average (the school at 1.8 m +7.6 / +3.6, the school with 64 beams +3.1 / -0.3, the office floor at 0.3 m -1.3 / +3.8, the school at 0.3 m -1.8 / +1.1, the one building +1.3 / +1.5, the varied plans -0.4 / +0.1, the many buildings and the office floor within 0.2). Room-level 1-NN rose a little on most rows and fell on the hospital floors (with 16 beams 71.6 against 68.4 %, with the own sensor 80.9 against 80.0 %). Hierarchical k-means++ moved either way (the many buildings +7.6, the office floor at 0.3 m +7.5, the school with 32 beams -3.2 points).
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets as in the eleventh round: met in 5 of 14 room rows, missed in 9.** Met: one building `indoor_plus` 96.0 / 95.6 %, many buildings `indoor_clutter` 95.1 / 97.5 %, with 16 beams 92.9 / 87.6 % (missed on 411-415 with 84.4 / 85.8 %), varied plans `indoor_clutter` 90.7 / 86.5 %, the office floor `indoor_columns` 87.6 / 86.4 %. Missed: the office floor at 0.3 m `indoor_columns` 88.0 / 79.8 % (met on 411-415 with 89.3 / 93.1 %), the school 84.4 / 76.8 %, with 16 beams 80.0 / 76.1 %, 32 beams 79.1 / 73.6 %, 64 beams 79.1 / 76.6 %, at 0.3 m 83.1 / 81.8 %, at 1.8 m 81.3 / 85.1 %, the hospital floors 84.4 / 78.3 % and with 16 beams 66.7 / 64.6 %. Best of 10 misses in eight of the nine, stride k-means in eight. Against 411-415 one row went from missed to met and one from met to missed; the same presets moved by up to 13 points a row (the office floor at 0.3 m's best of 10, 93.1 -> 79.8 %).
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.4 % (own sensor, lowest tree 97.0 %) and 98.5 % (32 beams, lowest 98.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 98.0 against 95.8 %, best of 10 98.2 against 95.8 %, the tree 98.3 against 96.1 %; 16 beams: 96.8 / 97.1 / 96.9 against 90.2 / 90.5 / 89.3 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidate is no preset and was not run on them).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# IRON as a global part: how a scan's surfaces stand to each other (issue 18, twelfth round)\n"
    )?;
    writeln!(o, "**Candidate.** `indoor_columns` with the part `iron` added at weight {IRON_WEIGHT} (the weight `columns` has there; no preset): after IRON (Schmiedel, Einhorn and Gross, IROS 2015), whose keypoint descriptor is a histogram of neighbouring NDT cells by distance and by the angle between their normals; here every planar NDT cell (0.4 m) within 16 m is a keypoint and the histograms over pairs within 4 m are summed over the scan: the separation of parallel pairs, the angle between normals, the distance of perpendicular pairs (src/descriptor/iron.rs). The hypothesis and the decision rule, written in docs/seeds.md before any run: how a room's surfaces stand to each other changes less from one spot of a room to another than what is seen at each range (docs/kinds-dev.md found the confused kinds spread scan by scan), so the part makes those kinds more compact.\n")?;
    round_body(&mut o, r, &FILES, &TEXT, NOTES)?;
    Ok(o)
}

fn main() -> Res<()> {
    family_round(
        &FILES,
        (FAMILY_DEV, FAMILY_TEST),
        &CANDIDATES,
        &CANDIDATES,
        family_set,
        render,
    )
}
