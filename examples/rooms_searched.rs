//! Issue 18, fifteenth round: the part weights the wider search found on
//! development sets (docs/rooms-dev.md, `examples/rooms_search.rs`) against
//! each family's presets of the earlier rounds, `indoor_columns` and
//! `indoor_searched`.
//!
//!     cargo run --release --example rooms_searched -- --dev   # dev seeds -> docs/rooms-searched-dev.json
//!     cargo run --release --example rooms_searched            # test seeds, once: docs/rooms-searched.{json,md}
//!     ... -- --render   # docs/rooms-searched.md again from its .json
//!
//! Seeds, hypothesis, the search's procedure and the decision rule were
//! fixed in docs/seeds.md ("issue 18, fifteenth round") before any run;
//! the rule was read on seeds 7-9 by `rooms_search` (not met: no preset).
//! Issue 18's families (examples/common/families.rs, every sensor) and the
//! hospital floors, on seeds 1-6 and 451-455. The candidate runs on the
//! room families only; the warehouse and outdoor rows are the presets'.
//! Each set at its true number of kinds: stride k-means, k-means++ best of
//! 10, hierarchical k-means++ with 10 trial splits (tree seeds 0-9: mean and
//! lowest), and room-level 1-NN. The test run refuses to overwrite its
//! report.

use placecat::descriptor::DescriptorParams;
use std::fmt::Write;

include!("common/family_round.rs");

/// Fixed in docs/seeds.md ("issue 18, fifteenth round") before any run.
const FAMILY_DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const FAMILY_TEST: &[u64] = &[451, 452, 453, 454, 455];
const FILES: RoundFiles = RoundFiles {
    dev: "rooms-searched-dev.json",
    report: "rooms-searched.json",
    md: "rooms-searched.md",
};
const TEXT: RoundText = RoundText {
    example: "rooms_searched",
    test_seeds: "451-455",
    candidates_on: "; the candidate on the room families",
};
/// The preset the search started from, whose descriptor settings the
/// candidate keeps.
const START: &str = "indoor_searched";
/// The one candidate.
const SEARCHED: &str = "wider search's weights";
const CANDIDATES: [&str; 1] = [SEARCHED];
/// The search's output, which names the weights.
const SEARCH: &str = "rooms-dev.json";
/// The weights the test run was made with (docs/rooms-dev.json, commit
/// 66e7696): the NDT histogram's, then one per part kind (`objects`, added
/// after it, 0).
const TESTED: [f32; 10] = [0.0, 0.0, 4.0, 16.0, 1.0, 20.0, 0.0, 5.0, 10.0, 0.0];

/// `indoor_searched`'s parameters with the weights the wider search found.
fn searched() -> Res<DescriptorParams> {
    searched_weights(SEARCHED, SEARCH, START, &TESTED)
}

fn family_set(f: &Family, sensor: Sensor, seed: u64, presets: &[String]) -> Res<FamilySet> {
    candidate_set(f, sensor, seed, presets, &[(SEARCHED, searched)])
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 451-455, commit 68e3bea's code; the seeds, the hypothesis, the search's procedure, its objective and the decision rule were fixed beforehand in seeds.md at 09:27, commit 3b0a2b9). The decision, from seeds 7-9 alone (docs/rooms-dev.md, written by `rooms_search` at 09:38 and committed in 66e7696 before this run): the candidate met the indoor target in 5 of the 14 room rows against 4 for `indoor_searched`, but its mean over the rows of (stride k-means + best of 10) / 2 was 85.41 against 85.44 %, so the rule (more rows, the mean not lower) was not met and the weights become no preset. The presets' rows are new samples of unchanged presets and methods. Differences below are computed from the JSON, candidate minus `indoor_searched`, stride k-means / best of 10.

