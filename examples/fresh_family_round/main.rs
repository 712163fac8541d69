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
//! The twenty-seventh round (`--gym`) runs it on sports-centre fitness
//! floors, a fifth family whose building and kinds another hand chose,
//! with the candidate as the twenty-sixth round left it; its rules read
//! the candidate on the gym rows and the recommendation on the five
//! later families' rows pooled:
//!
//!     ... -- --gym --dev   # docs/fresh-family-5-dev.json
//!     ... -- --gym         # test seeds 581-585, once: docs/fresh-family-5.{json,md}
//!     ... -- --gym --render
//!
//! Each plan and rule was fixed in docs/seeds.md ("issue 18,
//! twenty-third round" and the four after it) before its family existed. The development run
//! checks the harness only: on the hospital's rows it must give every
//! figure of the twenty-second round's development run. The test run
//! refuses to overwrite its report.

#[path = "../common/families.rs"]
mod families;
mod gym;
mod home;
mod hotel;
mod institute;
#[allow(dead_code)] // the listing of the earlier rounds
#[path = "../common/listed_rounds.rs"]
mod listed_rounds;
mod mall;
#[path = "../common/preset_rounds.rs"]
mod preset_rounds;
mod report;
#[allow(dead_code)]
#[path = "../common/rounds.rs"]
mod rounds;
#[path = "../common/seeds.rs"]
mod seeds;
#[allow(dead_code)]
#[path = "../common/site_rounds.rs"]
mod site_rounds;
use families::*;
use listed_rounds::*;
use report::*;
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
/// The twenty-seventh round's, fixed in docs/seeds.md before any run.
const GYM_TEST_SEEDS: &[u64] = &[581, 582, 583, 584, 585];
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

const ROUNDS: [Round; 5] = [
    Round {
        flag: "",
        stem: "fresh-family",
        family: hotel_family,
        test_seeds: TEST_SEEDS,
        render: hotel::render,
    },
    Round {
        flag: "--mall",
        stem: "fresh-family-2",
        family: mall_family,
        test_seeds: MALL_TEST_SEEDS,
        render: mall::render,
    },
    Round {
        flag: "--home",
        stem: "fresh-family-3",
        family: home_family,
        test_seeds: HOME_TEST_SEEDS,
        render: home::render,
    },
    Round {
        flag: "--institute",
        stem: "fresh-family-4",
        family: institute_family,
        test_seeds: INSTITUTE_TEST_SEEDS,
        render: institute::render,
    },
    Round {
        flag: "--gym",
        stem: "fresh-family-5",
        family: gym_family,
        test_seeds: GYM_TEST_SEEDS,
        render: gym::render,
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
