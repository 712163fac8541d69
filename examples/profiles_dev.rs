//! Issue 18, a development look (seeds 1-6 only; it changes no preset,
//! parameter or file but its report): k-means on each scan's row of the
//! distance matrix (the dissimilarity representation, Pekalska and Duin,
//! *The Dissimilarity Representation for Pattern Recognition*, 2005)
//! against k-means on the descriptors, for `indoor_searched` on every room
//! row. The diagnostic (docs/kinds-dev.md) found kinds whose scans are
//! spread out but lie at similar distances from the other kinds; a scan's
//! distances to every scan may hold such a kind together where one centre
//! in the descriptor space does not.
//!
//!     cargo run --release --example profiles_dev   # -> docs/profiles-dev.md

use placecat::cluster::*;
use placecat::*;
use std::fmt::Write;

include!("common/dev_look.rs");

const PRESET: &str = "indoor_searched";
const MAX_ITERATIONS: usize = 100;

struct Row {
    family: &'static str,
    sensor: String,
    /// Stride k-means, k-means++ best of 10 (mean over clustering seeds
    /// 0-9): on the descriptors, then on the distance rows.
    figures: [f64; 4],
}

fn main() -> Res<()> {
    check_dev()?;
    let t0 = std::time::Instant::now();
    let mut rows = vec![];
    for (f, sensor) in room_rows() {
        let per_seed: Vec<[f64; 4]> = DEV_SEEDS
            .iter()
            .map(|&seed| one_set(&f, sensor, seed))
            .collect::<Res<_>>()?;
        let mut figures = [0.0; 4];
        for s in &per_seed {
            for (m, x) in figures.iter_mut().zip(s) {
                *m += x / per_seed.len() as f64;
            }
        }
        eprintln!(
            "{} {}: {figures:?} ({:.0} s)",
            f.name,
            sensor.name(),
            t0.elapsed().as_secs_f64()
        );
        rows.push(Row {
            family: f.name,
            sensor: sensor.name(),
            figures,
        });
    }
    let mut t = String::new();
    writeln!(
        t,
        "# k-means on the distance rows (issue 18, a development look)\n"
    )?;
    writeln!(t, "{DEV_NOTE} Regenerate with `cargo run --release --example profiles_dev` ({:.0} s). `{PRESET}` on every room row, 45 scans a set at the true number of kinds. \"Descriptors\": the harness's stride k-means and k-means++ best of 10 (mean over clustering seeds 0-9). \"Distance rows\": each scan represented by its row of the Delta matrix (its distances to every scan of the set), then Euclidean k-means with the same seedings (stride: scans i n / k; k-means++ best of 10 by the lowest sum of squares, clustering seeds 0-9). Mean over the six seeds.\n", t0.elapsed().as_secs_f64())?;
    writeln!(t, "| row | stride, descriptors | stride, distance rows | best of 10, descriptors | best of 10, distance rows |")?;
    writeln!(t, "|---|---|---|---|---|")?;
    for r in &rows {
        let [a, b, c, d] = r.figures;
        writeln!(
            t,
            "| {}, {} | {} | {} | {} | {} |",
            r.family,
            r.sensor,
            pct(a),
            pct(b),
            pct(c),
            pct(d)
        )?;
    }
    let n = rows.len() as f64;
    let mean = |i: usize| rows.iter().map(|r| r.figures[i]).sum::<f64>() / n;
    writeln!(
        t,
        "| mean | {} | {} | {} | {} |",
        pct(mean(0)),
        pct(mean(1)),
        pct(mean(2)),
        pct(mean(3))
    )?;
    let better = |a: usize, b: usize| rows.iter().filter(|r| r.figures[b] > r.figures[a]).count();
    writeln!(
        t,
        "\nThe distance rows are better than the descriptors on {} of the {} rows with stride k-means and on {} with best of 10; over the rows they average {:+.1} and {:+.1} points against the descriptors. Not taken further.",
        better(0, 1),
        rows.len(),
        better(2, 3),
        100.0 * (mean(1) - mean(0)),
        100.0 * (mean(3) - mean(2))
    )?;
    write_doc("profiles-dev.md", &t)?;
    Ok(())
}

fn one_set(f: &Family, sensor: Sensor, seed: u64) -> Res<[f64; 4]> {
    let set = describe_set(f, sensor, seed, &[PRESET.into()])?;
    let (_, params, descriptors) = set.presets.first().ok_or("nothing described")?;
    let space = Space::new(descriptors, DistanceOptions::from(params))?;
    let k = set.kinds;
    let (stride, best) = kmeans_figures(&space, &set.truth, k)?;
    let m = space.matrix();
    let rows: Vec<Vec<f64>> = (0..m.n)
        .map(|i| (0..m.n).map(|j| f64::from(m.get(i, j))).collect())
        .collect();
    let n = rows.len();
    let stride_rows = once(
        &set.truth,
        &lloyd(&rows, (0..k).map(|i| i * n / k).collect()).0,
    )?;
    let best_rows = over_seeds(&set.truth, |seed| {
        let runs = (0..10).map(|r| lloyd(&rows, plus_plus(&rows, k, seed * 1000 + r)));
        Ok(runs.min_by(|a, b| a.1.total_cmp(&b.1)).ok_or("no run")?.0)
    })?;
    Ok([stride, stride_rows.accuracy, best, best_rows.accuracy])
}

fn squared(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

// The distance rows need Euclidean k-means, which placecat's k-means (on
// its descriptors' space) is not and no dependency of the crate offers;
// this look's few lines of it are below.

/// k-means++ seeds (Arthur and Vassilvitskii 2007) with a small xorshift.
fn plus_plus(x: &[Vec<f64>], k: usize, seed: u64) -> Vec<usize> {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut chosen = vec![(next() * x.len() as f64) as usize % x.len()];
    while chosen.len() < k {
        let d: Vec<f64> = (x.iter())
            .map(|p| {
                (chosen.iter())
                    .map(|&c| squared(p, &x[c]))
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        let total: f64 = d.iter().sum();
        let mut r = next() * total;
        let mut pick = x.len() - 1;
        for (i, di) in d.iter().enumerate() {
            if r < *di {
                pick = i;
                break;
            }
            r -= di;
        }
        chosen.push(pick);
    }
    chosen
}

/// Lloyd's iterations from the given points as centres: labels and the
/// sum of squares.
fn lloyd(x: &[Vec<f64>], seeds: Vec<usize>) -> (Vec<i32>, f64) {
    let mut centres: Vec<Vec<f64>> = seeds.iter().map(|&i| x[i].clone()).collect();
    let mut labels = vec![0i32; x.len()];
    for _ in 0..MAX_ITERATIONS {
        let new: Vec<i32> = (x.iter())
            .map(|p| {
                (0..centres.len())
                    .min_by(|&a, &b| squared(p, &centres[a]).total_cmp(&squared(p, &centres[b])))
                    .unwrap_or(0) as i32
            })
            .collect();
        let changed = new != labels;
        labels = new;
        for (c, centre) in centres.iter_mut().enumerate() {
            let members: Vec<&Vec<f64>> = (x.iter().zip(&labels))
                .filter(|(_, &l)| l == c as i32)
                .map(|(p, _)| p)
                .collect();
            if members.is_empty() {
                continue;
            }
            for (d, v) in centre.iter_mut().enumerate() {
                *v = members.iter().map(|p| p[d]).sum::<f64>() / members.len() as f64;
            }
        }
        if !changed {
            break;
        }
    }
    let cost = (x.iter().zip(&labels))
        .map(|(p, &l)| squared(p, &centres[l as usize]))
        .sum();
    (labels, cost)
}
