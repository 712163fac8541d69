//! Issue 18, a look after the nineteenth round at two of its reported
//! test figures (it changes no preset, parameter or method and judges
//! nothing): on the outdoor route with its own sensor and the paper's
//! `outdoor` preset, spectral clustering scored 54-58 % on four of the ten
//! test sets (481, 482, 492, 493) with every clustering seed, and on none
//! of ten development sets (docs/spectral-routes-dev.md). This runs the
//! ten test sets of those rounds again (their seeds are written in
//! docs/seeds.md and were run; nothing here can change their figures) and
//! says which kinds spectral clustering joined and split, and where in the
//! descriptor the split lies.
//!
//!     cargo run --release --example outdoor_spectral_look   # -> docs/outdoor-spectral-look.md

// dev_look.rs' development seeds and their check go unused: this look
// runs test seeds that were run already.
#![allow(dead_code)]

use placecat::cluster::{Spectral, SpectralParams};
use placecat::distance::Space;
use placecat::*;
use std::fmt::Write;

include!("common/dev_look.rs");

/// The eighteenth and nineteenth rounds' test seeds (docs/seeds.md).
const SEEDS: &[u64] = &[481, 482, 483, 484, 485, 491, 492, 493, 494, 495];

/// Mean Delta between scans of `a` and of `b` (no scan with itself).
fn mean_delta(m: &DistanceMatrix, a: &[usize], b: &[usize]) -> f64 {
    let (mut sum, mut pairs) = (0.0, 0usize);
    for &i in a {
        for &j in b.iter().filter(|&&j| j != i) {
            sum += f64::from(m.get(i, j));
            pairs += 1;
        }
    }
    sum / pairs.max(1) as f64
}

/// The scans whose true kind is `kind`.
fn of_kind(truth: &[String], kind: &str) -> Vec<usize> {
    (0..truth.len()).filter(|&i| truth[i] == kind).collect()
}

/// Mean share of `scans`' voxels (first orientation's matrix over its
/// total) in (row, col).
fn share(ds: &[Descriptor], scans: &[usize], row: usize, col: usize) -> f64 {
    let one = |d: &Descriptor| f64::from(d.matrices[0][row * d.cols + col]) / d.total() as f64;
    scans.iter().map(|&i| one(&ds[i])).sum::<f64>() / scans.len().max(1) as f64
}

/// Written after the run.
const SHOWS: &str = "The four failures have one shape: spectral clustering put most of the forest road and most of the forest path in one category and cut the open plain in two, along the line the plain's own two halves take (97-100 % of its scans), while k-means++ best of 10 kept the three kinds apart (91-96 %). Cut in two by itself, the plain divides the same way on every set, not only on those four: the half with more of its voxels in the first planar class at 7-10 m has fewer in the linear class there (by 0.7 to 4.3 points each way), and the halves are interleaved along the route (8 to 28 pieces among 33 to 38 scans), not two stretches of it. The halves differ in how many of their ground voxels at that range are planar rather than linear, by a few points (the per-scan split is not shown), as if one or two of the sensor's rings crossed a voxel; a likely cause is the lie of the ground under the vehicle (in a hollow the ground ahead rises and its rings come closer), not examined here. On the failing sets the halves are nearly as far apart as road from path (between-halves Delta over road-path Delta 0.75, 0.95, 0.81 and 0.71), on the others mostly less (0.53, 0.70, 0.62, 0.78, 0.67, 0.34); the two overlap (0.78 held, 0.71 failed), so the ratio alone does not say which set fails. A normalised cut favours parts of similar weight, and the plain's halves (13 to 25 scans each) are not far from the size of the road's and the path's stretches (28 to 37 scans); k-means' objective, which pays for each scan's distance to its centre, kept road and path apart. So the outdoor figures near 55 % follow from a split the descriptor itself makes in the plain meeting the cut's balance; nothing here points to a fault of the implementation (not checked against another one); with `outdoor_near` (ranges from 2 m and the Hellinger distance) spectral clustering gave 94-99 % on the same ten sets. Nothing changes: along a route the advice stays the tree or k-means.";

