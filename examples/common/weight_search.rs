//! What the weight searches share (issue 18, thirteenth round:
//! `weights_search.rs`; fifteenth: `rooms_search.rs`): room rows described
//! once with every part kind, so that a weighting is only a
//! [`DistanceOptions`] over the same descriptors; the harness's figures of
//! a weighting; and coordinate ascent over the nine weights their plans
//! named.
//! Include after `families.rs` and `rounds.rs`.

use crate::families::{room_rows, Family, Sensor};
use crate::rounds::{describe_set_with, room_level_nn, Apart, Res, CLUSTER_SEEDS};
use placecat::cluster::*;
use placecat::descriptor::{DescriptorParams, Part, PartKind};
use placecat::*;
use serde::Serialize;

/// The weights: the NDT histogram's, then one per part kind in
/// `PartKind::ALL`'s order.
pub const WEIGHTS: usize = 1 + PartKind::ALL.len();
pub type Weights = [f32; WEIGHTS];
/// The weights the thirteenth and fifteenth rounds' plans searched: the
/// NDT histogram's and the part kinds up to `iron`, nine. Kinds added
/// later (`objects`) keep their start weight, so that those searches run
/// again as they were planned and run.
pub const SEARCHED_WEIGHTS: usize = 2 + PartKind::Iron.index();
/// Trials for a weight w > 0 (multiples of w) and for a weight 0.
const STEPS: [f32; 5] = [0.0, 0.25, 0.5, 2.0, 4.0];
const FROM_ZERO: [f32; 5] = [1.0, 2.5, 5.0, 10.0, 20.0];
/// A trial is kept if it raises the objective by at least this (points).
const KEEP: f64 = 0.1;
const MAX_SWEEPS: usize = 4;

/// One set (a room row on one seed) described with every part kind.
pub struct Set {
    pub family: &'static str,
    pub sensor: String,
    pub seed: u64,
    pub truth: Vec<String>,
    pub kinds: usize,
    pub apart: Apart,
    pub params: DescriptorParams,
    pub descriptors: Vec<Descriptor>,
}

/// The harness's figures of one weighting on one set.
#[derive(Serialize, Clone, Copy)]
pub struct Figures {
    pub stride: f64,
    pub best_of_10: f64,
    pub nn: f64,
}

/// One kept step of the search.
#[derive(Serialize)]
pub struct Step {
    pub sweep: usize,
    pub weight: String,
    pub from: f32,
    pub to: f32,
    pub objective: f64,
}

/// `base`'s parameters with every part kind (weight 1 each: the weights
/// that count are a [`DistanceOptions`]'s).
fn all_parts(base: &str) -> Res<DescriptorParams> {
    let mut p = DescriptorParams::preset(base)?;
    p.preset = "every part".into();
    p.parts = (PartKind::ALL.iter())
        .map(|&kind| Part { kind, weight: 1.0 })
        .collect();
    p.validate()?;
    Ok(p)
}

/// One room row on one seed, described with every part kind on `base`'s
/// NDT settings. With `check`, the same simulation is also described with
/// `check` itself, and refused unless `check`'s weights over every part's
/// descriptors give the Delta matrix of its own descriptors: then a
/// weighting is the distance of a preset with those weights.
pub fn describe_all_parts(
    f: &Family,
    sensor: Sensor,
    seed: u64,
    base: &str,
    check: Option<&str>,
) -> Res<Set> {
    let params = all_parts(base)?;
    let p = params.clone();
    let checked: Vec<String> = check.into_iter().map(String::from).collect();
    let mut set = describe_set_with(f, sensor, seed, &checked, |_| {
        Ok(vec![(p.preset.clone(), p)])
    })?;
    let all = (set.presets.iter()).position(|d| d.0 == params.preset);
    let (_, _, descriptors) = all.map(|i| set.presets.remove(i)).ok_or_else(|| {
        format!(
            "{} {} seed {seed}: a scan could not be described",
            f.name,
            sensor.name()
        )
    })?;
    let out = Set {
        family: f.name,
        sensor: sensor.name(),
        seed,
        truth: set.truth,
        kinds: set.kinds,
        apart: set.apart,
        params,
        descriptors,
    };
    if let Some(name) = check {
        let (_, p, ds) = (set.presets.first()).ok_or("the preset described nothing")?;
        let theirs = Space::new(ds, DistanceOptions::from(p))?.matrix();
        let ours = space(&out, &weights_of(p))?.matrix();
        if theirs.data != ours.data {
            return Err(
                format!("{name}'s weights over every part differ from {name} itself").into(),
            );
        }
    }
    Ok(out)
}

