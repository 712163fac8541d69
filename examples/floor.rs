//! Issue 18, tenth round: the `clutter` and `columns` parts measuring
//! heights from a floor given as the sensor's height above it
//! (`sensor_height`), in place of each scan's own estimate, against each
//! family's presets of the earlier rounds and `indoor_columns`.
//!
//!     cargo run --release --example floor -- --dev   # dev seeds -> docs/floor-dev.json
//!     cargo run --release --example floor            # test seeds, once: docs/floor.{json,md}
//!     ... -- --render   # docs/floor.md again from docs/floor.json
//!
//! Seeds were fixed in docs/seeds.md ("issue 18, tenth round") before any
//! run: issue 18's families (examples/common/families.rs, every sensor)
//! and the hospital floors, on seeds 1-6 and 391-395. The candidates run
//! on the room families only (the indoor target); the warehouse and
//! outdoor rows are the presets'. Each set at its true number of kinds:
//! stride k-means, k-means++ best of 10, hierarchical k-means++ with 10
//! trial splits (tree seeds 0-9: mean and lowest), and room-level 1-NN.
//! The test run refuses to overwrite its report.

use placecat::descriptor::clutter::floor_and_ceiling;
use placecat::descriptor::DescriptorParams;
use placecat::sim::Simulation;
use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, tenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[391, 392, 393, 394, 395];
const FILES: RoundFiles = RoundFiles {
    dev: "floor-dev.json",
    report: "floor.json",
    md: "floor.md",
};
const TEXT: RoundText = RoundText {
    example: "floor",
    test_seeds: "391-395",
    candidates_on: "; the candidates on the room families",
};
/// The candidates, in the order of the tables.
const SENSOR_HEIGHT: &str = "columns, sensor's height";
const COLLECTION_FLOOR: &str = "columns, collection's floor";
const CANDIDATES: [&str; 2] = [SENSOR_HEIGHT, COLLECTION_FLOOR];

/// The simulated sensor's nominal height above the floor: the room
/// families draw each scan's from 1.0 to 1.3 m (src/sim), so the middle,
/// 1.15 m; a mount's own height where the sensor is one.
fn nominal_height(sensor: Sensor) -> f64 {
    match sensor {
        Sensor::Height(h) => h,
        _ => 1.15,
    }
}

/// The collection's floor: the 10th percentile of the scans' own floor
/// estimates (the lowest ones are those that saw the floor; the 10th
/// rather than the lowest, so one stray low point does not decide), as a
/// height below the sensor. None with no scan that has a floor.
fn collection_floor(sim: &Simulation) -> Option<f64> {
    let mut floors: Vec<f32> = (0..sim.len())
        .filter_map(|i| floor_and_ceiling(&sim.scan(i).points).map(|f| f.0))
        .collect();
    if floors.is_empty() {
        return None;
    }
    floors.sort_unstable_by(f32::total_cmp);
    let k = ((floors.len() - 1) as f64 * 0.1).round() as usize;
    Some(-floors[k] as f64)
}

