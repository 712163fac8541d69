//! Issue 18, eleventh round: the `clutter` and `columns` parts measuring
//! heights from each scan's true floor (an oracle: `sensor_height` set,
//! scan by scan, to the simulated sensor's height above the floor), against
//! each family's presets of the earlier rounds and `indoor_columns`, which
//! measures from each scan's own estimate.
//!
//!     cargo run --release --example true_floor -- --dev   # dev seeds -> docs/true-floor-dev.json
//!     cargo run --release --example true_floor            # test seeds, once: docs/true-floor.{json,md}
//!     ... -- --render   # docs/true-floor.md again from docs/true-floor.json
//!
//! Seeds, hypothesis and decision rule were fixed in docs/seeds.md ("issue
//! 18, eleventh round") before any run: issue 18's families
//! (examples/common/families.rs, every sensor) and the hospital floors, on
//! seeds 1-6 and 411-415. The candidate runs on the room families only;
//! the warehouse and outdoor rows are the presets'. Each set at its true
//! number of kinds: stride k-means, k-means++ best of 10, hierarchical
//! k-means++ with 10 trial splits (tree seeds 0-9: mean and lowest), and
//! room-level 1-NN. The test run refuses to overwrite its report.

use placecat::descriptor::DescriptorParams;
use placecat::sim::SimScan;
use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, eleventh round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[411, 412, 413, 414, 415];
const FILES: RoundFiles = RoundFiles {
    dev: "true-floor-dev.json",
    report: "true-floor.json",
    md: "true-floor.md",
};
const TEXT: RoundText = RoundText {
    example: "true_floor",
    test_seeds: "411-415",
    candidates_on: "; the candidate on the room families",
};
/// The one candidate.
const TRUE_FLOOR: &str = "columns, true floor";
const CANDIDATES: [&str; 1] = [TRUE_FLOOR];