- **The capped objective moved accuracy from the easy rows towards the hard ones, as it was built to, though not onto every hard row, and with little net gain.** Over the 14 room rows the candidate averages 86.5 % against `indoor_searched`'s 85.7 % and `indoor_columns`' 83.5 % (the mean of stride k-means and best of 10) and meets the target in 6 rows against 5 and 6. It gained on the office floor (+3.6 / +4.6, at 0.3 m +4.9 / +6.0: 89.8 / 91.7 %, where `indoor_searched` missed with 84.9 / 85.7 %), the hospital floors (+5.8 / +2.3, with 16 beams +3.6 / +2.3), the school at 0.3 m (+6.7 / +6.5) and with its own sensor (+4.4 / -0.4); it lost on the school with 16, 32 and 64 beams (-4.0 / -3.6, -3.6 / -1.8, -3.6 / -1.3) and on the rows far above the target (the one building 0.0 / -5.7, the many buildings -2.2 / -4.7, the varied plans +2.2 / -3.5). Hierarchical k-means++, which the objective did not look at, fell by 8 to 16 points on the four rows far above the target (the one building -11.3, the many buildings -15.5 and with 16 beams -9.1, the varied plans -8.1). Per row, on (stride k-means + best of 10) / 2: +1.5 points on average on the nine rows `indoor_searched` misses, -2.8 to -3.5 on the one building and the many buildings, +0.8 over the 14 rows, well within a row's noise (below).
- **The search dropped the paper's NDT histogram** (weight 1 -> 0 in its first step): leaving it out raised the objective by 0.11 point, just over the keep threshold of 0.1, so with these parts the histogram's share was within the search's resolution. Its other steps halved ESF (32 -> 16) and doubled clutter (10 -> 20); height_range went in and out again. The objective rose from 85.74 to 86.75 % on its 294 sets, a gain of 1.0 point where the thirteenth round's search on 42 sets gained 4.5; on seeds 7-9 the candidate and its start were level, and on these test seeds it is +0.8 points ahead on the mean. More sets did make the search overfit less; they did not find weights that lift every row.
- **These test seeds are hard for the school with every preset.** No preset meets the target on any of the six school rows (the school with its own sensor: `indoor_searched` 83.6 / 80.9 % against 95.6 / 94.3 % on 441-445). Per seed the school rows swing widely (with its own sensor, `indoor_searched`'s stride k-means runs 73.3 to 95.6 % over the five seeds); the median standard error of a row's five-seed mean, over the 14 rows of `indoor_searched` and the candidate, is 2.7 points (0.0 to 5.4). A row's verdict against 85 % on one five-seed sample is itself that uncertain, and a difference of a point between two weightings on one row is within it.
- **Issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10), read on the presets: met in 6 of 14 room rows** (the one building, the many buildings with both sensors, the varied plans, the office floor with both sensors; the office floor at 0.3 m by `indoor_columns` alone, 88.0 / 92.0 %), **missed in 8**: every school row and both hospital rows, with every preset. `indoor_searched` against `indoor_columns` on these fresh seeds: 85.7 against 83.5 % over the room rows (on 441-445 87.6 against 85.1 %).
- **Warehouse halls (at least 95 % with the tree of ten trials): met again** with `indoor_plus`, 97.6 % (own sensor, lowest tree 96.0 %) and 98.2 % (32 beams, lowest 96.0 %).
- **Outdoor (not worse than the paper's preset, `outdoor_near` against `outdoor`): met with both sensors.** Own sensor: stride 97.6 against 95.0 %, best of 10 97.6 against 95.9 %, the tree 97.0 against 95.4 %; 16 beams: 94.8 / 95.2 / 95.2 against 79.8 / 79.8 / 79.0 %.
- **Real scans:** every preset of the round finds a scan of the same place for 18 of 18 real scans (the candidate is no preset and was not run on them).";

fn render(r: &Report) -> Res<String> {
    let mut o = String::new();
    let p = searched()?;
    writeln!(
        o,
        "# Part weights chosen by a wider search (issue 18, fifteenth round)\n"
    )?;
    writeln!(o, "**Candidate.** `{START}`'s descriptor with the weights a coordinate-ascent search found over 294 development sets, each row's credit capped at 90 % ({}; `{START}` has {}): docs/rooms-dev.md, `cargo run --release --example rooms_search`. The procedure, its objective and the decision rule were written in docs/seeds.md before any run; on seeds 7-9, which the search never saw, the rule was not met, so the candidate is no preset and is reported here beside them.\n", weights_text(&p), weights_text(&DescriptorParams::preset(START)?))?;
    round_body(&mut o, r, &FILES, &TEXT, NOTES)?;
    Ok(o)
}

fn main() -> Res<()> {
    family_round(
        &FILES,
        (FAMILY_DEV, FAMILY_TEST),
        &[START, SEARCHED],
        &CANDIDATES,
        family_set,
        render,
    )
}
