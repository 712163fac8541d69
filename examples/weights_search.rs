//! Issue 18, thirteenth round, development: the nine part weights chosen by
//! a search instead of by hand, and the decision on them. Development
//! seeds only (1-3 for the search, 4-6 to judge it); the procedure, the
//! objective and the decision rule were fixed in docs/seeds.md ("issue
//! 18, thirteenth round") before any run.
//!
//!     cargo run --release --example weights_search   # -> docs/weights-dev.{md,json}
//!
//! Every room row (each room family with each of its sensors) on seeds 1-6
//! is described once with every part kind, so that a weighting is only a
//! [`DistanceOptions`] over the same descriptors. Coordinate ascent over the
//! weights of the NDT histogram and the eight part kinds, from
//! `indoor_columns`' weights, on seeds 1-3: the objective is the mean over
//! those sets of the mean of stride k-means' accuracy and k-means++ best of
//! 10's with clustering seed 0; within one weight's trials, in order, a
//! trial is kept if it beats the best so far (the kept trial's, else the
//! start's) by at least 0.1 point. Then `indoor_columns` and the weights found,
//! on seeds 4-6, with the harness's figures (stride k-means; k-means++ best
//! of 10, the mean over clustering seeds 0-9; room-level 1-NN), and the
//! rule's verdict.

use placecat::descriptor::DescriptorParams;
use rayon::prelude::*;
use serde::Serialize;
use std::fmt::Write;

#[path = "common/families.rs"]
mod families;
// The rounds' tables go unused here.
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
#[path = "common/seeds.rs"]
mod seeds;
// The later rounds' capped objective and judging go unused here.
#[allow(dead_code)]
#[path = "common/weight_search.rs"]
mod weight_search;
use weight_search::*;

/// Fixed in docs/seeds.md before any run.
const SEARCH_SEEDS: &[u64] = &[1, 2, 3];
const JUDGE_SEEDS: &[u64] = &[4, 5, 6];
const TEST_SEEDS: &[u64] = &[431, 432, 433, 434, 435];
const BASE: &str = "indoor_columns";
/// The rows that missed the target on the twelfth round's test seeds.
const MISSED: [(&str, &str); 9] = [
    ("school (fresh)", "own"),
    ("school (fresh)", "16 beams"),
    ("school (fresh)", "32 beams"),
    ("school (fresh)", "64 beams"),
    ("school (fresh)", "at 0.3 m"),
    ("school (fresh)", "at 1.8 m"),
    ("hospital (fresh)", "own"),
    ("hospital (fresh)", "16 beams"),
    ("office floor", "at 0.3 m"),
];
/// The rule: the least mean lift on the missed rows, and the most the
/// other rows' mean may fall (points), with both k-means.
const LIFT: f64 = 3.0;
const FALL: f64 = 2.0;
const REPORT: &str = "weights-dev";

#[derive(Serialize)]
struct RowOut {
    family: String,
    sensor: String,
    missed: bool,
    /// Per weighting (`indoor_columns`, the candidate), mean over the seeds.
    search: [Figures; 2],
    judge: [Figures; 2],
}

#[derive(Serialize)]
struct Out {
    base_weights: [f32; WEIGHTS],
    found_weights: [f32; WEIGHTS],
    base_objective: f64,
    found_objective: f64,
    steps: Vec<Step>,
    rows: Vec<RowOut>,
    /// Mean lift on the missed rows and on the others, stride / best of 10,
    /// on the judging seeds.
    missed_lift: [f64; 2],
    others_lift: [f64; 2],
    preset: bool,
    evaluations: usize,
    seconds: f64,
}

