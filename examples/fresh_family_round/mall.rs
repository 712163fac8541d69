//! The twenty-fourth round's report: shopping-mall floors.

use super::*;
use std::fmt::Write;

/// What the twenty-fourth round showed, written after its one test run.
const MALL_NOTES: &str = "Written after the one test run (seeds 551-555, 2026-12-06 06:49, the code of commit c8f9890; the plan and the rule were committed in docs/seeds.md at 06:06:50, commit e97d143, before the mall floors existed). Figures are computed from the JSON files of this round and the twenty-third.

- **By the rule fixed beforehand, the recommendation stands and `indoor_objects` carried over, at a far lower level.** Over the twelve hotel and mall rows spectral seeding with `indoor_objects` averages 73.7 % against best of 10's 71.8 % and the paper's `indoor` (with spectral seeding) 61.5 %. On the mall alone: 64.1 % against 62.0 % and 52.2 %; spectral seeding is above best of 10 in all six mall rows (by 1.3 to 3.4 points), and `indoor_objects` above `indoor` in every mall row with every method (by 0.5 to 37.3 points; room-level 1-NN by 19.1 to 37.3).
- **No mall row comes near issue 18's indoor target.** Spectral seeding with `indoor_objects` gives 60.1 to 72.1 % a row (its sets 42.7 to 84.4 %), best of 10 57.9 to 68.7 %, stride k-means 54.2 to 63.1 %; no method or preset reaches 85 % in any mall row. Per seed, over the rows: 50.8 to 76.7 %. With `indoor_searched` 57.3 %, with `indoor` 52.2 %.
- **On the mall, room-level 1-NN is above the clusterings** (69.4 % over the rows with `indoor_objects`, its sets 44.4 to 86.7 %; spectral seeding 1.6 to 8.0 points lower a row), and spectral clustering is above spectral seeding in every row (65.0 % over the rows): here k-means' centres lose some of what the neighbours hold, but the neighbours themselves are wrong for three scans in ten.
- **So the two simulated families written after the setting give 83.3 and 64.1 % (85 % in 1 of their 12 rows), against 91.5 % on the families it was chosen on.** Both are built on the same corridor-between-two-rows layout as the office, school and hospital floors. The mall's shopfronts are open to the lidar between a 0.3 m base and the fascia (the glass is not simulated, 6 cm mullions at most 1.5 m apart), so a shop's scans see the concourse and the shops opposite, which no earlier family does; how much of the mall's figure that explains is not measured here. What holds: issue 18's indoor target is met in 1 of 12 rows on families not looked at while the descriptors were built.
- **Which kinds** (a diagnostic after the run, docs/mall-kinds.md): errors over every kind, most between the shops (the electronics store 48.1 % of its scans grouped right with spectral seeding, the supermarket and the café 62.6 %, the clothing store 65.9 %, the concourse 79.3 %); shop scans in the concourse's cluster 102 of 1080, so the open shopfronts explain a part, not most.
- **Nothing in placecat changed** but the simulator's new family (with glazed shopfronts, `FloorPlan.glazed`, and the hotel's door placement shared with the mall's entrances; the other floors' scans byte-identical, the twenty-second round's development run and the hotel diagnostic re-ran to the same figures).";

pub fn render(dev: &Report, test: &Report) -> Res<String> {
    let (test_seeds, hotel_seeds) = (span(MALL_TEST_SEEDS), span(TEST_SEEDS));
    let pooled = pooled_before("--mall", test)?;
    let mut o = String::new();
    writeln!(o, "# The recommended room setting on a second family written after it: shopping-mall floors (issue 18, twenty-fourth round)\n")?;
    writeln!(o, "**Why.** On the hotel floors (test seeds {hotel_seeds}, docs/fresh-family.md), the first family written after `{RULE_PRESET}` and spectral seeding were chosen, the setting gave 83.3 % over six rows against 91.5 % on the families it was chosen on; one family cannot tell whether those flatter it or the hotel is harder. **What changed:** the simulator gained shopping-mall floors (`placecat simulate --scene mall`: the concourse, clothing stores, cafés, a supermarket, electronics stores), written by another hand (a helper) from a brief that named no descriptor, preset or figure; it ran no descriptor or clustering on them. Nothing else changed. The plan and the rule were fixed in docs/seeds.md (\"issue 18, twenty-fourth round\") before the family existed; this round's test run is the first description of it. Rule: over the twelve hotel and mall rows, if `{RULE_PRESET}` with spectral seeding has a mean below best of 10's with `{RULE_PRESET}`, the recommendation of spectral seeding for room sets is withdrawn; if below the paper's `{PAPER_PRESET}` with spectral seeding, the README says `{RULE_PRESET}` did not carry over to families written after it.\n")?;
    writeln!(
        o,
        "## The rule, computed on the hotel ({hotel_seeds}) and mall ({test_seeds}) rows pooled\n"
    )?;
    rule(&mut o, &pooled, "hotel and mall")?;
    writeln!(o, "\n## Readings on the mall, test seeds {test_seeds}\n")?;
    readings(&mut o, test)?;
    writeln!(o, "\n## Readings on the hotel and mall rows pooled\n")?;
    readings(&mut o, &pooled)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example fresh_family_round -- --mall --dev` (`fresh-family-2-dev.json`, {:.0} s) then `cargo run --release --example fresh_family_round -- --mall` (test seeds, this file and `fresh-family-2.json`, {:.0} s; it refuses to run again once `fresh-family-2.json` exists; `-- --mall --render` renders this file from them and docs/fresh-family.json). Rows, presets, methods and listing as docs/fresh-family.md.\n", dev.seconds, test.seconds)?;
    writeln!(o, "## What it shows\n\n{MALL_NOTES}\n")?;
    sections(&mut o, dev, test, &test_seeds, "")?;
    Ok(o)
}
