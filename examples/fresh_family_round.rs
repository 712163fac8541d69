//! Issue 18, twenty-third round: the setting the README recommends for
//! sets of room scans (`indoor_objects`, k-means with spectral seeding)
//! on a scene family written after it. Every room family it was judged on
//! before had been looked at on development seeds while its parts,
//! weights, preset and seeding were chosen; the hotel floors
//! (`--scene hotel`) were written by another hand from a brief that named
//! no descriptor, preset or figure, and this round's test run is the
//! first description of them.
//!
//!     cargo run --release --example fresh_family_round -- --dev   # seeds 1-6, the hospital rows: docs/fresh-family-dev.json
//!     cargo run --release --example fresh_family_round            # test seeds 541-545, once: docs/fresh-family.{json,md}
//!     ... -- --render   # docs/fresh-family.md again from the two .json
//!
//! The twenty-fourth round (`--mall`) runs the same on shopping-mall
//! floors, another family written after the twenty-third round's figures,
//! and reads the rule on the hotel and mall rows pooled:
//!
//!     ... -- --mall --dev   # docs/fresh-family-2-dev.json
//!     ... -- --mall         # test seeds 551-555, once: docs/fresh-family-2.{json,md}
//!     ... -- --mall --render
//!
//! The twenty-fifth round (`--home`) runs it on residential floors, a
//! third family written after that, and reads the rule on the hotel, mall
//! and home rows pooled:
//!
//!     ... -- --home --dev   # docs/fresh-family-3-dev.json
//!     ... -- --home         # test seeds 561-565, once: docs/fresh-family-3.{json,md}
//!     ... -- --home --render
//!
//! The twenty-sixth round (`--institute`) runs it on research-institute
//! floors, a fourth family written after that, with the candidate preset
//! `indoor_object_types` (chosen on development seeds by the round's plan,
//! docs/object-types-dev.md) beside the three presets; its rules read the
//! candidate on the institute rows and the recommendation on the hotel,
//! mall, home and institute rows pooled:
//!
//!     ... -- --institute --dev   # docs/fresh-family-4-dev.json
//!     ... -- --institute         # test seeds 571-575, once: docs/fresh-family-4.{json,md}
//!     ... -- --institute --render
//!
//! Each plan and rule was fixed in docs/seeds.md ("issue 18,
//! twenty-third round" and the three after it) before its family existed. The development run
//! checks the harness only: on the hospital's rows it must give every
//! figure of the twenty-second round's development run. The test run
//! refuses to overwrite its report.

use std::fmt::Write;

#[path = "common/families.rs"]
mod families;
#[allow(dead_code)] // the listing of the earlier rounds
#[path = "common/listed_rounds.rs"]
mod listed_rounds;
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
#[path = "common/seeds.rs"]
mod seeds;
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use families::*;
use listed_rounds::*;
use rounds::*;

/// Fixed in docs/seeds.md ("issue 18, twenty-third round") before any run.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];
const TEST_SEEDS: &[u64] = &[541, 542, 543, 544, 545];
/// The twenty-fourth round's, fixed in docs/seeds.md before any run.
const MALL_TEST_SEEDS: &[u64] = &[551, 552, 553, 554, 555];
/// The twenty-fifth round's, fixed in docs/seeds.md before any run.
const HOME_TEST_SEEDS: &[u64] = &[561, 562, 563, 564, 565];
/// The twenty-sixth round's, fixed in docs/seeds.md before any run.
const INSTITUTE_TEST_SEEDS: &[u64] = &[571, 572, 573, 574, 575];
/// The twenty-sixth round's candidate, judged against [`RULE_PRESET`].
const CANDIDATE: &str = "indoor_object_types";
/// The recommended preset, and the paper's.
const RULE_PRESET: &str = "indoor_objects";
const PAPER_PRESET: &str = "indoor";
/// The twenty-second round's development run, which the harness check
/// must reproduce on the hospital's rows.
const EARLIER_DEV: &str = "spectral-seeding-again-dev.json";

/// One round: its flag, files, family, test seeds and report.
struct Round {
    /// The flag that selects it ("" for the twenty-third round).
    flag: &'static str,
    /// docs/`stem`-dev.json, docs/`stem`.json and docs/`stem`.md.
    stem: &'static str,
    family: fn() -> Family,
    test_seeds: &'static [u64],
    render: fn(&Report, &Report) -> Res<String>,
}

