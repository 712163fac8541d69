//! Issue 18, a development look after the twentieth round
//! (docs/order-free.md; development seeds 1-6 only; it changes no preset
//! or method and tunes nothing): k-means++ best of 10 misses 85 % on six
//! room rows with `indoor_objects`. Is that the search (more restarts
//! would find a cheaper grouping closer to the kinds) or the objective (the
//! kinds are not where k-means' cost is lowest)? For each set: the cheapest
//! of 10, 30 and 100 k-means++ runs, and k-means started from the true
//! kinds' means (Lloyd's iterations to convergence: the local minimum
//! nearest the truth), with its cost against the cheapest of 100.
//!
//!     cargo run --release --example restart_count_dev   # -> docs/restart-count-dev.md

use placecat::cluster::{KMeans, KMeansParams};
use placecat::distance::Space;
use placecat::eval::evaluate;
use placecat::*;
use std::fmt::Write;

include!("common/dev_look.rs");

const PRESET: &str = "indoor_objects";
/// Clustering seeds 0-4, 100 k-means++ runs each (runs 0-9 are best of
/// 10's, 0-29 best of 30's).
const SEEDS: u64 = 5;
const RUNS: usize = 100;
const COUNTS: [usize; 3] = [10, 30, 100];
/// Lloyd's iterations from the true kinds' means (`KMeansParams`' default
/// bound).
const ITERATIONS: usize = 100;

/// Written after the run.
const SHOWS: &str = "It is the objective, not the search. More restarts barely move the cheapest run's accuracy (over the 14 rows 87.8 % with 10, 88.0 with 30, 88.2 with 100; on the rows that miss 85 % it goes up on some, the school with 16 beams 82.5 -> 85.2 % and the hospital with 16 beams 76.1 -> 79.3 %, and down on others, the office floor at 0.3 m 83.3 -> 81.1 %). k-means started from the true kinds' means stops at a grouping of 93.3 to 100 % accuracy in every row (97.0 % over them), but that local minimum costs 0.2 to 3.0 % more than the cheapest of 100 runs (1.4 % over the rows) and is cheaper than every one of the 500 runs on none of the 84 sets. So on `indoor_objects`' distance the kinds are a local minimum of k-means' cost near which the cheapest groupings lie, not the cheapest grouping; a search that finds lower cost does not find the kinds, and meeting the target with k-means needs a distance under which the kinds are cheaper, not more restarts. (The walk from the truth needs the labels: it is a bound, not a method. It does say that k-means started from a few scans the user has named, semi-supervised seeding in the manner of Basu, Banerjee and Mooney, ICML 2002, would keep the kinds; that is not training-free and was not tried.)";

/// One set's figures: accuracy of the cheapest of 10, 30 and 100 runs
/// (means over the clustering seeds); k-means from the truth's accuracy;
/// its cost over the cheapest of 100's (mean over seeds); and whether it
/// is cheaper than that on every seed.
struct SetFigures {
    cheapest: [f64; 3],
    from_truth: f64,
    cost_ratio: f64,
    truth_cheaper: bool,
}

fn measure(space: &Space, truth: &[String], k: usize) -> Res<SetFigures> {
    let mut cheapest = [0.0; 3];
    let mut lowest_cost = f64::INFINITY;
    let mut ratio_sum = 0.0;
    // The true kinds as groups 0..k (in sorted order).
    let mut kinds: Vec<&String> = truth.iter().collect();
    kinds.sort();
    kinds.dedup();
    let groups: Vec<i32> = (truth.iter())
        .map(|t| {
            kinds
                .iter()
                .position(|&kind| kind == t)
                .map_or(-1, |g| g as i32)
        })
        .collect();
    let walk = KMeans::fit_from_groups(space, &groups, kinds.len(), ITERATIONS)?;
    let from_truth = evaluate(truth, &walk.labels)?.accuracy;
    for s in 0..SEEDS {
        let runs = KMeans::runs(space, &KMeansParams::new(k).seed(s).restarts(RUNS))?;
        for (c, &count) in COUNTS.iter().enumerate() {
            let best = (runs[..count].iter())
                .min_by(|a, b| a.cost.total_cmp(&b.cost))
                .ok_or("no run")?;
            cheapest[c] += evaluate(truth, &best.labels)?.accuracy / SEEDS as f64;
            if count == RUNS {
                lowest_cost = lowest_cost.min(best.cost);
                ratio_sum += walk.cost / best.cost;
            }
        }
    }
    Ok(SetFigures {
        cheapest,
        from_truth,
        cost_ratio: ratio_sum / SEEDS as f64,
        truth_cheaper: (walk.cost) < lowest_cost,
    })
}