/// Every room row on each of `seeds`, described with every part kind on
/// `base`'s NDT settings (progress on stderr); the first set also with
/// `check` (see [`describe_all_parts`]).
pub fn describe_rows(
    seeds: &[u64],
    base: &str,
    check: &str,
    t0: std::time::Instant,
) -> Res<Vec<Set>> {
    let mut sets = vec![];
    for (f, sensor) in room_rows() {
        for &seed in seeds {
            eprintln!(
                "{} {} seed {seed} ({:.0} s)",
                f.name,
                sensor.name(),
                t0.elapsed().as_secs_f64()
            );
            let first = sets.is_empty().then_some(check);
            sets.push(describe_all_parts(&f, sensor, seed, base, first)?);
        }
    }
    Ok(sets)
}

/// The rows (family, sensor) of `sets`, each once, in the order they first
/// appear.
pub fn row_keys(sets: &[Set]) -> Vec<(&str, &str)> {
    let mut keys: Vec<(&str, &str)> = vec![];
    for key in sets.iter().map(|s| (s.family, s.sensor.as_str())) {
        if !keys.contains(&key) {
            keys.push(key);
        }
    }
    keys
}

/// A preset's weights in the order of [`WEIGHTS`].
pub fn weights_of(p: &DescriptorParams) -> Weights {
    let opts = DistanceOptions::from(p);
    let mut w = [0f32; WEIGHTS];
    w[0] = opts.ndt_weight;
    w[1..].copy_from_slice(&opts.part_weights);
    w
}

pub fn weight_name(c: usize) -> String {
    if c == 0 {
        return "ndt_histogram".into();
    }
    PartKind::ALL[c - 1].name().into()
}

/// The weights above 0, named ("ndt_histogram 1, slice 4").
pub fn show(w: &Weights) -> String {
    (0..WEIGHTS)
        .filter(|&c| w[c] > 0.0)
        .map(|c| format!("{} {}", weight_name(c), w[c]))
        .collect::<Vec<_>>()
        .join(", ")
}

fn space(s: &Set, w: &Weights) -> placecat::Result<Space> {
    let mut opts = DistanceOptions::from(&s.params);
    opts.ndt_weight = w[0];
    opts.part_weights.copy_from_slice(&w[1..]);
    Space::new(&s.descriptors, opts)
}

fn accuracy(s: &Set, labels: &[i32]) -> placecat::Result<f64> {
    Ok(placecat::eval::evaluate(&s.truth, labels)?.accuracy)
}

/// Stride k-means' accuracy, and k-means++ best of 10's with each of
/// `seeds` (Send results: the sets run in parallel).
fn kmeans(s: &Set, sp: &Space, seeds: std::ops::Range<u64>) -> placecat::Result<(f64, Vec<f64>)> {
    let stride = KMeans::fit(sp, &KMeansParams::new(s.kinds).seeding(Seeding::Stride))?;
    let best = (seeds.map(|seed| {
        accuracy(
            s,
            &KMeans::fit(sp, &KMeansParams::new(s.kinds).seed(seed).restarts(10))?.labels,
        )
    }))
    .collect::<placecat::Result<_>>()?;
    Ok((accuracy(s, &stride.labels)?, best))
}

/// What the searches score a weighting by on one set: stride k-means' and
/// k-means++ best of 10's (clustering seed 0) accuracy.
pub fn quick(s: &Set, w: &Weights) -> placecat::Result<(f64, f64)> {
    let (stride, best) = kmeans(s, &space(s, w)?, 0..1)?;
    Ok((stride, best[0]))
}

/// The harness's figures: stride k-means, k-means++ best of 10 (the mean
/// over clustering seeds 0-9, as `rounds::over_seeds`), room-level 1-NN.
pub fn full(s: &Set, w: &Weights) -> placecat::Result<Figures> {
    let sp = space(s, w)?;
    let (stride, best) = kmeans(s, &sp, 0..CLUSTER_SEEDS)?;
    Ok(Figures {
        stride,
        best_of_10: best.iter().map(|a| a / CLUSTER_SEEDS as f64).sum(),
        nn: room_level_nn(&sp.matrix(), &s.truth, &s.apart),
    })
}