const ROUNDS: [Round; 4] = [
    Round {
        flag: "",
        stem: "fresh-family",
        family: hotel_family,
        test_seeds: TEST_SEEDS,
        render,
    },
    Round {
        flag: "--mall",
        stem: "fresh-family-2",
        family: mall_family,
        test_seeds: MALL_TEST_SEEDS,
        render: render_mall,
    },
    Round {
        flag: "--home",
        stem: "fresh-family-3",
        family: home_family,
        test_seeds: HOME_TEST_SEEDS,
        render: render_home,
    },
    Round {
        flag: "--institute",
        stem: "fresh-family-4",
        family: institute_family,
        test_seeds: INSTITUTE_TEST_SEEDS,
        render: render_institute,
    },
];

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let has = |flag: &str| args.iter().any(|a| a == flag);
    // The last round whose flag is given; the twenty-third without one.
    let round = (ROUNDS.iter().rev())
        .find(|r| r.flag.is_empty() || has(r.flag))
        .ok_or("no round")?;
    let with = |what: &str| format!("{} {what}", round.flag).trim_start().to_string();
    let (dev_name, test_name) = (
        format!("{}-dev.json", round.stem),
        format!("{}.json", round.stem),
    );
    let (dev_json, test_json) = (docs().join(&dev_name), docs().join(&test_name));
    if has("--dev") {
        seeds::check_round_seeds(DEV_SEEDS, &[])?;
        let r = run(vec![hospital_family()], DEV_SEEDS, true, Listing::PerRow)?;
        eprintln!(
            "{} figures the same as the twenty-second round's",
            same_as_again_dev(&r)?
        );
        return write(&dev_name, &serde_json::to_string_pretty(&r)?);
    }
    if !has("--render") {
        if !dev_json.exists() {
            return Err(format!("run the development seeds first ({})", with("--dev")).into());
        }
        seeds::check_round_seeds(DEV_SEEDS, round.test_seeds)?;
        if test_json.exists() {
            return Err(format!(
                "docs/{test_name} exists: the test seeds were run once already (use {})",
                with("--render")
            )
            .into());
        }
        let r = run(
            vec![(round.family)()],
            round.test_seeds,
            true,
            Listing::PerRow,
        )?;
        write(&test_name, &serde_json::to_string_pretty(&r)?)?;
    }
    let dev: Report = read_json(&dev_json)?;
    let test: Report = read_json(&test_json)?;
    write(&format!("{}.md", round.stem), &(round.render)(&dev, &test)?)
}

/// Every figure of the development run (the hospital's rows, each listed
/// in its own order) must equal the twenty-second round's development run
/// on the same rows, which ran them with the same families' code; returns
/// how many figures were compared.
fn same_as_again_dev(dev: &Report) -> Res<usize> {
    let earlier: Report = read_json(&docs().join(EARLIER_DEV))?;
    if dev.seeds != earlier.seeds {
        return Err(format!("not the seeds of docs/{EARLIER_DEV}").into());
    }
    let hospital = hospital_family().name;
    let theirs = earlier.rows.iter().filter(|e| e.family == hospital).count();
    if dev.rows.len() != theirs || dev.rows.iter().any(|r| r.family != hospital) {
        return Err(format!("not the hospital rows of docs/{EARLIER_DEV}").into());
    }
    let mut compared = 0;
    for r in &dev.rows {
        let e = (earlier.rows.iter())
            .find(|e| (&e.family, &e.sensor, &e.preset) == (&r.family, &r.sensor, &r.preset))
            .ok_or_else(|| {
                format!(
                    "{} {} {}: not in docs/{EARLIER_DEV}",
                    r.family, r.sensor, r.preset
                )
            })?;
        let pairs = [
            (&r.stride, &e.stride),
            (&r.best_of_10, &e.best_of_10),
            (&r.tree, &e.tree),
            (&r.spectral, &e.spectral),
            (&r.nearest, &e.nearest),
            (&r.seeded, &e.seeded),
        ];
        compared += equal_figures(r, &format!("docs/{EARLIER_DEV}"), &pairs)?;
    }
    if compared == 0 {
        return Err("no figure compared".into());
    }
    Ok(compared)
}

/// The rows of `preset`, in the report's order.
fn rows_of<'a>(r: &'a Report, preset: &str) -> Vec<&'a Row> {
    r.rows.iter().filter(|x| x.preset == preset).collect()
}

/// The mean over `rows` of each row's mean of `f`.
fn over_rows(rows: &[&Row], f: fn(&Row) -> &Vec<f64>) -> f64 {
    rows.iter().map(|x| mean(f(x))).sum::<f64>() / rows.len() as f64
}

fn at_target(x: f64) -> bool {
    100.0 * x >= ROOM_TARGET
}

/// The rule fixed in the plan, computed on the test report.
fn rule(o: &mut String, r: &Report, what: &str) -> Res<()> {
    let (ours, paper) = (rows_of(r, RULE_PRESET), rows_of(r, PAPER_PRESET));
    if ours.is_empty() || ours.len() != paper.len() {
        return Err("the report lacks the rule's rows".into());
    }
    let seeded = over_rows(&ours, |x| &x.seeded);
    let best = over_rows(&ours, |x| &x.best_of_10);
    let paper_seeded = over_rows(&paper, |x| &x.seeded);
    let recommendation = if seeded < best {
        "below it, so the README's recommendation of spectral seeding for room sets is withdrawn (it stays an option with its figures)"
    } else {
        "not below it, so the recommendation stands"
    };
    let preset = if seeded < paper_seeded {
        format!("below it, so `{RULE_PRESET}` did not carry over to a family written after it")
    } else {
        format!("not below it, so `{RULE_PRESET}` carried over")
    };
    writeln!(o, "- Over the {} {what} rows, `{RULE_PRESET}` with spectral seeding averages **{} %** against k-means++ best of 10's {} % with `{RULE_PRESET}`: {recommendation}.", ours.len(), pct(seeded), pct(best))?;
    writeln!(
        o,
        "- Against the paper's `{PAPER_PRESET}` with spectral seeding ({} %): {preset}.",
        pct(paper_seeded)
    )?;
    Ok(())
}