fn main() -> Res<()> {
    let dev: Vec<u64> = SEARCH_SEEDS.iter().chain(JUDGE_SEEDS).copied().collect();
    seeds::check_round_seeds(&dev, TEST_SEEDS)?;
    let t0 = std::time::Instant::now();
    // The first set is also described with `BASE` itself.
    let sets = describe_rows(&dev, BASE, BASE, t0)?;
    let described = t0.elapsed().as_secs_f64();
    let base = weights_of(&DescriptorParams::preset(BASE)?);

    let search: Vec<&Set> = (sets.iter())
        .filter(|s| SEARCH_SEEDS.contains(&s.seed))
        .collect();
    let mut evaluations = 0;
    let mut objective = |w: &Weights| -> Res<f64> {
        evaluations += 1;
        let v: Vec<f64> = search
            .par_iter()
            .map(|s| quick(s, w).map(|(stride, best)| (stride + best) / 2.0))
            .collect::<placecat::Result<_>>()?;
        Ok(100.0 * v.iter().sum::<f64>() / v.len() as f64)
    };
    let base_objective = objective(&base)?;
    eprintln!(
        "start {base:?}: {base_objective:.2} ({:.0} s)",
        t0.elapsed().as_secs_f64()
    );
    let (w, best, steps) = ascend(base, base_objective, &mut objective, |line| {
        eprintln!("{line} ({:.0} s)", t0.elapsed().as_secs_f64())
    })?;

    // Every row, both weightings, the harness's figures on both seed sets.
    let figures = both(&sets, &base, &w)?;
    let keys = row_keys(&sets);
    let of = |key, seeds: &[u64], which| row_figures(&sets, &figures, key, seeds, which);
    let rows: Vec<RowOut> = (keys.iter())
        .map(|&key| RowOut {
            family: key.0.into(),
            sensor: key.1.into(),
            missed: MISSED.contains(&key),
            search: [of(key, SEARCH_SEEDS, 0), of(key, SEARCH_SEEDS, 1)],
            judge: [of(key, JUDGE_SEEDS, 0), of(key, JUDGE_SEEDS, 1)],
        })
        .collect();
    let lift = |missed: bool| -> [f64; 2] {
        let r: Vec<&RowOut> = rows.iter().filter(|r| r.missed == missed).collect();
        let n = r.len() as f64;
        [
            100.0
                * r.iter()
                    .map(|r| r.judge[1].stride - r.judge[0].stride)
                    .sum::<f64>()
                / n,
            100.0
                * r.iter()
                    .map(|r| r.judge[1].best_of_10 - r.judge[0].best_of_10)
                    .sum::<f64>()
                / n,
        ]
    };
    let (missed_lift, others_lift) = (lift(true), lift(false));
    if rows.iter().filter(|r| r.missed).count() != MISSED.len() {
        return Err("a row the rule names is not among the room rows".into());
    }
    let preset = missed_lift.iter().all(|&l| l >= LIFT) && others_lift.iter().all(|&l| l > -FALL);
    let out = Out {
        base_weights: base,
        found_weights: w,
        base_objective,
        found_objective: best,
        steps,
        rows,
        missed_lift,
        others_lift,
        preset,
        evaluations,
        seconds: t0.elapsed().as_secs_f64(),
    };
    write_report(REPORT, &out, render(&out, described)?, t0)
}

fn render(o: &Out, described: f64) -> Res<String> {
    let mut t = String::new();
    writeln!(
        t,
        "# Part weights chosen by a search (issue 18, thirteenth round, development seeds)\n"
    )?;
    writeln!(t, "Regenerate with `cargo run --release --example weights_search` ({:.0} s on the shared two-core machine, {described:.0} s of it describing). The procedure, its objective and the decision rule were written in docs/seeds.md (\"issue 18, thirteenth round\") before any run. Every room row (each room family with each of its sensors) on development seeds 1-6, 45 scans a set, described once with every part kind; a weighting is a distance over the same descriptors (checked: `{BASE}`'s weights over them give the Delta matrix of `{BASE}`'s own descriptors, bit for bit).\n", o.seconds)?;
    writeln!(t, "**The search** (seeds 1-3 only): coordinate ascent over the nine weights from `{BASE}`'s; objective, the mean over the 14 rows x 3 seeds of (stride k-means + k-means++ best of 10 with clustering seed 0) / 2. {} evaluations.\n", o.evaluations)?;
    render_path(
        &mut t,
        (&o.base_weights, o.base_objective),
        &o.steps,
        (&o.found_weights, o.found_objective),
    )?;
    writeln!(t, "**The decision** (seeds 4-6, which the search never saw; harness figures: stride k-means, k-means++ best of 10 as the mean over clustering seeds 0-9): on the nine rows that missed on the twelfth round's test seeds the found weights lift stride k-means by {:+.1} and best of 10 by {:+.1} points on average against `{BASE}` (the rule asks at least {LIFT}); the other five room rows move by {:+.1} / {:+.1} (the rule allows a fall of less than {FALL}). {}\n",
        o.missed_lift[0], o.missed_lift[1], o.others_lift[0], o.others_lift[1],
        if o.preset { "The rule is met: the weights become the preset `indoor_searched`, which the test run (431-435) judges." } else { "The rule is not met: no preset; the test run (431-435) reports the candidate beside the presets." })?;
    for (title, judge) in [
        ("Seeds 4-6 (judging)", true),
        ("Seeds 1-3 (the search's own)", false),
    ] {
        writeln!(t, "## {title}\n")?;
        writeln!(t, "Mean over the seeds, `{BASE}` -> found weights; \"missed\": one of the nine rows the rule names.\n")?;
        writeln!(
            t,
            "| row | missed | stride k-means | best of 10 | room-level 1-NN |"
        )?;
        writeln!(t, "|---|---|---|---|---|")?;
        for r in &o.rows {
            let f = if judge { &r.judge } else { &r.search };
            let missed = if r.missed { "yes" } else { "" };
            let (family, sensor) = (&r.family, &r.sensor);
            writeln!(t, "| {family}, {sensor} | {missed} | {} |", cells(f))?;
        }
        writeln!(t)?;
    }
    Ok(t)
}