/// `indoor_columns` with the floor `height` below the sensor, named `name`.
fn with_height(name: &str, height: f64) -> DescriptorParams {
    DescriptorParams {
        preset: name.into(),
        sensor_height: Some(height),
        ..DescriptorParams::indoor_columns()
    }
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let wanted = |c: &str| presets.iter().any(|p| p == c);
    let set = describe_set_with(f, sensor, seed, &without(presets, &CANDIDATES), |sim| {
        let mut extra = vec![];
        if wanted(SENSOR_HEIGHT) {
            extra.push((
                SENSOR_HEIGHT.to_string(),
                with_height(SENSOR_HEIGHT, nominal_height(sensor)),
            ));
        }
        if wanted(COLLECTION_FLOOR) {
            let h = collection_floor(sim)
                .ok_or_else(|| format!("{} {} seed {seed}: no floor", f.name, sensor.name()))?;
            extra.push((
                COLLECTION_FLOOR.to_string(),
                with_height(COLLECTION_FLOOR, h),
            ));
        }
        Ok(extra)
    })?;
    measured_set(f, sensor, seed, &set)
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 391-395, commit e345cfd's code; the seeds, the hypothesis and the decision were fixed beforehand in seeds.md). The decision, from the development seeds alone: no preset, since a given floor fell far with the own sensors and helped only with 16 beams, on rows it left short of the target; `sensor_height` stays an option no preset uses. The presets' rows are new samples of unchanged presets and methods.

- **The hypothesis was not supported with a nominal or a collection-wide height.** Measuring the `clutter` and `columns` parts from a floor given that way lifted none of the rows it was aimed at above `indoor_columns` with both methods, and none that missed to the target. Against `indoor_columns` (stride k-means / best of 10) on the test seeds, the sensor's nominal height: the school with 16 beams 83.1 / 73.3 against 83.1 / 76.7 %, 32 beams 72.4 / 68.1 against 81.8 / 76.9 %, at 0.3 m 91.1 / 81.6 against 92.9 / 80.7 %; the office floor at 0.3 m 90.7 / 85.6 against 91.1 / 87.3 %; the hospital floors 69.8 / 60.6 against 83.1 / 79.2 %, with 16 beams 67.1 / 69.2 against 69.8 / 69.1 %; the many buildings 86.2 / 78.6 against 95.1 / 91.8 %, with 16 beams 88.4 / 83.5 against 86.7 / 84.8 %. The collection's floor was lower still on most (the hospital 54.2 / 52.4 %, the school with 32 beams 69.3 / 62.5 %), about equal at the 0.3 m mounts (the office floor 91.1 / 87.3 %, the school 92.9 / 80.4 against 92.9 / 80.7 %), a point either way with 16 beams on the hospital and the many buildings, and lower on the school with 16 beams (80.4 / 72.1 against 83.1 / 76.7 %). With the own sensors both fell far, as on the development seeds: the office floor 77.8 / 72.7 and 71.6 / 64.8 against 90.7 / 91.6 %, the school 68.9 / 64.4 and 65.3 / 55.4 against 88.9 / 82.8 %. The development seeds' gain on the hospital with 16 beams (+4.4 / +5.5 points with the nominal height) did not come back (-2.7 / +0.1). Why, as read on the development seeds: the room families draw each scan's sensor height from 1.0 to 1.3 m, so one given height leaves each scan up to 0.15 m off, which moves every height of the two parts by that scan's error, more than the estimate is off where the floor is seen; where the height is exact (the 0.3 and 1.8 m mounts) the floor was seen anyway and little changes. The 16-beam rows draw their mount from 1.0 to 1.3 m too, so there the given height's error is as large as the estimate's it was to replace: the hypothesis itself (the true floor helps where it is not seen) was not tested, which would take each scan's true height or a family with a fixed mount and a sensor that does not see the floor. The option is meant for that case; these figures neither support nor rule it out.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets as decided: met in 6 of 14 room rows, missed in 8.** Met: one building `indoor_plus` 95.6 / 97.0 %, many buildings `indoor_clutter` 96.0 / 93.0 %, varied plans `indoor_clutter` 94.2 / 90.4 %, the office floor `indoor_columns` 90.7 / 91.6 %, at 0.3 m 91.1 / 87.3 %, the school at 1.8 m 93.8 / 85.8 %. Missed: many buildings with 16 beams `indoor_clutter` 91.1 / 84.6 %, the school `indoor_columns` 88.9 / 82.8 % (met on 381-385 with 86.7 / 86.2 %), with 16 beams 83.1 / 76.7 %, 32 beams 81.8 / 76.9 %, 64 beams 87.6 / 82.0 % (met on 381-385), at 0.3 m 92.9 / 80.7 %, the hospital floors 83.1 / 79.2 % and with 16 beams 69.8 / 69.1 %. Best of 10 misses in all eight; stride k-means in four (the school with 16 and 32 beams, the hospital with both sensors). Against the ninth round's seeds (381-385) three rows went from met to missed (the school with its own sensor and with 64 beams, the many buildings with 16 beams) and two from missed to met (the many buildings with its own sensor, 94.2 / 81.9 -> 96.0 / 93.0 %; the office floor at 0.3 m, 84.9 / 83.2 -> 91.1 / 87.3 %); the presets the targets are read on moved by up to 11 points a row (that best of 10, 81.9 -> 93.0 %): five 45-scan sets do not read a row to better than a few points.
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.1 % (own sensor, lowest tree 95.0 %) and 98.0 % (32 beams, lowest 95.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 97.8 against 96.0 %, best of 10 97.8 against 96.0 %, the tree 98.0 against 96.0 %; 16 beams: 96.8 / 97.2 / 97.7 against 88.6 / 88.2 / 87.8 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidates are no presets and were not run on them: the real scans' sensor heights are not all known).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    writeln!(
        o,
        "# The floor the robot knows: heights from the sensor's height (issue 18, tenth round)\n"
    )?;
    writeln!(o, "**Candidates.** With `\"sensor_height\": h` (m above the floor) the `clutter` and `columns` parts measure heights from a floor `h` below the sensor instead of each scan's own estimate (the 2nd percentile of height within 8 m). Two candidates on `indoor_columns`: the simulated sensor's nominal height (1.15 m, the middle of the 1.0-1.3 m the room families draw per scan; 0.3 and 1.8 m for those mounts), and the collection's floor (the 10th percentile of the set's own floor estimates, no input). The hypothesis, written in docs/seeds.md before any run: with 16 beams the floor is not seen in small rooms and the estimate lands 0.1-0.2 m up, on what stands in them.\n")?;
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