fn main() -> Res<()> {
    seeds::check_round_seeds(&[], SEEDS)?;
    let t0 = std::time::Instant::now();
    let f = (families().into_iter())
        .find(|f| f.name == "outdoor")
        .ok_or("no outdoor family")?;
    let mut table = String::new();
    for &seed in SEEDS {
        let set = describe_set(&f, Sensor::Own, seed, &["outdoor".to_string()])?;
        let (_, params, ds) = &set.presets[0];
        let space = Space::new(ds, DistanceOptions::from(params))?;
        let m = space.matrix();
        let truth = &set.truth;
        let spectral = Spectral::fit(&m, &SpectralParams::new(set.kinds))?;
        let best = best_of_10(&space, truth, set.kinds)?;
        let labels = &spectral.labels;
        let (plain, road, path) = (
            of_kind(truth, "open_plain"),
            of_kind(truth, "forest_road"),
            of_kind(truth, "forest_path"),
        );
        // The plain in two: spectral clustering of its scans alone at 2,
        // so that sets where the whole set's clustering kept the plain
        // whole are measured alike.
        let sub = DistanceMatrix::from_fn(plain.len(), |i, j| m.get(plain[i], plain[j]));
        let halves = Spectral::fit(&sub, &SpectralParams::new(2))?.labels;
        let half = |h: i32| -> Vec<usize> {
            (plain.iter().zip(&halves))
                .filter(|(_, &l)| l == h)
                .map(|(&i, _)| i)
                .collect()
        };
        let (h0, h1) = (half(0), half(1));
        let majority = |scans: &[usize]| {
            let mut counts = std::collections::BTreeMap::new();
            for &i in scans {
                *counts.entry(labels[i]).or_insert(0) += 1;
            }
            counts
                .into_iter()
                .max_by_key(|&(l, c)| (c, -l))
                .map(|(l, _)| l)
        };
        let joined = majority(&road) == majority(&path);
        // Categories holding at least a fifth of the plain's scans (a
        // scan or two where the route leaves the plain go elsewhere).
        let plain_categories = {
            let mut ls: Vec<i32> = plain.iter().map(|&i| labels[i]).collect();
            ls.sort();
            let sizes = ls.chunk_by(|a, b| a == b).map(<[i32]>::len);
            sizes.filter(|&c| 5 * c >= plain.len()).count()
        };
        let agree = {
            // How far the whole set's split of the plain follows the
            // plain's own (the share of plain scans in the category their
            // own half is mostly in), when the plain was split.
            let mut hits = 0;
            for h in [&h0, &h1] {
                let l = majority(h);
                hits += h.iter().filter(|&&i| Some(labels[i]) == l).count();
            }
            hits as f64 / plain.len() as f64
        };
        // Planar first class (row 1) and linear (last row) at 7-10 m: where the halves' mean histograms differ most on the
        // first failing set (481), found before this table was written.
        let (rows, linear) = (ds[0].rows, ds[0].rows - 1);
        let cells = [
            seed.to_string(),
            pct(placecat::eval::evaluate(truth, labels)?.accuracy),
            pct(best.accuracy),
            if joined { "yes" } else { "no" }.into(),
            plain_categories.to_string(),
            format!("{}, {}", road.len(), path.len()),
            format!("{}, {}", h0.len(), h1.len()),
            // Along the route (the plain's scans in route order): 1 + the
            // times a scan's half differs from the one before.
            (1 + halves.windows(2).filter(|w| w[0] != w[1]).count()).to_string(),
            format!("{:.3}", mean_delta(&m, &road, &path)),
            format!("{:.3}", mean_delta(&m, &h0, &h1)),
            format!(
                "{:.3}, {:.3}",
                mean_delta(&m, &h0, &h0),
                mean_delta(&m, &h1, &h1)
            ),
            if plain_categories > 1 {
                pct(agree)
            } else {
                "-".into()
            },
            format!(
                "{}, {}",
                pct(share(ds, &h0, 1, 1)),
                pct(share(ds, &h1, 1, 1))
            ),
            format!(
                "{}, {}",
                pct(share(ds, &h0, linear, 1)),
                pct(share(ds, &h1, linear, 1))
            ),
            format!("{:.3}", spectral.eigenvalues[2]),
        ];
        if rows != 11 {
            return Err(
                format!("the outdoor preset has {rows} rows, not its 1 + 9 + 1 classes").into(),
            );
        }
        eprintln!(
            "{} ({:.0} s)",
            cells.join(" | "),
            t0.elapsed().as_secs_f64()
        );
        writeln!(table, "| {} |", cells.join(" | "))?;
    }
    let mut o = String::new();
    writeln!(o, "# Spectral clustering's two outdoor failures, a look (issue 18, after the nineteenth round)\n")?;
    writeln!(o, "A look at figures already reported: the eighteenth and nineteenth rounds' test sets of the outdoor route (seeds 481-485, 491-495, own sensor, the paper's `outdoor` preset, 100 scans, 3 kinds), run again; it changes no preset, parameter or method and judges nothing. Regenerate with `cargo run --release --example outdoor_spectral_look` ({:.0} s).\n", t0.elapsed().as_secs_f64())?;
    writeln!(o, "Columns: spectral clustering (clustering seed 0; on these sets every seed gave the same figure, docs/spectral.json and spectral-2.json) and k-means++ best of 10 (mean over clustering seeds 0-9); whether spectral clustering put most of the forest road and most of the forest path in one category; how many of its categories hold at least a fifth of the open plain's scans; the forest road's and the forest path's scans. Then the plain alone cut in two by spectral clustering of its own scans at k = 2 (its halves' sizes, and the pieces they make along the route: 1 + the times a plain scan's half differs from the previous plain scan's), the mean Delta between forest road and forest path scans, between the plain's halves and within each; where the whole set's clustering split the plain, the share of its scans in the category that holds most of their half (100 %: it split the plain along the same line); the share of a scan's voxels in the first planar class at 7-10 m and in the linear class at 7-10 m, per half; and the third eigenvalue of the normalised affinity.\n")?;
    writeln!(o, "**What it shows** (written after the run): {SHOWS}\n")?;
    writeln!(o, "| seed | spectral % | best of 10 % | road and path joined | plain's categories | road, path scans | plain's halves | halves' pieces | Delta road-path | Delta between halves | Delta within halves | split as the halves % | planar 7-10 m %, halves | linear 7-10 m %, halves | third eigenvalue |")?;
    writeln!(
        o,
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    )?;
    o.push_str(&table);
    write_doc("outdoor-spectral-look.md", &o)
}
