//! Issue 18: where k-means goes wrong on the room rows that miss the indoor
//! target, though room-level 1-NN is high there. A diagnostic on the
//! development seeds 1-6 only: it changes no preset and tunes nothing.
//!
//!     cargo run --release --example kinds_dev    # -> docs/kinds-dev.md
//!
//! Each row (family and sensor) with `indoor_columns`, each set as the
//! rounds make it (45 scans, k = its number of kinds) and described once.
//! Summed over the seeds: the confusion matrices of stride k-means, of
//! k-means++ best of 10 (clustering seed 0) and of room-level 1-NN; per
//! seed, the k-means objective of the true grouping against the found one
//! and k-means started at the true centres; per kind, the mean Delta within
//! the kind and to each other kind.

use placecat::cluster::*;
use placecat::eval::confusion;
use placecat::*;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

#[path = "common/families.rs"]
mod families;
use families::*;
// The rounds' tables go unused here.
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
use rounds::*;
// Only its trees, through `measure`.
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use preset_rounds::{measure, TRIALS};
#[path = "common/seeds.rs"]
mod seeds;

/// The rounds' development seeds (docs/seeds.md, issue 18).
const DEV: &[u64] = &[1, 2, 3, 4, 5, 6];
const PRESET: &str = "indoor_columns";
const REPORT: &str = "kinds-dev.md";
/// The rows that miss the target: family, sensor.
const ROWS: [(&str, Sensor); 6] = [
    ("school (fresh)", Sensor::Own),
    ("school (fresh)", Sensor::Beams(16)),
    ("school (fresh)", Sensor::Beams(32)),
    ("hospital (fresh)", Sensor::Own),
    ("hospital (fresh)", Sensor::Beams(16)),
    ("indoor (many buildings)", Sensor::Beams(16)),
];
/// k-means iterations at most, as `KMeansParams::new`.
const ITERATIONS: usize = 100;

type Counts = Vec<Vec<usize>>;