/// The fifteenth round's objective of weighting `w` over `sets`: the mean
/// over the rows `keys` of (min(S, cap) + min(B, cap)) / 2, S and B the
/// row's [`quick`] stride k-means and best of 10 accuracy (%), each the
/// mean over the row's sets.
pub fn capped_objective(sets: &[&Set], keys: &[(&str, &str)], w: &Weights, cap: f64) -> Res<f64> {
    use rayon::prelude::*;
    let v: Vec<(f64, f64)> = sets
        .par_iter()
        .map(|s| quick(s, w))
        .collect::<placecat::Result<_>>()?;
    let credit = |&(family, sensor): &(&str, &str)| {
        let row: Vec<&(f64, f64)> = (sets.iter().zip(&v))
            .filter(|(s, _)| (s.family, s.sensor.as_str()) == (family, sensor))
            .map(|(_, f)| f)
            .collect();
        let n = row.len() as f64;
        let stride = 100.0 * row.iter().map(|f| f.0).sum::<f64>() / n;
        let best = 100.0 * row.iter().map(|f| f.1).sum::<f64>() / n;
        (stride.min(cap) + best.min(cap)) / 2.0
    };
    Ok(keys.iter().map(credit).sum::<f64>() / keys.len() as f64)
}

/// How rows' figures stand against issue 18's indoor target: how many
/// rows meet `target` (%) with both stride k-means and best of 10, and the
/// mean over the rows of (stride k-means + best of 10) / 2 (%).
pub fn against_target(rows: &[Figures], target: f64) -> (usize, f64) {
    let met = (rows.iter())
        .filter(|f| 100.0 * f.stride >= target && 100.0 * f.best_of_10 >= target)
        .count();
    let mean = (rows.iter())
        .map(|f| 100.0 * (f.stride + f.best_of_10) / 2.0)
        .sum::<f64>()
        / rows.len() as f64;
    (met, mean)
}

/// A row: (family, sensor).
pub type RowKey<'a> = (&'a str, &'a str);
/// Figures of two weightings, the first then the second.
pub type Pair = [Figures; 2];

/// Two weightings' harness figures ([`both`]) row by row, on the seeds
/// that chose the second (`fitted`) and on the seeds that judge it, and on
/// the latter [`against_target`] for each: what the fifteenth and
/// sixteenth rounds' decisions read.
pub struct Judged<'a> {
    /// Each row (family, sensor), its figures on the fitted seeds, then
    /// on the judging seeds; each pair the first weighting, then the
    /// second.
    pub rows: Vec<(RowKey<'a>, Pair, Pair)>,
    /// On the judging seeds, per weighting: rows meeting the target, and
    /// the mean over the rows of (stride k-means + best of 10) / 2 (%).
    pub met: [usize; 2],
    pub mean: [f64; 2],
}

impl Judged<'_> {
    /// The rounds' rule: the second weighting meets the target in more
    /// rows, and its mean is not lower.
    pub fn second_wins(&self) -> bool {
        self.met[1] > self.met[0] && self.mean[1] >= self.mean[0]
    }
}

/// [`Judged`] for weightings `a` and `b` over every row of `sets`.
pub fn judge_both<'a>(
    sets: &'a [Set],
    (a, b): (&Weights, &Weights),
    (fitted, judging): (&[u64], &[u64]),
    target: f64,
) -> Res<Judged<'a>> {
    let figures = both(sets, a, b)?;
    let of = |key, seeds: &[u64], which| row_figures(sets, &figures, key, seeds, which);
    let rows: Vec<_> = (row_keys(sets).into_iter())
        .map(|key| {
            let pair = |seeds: &[u64]| [of(key, seeds, 0), of(key, seeds, 1)];
            (key, pair(fitted), pair(judging))
        })
        .collect();
    let judged = |which: usize| {
        let figures: Vec<Figures> = rows.iter().map(|r| r.2[which]).collect();
        against_target(&figures, target)
    };
    let ((met0, mean0), (met1, mean1)) = (judged(0), judged(1));
    Ok(Judged {
        rows,
        met: [met0, met1],
        mean: [mean0, mean1],
    })
}

/// A report's table of rows' figures for two weightings ([`cells`]), under
/// `## title` and a line saying which two.
pub fn figures_table<'a>(
    t: &mut String,
    title: &str,
    lead: &str,
    rows: impl Iterator<Item = (&'a str, &'a str, &'a [Figures; 2])>,
) -> std::fmt::Result {
    use std::fmt::Write;
    writeln!(t, "## {title}\n")?;
    writeln!(t, "{lead}\n")?;
    writeln!(t, "| row | stride k-means | best of 10 | room-level 1-NN |")?;
    writeln!(t, "|---|---|---|---|")?;
    for (family, sensor, f) in rows {
        writeln!(t, "| {family}, {sensor} | {} |", cells(f))?;
    }
    writeln!(t)
}

