//! Issue 18, thirteenth round: the part weights a search found on
//! development seeds (docs/weights-dev.md, `examples/weights_search.rs`)
//! against each family's presets of the earlier rounds and
//! `indoor_columns` itself.
//!
//!     cargo run --release --example searched -- --dev   # dev seeds -> docs/searched-dev.json
//!     cargo run --release --example searched            # test seeds, once: docs/searched.{json,md}
//!     ... -- --render   # docs/searched.md again from docs/searched.json
//!
//! Seeds, hypothesis, the search's procedure and the decision rule were
//! fixed in docs/seeds.md ("issue 18, thirteenth round") before any run;
//! the rule was read on seeds 4-6 by `weights_search` (not met: no preset).
//! Issue 18's families (examples/common/families.rs, every sensor) and the
//! hospital floors, on seeds 1-6 and 431-435. The candidate runs on the
//! room families only; the warehouse and outdoor rows are the presets'.
//! Each set at its true number of kinds: stride k-means, k-means++ best of
//! 10, hierarchical k-means++ with 10 trial splits (tree seeds 0-9: mean and
//! lowest), and room-level 1-NN. The test run refuses to overwrite its
//! report.

use placecat::descriptor::DescriptorParams;
use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, thirteenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[431, 432, 433, 434, 435];
const FILES: RoundFiles = RoundFiles {
    dev: "searched-dev.json",
    report: "searched.json",
    md: "searched.md",
};
const TEXT: RoundText = RoundText {
    example: "searched",
    test_seeds: "431-435",
    candidates_on: "; the candidate on the room families",
};
/// The one candidate.
const SEARCHED: &str = "searched weights";
const CANDIDATES: [&str; 1] = [SEARCHED];
/// The search's output, which names the weights.
const SEARCH: &str = "weights-dev.json";
/// The weights the test run was made with (docs/weights-dev.json, commit
/// 7fa6525): the NDT histogram's, then one per part kind (`objects`, added
/// after it, 0).
const TESTED: [f32; 10] = [1.0, 0.0, 4.0, 32.0, 1.0, 10.0, 0.0, 5.0, 10.0, 0.0];

/// `indoor_columns`' parameters with the weights the search found.
fn searched() -> Res<DescriptorParams> {
    searched_weights(SEARCHED, SEARCH, BASE, &TESTED)
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[(SEARCHED, searched)])
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 431-435, commit 7fa6525's code; the seeds, the hypothesis, the search's procedure and the decision rule were fixed beforehand in seeds.md). The decision, from seeds 4-6 alone (docs/weights-dev.md): the rule (a mean lift of at least 3 points with both stride k-means and best of 10 on the nine room rows that missed on 421-425, the others' mean falling by less than 2) was not met, +1.0 / +1.3 points; the weights become no preset. Check: the candidate's own descriptors (only the parts it weighs) give every figure of the search's weighting over all-part descriptors on seeds 1-6 (168 figures, none differs). The presets' rows are new samples of unchanged presets and methods.

- **The search overfits its own seeds, and the weights still carry over in part.** The search raised its objective on seeds 1-3 from 85.0 to 89.5 %; on seeds 4-6 the nine rows rose by +1.0 / +1.3 points, on these test seeds by +2.4 / +2.7 (stride k-means / best of 10, `indoor_columns` then the candidate): the school 88.9 / 82.1 against 95.6 / 86.3 %, with 16 beams 84.9 / 84.0 against 87.1 / 88.8 %, 32 beams 85.3 / 77.0 against 88.0 / 85.2 %, 64 beams 89.3 / 80.0 against 89.3 / 87.2 %, at 0.3 m 92.4 / 88.6 against 95.1 / 90.2 %, at 1.8 m 95.1 / 92.8 against 99.1 / 96.8 %; the hospital floors 79.1 / 81.8 against 80.0 / 81.9 %, with 16 beams 68.0 / 68.6 against 72.9 / 70.6 %; **the office floor at 0.3 m fell**, 88.9 / 90.0 against 86.2 / 81.5 %. On both judging sets the lift is short of the 3 points the rule asks, so the rule's verdict would not change. The other five room rows gained +1.6 / +7.8: the one building 91.6 / 80.3 against 93.8 / 92.6 %, the many buildings 97.3 / 83.5 against 94.7 / 90.3 %, with 16 beams 89.3 / 83.5 against 96.4 / 94.6 %, the varied plans 88.4 / 77.8 against 95.1 / 84.7 %; **the office floor with its own sensor fell with stride k-means**, 91.1 / 85.5 against 85.8 / 87.3 %. Room-level 1-NN fell on the office floor (93.8 against 88.9 %, at 0.3 m 91.1 against 81.8 %) and moved by at most 3.1 points elsewhere; hierarchical k-means++ rose on 11 of the 14 rows (the many buildings +9.3 points) and fell on the office floor (-1.9, at 0.3 m -3.3) and the hospital with 16 beams (-0.8). The weights the search kept (ESF 2 -> 32, iron 0 -> 10, slice 2 -> 4, ring 2 -> 1) move the distance from what stands in a room towards the shape of the whole scan and how its surfaces stand to each other; the office floor, whose confused kinds differ in what stands in them (a private office and a restroom of one size; docs/seeds.md, eighth round), is where that costs.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets as in the twelfth round: met in 7 of 14 room rows, missed in 7.** Met: one building `indoor_plus` 92.4 / 92.3 %, many buildings `indoor_clutter` 95.1 / 88.7 %, with 16 beams 92.4 / 87.9 %, the office floor `indoor_columns` 91.1 / 85.5 %, at 0.3 m 88.9 / 90.0 %, the school at 0.3 m 92.4 / 88.6 %, at 1.8 m 95.1 / 92.8 %. Missed: the varied plans `indoor_clutter` 94.2 / 82.3 % (met on 421-425), the school `indoor_columns` 88.9 / 82.1 %, with 16 beams 84.9 / 84.0 %, 32 beams 85.3 / 77.0 %, 64 beams 89.3 / 80.0 %, the hospital floors 79.1 / 81.8 % and with 16 beams 68.0 / 68.6 %. Best of 10 misses in all seven, stride k-means in three. The candidate, no preset, meets it in 10 of 14 (all but the varied plans' best of 10 at 84.7 %, the office floor at 0.3 m and the two hospital rows).
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.6 % (own sensor, lowest tree 96.0 %) and 99.0 % (32 beams, lowest 98.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 97.8 against 97.0 %, best of 10 98.0 against 96.9 %, the tree 97.3 against 95.6 %; 16 beams: 96.0 / 95.8 / 89.4 against 86.6 / 86.8 / 87.9 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidate is no preset and was not run on them).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    let p = searched()?;
    writeln!(
        o,
        "# Part weights chosen by a search (issue 18, thirteenth round)\n"
    )?;
    writeln!(o, "**Candidate.** `indoor_columns`' descriptor with the weights a coordinate-ascent search found on development seeds 1-3 ({}; `indoor_columns` has the NDT histogram 1, slice, ESF and ring 2 each, clutter 10, columns 5): docs/weights-dev.md, `cargo run --release --example weights_search`. The procedure, its objective and the decision rule were written in docs/seeds.md before any run; on seeds 4-6, which the search never saw, the rule was not met, so the candidate is no preset and is reported here beside them.\n", weights_text(&p))?;
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