/// The readings the plan names, on one report's rows.
fn readings(o: &mut String, r: &Report) -> Res<()> {
    let (ours, paper) = (rows_of(r, RULE_PRESET), rows_of(r, PAPER_PRESET));
    if ours.len() != paper.len()
        || ours
            .iter()
            .zip(&paper)
            .any(|(x, p)| (&x.family, &x.sensor) != (&p.family, &p.sensor))
    {
        return Err("the two presets' rows are not the same sensors".into());
    }
    writeln!(o, "Per row, `{RULE_PRESET}`: k-means with spectral seeding against 85 %, against `{PAPER_PRESET}` with spectral seeding and against best of 10 with `{RULE_PRESET}`:\n")?;
    for (x, p) in ours.iter().zip(&paper) {
        let seeded = mean(&x.seeded);
        let verdict = if at_target(seeded) {
            "at least 85 %"
        } else {
            "below 85 %"
        };
        let versus = |other: f64| {
            if seeded >= other {
                "above or level"
            } else {
                "below"
            }
        };
        writeln!(o, "- {}, {}: **{} %** ({verdict}); `{PAPER_PRESET}` {} % ({}); best of 10 {} % ({}); stride k-means {} %.", x.family, x.sensor, pct(seeded), pct(mean(&p.seeded)), versus(mean(&p.seeded)), pct(mean(&x.best_of_10)), versus(mean(&x.best_of_10)), pct(mean(&x.stride)))?;
    }
    writeln!(o)?;
    // The presets in the report's order: the rounds' three, and the
    // twenty-sixth round's candidate where its family ran.
    let mut presets: Vec<&str> = vec![];
    for x in &r.rows {
        if !presets.contains(&x.preset.as_str()) {
            presets.push(&x.preset);
        }
    }
    for preset in presets {
        let rows = rows_of(r, preset);
        let count = |f: fn(&Row) -> bool| rows.iter().filter(|x| f(x)).count();
        let seeded = count(|x| at_target(mean(&x.seeded)));
        let both = count(|x| at_target(mean(&x.stride)) && at_target(mean(&x.best_of_10)));
        let stride = count(|x| at_target(mean(&x.stride)));
        let best = count(|x| at_target(mean(&x.best_of_10)));
        let spectral = count(|x| at_target(mean(&x.spectral)));
        let avg = |f: fn(&Row) -> &Vec<f64>| pct(over_rows(&rows, f));
        let only = if rows.len() < rows_of(r, RULE_PRESET).len() {
            " (only the rows it ran on)"
        } else {
            ""
        };
        writeln!(o, "- `{preset}`, rows of {}{only} at least 85 %: with spectral seeding **{seeded}**; with stride k-means and best of 10 both {both}; stride k-means {stride}; best of 10 {best}; spectral clustering {spectral}. Means over the rows: stride {}, best of 10 {}, spectral seeding {}, hk-means++ {}, spectral {}, room-level 1-NN {} %.", rows.len(), avg(|x| &x.stride), avg(|x| &x.best_of_10), avg(|x| &x.seeded), avg(|x| &x.tree), avg(|x| &x.spectral), avg(|x| &x.nearest))?;
    }
    let s = &r.stride_starts;
    writeln!(
        o,
        "- Stride seeding's first centres were one scan of each kind on {} of the {} room sets.",
        s.one_of_each_kind, s.room_sets
    )?;
    Ok(())
}

/// Every set's figure of `preset`: spectral seeding, best of 10 and
/// stride k-means, seed by seed.
fn per_set(o: &mut String, r: &Report, preset: &str) -> Res<()> {
    let seeds: Vec<String> = r.seeds.iter().map(|s| s.to_string()).collect();
    writeln!(o, "| family | sensor | {} |", seeds.join(" | "))?;
    writeln!(o, "|---|---|{}", "---|".repeat(seeds.len()))?;
    for x in rows_of(r, preset) {
        let cells: Vec<String> = (0..seeds.len())
            .map(|i| {
                format!(
                    "{} / {} / {}",
                    pct(x.seeded[i]),
                    pct(x.best_of_10[i]),
                    pct(x.stride[i])
                )
            })
            .collect();
        writeln!(o, "| {} | {} | {} |", x.family, x.sensor, cells.join(" | "))?;
    }
    Ok(())
}

/// What the round showed, written after its one test run.
const NOTES: &str = "Written after the one test run (seeds 541-545, 2026-12-06 05:18, the code of commit ebee06a; the plan and the rule were committed in docs/seeds.md at 04:45, commit dbf2c87, before the hotel floors existed; the family was committed in 3a73c54). Figures are computed from the JSON files of this round and the twenty-second.