/// Coordinate ascent from `start`: for each weight in turn, its five
/// trials (multiples of a weight above 0, fixed values for a weight 0),
/// one kept, in order, if it beats the best objective so far (the kept
/// trial's, else the start's) by at least 0.1 point; sweeps over the
/// [`SEARCHED_WEIGHTS`] weights until one keeps nothing, at most four. Returns the
/// weights found, their objective and the kept steps.
pub fn ascend(
    start: Weights,
    start_objective: f64,
    mut objective: impl FnMut(&Weights) -> Res<f64>,
    mut log: impl FnMut(&str),
) -> Res<(Weights, f64, Vec<Step>)> {
    let (mut w, mut best) = (start, start_objective);
    let mut steps = vec![];
    for sweep in 1..=MAX_SWEEPS {
        let mut kept_any = false;
        for c in 0..SEARCHED_WEIGHTS {
            let trials: Vec<f32> = if w[c] > 0.0 {
                STEPS.iter().map(|m| m * w[c]).collect()
            } else {
                FROM_ZERO.to_vec()
            };
            let mut kept: Option<(f32, f64)> = None;
            for t in trials {
                let mut trial = w;
                trial[c] = t;
                if trial.iter().all(|&x| x == 0.0) {
                    continue;
                }
                let o = objective(&trial)?;
                if o >= kept.map_or(best, |k| k.1) + KEEP {
                    kept = Some((t, o));
                }
            }
            if let Some((t, o)) = kept {
                log(&format!(
                    "sweep {sweep}: {} {} -> {t}: {o:.2}",
                    weight_name(c),
                    w[c]
                ));
                steps.push(Step {
                    sweep,
                    weight: weight_name(c),
                    from: w[c],
                    to: t,
                    objective: o,
                });
                (w[c], best, kept_any) = (t, o, true);
            }
        }
        if !kept_any {
            break;
        }
    }
    Ok((w, best, steps))
}

/// The harness's figures of weightings `a` and `b` on every set (in
/// parallel).
pub fn both(sets: &[Set], a: &Weights, b: &Weights) -> Res<Vec<[Figures; 2]>> {
    use rayon::prelude::*;
    Ok(sets
        .par_iter()
        .map(|s| Ok([full(s, a)?, full(s, b)?]))
        .collect::<placecat::Result<_>>()?)
}

/// One row's figures (weighting `which` of [`both`]), the mean over the
/// sets of `seeds`.
pub fn row_figures(
    sets: &[Set],
    figures: &[[Figures; 2]],
    (family, sensor): (&str, &str),
    seeds: &[u64],
    which: usize,
) -> Figures {
    let v: Vec<&Figures> = (sets.iter().zip(figures))
        .filter(|(t, _)| (t.family, t.sensor.as_str()) == (family, sensor))
        .filter(|(t, _)| seeds.contains(&t.seed))
        .map(|(_, f)| &f[which])
        .collect();
    let mean = |g: fn(&Figures) -> f64| v.iter().map(|f| g(f)).sum::<f64>() / v.len() as f64;
    Figures {
        stride: mean(|f| f.stride),
        best_of_10: mean(|f| f.best_of_10),
        nn: mean(|f| f.nn),
    }
}

/// The search's path as a list: the start, each kept step, the weights
/// found, with their objectives.
pub fn render_path(
    t: &mut String,
    (start, start_objective): (&Weights, f64),
    steps: &[Step],
    (found, found_objective): (&Weights, f64),
) -> std::fmt::Result {
    use std::fmt::Write;
    writeln!(
        t,
        "- start: {} (objective {start_objective:.2} %)",
        show(start)
    )?;
    for s in steps {
        writeln!(
            t,
            "- sweep {}: {} {} -> {} (objective {:.2} %)",
            s.sweep, s.weight, s.from, s.to, s.objective
        )?;
    }
    writeln!(
        t,
        "- found: {} (objective {found_objective:.2} %)\n",
        show(found)
    )
}

/// A table row's cells for two weightings: stride k-means, best of 10 and
/// room-level 1-NN, each "first -> second".
pub fn cells(f: &[Figures; 2]) -> String {
    use crate::families::pct;
    format!(
        "{} -> {} | {} -> {} | {} -> {}",
        pct(f[0].stride),
        pct(f[1].stride),
        pct(f[0].best_of_10),
        pct(f[1].best_of_10),
        pct(f[0].nn),
        pct(f[1].nn)
    )
}

/// Write `out` to docs/`name`.json and `md` to docs/`name`.md.
pub fn write_report(
    name: &str,
    out: &impl Serialize,
    md: String,
    t0: std::time::Instant,
) -> Res<()> {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    std::fs::write(
        docs.join(format!("{name}.json")),
        serde_json::to_string_pretty(out)? + "\n",
    )?;
    std::fs::write(docs.join(format!("{name}.md")), md)?;
    eprintln!(
        "wrote docs/{name}.md and .json ({:.0} s)",
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
