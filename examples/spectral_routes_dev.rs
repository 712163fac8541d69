//! Issue 18, a development look after the nineteenth round (development
//! seeds only: 1-6, then 7-10; it changes no preset and tunes nothing): why spectral clustering
//! does poorly along routes, and whether leaving a scan's own stretch of
//! route out of its scale helps. Its guess (docs/spectral.md): consecutive
//! scans are near copies, so a scan's 7th neighbour is a scan of the same
//! stretch and its scale that of a stretch, not of a place; the graph is
//! then a chain, and its leading eigenvectors cut the route into pieces.
//! A variant was tried in this look's first run and not kept: scans
//! within the window of the rounds' route 1-NN (25 of 300 scans, issue 18's
//! rule; 9 of these 100) left out of a scan's neighbours for its scale
//! (a `window` field of `SpectralParams`, since removed). Its figures are
//! in the report's text.
//!
//!     cargo run --release --example spectral_routes_dev   # -> docs/spectral-routes-dev.md

use placecat::cluster::{KMeans, KMeansParams, Spectral, SpectralParams};
use placecat::distance::Space;
use placecat::*;
use std::fmt::Write;

include!("common/dev_look.rs");

/// The route families and the presets the rounds ran on them.
const ROUTES: &[(&str, &[&str])] = &[
    ("warehouse", &["indoor", "indoor_plus"]),
    ("outdoor", &["outdoor", "outdoor_near"]),
];

/// The smallest group's share of the scans (%).
fn smallest<T: Ord + Clone>(labels: &[T]) -> f64 {
    let mut sorted = labels.to_vec();
    sorted.sort();
    let sizes = sorted.chunk_by(|a, b| a == b).map(<[T]>::len);
    100.0 * sizes.min().unwrap_or(0) as f64 / labels.len() as f64
}

/// The share of the smallest true kind's scans (%) in a category where
/// that kind is the most common: 0 when the kind is lost in others.
fn smallest_found(truth: &[String], labels: &[i32]) -> f64 {
    let count = |f: &dyn Fn(usize) -> bool| (0..truth.len()).filter(|&i| f(i)).count();
    let Some(kind) = (truth.iter()).min_by_key(|t| (count(&|i| &truth[i] == *t), (*t).clone()))
    else {
        return f64::NAN;
    };
    let majority = |label: i32| {
        (truth.iter())
            .max_by_key(|t| {
                (
                    count(&|i| labels[i] == label && &truth[i] == *t),
                    std::cmp::Reverse((*t).clone()),
                )
            })
            .cloned()
    };
    let of_kind: Vec<usize> = (0..truth.len()).filter(|&i| &truth[i] == kind).collect();
    let found = (of_kind.iter())
        .filter(|&&i| majority(labels[i]).as_ref() == Some(kind))
        .count();
    100.0 * found as f64 / of_kind.len() as f64
}

/// Written after the run.
const SHOWS: &str = "On seeds 1-6 (the first table) spectral clustering is below best of 10 on the warehouse with its own sensor (`indoor_plus` 73.5 against 99.4 %, `indoor` 56.9 against 68.7 %) and with 32 beams and `indoor` (61.0 against 63.9 %), and within 1.0 point of it on the other five rows; the two outdoor sets near 55 % of the test seeds have no match here. The guess of docs/spectral.md, that neighbourhoods chain along the route, does not fit: chaining would cut the route into few long pieces, while spectral clustering's labels change as often as best of 10's or more (7.3 against 5.0 pieces with `indoor_plus` and the own sensor, 12.2 against 11.2 with `indoor`; 5 true pieces). Where it falls furthest, the warehouse with `indoor_plus` and the own sensor, what differs is the smallest kind, the airlock (10.3 % of the scans): best of 10 puts 97.2 % of its scans in a category where the airlock is the most common kind, spectral clustering 16.7 %, and its smallest category (15.7 % of the scans) is a piece of a hall. The leading eigenvectors of the normalised affinity favour groups of similar weight (the balance of a normalised cut: Shi and Malik 2000, von Luxburg 2007), so a kind of a tenth of the scans goes in with another and a hall is split. That does not explain every row: with the paper's `indoor` and the own sensor both methods lose the airlock (0.0 %); with 32 beams spectral clustering finds more of it than best of 10 with `indoor` (50.0 against 0.0 %) yet is lower (61.0 against 63.9 %), and less with `indoor_plus` (33.3 against 50.0 %) yet is higher (85.2 against 84.4 %). A variant in this look's first run took a scan's neighbours for its scale only from scans more than 9 apart along the route (the window of the rounds' route 1-NN): worse on the warehouse with `indoor_plus` (63.7 and 59.9 % with the own sensor and 32 beams, against 73.5 and 85.2 %), a little better with `indoor` (57.5 and 64.2 against 56.9 and 61.0 %), outdoors within 0.1 point; it was not kept. On the second sample, seeds 7-10 (the second table), the picture is mixed: with `indoor_plus` spectral clustering is again lower with the own sensor (89.5 against 97.6 %; it finds 72.7 % of the airlock against 93.0 %) but higher with 32 beams (97.7 against 89.3 %; 97.7 % of the airlock against 70.2 %); with `indoor` it is lower with the own sensor (60.8 against 70.7 %) and about level with 32 beams (72.9 against 71.6 %). Outdoors it is within a point of best of 10 on both samples (from 0.4 below to 1.0 above), and no outdoor set of these ten seeds falls near 55 %: the test seeds' two outdoor failures have no match here and stay unexplained. (Added after a later look at those test sets themselves, docs/outdoor-spectral-look.md: on all four spectral clustering joined forest road and forest path and cut the open plain in two, along a split the plain shows on every set, its halves differing in how many ground voxels at 7-10 m are planar rather than linear.) The advice stands: spectral clustering is not for routes, nor for sets with a much smaller kind such as a route's airlock or passage; the tree or k-means there.";