- **By the rule fixed beforehand, the recommendation stands and `indoor_objects` carried over.** Over the six hotel rows k-means with spectral seeding averages 83.3 % with `indoor_objects`, against k-means++ best of 10's 81.6 % and the paper's `indoor` with spectral seeding at 70.9 %. `indoor_objects` is above `indoor` in every row, with every method: by 10.8 to 14.3 points with spectral seeding, 16.4 to 21.8 with room-level 1-NN, 10.4 to 18.9 with best of 10, 6.8 to 21.2 with the tree and 3.1 to 15.1 with stride k-means.
- **Issue 18's indoor target is not met on the fresh family.** Spectral seeding with `indoor_objects` reaches 85 % in 1 of the 6 rows (the own sensor, 86.7 %); the other five lie at 80.8 to 83.7 %, and its sets at 70.9 to 93.3 %. Best of 10 reaches it in one row (64 beams, 85.8 %), stride k-means and best of 10 together in none. With `indoor_searched` spectral seeding averages 82.2 % (85 % in one row, the own sensor, 85.4 %); with `indoor` 70.9 % (none).
- **Lower than on the families the setting was chosen on, by about eight points; one family cannot say why.** On the twenty-second round's 14 room rows (531-535) spectral seeding with `indoor_objects` averaged 91.5 % and reached 85 % in 13; here 83.3 % and 1 of 6. Like for like, the school (written fresh in an earlier round, but looked at on development seeds while `indoor_objects` was chosen) gave 87.8 to 96.8 % on the same six sensors there (92.8 % on average), the hotel 80.8 to 86.7 % (83.3 %). But the hospital, also looked at while the preset was chosen, averaged 82.7 % on its two sensors there (88.1 and 77.3 %), where the hotel gives 85.1 % (86.7 and 83.5 %). With one fresh family and five seeds, whether the earlier families flatter the setting or the hotel is a harder family cannot be told apart; what holds is that on a family placecat was not developed on it gave the low eighties.
- **Room-level 1-NN is level with the clusterings.** With `indoor_objects` it is 83.3 % over the rows (its sets 66.7 to 95.6 %), as spectral seeding (83.3 %) and spectral clustering (83.2 %; spectral seeding within -0.2 to +0.4 points of it a row): a scan's nearest scan from another room is of its kind about as often as the clusterings group it right, as on the hospital with 16 beams. It is no ceiling row by row (with 64 beams best of 10 gives 85.8 % against 1-NN's 83.6 %; at 0.3 m the clusterings give 80.7 to 81.2 % against 78.7 %).
- **Spectral seeding is below best of 10 in 2 of the 6 rows** (64 beams, 83.2 against 85.8 %; the sensor at 0.3 m, 80.8 against 81.2 %) and above it by 0.6 to 5.5 points in the other four.
- **Order-free methods as before:** stride k-means averages 73.1 % with `indoor_objects` (its first centres were one scan of each kind on none of the 30 sets), the tree 73.8 %.
- **Per seed**, over the six rows with `indoor_objects`: spectral seeding 77.7 to 86.6 %, best of 10 76.5 to 83.9 %, room-level 1-NN 74.1 to 87.4 %.
- **Which kinds** (a diagnostic after the run, docs/hotel-kinds.md): the breakfast room (59.3 % of its scans grouped right with spectral seeding, 53.0 % by 1-NN) and the lobby (74.8 %, 86.7 %) are confused with each other and the conference room; guest rooms, corridors and conference rooms are grouped right for 91.9 to 98.5 % of their scans.
- **Nothing in placecat changed** but the simulator's new family (and a door hook of the floor plans that keeps the other floors' scans byte-identical: the twenty-second round's development run re-ran to the same figures).";