/// Read off the tables below after the run (the same on every run: the
/// seeds fix every figure); the per-row lines after it are computed.
const NOTES: &str = "- **On five of the six rows the true grouping costs k-means more than the grouping best of 10 finds, on every seed**: 6 of 6 seeds for the school with 16 and 32 beams, the hospital with both sensors and the many buildings with 16 beams (by +7.0, +7.2, +3.3, +5.3 and +1.6 % on average), and 60, 60, 58, 60 and 55 of the 60 best-of-10 runs (clustering seeds 0-9 on each seed) find a grouping cheaper than the truth. Started at the true centres, Lloyd's iterations walk away from the truth (they keep 92.6, 92.2, 95.6, 87.0 and 97.0 %) to groupings no cheaper than the found one on 6, 5, 4, 6 and 5 of 6 seeds. On these rows the objective itself prefers wrong groupings: the descriptor geometry (with one centre a kind), not the search, is what fails; a better search would move further from the truth.
- **The school with its own sensor is the exception** (91.1 / 87.7 % on these seeds, where it meets the target; it missed on test seeds): the truth costs more on 4 of 6 seeds, by +1.4 % on average, one seed (4, +7.8 %) carrying most of it; on seeds 1, 3 and 5 the two lie within 0.6 %, and 33 of 60 runs find a cheaper grouping. There search and geometry both matter.
- **The errors sit in two or three kinds a family; the others stay at 85-100 %** (corridor everywhere, cafeteria in the school, kitchen in the many buildings, day_room in the hospital with its own sensor).
- **School: the library is spread out and lies against the staff room.** Its within-kind distance (other rooms) is 2.23 / 2.56 / 2.30 (own / 16 / 32 beams) against 1.38-1.84 for every other kind, and within one room it is as large (2.19 / 2.59 / 2.28): library scans differ scan by scan, not room by room. Its nearest kind is the staff room at 1.24 / 0.96 / 0.99 times its own spread: with 16 and 32 beams a library scan is on average as near the staff-room scans as the other library scans (35 and 32 of its 54 scans nearer on average to another kind). Best of 10 splits the library (5 and 4 of 6 seeds) and merges it with the staff room (5 and 4 of 6): 19 of 54 library scans land in the staff-room cluster with 16 and with 32 beams, the library row at 51.9 % with both methods. Stride also sends classrooms to the staff room (17 and 13 of 54).
- **Hospital: nurse station, patient room and treatment room lie close together** (nearest other kind at 1.17-1.21 times their spread with the own sensor, 1.06-1.12 with 16 beams, where the nurse station, the widest kind at 1.92, lies nearest the day room). Best of 10 merges patient + treatment room (4 and 5 of 6 seeds) and nurse station + treatment room (4 and 3), and splits the nurse station (4 and 4); those three rows are at 44-70 %. Unlike the school, 1-NN is low here too (84.1 and 79.6 %): with the own sensor 17 of 54 patient-room scans have a treatment room as nearest neighbour, with 16 beams the nurse station is at 61.1 %.
- **Many buildings with 16 beams: the office and the study room** (office's nearest kind at 1.11 times its spread; 15 of 54 office scans nearer on average to the study rooms). Stride sends 20 office scans to the study-room cluster; best of 10 swaps 11 and 12 both ways and merges the two on 4 of 6 seeds; lab scans go to those two clusters too (9 of 54 with stride, 11 with best of 10). The truth's excess is the smallest of the rows (+1.6 %) but on 6 of 6 seeds.
- **1-NN errs on the same pairs, less often**: in the school with 16 and 32 beams the library is at 81.5 % by 1-NN against 51.9 % by k-means. A library scan's nearest scan from another room is mostly a library scan, while the kind's mean is not near its scans: a spread kind that a single centre does not hold.";

/// One set's diagnostics; `kinds` sorted, as the confusion's rows.
struct SetOut {
    seed: u64,
    kinds: Vec<String>,
    /// Accuracy of stride k-means, best of 10 (mean over clustering seeds
    /// 0-9, as the harness), best of 10 with seed 0, room-level 1-NN.
    accuracy: [f64; 4],
    /// Mapped confusion (true kind x kind of the cluster) of stride,
    /// best of 10 (seed 0) and 1-NN; columns: the kinds, then unassigned.
    confusions: [Counts; 3],
    /// Kind pairs sharing a cluster and kinds split, of stride and best of 10.
    merges: [Vec<(usize, usize)>; 2],
    splits: [Vec<usize>; 2],
    objective: Objective,
    /// Mean Delta between the kinds' scans; the diagonal within the kind,
    /// pairs from different rooms only (as room-level 1-NN sees them).
    between: Vec<Vec<f64>>,
    /// Mean Delta within the kind, pairs from the same room.
    within_room: Vec<f64>,
    /// Scans nearer on average to another kind than to their own kind's
    /// scans of other rooms.
    nearer_other: Vec<usize>,
}

/// The k-means objective (sum over scans of the distance to the centre of
/// its group) of groupings of one set.
struct Objective {
    truth: f64,
    /// Best of 10 (seed 0) with centres recomputed as for the truth, and
    /// the cost k-means itself reported.
    found: f64,
    found_own: f64,
    /// Of the best-of-10 runs with clustering seeds 0-9, those whose
    /// grouping costs less than the truth.
    cheaper: usize,
    /// k-means started at the true kinds' centres: its cost and accuracy.
    from_truth: f64,
    from_truth_accuracy: f64,
}

fn main() -> Res<()> {
    // Development seeds only: no test seed of its own.
    seeds::check_round_seeds(DEV, &[])?;
    let t0 = std::time::Instant::now();
    let all: Vec<Family> = families().into_iter().chain([hospital_family()]).collect();
    let mut rows = vec![];
    for (name, sensor) in ROWS {
        let f = (all.iter().find(|f| f.name == name))
            .ok_or_else(|| format!("no family {name:?} in examples/common/families.rs"))?;
        // A row the rounds run: the family's own sensor or one of its others.
        let known = std::iter::once(Sensor::Own).chain(f.sensors.iter().copied());
        if !known.map(Sensor::name).any(|s| s == sensor.name()) {
            return Err(format!("{name} is not run with {}", sensor.name()).into());
        }
        let mut sets = vec![];
        for &seed in DEV {
            eprintln!(
                "{name} {} seed {seed} ({:.0} s)",
                sensor.name(),
                t0.elapsed().as_secs_f64()
            );
            sets.push(one_set(f, sensor, seed)?);
        }
        rows.push((name, sensor.name(), sets));
    }
    let seconds = t0.elapsed().as_secs_f64();
    let out = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs")
        .join(REPORT);
    std::fs::write(&out, render(&rows, seconds)?)?;
    eprintln!("wrote {} ({seconds:.0} s)", out.display());
    Ok(())
}

fn one_set(f: &Family, sensor: Sensor, seed: u64) -> Res<SetOut> {
    let set = describe_set(f, sensor, seed, &[PRESET.to_string()])?;
    let (_, params, ds) = (set.presets.first()).ok_or_else(|| {
        format!(
            "{PRESET} could not describe every scan of {} seed {seed}",
            f.name
        )
    })?;
    let (truth, k) = (&set.truth, set.kinds);
    // The harness's figures, from its own clusterings.
    let (figures, space, m, _) = measure(ds, params, truth, k)?;
    let stride = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?.labels;
    let best = |s| KMeans::fit(&space, &KMeansParams::new(k).seed(s).restarts(TRIALS));
    let found = best(0)?;
    let stride_c = confusion(truth, &stride);
    let best_c = confusion(truth, &found.labels);
    let kinds = stride_c.rows.clone();
    let kind: Vec<usize> = truth
        .iter()
        .map(|t| kinds.binary_search(t).expect("the kinds are the truth's"))
        .collect();
    // 1-NN names a kind itself: its table needs no mapping. It must agree
    // with the harness's figure.
    let nn = nearest_kinds(&m, &kind, k, &set.apart);
    let nn_accuracy = room_level_nn(&m, truth, &set.apart);
    let nn_right: usize = (0..k).map(|t| nn[t][t]).sum();
    if nn_right as f64 / m.n as f64 != nn_accuracy {
        return Err(format!("1-NN table against room_level_nn {nn_accuracy}").into());
    }

    let true_centres = centres(&space, &m, &kind, k);
    let truth_cost = cost(&space, &true_centres, &kind);
    let found_labels: Vec<usize> = found.labels.iter().map(|&l| l as usize).collect();
    let found_cost = cost(
        &space,
        &centres(&space, &m, &found_labels, k),
        &found_labels,
    );
    let mut cheaper = 0;
    for s in 0..CLUSTER_SEEDS {
        let l: Vec<usize> = best(s)?.labels.iter().map(|&l| l as usize).collect();
        cheaper += usize::from(cost(&space, &centres(&space, &m, &l, k), &l) < truth_cost);
    }
    let drift = KMeans::fit_from_centres(&space, true_centres, ITERATIONS)?;

    let (between, within_room, nearer_other) = kind_distances(&m, &kind, k, &set.apart);
    Ok(SetOut {
        seed,
        accuracy: [
            figures.stride.accuracy,
            figures.best_of_10.accuracy,
            best_c.accuracy,
            nn_accuracy,
        ],
        merges: [shared(&kind, &stride, k), shared(&kind, &found.labels, k)],
        splits: [split(&kind, &stride, k), split(&kind, &found.labels, k)],
        confusions: [stride_c.counts, best_c.counts, nn],
        objective: Objective {
            truth: truth_cost,
            found: found_cost,
            found_own: found.cost,
            cheaper,
            from_truth: drift.cost,
            from_truth_accuracy: confusion(truth, &drift.labels).accuracy,
        },
        between,
        within_room,
        nearer_other,
        kinds,
    })
}

/// The centre k-means would hold for each group: `Space::mean` repeated to
/// a fixed point (each member's candidate alignment depends on the centre),
/// started at the member with the least Delta to the others.
fn centres(space: &Space, m: &DistanceMatrix, labels: &[usize], k: usize) -> Vec<Centre> {
    (0..k)
        .map(|c| {
            let members: Vec<usize> = (0..labels.len()).filter(|&i| labels[i] == c).collect();
            let spread = |a: usize| members.iter().map(|&b| m.get(a, b) as f64).sum::<f64>();
            let Some(&start) = members
                .iter()
                .min_by(|&&a, &&b| spread(a).total_cmp(&spread(b)))
            else {
                // An empty group (k-means never leaves one): a centre no scan uses.
                return space.centre_of(0);
            };
            let mut centre = space.centre_of(start);
            for _ in 0..ITERATIONS {
                let next = space.mean(&members, &centre).expect("members");
                if next == centre {
                    break;
                }
                centre = next;
            }
            centre
        })
        .collect()
}

/// The objective of a grouping with the given centres, summed as k-means'
/// `cost` is.
fn cost(space: &Space, centres: &[Centre], labels: &[usize]) -> f64 {
    (0..labels.len())
        .map(|i| space.to_centre(&centres[labels[i]], i).0 as f64)
        .sum()
}

/// The kinds of each cluster of `labels` holding at least a room's worth
/// of that kind's scans.
fn holdings(kind: &[usize], labels: &[i32], k: usize) -> Vec<Vec<usize>> {
    let mut table = vec![vec![0usize; k]; k];
    for (&t, &l) in kind.iter().zip(labels) {
        if let Some(row) = usize::try_from(l).ok().and_then(|l| table.get_mut(l)) {
            row[t] += 1;
        }
    }
    (table.iter())
        .map(|row| (0..k).filter(|&t| row[t] >= ROOM_SCANS).collect())
        .collect()
}

/// Kind pairs that share a cluster, each with a room's worth of scans in it.
fn shared(kind: &[usize], labels: &[i32], k: usize) -> Vec<(usize, usize)> {
    let mut pairs: Vec<(usize, usize)> = holdings(kind, labels, k)
        .iter()
        .flat_map(|h| {
            h.iter()
                .flat_map(|&a| h.iter().filter(move |&&b| a < b).map(move |&b| (a, b)))
        })
        .collect();
    pairs.sort();
    pairs.dedup();
    pairs
}

/// Kinds with a room's worth of scans in each of two clusters or more.
fn split(kind: &[usize], labels: &[i32], k: usize) -> Vec<usize> {
    let h = holdings(kind, labels, k);
    (0..k)
        .filter(|t| h.iter().filter(|c| c.contains(t)).count() > 1)
        .collect()
}

/// The mean Delta between each two kinds (the diagonal: pairs of the same
/// kind that `apart` allows), within each kind over the pairs it does not
/// (the same room), and per
/// kind the scans whose mean Delta to some other kind is below that to
/// their own kind's allowed scans.
fn kind_distances(
    m: &DistanceMatrix,
    kind: &[usize],
    k: usize,
    apart: &Apart,
) -> (Vec<Vec<f64>>, Vec<f64>, Vec<usize>) {
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    let mut nearer_other = vec![0; k];
    // Per scan, its mean Delta to each kind (its own: allowed scans only).
    let to_kind: Vec<Vec<f64>> = (0..m.n)
        .map(|i| {
            (0..k)
                .map(|t| {
                    let d: Vec<f64> = (0..m.n)
                        .filter(|&j| j != i && kind[j] == t && (t != kind[i] || apart.allows(i, j)))
                        .map(|j| m.get(i, j) as f64)
                        .collect();
                    mean(&d)
                })
                .collect()
        })
        .collect();
    for (i, d) in to_kind.iter().enumerate() {
        let own = d[kind[i]];
        if (0..k).any(|t| t != kind[i] && d[t] < own) {
            nearer_other[kind[i]] += 1;
        }
    }
    let between = (0..k)
        .map(|a| {
            (0..k)
                .map(|b| {
                    let d: Vec<f64> = (0..m.n)
                        .filter(|&i| kind[i] == a)
                        .map(|i| to_kind[i][b])
                        .collect();
                    mean(&d)
                })
                .collect()
        })
        .collect();
    let within_room = (0..k)
        .map(|a| {
            let d: Vec<f64> = (0..m.n)
                .flat_map(|i| (0..m.n).map(move |j| (i, j)))
                .filter(|&(i, j)| i != j && kind[i] == a && kind[j] == a && !apart.allows(i, j))
                .map(|(i, j)| m.get(i, j) as f64)
                .collect();
            mean(&d)
        })
        .collect();
    (between, within_room, nearer_other)
}

/// The element-wise sum of the sets' tables.
fn summed(tables: impl Iterator<Item = Counts>) -> Counts {
    tables
        .reduce(|a, b| {
            a.iter()
                .zip(&b)
                .map(|(x, y)| x.iter().zip(y).map(|(p, q)| p + q).collect())
                .collect()
        })
        .unwrap_or_default()
}

/// A confusion table (rows: true kinds; columns: the kinds, "unassigned"
/// only if a scan is).
fn confusion_table(o: &mut String, kinds: &[String], c: &Counts, corner: &str) -> Res<()> {
    let unassigned = c.iter().any(|r| r.get(kinds.len()).is_some_and(|&v| v > 0));
    let cols = kinds.len() + usize::from(unassigned);
    let head: Vec<&str> = (kinds.iter().map(String::as_str))
        .chain(unassigned.then_some("unassigned"))
        .collect();
    writeln!(
        o,
        "| {corner} | {} | right |\n|---|{}---|",
        head.join(" | "),
        "---|".repeat(cols)
    )?;
    for (r, kind) in kinds.iter().enumerate() {
        let cells: Vec<String> = (0..cols)
            .map(|j| {
                if j == r {
                    format!("**{}**", c[r][j])
                } else {
                    c[r][j].to_string()
                }
            })
            .collect();
        let all: usize = c[r].iter().sum();
        writeln!(
            o,
            "| {kind} | {} | {} |",
            cells.join(" | "),
            pct(c[r][r] as f64 / all as f64)
        )?;
    }
    Ok(())
}

/// The largest off-diagonal cells: "true -> found n".
fn largest_errors(kinds: &[String], c: &Counts, n: usize) -> String {
    let mut cells: Vec<(usize, usize, usize)> = (0..kinds.len())
        .flat_map(|r| {
            (0..kinds.len())
                .filter(move |&j| j != r)
                .map(move |j| (r, j))
        })
        .map(|(r, j)| (c[r][j], r, j))
        .filter(|x| x.0 > 0)
        .collect();
    cells.sort_by(|a, b| b.0.cmp(&a.0).then((a.1, a.2).cmp(&(b.1, b.2))));
    let parts: Vec<String> = (cells.iter().take(n))
        .map(|&(v, r, j)| format!("{} -> {} {v}", kinds[r], kinds[j]))
        .collect();
    if parts.is_empty() {
        "none".into()
    } else {
        parts.join(", ")
    }
}

/// How many seeds each merged pair / split kind came on, most first.
fn tally<T: Ord + Clone>(
    per_seed: impl Iterator<Item = Vec<T>>,
    name: impl Fn(&T) -> String,
) -> String {
    let mut n: BTreeMap<T, usize> = BTreeMap::new();
    for v in per_seed {
        for x in v {
            *n.entry(x).or_default() += 1;
        }
    }
    let mut v: Vec<(T, usize)> = n.into_iter().collect();
    v.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let parts: Vec<String> = v
        .iter()
        .map(|(x, c)| format!("{} ({c})", name(x)))
        .collect();
    if parts.is_empty() {
        "none".into()
    } else {
        parts.join(", ")
    }
}

fn render(rows: &[(&str, String, Vec<SetOut>)], seconds: f64) -> Res<String> {
    let mut o = String::new();
    let mut shows = String::new();
    let mut body = String::new();
    for (family, sensor, sets) in rows {
        row_section(&mut body, &mut shows, family, sensor, sets)?;
    }
    writeln!(o, "# Where k-means goes wrong on the room rows that miss the target (issue 18, a diagnostic)\n")?;
    writeln!(o, "A look at the room rows that miss issue 18's indoor target (every room row at least 85 % with stride k-means and with k-means++ best of 10) although room-level 1-NN is higher there: which kinds k-means merges or splits, whether the true grouping is cheaper for k-means than the grouping it finds, and which kinds lie close in `{PRESET}`'s distance. **Development seeds 1-6 only** (each set as the rounds make it: 45 scans, 9 a kind in rooms of 3, k = the number of kinds); it changes no preset, parameter or file but this one and tunes nothing.\n")?;
    writeln!(o, "Regenerate with `cargo run --release --example kinds_dev` ({seconds:.0} s on the shared two-core machine). Preset `{PRESET}`. Per row, summed over the six seeds: the confusion matrices (rows: true kind; columns: the kind its cluster is mapped to, by the one-to-one assignment the harness's accuracy uses, `placecat::eval::confusion`) of stride k-means, of k-means++ best of 10 with clustering seed 0, and of room-level 1-NN (columns: the kind of the nearest scan outside the scan's own room, as `room_level_nn`). \"Merged\": one cluster holds at least a room's worth (3 scans) of each of the two kinds, on that many seeds of 6; \"split\": a kind has a room's worth in two clusters or more. The objective is k-means' cost: the sum over scans of the distance to its group's centre in the space k-means uses (`Space::to_centre`; centres by `Space::mean`, repeated to a fixed point). Distances: the mean distance (the preset's Delta with its parts, `Space::matrix`) between two kinds' scans, averaged over seeds; the diagonal and \"within, other rooms\" count pairs of the kind from different rooms only.\n")?;
    writeln!(
        o,
        "## What it shows\n\n{NOTES}\n\nRow by row, as computed:\n\n{shows}"
    )?;
    o.push_str(&body);
    Ok(o)
}

fn row_section(
    o: &mut String,
    shows: &mut String,
    family: &str,
    sensor: &str,
    sets: &[SetOut],
) -> Res<()> {
    let kinds = &sets[0].kinds;
    if sets.iter().any(|s| &s.kinds != kinds) {
        return Err(format!("{family} {sensor}: the seeds' kinds differ").into());
    }
    let k = kinds.len();
    let seeds = sets.len() as f64;
    let mean_acc = |i: usize| sets.iter().map(|s| s.accuracy[i]).sum::<f64>() / seeds;
    writeln!(o, "## {family}, {sensor}\n")?;
    writeln!(o, "Accuracy, mean of seeds 1-6: stride k-means {} %, k-means++ best of 10 {} % (clustering seeds 0-9, as the harness; seed 0, the matrices below: {} %), room-level 1-NN {} %.\n", pct(mean_acc(0)), pct(mean_acc(1)), pct(mean_acc(2)), pct(mean_acc(3)))?;
    let methods = [
        "Stride k-means",
        "k-means++ best of 10 (clustering seed 0)",
        "Room-level 1-NN",
    ];
    let mut tables = vec![];
    for (i, method) in methods.iter().enumerate() {
        let c = summed(sets.iter().map(|s| s.confusions[i].clone()));
        writeln!(
            o,
            "**{method}** ({} scans a kind):\n",
            c[0].iter().sum::<usize>()
        )?;
        confusion_table(o, kinds, &c, "true \\ found")?;
        if i < 2 {
            writeln!(
                o,
                "\nMerged: {}. Split: {}.",
                tally(sets.iter().map(|s| s.merges[i].clone()), |&(a, b)| format!(
                    "{} + {}",
                    kinds[a], kinds[b]
                )),
                tally(sets.iter().map(|s| s.splits[i].clone()), |&a| kinds[a]
                    .clone())
            )?;
        }
        writeln!(o)?;
        tables.push(c);
    }

    writeln!(o, "**The objective, per seed** (lower is better for k-means; \"cheaper runs\": best-of-10 groupings of clustering seeds 0-9 that cost less than the true grouping; \"from the truth\": Lloyd's iterations started at the true kinds' centres):\n")?;
    writeln!(o, "| seed | stride | best of 10 (seeds 0-9) | 1-NN | true grouping | found (best of 10, seed 0) | k-means' own cost | true - found | cheaper runs of 10 | from the truth: cost | its accuracy |\n|---|---|---|---|---|---|---|---|---|---|---|")?;
    for s in sets {
        let b = &s.objective;
        writeln!(
            o,
            "| {} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {:+.1} % | {} | {:.2} | {} |",
            s.seed,
            pct(s.accuracy[0]),
            pct(s.accuracy[1]),
            pct(s.accuracy[3]),
            b.truth,
            b.found,
            b.found_own,
            100.0 * (b.truth - b.found) / b.found,
            b.cheaper,
            b.from_truth,
            pct(b.from_truth_accuracy)
        )?;
    }
    let dearer = sets
        .iter()
        .filter(|s| s.objective.truth > s.objective.found)
        .count();
    // The same against k-means' own cost: its centres came by another path,
    // and the candidate each scan aligns by depends on it.
    let dearer_own = sets
        .iter()
        .filter(|s| s.objective.truth > s.objective.found_own)
        .count();
    let path = sets
        .iter()
        .map(|s| (s.objective.found / s.objective.found_own - 1.0).abs())
        .fold(0.0, f64::max);
    writeln!(o, "\nThe true grouping costs more than the found one on {dearer} of 6 seeds ({dearer_own} against k-means' own cost; the two costs of the found grouping differ by at most {:.1} %, the centres' paths differing).", 100.0 * path)?;
    let cheaper: usize = sets.iter().map(|s| s.objective.cheaper).sum();
    let excess = sets
        .iter()
        .map(|s| (s.objective.truth - s.objective.found) / s.objective.found)
        .sum::<f64>()
        / seeds;
    let drift_below = sets
        .iter()
        .filter(|s| s.objective.from_truth < s.objective.found)
        .count();
    let from_truth = sets
        .iter()
        .map(|s| s.objective.from_truth_accuracy)
        .sum::<f64>()
        / seeds;

    let per_kind = tables[0][0].iter().sum::<usize>();
    writeln!(o, "\n**Distances between kinds** (mean Delta, averaged over seeds; rows: a kind's scans; \"nearer another kind\": of its {per_kind} scans, those whose mean distance to some other kind is below that to their own kind's other rooms):\n")?;
    let between: Vec<Vec<f64>> = (0..k)
        .map(|a| {
            (0..k)
                .map(|b| sets.iter().map(|s| s.between[a][b]).sum::<f64>() / seeds)
                .collect()
        })
        .collect();
    writeln!(o, "| kind | {} | within, same room | nearest other kind | its distance / within, other rooms | nearer another kind |\n|---|{}---|---|---|---|", kinds.join(" | "), "---|".repeat(k))?;
    let mut closest = vec![];
    for a in 0..k {
        let near = (0..k)
            .filter(|&b| b != a)
            .min_by(|&x, &y| between[a][x].total_cmp(&between[a][y]))
            .unwrap_or(a);
        let ratio = between[a][near] / between[a][a];
        closest.push((ratio, a, near));
        let cells: Vec<String> = (0..k)
            .map(|b| {
                if a == b {
                    format!("**{:.3}**", between[a][b])
                } else {
                    format!("{:.3}", between[a][b])
                }
            })
            .collect();
        let within = sets.iter().map(|s| s.within_room[a]).sum::<f64>() / seeds;
        let nearer: usize = sets.iter().map(|s| s.nearer_other[a]).sum();
        writeln!(
            o,
            "| {} | {} | {within:.3} | {} | {ratio:.2} | {nearer} |",
            kinds[a],
            cells.join(" | "),
            kinds[near]
        )?;
    }
    writeln!(o)?;
    closest.sort_by(|x, y| x.0.total_cmp(&y.0));

    let scans = per_kind * k;
    writeln!(shows, "- **{family}, {sensor}** (stride {} %, best of 10 {} %, 1-NN {} %). Largest errors (true -> found, of {scans} scans): stride {}; best of 10 {}; 1-NN {}. Merged (best of 10, seeds): {}; split: {}. The true grouping costs more than the found one on {dearer} of 6 seeds (by {:+.1} % on average; {dearer_own} against k-means' own cost); {cheaper} of 60 best-of-10 runs find a grouping cheaper than the truth. Started at the true centres, k-means keeps {} % and ends cheaper than the found grouping on {drift_below} of 6 seeds. Closest kinds (nearest other / within, other rooms): {}.", pct(mean_acc(0)), pct(mean_acc(1)), pct(mean_acc(3)), largest_errors(kinds, &tables[0], 3), largest_errors(kinds, &tables[1], 3), largest_errors(kinds, &tables[2], 3), tally(sets.iter().map(|s| s.merges[1].clone()), |&(a, b)| format!("{} + {}", kinds[a], kinds[b])), tally(sets.iter().map(|s| s.splits[1].clone()), |&a| kinds[a].clone()), 100.0 * excess, pct(from_truth), closest.iter().take(2).map(|(r, a, b)| format!("{} to {} {r:.2}", kinds[*a], kinds[*b])).collect::<Vec<_>>().join(", "))?;
    Ok(())
}