/// Pieces of a route: 1 + the times the label changes from one scan to the next.
fn pieces<T: PartialEq>(labels: &[T]) -> usize {
    1 + labels.windows(2).filter(|w| w[0] != w[1]).count()
}

/// A second sample: development seeds too (docs/seeds.md; 7-9 judged the
/// fifteenth and sixteenth rounds' candidates on the room rows, 10 is one
/// of issue 14's), added after the first table to see whether the outdoor
/// sets near 55 % of the test seeds have a match.
const MORE_SEEDS: &[u64] = &[7, 8, 9, 10];

fn main() -> Res<()> {
    check_dev()?;
    seeds::check_round_seeds(MORE_SEEDS, &[])?;
    let t0 = std::time::Instant::now();
    let first = table_of(DEV_SEEDS, t0)?;
    let second = table_of(MORE_SEEDS, t0)?;
    let mut o = String::new();
    writeln!(
        o,
        "# Spectral clustering along routes, a look (issue 18, after the nineteenth round)\n"
    )?;
    writeln!(o, "Development seeds only (1-6, and 7-10 in a second table); it changes no preset, parameter or file but this one and tunes nothing. Regenerate with `cargo run --release --example spectral_routes_dev` ({:.0} s). The route rows of the eighteenth and nineteenth rounds (100 scans a route, k the true number of kinds): k-means++ best of 10 and spectral clustering, each the mean over clustering seeds 0-9, and spectral clustering on each seed. Then, with clustering seed 0: pieces, 1 + the times the label changes from one scan to the next along the route (the truth's, best of 10's, spectral clustering's); smallest, the share of the scans in the smallest true kind and in the smallest category of each; found, the share of the smallest kind's scans in a category where that kind is the most common (0 when it is lost in the others). A second table, added after the first, runs development seeds 7-10 too (7-9 judged the fifteenth and sixteenth rounds' candidates on the room rows; none is a test seed).\n", t0.elapsed().as_secs_f64())?;
    writeln!(o, "**What it shows** (written after the run): {SHOWS}\n")?;
    for (title, table) in [
        ("Development seeds 1-6", first),
        ("Development seeds 7-10", second),
    ] {
        writeln!(o, "## {title}\n")?;
        writeln!(o, "| row | preset | best of 10 % | spectral % | spectral per seed % | true pieces | best of 10's | spectral's | smallest kind % | best of 10's smallest % | spectral's smallest % | smallest kind found, best of 10 % | found, spectral % |")?;
        writeln!(o, "|---|---|---|---|---|---|---|---|---|---|---|---|---|")?;
        o.push_str(&table);
        o.push('\n');
    }
    write_doc("spectral-routes-dev.md", &format!("{}\n", o.trim_end()))
}

/// The table's rows for these seeds.
fn table_of(seeds: &[u64], t0: std::time::Instant) -> Res<String> {
    let mut table = String::new();
    for f in families()
        .into_iter()
        .filter(|f| ROUTES.iter().any(|r| r.0 == f.name))
    {
        let presets: Vec<String> = (ROUTES.iter().find(|r| r.0 == f.name))
            .map(|r| r.1.iter().map(|p| p.to_string()).collect())
            .unwrap_or_default();
        let sensors = std::iter::once(Sensor::Own).chain(f.sensors.iter().copied());
        for sensor in sensors.collect::<Vec<_>>() {
            // Per preset and seed: the columns of the report (below).
            let mut rows = vec![[(); 10].map(|_| Vec::<f64>::new()); presets.len()];
            for &seed in seeds {
                let set = describe_set(&f, sensor, seed, &presets)?;
                for (name, params, descriptors) in &set.presets {
                    let p = presets.iter().position(|x| x == name).ok_or("preset")?;
                    let space = Space::new(descriptors, DistanceOptions::from(params))?;
                    let k = set.kinds;
                    let best = best_of_10(&space, &set.truth, k)?;
                    let matrix = space.matrix();
                    let spectral = spectral_over_seeds(&matrix, &set.truth, k)?;
                    let first = Spectral::fit(&matrix, &SpectralParams::new(k))?.labels;
                    let km0 = KMeans::fit(&space, &KMeansParams::new(k).restarts(10))?.labels;
                    let r = &mut rows[p];
                    r[0].push(best.accuracy);
                    r[1].push(spectral.accuracy);
                    r[2].push(pieces(&set.truth) as f64);
                    r[3].push(pieces(&km0) as f64);
                    r[4].push(pieces(&first) as f64);
                    r[5].push(smallest(&set.truth));
                    r[6].push(smallest(&km0));
                    r[7].push(smallest(&first));
                    r[8].push(smallest_found(&set.truth, &km0));
                    r[9].push(smallest_found(&set.truth, &first));
                }
            }
            for (p, r) in rows.iter().enumerate() {
                let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
                let share = |v: &[f64]| pct(mean(v) / 100.0);
                let cells = [
                    format!("`{}`", presets[p]),
                    pct(mean(&r[0])),
                    pct(mean(&r[1])),
                    r[1].iter().map(|x| pct(*x)).collect::<Vec<_>>().join(", "),
                    [2, 3, 4].map(|c| format!("{:.1}", mean(&r[c]))).join(" | "),
                    [5, 6, 7, 8, 9].map(|c| share(&r[c])).join(" | "),
                ];
                eprintln!(
                    "{} {}: {} ({:.0} s)",
                    f.name,
                    sensor.name(),
                    cells.join(" | "),
                    t0.elapsed().as_secs_f64()
                );
                table_row(&mut table, &f, sensor, &cells)?;
            }
        }
    }
    Ok(table)
}