fn render(dev: &Report, test: &Report) -> Res<String> {
    let span = |s: &[u64]| format!("{}-{}", s[0], s[s.len() - 1]);
    let test_seeds = span(TEST_SEEDS);
    let mut o = String::new();
    writeln!(o, "# The recommended room setting on a family written after it: hotel floors (issue 18, twenty-third round)\n")?;
    writeln!(o, "**Why.** The README recommends `{RULE_PRESET}` with k-means of spectral seeding for sets of room scans. Every room family it was judged on (indoor, office floor, school, hospital) had been looked at on development seeds while its parts, weights, preset and seeding were chosen, so its figures there flatter it. **What changed:** the simulator gained hotel floors (`placecat simulate --scene hotel`: corridors, guest rooms, a breakfast room, a lobby, conference rooms), written by another hand (a helper) from a brief that named no descriptor, preset or figure; it ran no descriptor or clustering on them. Nothing else changed: no method, part, weight, preset or default. The plan and the rule were fixed in docs/seeds.md (\"issue 18, twenty-third round\") before the family existed; this round's test run is the first description of it. Rule: over the six hotel rows, if `{RULE_PRESET}` with spectral seeding has a mean below best of 10's with `{RULE_PRESET}`, the recommendation of spectral seeding for room sets is withdrawn; if below the paper's `{PAPER_PRESET}` with spectral seeding, the README says `{RULE_PRESET}` did not carry over.\n")?;
    writeln!(o, "## The rule, computed on the test seeds {test_seeds}\n")?;
    rule(&mut o, test, "hotel")?;
    writeln!(o, "\n## Readings on the test seeds {test_seeds}\n")?;
    readings(&mut o, test)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example fresh_family_round -- --dev` (`fresh-family-dev.json`, {:.0} s) then `cargo run --release --example fresh_family_round` (test seeds, this file and `fresh-family.json`, {:.0} s; it refuses to run again once `fresh-family.json` exists; `-- --render` renders this file from them). The hotel with its own sensor, 16, 32 and 64 beams, and the sensor at 0.3 m and 1.8 m; 45 scans a set (5 kinds, rooms of 3 scans), each set listed in a random order of its own (drawn from its seed, family and sensor, as in the twenty-second round, docs/spectral-seeding-again.md); k the true number of kinds. Stride k-means runs once; k-means++ best of 10, k-means with spectral seeding and spectral clustering with clustering seeds 0-9, hk-means++ (ten trial splits a node, cut at k) with tree seeds 0-9 (means). Room-level 1-NN: no neighbour from the scan's own room. Target column: stride k-means and best of 10 each at least 85 % (as the earlier rounds read issue 18's target).\n", dev.seconds, test.seconds)?;
    writeln!(o, "## What it shows\n\n{NOTES}\n")?;
    sections(
        &mut o,
        dev,
        test,
        &test_seeds,
        ", so this example runs the rounds' harness unchanged",
    )?;
    Ok(o)
}

/// The rows of the earlier rounds' reports `earlier` (docs/`stem`.json)
/// and of `last` as one report (the twenty-fourth and twenty-fifth
/// rounds' rules read them pooled).
fn pooled(earlier: &[&str], last: &Report) -> Res<Report> {
    let mut all = Report {
        seeds: last.seeds.clone(),
        seconds: 0.0,
        rows: vec![],
        stride_starts: StrideStarts {
            room_sets: 0,
            one_of_each_kind: 0,
        },
    };
    let reports: Vec<Report> = (earlier.iter())
        .map(|stem| read_json(&docs().join(format!("{stem}.json"))))
        .collect::<Res<_>>()?;
    for r in reports.iter().chain([last]) {
        all.seconds += r.seconds;
        all.rows.extend(r.rows.iter().cloned());
        all.stride_starts.room_sets += r.stride_starts.room_sets;
        all.stride_starts.one_of_each_kind += r.stride_starts.one_of_each_kind;
    }
    Ok(all)
}

/// What the twenty-fourth round showed, written after its one test run.
const MALL_NOTES: &str = "Written after the one test run (seeds 551-555, 2026-12-06 06:49, the code of commit c8f9890; the plan and the rule were committed in docs/seeds.md at 06:06:50, commit e97d143, before the mall floors existed). Figures are computed from the JSON files of this round and the twenty-third.

- **By the rule fixed beforehand, the recommendation stands and `indoor_objects` carried over, at a far lower level.** Over the twelve hotel and mall rows spectral seeding with `indoor_objects` averages 73.7 % against best of 10's 71.8 % and the paper's `indoor` (with spectral seeding) 61.5 %. On the mall alone: 64.1 % against 62.0 % and 52.2 %; spectral seeding is above best of 10 in all six mall rows (by 1.3 to 3.4 points), and `indoor_objects` above `indoor` in every mall row with every method (by 0.5 to 37.3 points; room-level 1-NN by 19.1 to 37.3).
- **No mall row comes near issue 18's indoor target.** Spectral seeding with `indoor_objects` gives 60.1 to 72.1 % a row (its sets 42.7 to 84.4 %), best of 10 57.9 to 68.7 %, stride k-means 54.2 to 63.1 %; no method or preset reaches 85 % in any mall row. Per seed, over the rows: 50.8 to 76.7 %. With `indoor_searched` 57.3 %, with `indoor` 52.2 %.
- **On the mall, room-level 1-NN is above the clusterings** (69.4 % over the rows with `indoor_objects`, its sets 44.4 to 86.7 %; spectral seeding 1.6 to 8.0 points lower a row), and spectral clustering is above spectral seeding in every row (65.0 % over the rows): here k-means' centres lose some of what the neighbours hold, but the neighbours themselves are wrong for three scans in ten.
- **So the two simulated families written after the setting give 83.3 and 64.1 % (85 % in 1 of their 12 rows), against 91.5 % on the families it was chosen on.** Both are built on the same corridor-between-two-rows layout as the office, school and hospital floors. The mall's shopfronts are open to the lidar between a 0.3 m base and the fascia (the glass is not simulated, 6 cm mullions at most 1.5 m apart), so a shop's scans see the concourse and the shops opposite, which no earlier family does; how much of the mall's figure that explains is not measured here. What holds: issue 18's indoor target is met in 1 of 12 rows on families not looked at while the descriptors were built.
- **Which kinds** (a diagnostic after the run, docs/mall-kinds.md): errors over every kind, most between the shops (the electronics store 48.1 % of its scans grouped right with spectral seeding, the supermarket and the café 62.6 %, the clothing store 65.9 %, the concourse 79.3 %); shop scans in the concourse's cluster 102 of 1080, so the open shopfronts explain a part, not most.
- **Nothing in placecat changed** but the simulator's new family (with glazed shopfronts, `FloorPlan.glazed`, and the hotel's door placement shared with the mall's entrances; the other floors' scans byte-identical, the twenty-second round's development run and the hotel diagnostic re-ran to the same figures).";

fn render_mall(dev: &Report, test: &Report) -> Res<String> {
    let span = |s: &[u64]| format!("{}-{}", s[0], s[s.len() - 1]);
    let (test_seeds, hotel_seeds) = (span(MALL_TEST_SEEDS), span(TEST_SEEDS));
    let pooled = pooled(&["fresh-family"], test)?;
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

fn render_home(dev: &Report, test: &Report) -> Res<String> {
    let span = |s: &[u64]| format!("{}-{}", s[0], s[s.len() - 1]);
    let test_seeds = span(HOME_TEST_SEEDS);
    let (hotel_seeds, mall_seeds) = (span(TEST_SEEDS), span(MALL_TEST_SEEDS));
    let pooled = pooled(&["fresh-family", "fresh-family-2"], test)?;
    let mut o = String::new();
    writeln!(o, "# The recommended room setting on a third family written after it: residential floors (issue 18, twenty-fifth round)\n")?;
    writeln!(o, "**Why.** On the hotel floors (test seeds {hotel_seeds}, docs/fresh-family.md) and the shopping-mall floors ({mall_seeds}, docs/fresh-family-2.md), the two families written after `{RULE_PRESET}` and spectral seeding were chosen, the setting gave 83.3 and 64.1 % (85 % in 1 of 12 rows); both are public buildings. A family of another domain tells whether the shortfall holds beyond them. **What changed:** the simulator gained residential floors (`placecat simulate --scene home`: living rooms, kitchens, bedrooms and bathrooms off a building's shared corridor; no apartments are modelled, every room has its own door onto the corridor and is as deep as its row), written by another hand (a helper) from a brief that named no descriptor, preset or figure; it ran no descriptor or clustering on them. Nothing else changed in what is judged (two development looks in between, docs/part-weights-dev.md and docs/near-crop-dev.md, changed nothing). The plan and the rule were fixed in docs/seeds.md (\"issue 18, twenty-fifth round\") before the family existed; this round's test run is the first description of it. Rule: over the eighteen hotel, mall and home rows, if `{RULE_PRESET}` with spectral seeding has a mean below best of 10's with `{RULE_PRESET}`, the recommendation of spectral seeding for room sets is withdrawn; if below the paper's `{PAPER_PRESET}` with spectral seeding, the README says `{RULE_PRESET}` did not carry over to families written after it.\n")?;
    writeln!(
        o,
        "## The rule, computed on the hotel ({hotel_seeds}), mall ({mall_seeds}) and home ({test_seeds}) rows pooled\n"
    )?;
    rule(&mut o, &pooled, "hotel, mall and home")?;
    writeln!(
        o,
        "\n## Readings on the home floors, test seeds {test_seeds}\n"
    )?;
    readings(&mut o, test)?;
    writeln!(o, "\n## Readings on the hotel, mall and home rows pooled\n")?;
    readings(&mut o, &pooled)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example fresh_family_round -- --home --dev` (`fresh-family-3-dev.json`, {:.0} s) then `cargo run --release --example fresh_family_round -- --home` (test seeds, this file and `fresh-family-3.json`, {:.0} s; it refuses to run again once `fresh-family-3.json` exists; `-- --home --render` renders this file from them and the two earlier rounds' JSON). Rows, presets, methods and listing as docs/fresh-family.md.\n", dev.seconds, test.seconds)?;
    if !HOME_NOTES.is_empty() {
        writeln!(o, "## What it shows\n\n{HOME_NOTES}\n")?;
    }
    sections(&mut o, dev, test, &test_seeds, "")?;
    Ok(o)
}

/// What the twenty-fifth round showed, written after its one test run.
const HOME_NOTES: &str = "Written after the one test run (seeds 561-565, 2026-12-06 09:32, the code of commit b42bb34; the plan and the rule were committed in docs/seeds.md at 09:06:57, commit 9bdc9e6, before the home floors existed, 24d5f6d). Figures are computed from the JSON files of this round and the two before it.

- **By the rule fixed beforehand, the recommendation stands and `indoor_objects` carried over.** Over the eighteen hotel, mall and home rows spectral seeding with `indoor_objects` averages 74.6 % against best of 10's 72.8 % and the paper's `indoor` (with spectral seeding) 60.9 %. On the home floors alone: 76.3 % against 74.8 % and 59.6 %; spectral seeding is below best of 10 in one home row (16 beams, 67.8 against 68.4 %) and above it by 0.2 to 4.1 points in the other five; `indoor_objects` is above `indoor` in every home row with every method (by 0.4 to 39.1 points; room-level 1-NN by 23.6 to 39.1).
- **Issue 18's indoor target is met in 1 of the 6 home rows** (the sensor at 0.3 m, 86.6 %; at 1.8 m 84.8 %, the own sensor 78.2 %, 16 to 64 beams 67.8 to 70.8 %); its sets lie at 64.0 to 92.9 %. No row meets it with stride k-means and best of 10 together. Per seed, over the rows: 73.7 to 78.7 %. With `indoor_searched` 73.7 %, with `indoor` 59.6 %.
- **So on the three families written after the setting it gave 83.3, 64.1 and 76.3 %, 85 % in 2 of their 18 rows** (the hotel with its own sensor, the home at 0.3 m), against 91.5 % and 13 of 14 rows on the families it was chosen on. The three families share the corridor-between-two-rows layout of the office, school and hospital floors. On the home floors no apartments are modelled (every room opens onto the shared corridor) and every room is as deep as its row (4.2 to 5.8 m, bathrooms too, unlike most real flats); whether that causes the confusions below was not tested.
- **Room-level 1-NN** (74.0 % over the rows) is within 0.6 points of spectral seeding with the own sensor, 16 and 32 beams (0.5 and 0.6 above it with 16 and 32 beams), and below it by 1.4 points with 64 beams and by 6.2 and 7.5 at 0.3 and 1.8 m.
- **Which kinds** (a diagnostic after the run, docs/home-kinds.md; clustering seed 0): the corridor and the living room keep about 96 % of their scans in their own cluster, but the living room's cluster also takes in 55 scans of other kinds; the kitchen (60.0 %), the bedroom (63.7 %) and the bathroom (65.6 %) lose most: the kitchen's scans mostly to the bedroom's cluster, the bathroom's to the bedroom's and the kitchen's, the bedroom's mostly to the living room's.
- **Nothing in placecat changed** but the simulator's new family (every other family's simulated scans pinned by digest and unchanged; the twenty-second round's development run re-ran to the same 216 figures on the hospital rows).";

/// A round's report after its notes: the test table, every test set of
/// [`RULE_PRESET`], and the development run with its check (`check_tail`
/// ends the check's sentence).
fn sections(
    o: &mut String,
    dev: &Report,
    test: &Report,
    test_seeds: &str,
    check_tail: &str,
) -> Res<()> {
    writeln!(o, "## 1. Test seeds {test_seeds}\n")?;
    seeding_table(o, test)?;
    writeln!(o, "\n## 2. Every test set, `{RULE_PRESET}` (spectral seeding / best of 10 / stride k-means, %)\n")?;
    per_set(o, test, RULE_PRESET)?;
    writeln!(o, "\n## 3. Development seeds 1-6, the hospital's rows (run first, to check the harness; they decide nothing)\n")?;
    let compared = same_as_again_dev(dev)?;
    writeln!(o, "**Check.** Every figure equals the twenty-second round's development run on the same rows (docs/{EARLIER_DEV}; {compared} figures, checked each time this file is rendered){check_tail}.\n")?;
    seeding_table(o, dev)
}

/// The twenty-sixth round's rule on its candidate, on the institute rows.
fn candidate_rule(o: &mut String, r: &Report) -> Res<()> {
    let (cand, ours) = (rows_of(r, CANDIDATE), rows_of(r, RULE_PRESET));
    if cand.is_empty() || cand.len() != ours.len() {
        return Err("the report lacks the candidate's rows".into());
    }
    let (c, b) = (
        over_rows(&cand, |x| &x.seeded),
        over_rows(&ours, |x| &x.seeded),
    );
    let verdict = if c > b {
        "above it, so the preset stays, an option no default uses"
    } else {
        "not above it, so the preset is withdrawn"
    };
    writeln!(o, "- Over the {} institute rows, `{CANDIDATE}` with spectral seeding averages **{} %** against `{RULE_PRESET}`'s {} %: {verdict}.", cand.len(), pct(c), pct(b))?;
    let higher = (cand.iter().zip(&ours))
        .filter(|(x, y)| mean(&x.seeded) > mean(&y.seeded))
        .count();
    writeln!(
        o,
        "- Row by row it is above `{RULE_PRESET}` in {higher} of the {} rows.",
        cand.len()
    )?;
    Ok(())
}

fn render_institute(dev: &Report, test: &Report) -> Res<String> {
    let span = |s: &[u64]| format!("{}-{}", s[0], s[s.len() - 1]);
    let test_seeds = span(INSTITUTE_TEST_SEEDS);
    let earlier = [TEST_SEEDS, MALL_TEST_SEEDS, HOME_TEST_SEEDS].map(span);
    let pooled = pooled(&["fresh-family", "fresh-family-2", "fresh-family-3"], test)?;
    let mut o = String::new();
    writeln!(o, "# A candidate preset and a fourth family written after the recommended room setting: research-institute floors (issue 18, twenty-sixth round)\n")?;
    writeln!(o, "**Why.** On the three families written after `{RULE_PRESET}` and spectral seeding were chosen (hotel {}, mall {}, home {}; docs/fresh-family.md, -2, -3) the setting gave 83.3, 64.1 and 76.3 % (85 % in 2 of 18 rows). **What changed (besides the model files' and `objects.rs`' plumbing for them):** two parts that describe the `objects` part's pieces by footprint class and top together (`object_types`) and by their layout (`object_layout`); the round's plan fixed them, their weights and the rule that chose among them on development seeds 1-6 of the hotel, mall and home floors before any run, and the rule made the candidate `{CANDIDATE}` (`{RULE_PRESET}` plus `object_types` at 20/3 and `object_layout` at 10/3; docs/object-types-dev.md: 78.1 against 75.2 % there, 91.2 against 92.1 % on the 14 earlier room rows). And the simulator gained research-institute floors (`placecat simulate --scene institute`: the corridor, laboratories, workshops, server rooms, seminar rooms; every room opens onto the corridor and is as deep as its row), written by another hand (a helper) in its own branch from a brief that named no descriptor, part, preset or figure, while the probe ran; it ran no descriptor or clustering on them, and the family was merged only after the candidate was committed. Nothing else changed. The plan and the rules were fixed in docs/seeds.md (\"issue 18, twenty-sixth round\") before the family existed or any run; this round's test run is the first description of the family. Rules: the candidate is withdrawn if over the six institute rows its mean with spectral seeding is not above `{RULE_PRESET}`'s; over the twenty-four hotel, mall, home and institute rows, if `{RULE_PRESET}` with spectral seeding has a mean below best of 10's with `{RULE_PRESET}`, the recommendation of spectral seeding for room sets is withdrawn, and if below the paper's `{PAPER_PRESET}` with spectral seeding, the README says `{RULE_PRESET}` did not carry over.\n", earlier[0], earlier[1], earlier[2])?;
    writeln!(
        o,
        "## The candidate's rule, computed on the institute rows, test seeds {test_seeds}\n"
    )?;
    candidate_rule(&mut o, test)?;
    writeln!(
        o,
        "\n## The recommendation's rule, computed on the hotel, mall, home and institute rows pooled\n"
    )?;
    rule(&mut o, &pooled, "hotel, mall, home and institute")?;
    writeln!(
        o,
        "\n## Readings on the institute floors, test seeds {test_seeds}\n"
    )?;
    readings(&mut o, test)?;
    writeln!(
        o,
        "\n## Readings on the hotel, mall, home and institute rows pooled\n"
    )?;
    readings(&mut o, &pooled)?;
    writeln!(o, "\nRegenerate with `cargo run --release --example fresh_family_round -- --institute --dev` (`fresh-family-4-dev.json`, {:.0} s) then `cargo run --release --example fresh_family_round -- --institute` (test seeds, this file and `fresh-family-4.json`, {:.0} s; it refuses to run again once `fresh-family-4.json` exists; `-- --institute --render` renders this file from them and the three earlier rounds' JSON). Rows, methods and listing as docs/fresh-family.md; the institute rows also with `{CANDIDATE}`.\n", dev.seconds, test.seconds)?;
    if !INSTITUTE_NOTES.is_empty() {
        writeln!(o, "## What it shows\n\n{INSTITUTE_NOTES}\n")?;
    }
    sections(&mut o, dev, test, &test_seeds, "")?;
    writeln!(
        o,
        "\n## Every test set, `{CANDIDATE}` (spectral seeding / best of 10 / stride k-means, %)\n"
    )?;
    per_set(&mut o, test, CANDIDATE)?;
    Ok(o)
}

/// What the twenty-sixth round showed, written after its one test run.
const INSTITUTE_NOTES: &str = "Written after the one test run (seeds 571-575, 2026-12-06 11:57, the code of commit e9a2e23; the plan and the rules were committed in docs/seeds.md at 11:03:00, commit 3ac27eb, before the parts, the probe and the family existed; the candidate at 11:52:25, 95d92ea, before the family was read or merged, 9a320b7). Figures are computed from the JSON files of this round and the three before it.

- **By the rule fixed beforehand, the candidate `indoor_object_types` stays, an option no default uses.** Over the six institute rows it averages 89.3 % with spectral seeding against `indoor_objects`' 87.1 % (+2.3 from the unrounded means; on the development seeds of the hotel, mall and home floors +2.9). It is above in 5 of the 6 rows (the own sensor 96.0 against 94.7, 16 beams 86.7 against 86.5, 32 beams 87.3 against 84.1, 64 beams 90.1 against 85.5, 1.8 m 87.1 against 81.8 %) and below at 0.3 m (88.9 against 89.8 %); set by set above in 15 of 30, below in 9, level in 6. Per seed over the rows it gives 81.6 to 95.9 % (`indoor_objects` 81.3 to 92.6 %), its sets 73.3 to 100 %.
- **It reaches 85 % with spectral seeding in all 6 institute rows, `indoor_objects` in 4** (not with 32 beams, 84.1 %, or at 1.8 m, 81.8 %). With stride k-means and best of 10 both at least 85 %: no row with either preset.
- **What got worse with the candidate:** stride k-means, 76.5 against 78.4 % over the rows (64 beams 75.6 against 84.0 %, 0.3 m 72.9 against 75.1 %); room-level 1-NN, 90.1 against 90.6 % (0.3 m 87.6 against 90.2, 1.8 m 83.1 against 84.9 %); best of 10 at 0.3 m (82.4 against 83.8) and 1.8 m (77.2 against 80.1 %). It is better with best of 10 over the rows (86.8 against 84.8 %), the tree (81.2 against 77.3 %) and spectral clustering (88.4 against 87.0 %). On the development seeds of the 14 earlier room rows it was 0.9 points below `indoor_objects` (docs/object-types-dev.md).
- **The institute is the easiest of the four families written after the setting** for `indoor_objects` (87.1 % against the hotel's 83.3, the mall's 64.1 and the home's 76.3 %), and its figures here say little about the harder families. A reading after this run, which decides nothing (docs/object-types-seen.md): on the hotel's, mall's and home's test seeds, which the choice among the probe's variants never looked at (it looked at seeds 1-6 of the same families), the candidate gives 77.2 against 74.6 % over the 18 rows (hotel 87.4 against 83.3, mall 65.4 against 64.1, home 78.9 against 76.3 %), lower in 3 rows (mall 32 beams, home 16 beams and 1.8 m), 85 % in 5 rows against 2.
- **By the recommendation's rule, it stands and `indoor_objects` carried over.** Over the 24 hotel, mall, home and institute rows `indoor_objects` with spectral seeding averages 77.7 % against best of 10's 75.8 % and the paper's `indoor` (with spectral seeding) 63.2 %; on the institute alone 87.1 against 84.8 and 70.3 %. Spectral seeding is below best of 10 in one institute row (32 beams, 84.1 against 84.9 %); `indoor_objects` is above `indoor` in every institute row with every method (by 6.1 to 28.9 points).
- **So on the four families written after the setting `indoor_objects` gave 83.3, 64.1, 76.3 and 87.1 % (85 % in 6 of 24 rows), and the candidate, on the institute only as a test, 89.3 %.** No apartments, offices, kitchens or restrooms on the institute floors; every room opens onto the corridor and is as deep as its row (6 to 8 m); one workshop, server room and seminar room a floor, laboratories in the rest (src/sim/institute.rs says what it leaves out).
- **The family is not independent of the hypothesis.** The same plan that stated it (objects differ in which sizes stand at which heights, and rows stand parallel) also named the family's kinds, among them server rooms of rack rows, laboratories of bench runs and seminar rooms of table rows; the helper's brief named no descriptor, part or figure and asked for realistic rooms, but a family of kinds chosen by someone else might favour the candidate less.
- **What else changed in placecat:** the simulator's new family (every other family's simulated scans pinned by digest and unchanged; the twenty-second round's development run re-ran to the same 216 figures on the hospital rows), the two parts and the preset, `objects.rs` exposing its pieces to them (every earlier part's values unchanged, by the parts' digests) and model files taking eleven part weights. No method or default changed.";
