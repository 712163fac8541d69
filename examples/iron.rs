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
use std::path::Path;

#[path = "common/families.rs"]
mod families;
use families::*;
#[path = "common/real.rs"]
mod real;
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
// This round has no site: the shared site code goes unused here.
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use site_rounds::*;
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
use preset_rounds::*;
#[path = "common/family_sets.rs"]
mod family_sets;
use family_sets::*;
#[path = "common/seeds.rs"]
mod seeds;

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

/// The presets to describe with: `names` but the candidate.
fn described(names: &[String]) -> Vec<String> {
    names
        .iter()
        .filter(|n| !CANDIDATES.contains(&n.as_str()))
        .cloned()
        .collect()
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    let wanted = presets.iter().any(|p| p == WITH_IRON);
    let set = describe_set_with(f, sensor, seed, &described(presets), |_| {
        Ok(if wanted {
            vec![(WITH_IRON.to_string(), with_iron()?)]
        } else {
            vec![]
        })
    })?;
    if wanted && !set.presets.iter().any(|p| p.0 == WITH_IRON) {
        return Err(format!(
            "{} {} seed {seed}: a scan could not be described with the candidate",
            f.name,
            sensor.name()
        )
        .into());
    }
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

/// What the round showed, written after its one test run.
const NOTES: &str = "(written after the test run)";

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
    seeds::check_round_seeds(FAMILY_DEV, FAMILY_TEST)?;
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = round_presets(&docs, &CANDIDATES)?;
    every_family_round(
        &FILES,
        &presets,
        (FAMILY_DEV, FAMILY_TEST),
        family_set,
        described,
        render,
    )
}
