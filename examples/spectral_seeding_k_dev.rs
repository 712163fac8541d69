//! Issue 18, a development look after the twenty-second round (seeds 1-6
//! only; it changes no preset, parameter or file but its report and tunes
//! nothing): what the CLI's `--k auto` (and Python's `k="auto"`) gives for
//! k-means with spectral seeding on room sets, the sets that seeding is
//! recommended for. (After this look a set's choice refuses spectral
//! seeding; the look calls the choice module directly, as the set did.) `--k auto` is the CLI's default for k-means, so
//! `placecat cluster --method kmeans --seeding spectral` without `--k`
//! takes this path. The rule is the library's default, `silhouette_gap`
//! (docs/choose_k.md), with every K and every reference set clustered by
//! k-means with spectral seeding.
//!
//!     cargo run --release --example spectral_seeding_k_dev   # -> docs/spectral-seeding-k-dev.md

use placecat::cluster::choose_k::{choose_k, ChooseKParams, Clusterer, DEFAULT_RULE};
use placecat::cluster::{KMeansParams, Seeding};
use placecat::distance::Space;
use placecat::DistanceOptions;
use std::fmt::Write;

include!("common/dev_look.rs");

const PRESETS: [&str; 2] = ["indoor_searched", "indoor_objects"];

/// Written after the run.
const SHOWS: &str = "The CLI's `--k auto` with spectral seeding finds the five kinds of none of these room sets: it names 5 on none of the 84 sets with either preset, and one category on all 60 sets of the office floors, schools and hospital wards, whose best mean silhouette over K = 2..10 is 0.29 to 0.49, under the rule's bound of 0.5; on placecat's own indoor families (24 sets) it says 2 to 4, or 1 (on 1 set with `indoor_searched`, 9 with `indoor_objects`). As for spectral clustering (docs/spectral-k-dev.md), no rule for the number of kinds is found for these sets. So after this look a set's choice of K (the CLI's `--k auto`, its default for k-means, and Python's `k=\"auto\"`, also its default) refuses spectral seeding with an error that asks for k, rather than answering one category; the choice module itself still runs it, for looks such as this one. No other rule or bound was tried.";

fn main() -> Res<()> {
    check_dev()?;
    let t0 = std::time::Instant::now();
    let presets: Vec<String> = PRESETS.iter().map(|p| p.to_string()).collect();
    let mut table = String::new();
    // Per preset: sets where the rule named the true number of kinds, and
    // where it named one category.
    let mut totals = [[0usize; 2]; PRESETS.len()];
    let mut sets = 0usize;
    for (f, sensor) in room_rows() {
        let f = Family { shuffle: true, ..f };
        // Per preset: the chosen K and the best mean silhouette on each seed.
        let mut ks = vec![(vec![], vec![]); PRESETS.len()];
        for &seed in DEV_SEEDS {
            let set = describe_set(&f, sensor, seed, &presets)?;
            sets += 1;
            for (p, (_, params, descriptors)) in set.presets.iter().enumerate() {
                // What a set's choice computed (Collection::choose_categories
                // with its Delta matrix), which now refuses spectral seeding.
                let space = Space::new(descriptors, DistanceOptions::from(params))?;
                let seeded = KMeansParams::new(1).seeding(Seeding::Spectral);
                let choice = choose_k(
                    &space,
                    Some(&space.matrix()),
                    Clusterer::KMeans(&seeded),
                    &ChooseKParams::default(),
                    DEFAULT_RULE,
                )?;
                totals[p][0] += usize::from(choice.k == set.kinds);
                totals[p][1] += usize::from(choice.k == 1);
                let silhouette = choice.one_category.unwrap_or(f64::NAN);
                ks[p].0.push(choice.k);
                ks[p].1.push(silhouette);
            }
        }
        let cells: Vec<String> = (ks.iter())
            .flat_map(|(k, s)| {
                let k: Vec<String> = k.iter().map(|k| k.to_string()).collect();
                let s: Vec<String> = s.iter().map(|s| format!("{s:.2}")).collect();
                [k.join(", "), s.join(", ")]
            })
            .collect();
        finish_row(&mut table, &f, sensor, &cells, t0)?;
    }
    let mut o = String::new();
    writeln!(o, "# Choosing k for k-means with spectral seeding, a look (issue 18, after the twenty-second round)\n")?;
    writeln!(o, "{DEV_NOTE} Regenerate with `cargo run --release --example spectral_seeding_k_dev` ({:.0} s). Every room row, 45 scans a set of 5 kinds listed in a random order, development seeds 1-6. For each set, the K that the CLI's `--k auto` (its default for k-means) chooses with `--seeding spectral`: the library's default rule, `silhouette_gap` (docs/choose_k.md: one category unless the mean silhouette on Delta reaches 0.5 at some K in 2..10, else the gap statistic's 1-SE rule), every K and every reference set clustered by k-means with spectral seeding (seed 0), and that best mean silhouette.\n", t0.elapsed().as_secs_f64())?;
    writeln!(o, "**What it shows** (written after the run): {SHOWS}\n")?;
    for (p, name) in PRESETS.iter().enumerate() {
        let share = |n: usize| pct(n as f64 / sets as f64);
        writeln!(
            o,
            "- `{name}`: the rule names the 5 kinds in {} of {sets} sets ({} %) and one category in {} ({} %).",
            totals[p][0],
            share(totals[p][0]),
            totals[p][1],
            share(totals[p][1])
        )?;
    }
    writeln!(o, "\n| row | `{0}`: K per seed | its best silhouette | `{1}`: K per seed | its best silhouette |", PRESETS[0], PRESETS[1])?;
    writeln!(o, "|---|---|---|---|---|")?;
    o.push_str(&table);
    write_doc("spectral-seeding-k-dev.md", &o)
}