/// `indoor_columns` measuring from this scan's true floor: the room
/// families stand on a floor at z = 0 (src/sim), so the sensor's height
/// above it is its pose's z. A height outside what the parameters take
/// would be a scene this round does not know: describing then fails, and
/// the set drops the candidate loudly (its row goes missing) rather than
/// measuring from a wrong floor.
fn true_floor(base: &DescriptorParams, scan: &SimScan) -> DescriptorParams {
    DescriptorParams {
        sensor_height: Some(scan.pose.position[2]),
        ..base.clone()
    }
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let per_scan: Vec<(String, DescriptorParams, PerScan)> =
        if presets.iter().any(|p| p == TRUE_FLOOR) {
            let base = DescriptorParams {
                preset: TRUE_FLOOR.into(),
                ..DescriptorParams::preset(BASE)?
            };
            vec![(TRUE_FLOOR.to_string(), base, true_floor as PerScan)]
        } else {
            vec![]
        };
    let set = describe_set_per_scan(f, sensor, seed, &without(presets, &CANDIDATES), &per_scan)?;
    if per_scan.len() == 1 && !set.presets.iter().any(|p| p.0 == TRUE_FLOOR) {
        return Err(format!(
            "{} {} seed {seed}: a scan's true floor was refused",
            f.name,
            sensor.name()
        )
        .into());
    }
    measured_set(f, sensor, seed, &set)
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 411-415, commit 6f00675's code; the seeds, the hypothesis and the decision rule were fixed beforehand in seeds.md). The decision, from the development seeds alone: the rule (a mean lift of at least 3 points with both stride k-means and best of 10 on the 16- and 32-beam room rows) was not met, +1.9 / +1.9 points; no preset changes and the docs do not recommend `sensor_height` for sparse sensors. The presets' rows are new samples of unchanged presets and methods.

- **The true floor does not explain the sparse sensors' misses.** On the test seeds, the rows the rule names (stride k-means / best of 10, `indoor_columns` then the true floor): the many buildings with 16 beams 86.2 / 80.7 against 88.9 / 85.6 % (+2.7 / +5.0 points), the hospital floors with 16 beams 69.8 / 66.9 against 71.1 / 70.8 % (+1.3 / +3.9), the school with 16 beams 83.6 / 79.9 against 81.8 / 81.3 % (-1.8 / +1.4), with 32 beams 86.2 / 78.8 against 86.2 / 78.1 % (0.0 / -0.6). Mean lift +0.6 / +2.4 points, below the development seeds' +1.9 / +1.9. As there, the true floor helps the hospital and the many buildings with 16 beams, by a few points, and not the school. Where the sensor sees the floor it changes little or costs: the office floor 93.3 / 91.1 against 92.4 / 88.9 % (-0.9 / -2.2; -4.1 / -1.9 on development seeds), the hospital floors 79.1 / 77.0 against 77.8 / 76.1 %, the school at 1.8 m 80.9 / 83.4 against 80.0 / 83.0 %, the school with 64 beams 83.1 / 77.8 against 83.1 / 78.3 %; the one building, the many buildings, the varied plans, the school and the 0.3 m mounts within half a point. Room-level 1-NN moved the same way (the hospital with 16 beams 71.6 against 76.9 %, the office floor 95.1 against 91.6 %). Even with the floor exact, the hospital with 16 beams stays 14 points short of the target.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets as in the tenth round: met in 5 of 14 room rows, missed in 9.** Met: one building `indoor_plus` 93.3 / 88.4 %, many buildings `indoor_clutter` 96.0 / 89.2 %, varied plans `indoor_clutter` 88.4 / 92.0 %, the office floor `indoor_columns` 93.3 / 91.1 %, at 0.3 m 89.3 / 93.1 %. Missed: many buildings with 16 beams `indoor_clutter` 84.4 / 85.8 %, the school `indoor_columns` 79.6 / 79.5 %, with 16 beams 83.6 / 79.9 %, 32 beams 86.2 / 78.8 %, 64 beams 83.1 / 77.8 %, at 0.3 m 85.8 / 83.2 %, at 1.8 m 80.9 / 83.4 % (met on 391-395 with 93.8 / 85.8 %), the hospital floors 79.1 / 77.0 % and with 16 beams 69.8 / 66.9 %. Against 391-395 (6 of 14 met) the school at 1.8 m went from met to missed, no row the other way, and the one building's best of 10 fell from 97.0 to 88.4 %; the many buildings with 16 beams now misses with stride k-means (91.1 -> 84.4 %) instead of best of 10 (84.6 -> 85.8 %). On these seeds `indoor_clutter` did better than `indoor_columns` on the school rows but for stride k-means with 32 beams (84.9 against 86.2 %; the school 89.8 / 85.4 %, at 1.8 m 88.0 / 88.6 %): the presets the targets are read on were chosen on earlier seeds and are not re-chosen on these.
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.5 % (own sensor, lowest tree 96.0 %) and 97.9 % (32 beams, lowest 96.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 98.2 against 95.6 %, best of 10 98.1 against 95.8 %, the tree 97.9 against 95.6 %; 16 beams: 96.2 / 96.1 / 96.2 against 82.4 / 84.7 / 84.3 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidate is an oracle, no preset, and was not run on them: the real scans' sensor heights are not all known).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# Each scan's true floor: does the floor's error explain the sparse sensors? (issue 18, eleventh round)\n"
    )?;
    writeln!(o, "**Candidate.** `indoor_columns` with `sensor_height` set, scan by scan, to that scan's true height above the floor (an oracle, no preset; what a robot with a fixed, known mount gives). `indoor_columns` itself measures the `clutter` and `columns` heights from each scan's own floor estimate (the 2nd percentile of height within 8 m). The hypothesis and the decision rule, written in docs/seeds.md before any run: where the sensor does not see the floor (16 and 32 beams), the true floor separates the confused kinds better.\n")?;
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