fn main() -> Res<()> {
    check_dev()?;
    let t0 = std::time::Instant::now();
    let mut table = String::new();
    let rows = room_rows();
    // Sums over the rows of each column's mean, for the summary.
    let mut totals = [0.0f64; 5];
    let mut truth_cheaper = 0;
    let mut sets = 0;
    for (f, sensor) in &rows {
        let f = Family {
            shuffle: true,
            ..f.clone()
        };
        let mut cols = [0.0f64; 5];
        let mut cheaper_here = 0;
        for &seed in DEV_SEEDS {
            let set = describe_set(&f, *sensor, seed, &[PRESET.to_string()])?;
            let (_, params, ds) = set.presets.first().ok_or("the preset described nothing")?;
            let space = Space::new(ds, DistanceOptions::from(params))?;
            let m = measure(&space, &set.truth, set.kinds)?;
            let values = [
                m.cheapest[0],
                m.cheapest[1],
                m.cheapest[2],
                m.from_truth,
                m.cost_ratio,
            ];
            for (c, v) in cols.iter_mut().zip(values) {
                *c += v / DEV_SEEDS.len() as f64;
            }
            cheaper_here += m.truth_cheaper as usize;
            sets += 1;
        }
        truth_cheaper += cheaper_here;
        for (t, c) in totals.iter_mut().zip(cols) {
            *t += c / rows.len() as f64;
        }
        let mut cells: Vec<String> = cols[..4].iter().map(|x| pct(*x)).collect();
        cells.push(format!("{:.3}", cols[4]));
        cells.push(format!("{cheaper_here} of {}", DEV_SEEDS.len()));
        eprintln!(
            "{} {}: {} ({:.0} s)",
            f.name,
            sensor.name(),
            cells.join(" | "),
            t0.elapsed().as_secs_f64()
        );
        table_row(&mut table, &f, *sensor, &cells)?;
    }
    let mut o = String::new();
    writeln!(
        o,
        "# More k-means restarts, or another objective? (issue 18, a development look)\n"
    )?;
    writeln!(o, "{DEV_NOTE} Regenerate with `cargo run --release --example restart_count_dev` ({:.0} s). The 14 room rows (45 scans listed in a random order, 5 kinds, k = 5), `{PRESET}`. For each set and clustering seed 0-{}: {RUNS} k-means++ runs (`KMeans::runs`, RNG streams 0-{} of the seed; the first 10 are the rounds' best of 10), and the accuracy of the cheapest of the first 10, 30 and {RUNS}. Beside them, k-means started from the true kinds' means (Lloyd's iterations, at most {ITERATIONS}: the local minimum nearest the truth, which needs the labels), its accuracy, its cost over the cheapest of {RUNS}'s (above 1: costlier than what the restarts found), and on how many sets it is cheaper than every one of the {} runs.\n", t0.elapsed().as_secs_f64(), SEEDS - 1, RUNS - 1, SEEDS as usize * RUNS)?;
    writeln!(o, "**What it shows** (written after the run): {SHOWS}\n")?;
    writeln!(o, "Over the 14 rows: cheapest of 10 {}, of 30 {}, of {RUNS} {} %; from the truth {} %, its cost {:.3} times the cheapest of {RUNS}'s; cheaper than every run on {truth_cheaper} of {sets} sets.\n", pct(totals[0]), pct(totals[1]), pct(totals[2]), pct(totals[3]), totals[4])?;
    writeln!(o, "| row | cheapest of 10 % | cheapest of 30 % | cheapest of {RUNS} % | k-means from the truth % | its cost / cheapest of {RUNS}'s | sets where it is cheaper than every run |")?;
    writeln!(o, "|---|---|---|---|---|---|---|")?;
    o.push_str(&table);
    write_doc("restart-count-dev.md", &o)
}
