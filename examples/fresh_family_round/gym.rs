//! The twenty-seventh round's report: sports-centre fitness floors, a fifth family whose
//! building and room kinds another hand chose, with the candidate
//! `indoor_object_types` as the twenty-sixth round left it.

use super::*;
use std::fmt::Write;

pub fn render(dev: &Report, test: &Report) -> Res<String> {
    let span = |s: &[u64]| format!("{}-{}", s[0], s[s.len() - 1]);
    let test_seeds = span(FIFTH_TEST_SEEDS);
    let earlier = [
        TEST_SEEDS,
        MALL_TEST_SEEDS,
        HOME_TEST_SEEDS,
        INSTITUTE_TEST_SEEDS,
    ]
    .map(span);
    let stems = [
        "fresh-family",
        "fresh-family-2",
        "fresh-family-3",
        "fresh-family-4",
    ];
    let pooled = pooled(&stems, test)?;
    let judged = pooled_candidate(test)?;
    let mut o = String::new();
    writeln!(o, "# The candidate and the recommended room setting on a fifth family whose building and kinds another hand chose: sports-centre fitness floors (issue 18, twenty-seventh round)\n")?;
    writeln!(o, "**Why.** The twenty-sixth round's candidate `{CANDIDATE}` was judged on one family only, the research-institute floors (test seeds {}, docs/fresh-family-4.md: 89.3 against `{RULE_PRESET}`'s 87.1 % with spectral seeding). That family was the easiest of the four written after the recommended setting (hotel {}, mall {}, home {}: 83.3, 64.1 and 76.3 %), and the plan that stated the candidate's hypothesis also named its kinds, so it was not independent of it. **What changed:** nothing in what is judged; every part, weight, preset and method is as the twenty-sixth round left them (commit 1d44b46). The simulator gained sports-centre fitness floors (`placecat simulate --scene gym`: the corridor, cardio rooms, weight rooms, studios, changing rooms; every room opens onto the corridor and is as deep as its row), written by another hand (a helper) in its own branch from a brief that named no descriptor, part, preset, figure or hypothesis and no building type or room kind: the helper chose the building and its four room kinds. It ran no descriptor or clustering on them. The plan and the rules were fixed in docs/seeds.md (\"issue 18, twenty-seventh round\") before the family existed or any run; this round's test run is the first description of the family. Rules, on the six new rows with spectral seeding: the candidate is withdrawn if its mean is not above `{RULE_PRESET}`'s; if above by at least 1 point, the README's recommendation for sets of room scans names it in place of `{RULE_PRESET}`; otherwise it stays an option. Over the thirty hotel, mall, home, institute and new rows, if `{RULE_PRESET}` with spectral seeding has a mean below best of 10's with `{RULE_PRESET}`, the recommendation of spectral seeding for room sets is withdrawn; if below the paper's `{PAPER_PRESET}` with spectral seeding, the README says `{RULE_PRESET}` did not carry over.\n", earlier[3], earlier[0], earlier[1], earlier[2])?;
    writeln!(
        o,
        "## The candidate's rule, computed on the gym rows, test seeds {test_seeds}\n"
    )?;
    candidate_rule(&mut o, test, "gym", Some(1.0))?;
    writeln!(
        o,
        "\n## The recommendation's rule, computed on the hotel, mall, home, institute and gym rows pooled\n"
    )?;
    rule(&mut o, &pooled, "hotel, mall, home, institute and gym")?;
    writeln!(
        o,
        "\n## Readings on the sports-centre fitness floors, test seeds {test_seeds}\n"
    )?;
    readings(&mut o, test)?;
    writeln!(
        o,
        "\n## Readings on the two families that judge the candidate, the institute and gym rows pooled (a reading; the rule reads the gym rows alone)\n"
    )?;
    candidate_rule(&mut o, &judged, "institute and gym", None)?;
    readings(&mut o, &judged)?;
    writeln!(
        o,
        "\n## Readings on the hotel, mall, home, institute and gym rows pooled\n"
    )?;
    readings(&mut o, &pooled)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example fresh_family_round -- --gym --dev` (`fresh-family-5-dev.json`, {:.0} s) then `cargo run --release --example fresh_family_round -- --gym` (test seeds, this file and `fresh-family-5.json`, {:.0} s; it refuses to run again once `fresh-family-5.json` exists; `-- --gym --render` renders this file from them and the four earlier rounds' JSON). Rows, methods and listing as docs/fresh-family.md; the gym rows also with `{CANDIDATE}`.\n", dev.seconds, test.seconds)?;
    if !NOTES.is_empty() {
        writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    }
    sections(&mut o, dev, test, &test_seeds, "")?;
    writeln!(
        o,
        "\n## Every test set, `{CANDIDATE}` (spectral seeding / best of 10 / stride k-means, %)\n"
    )?;
    per_set(&mut o, test, CANDIDATE)?;
    Ok(o)
}

/// The institute's and this family's rows, both presets' and the
/// candidate's: the two families no choice of the candidate looked at.
fn pooled_candidate(test: &Report) -> Res<Report> {
    pooled(&["fresh-family-4"], test)
}

/// What the twenty-seventh round showed, written after its one test run.
const NOTES: &str = "";
