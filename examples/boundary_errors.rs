//! Where on the outdoor site the categories go wrong (issue 14, fourth
//! round): an analysis of seeds already run, with the code as it is.
//! For each seed, `placecat simulate --scene outdoor --seed S` described
//! with the `outdoor` preset and clustered as section 4 of
//! docs/experiments.md does (stride k-means at K = 3; hierarchical
//! k-means++ cut at 3, tree seeds 0-9) and as the page's demo does
//! (`placecat cluster --method hkmeans --categories auto --seed 0`); the
//! clusters mapped to kinds as `placecat evaluate` maps them. Each scan's
//! distance along the route (m, from the sensor poses) to the nearest
//! change of true kind, and per seed and method: accuracy, scans wrong,
//! how many of them lie within the preset's range (20 m) of a change, and
//! the accuracy on the scans further than that from any change.
//!
//!     cargo run --release --example boundary_errors -- [--json FILE] [seed ...]
//!
//! Default seeds: the outdoor site's development seeds 1-10 (1 is the
//! demo's) and its fourth round's test seeds 501-505, which have been run
//! once and are seen (docs/seeds.md). Any other seed is refused: this
//! looks at figures already reported, it does not make new ones.

#[path = "common/boundary.rs"]
mod boundary;
// Only run_site and the seed lists are used here.
#[allow(dead_code)]
#[path = "common/sites.rs"]
mod sites;

use placecat::cluster::choose_k::{ChooseKParams, Clusterer};
use placecat::cluster::hkmeans::HkMeansParams;
use placecat::eval::{evaluate, Evaluation};
use placecat::sim::SceneKind;
use placecat::*;
use serde::Serialize;
use std::fmt::Write;

/// One labelling of one seed's scans, scan by scan against the truth.
#[derive(Serialize, Default, Clone)]
struct Tally {
    scans: usize,
    wrong: usize,
    /// Wrong scans within the range of a change of kind.
    wrong_near: usize,
    /// Scans further than the range from any change, and of them wrong.
    far: usize,
    far_wrong: usize,
}

impl Tally {
    fn add(&mut self, o: &Tally) {
        self.scans += o.scans;
        self.wrong += o.wrong;
        self.wrong_near += o.wrong_near;
        self.far += o.far;
        self.far_wrong += o.far_wrong;
    }

    fn accuracy(&self) -> f64 {
        1.0 - self.wrong as f64 / self.scans as f64
    }

    fn far_accuracy(&self) -> f64 {
        1.0 - self.far_wrong as f64 / self.far as f64
    }
}

#[derive(Serialize)]
struct MethodResult {
    /// `evaluate`'s accuracy (for the check against the tally).
    accuracy: f64,
    /// The number of categories (the rule's choice for the demo's path).
    categories: usize,
    tally: Tally,
    /// The misclassified scans: [scan, the kind its cluster was mapped to
    /// ("unassigned": none)].
    wrong: Vec<(usize, String)>,
}

#[derive(Serialize)]
struct SeedResult {
    seed: u64,
    scans: usize,
    /// Scans within the range of a change of kind.
    near: usize,
    metres_driven: f64,
    /// The true kinds along the route: [first scan, kind] of each stretch.
    stretches: Vec<(usize, String)>,
    /// Each scan's distance along the route to the nearest change of kind
    /// (m, to 0.1 m; null: the route has none).
    metres_to_change: Vec<Option<f64>>,
    /// Each scan's straight-line distance (m, to 0.1 m) to the nearest
    /// scan of another true kind: the route turns and loops, so a scan far
    /// from a change along it could still stand near another kind's place.
    metres_to_other_kind: Vec<f64>,
    stride: MethodResult,
    /// Tree seeds 0-9, cut at 3.
    hk3: Vec<MethodResult>,
    /// Tree seed 0, cut where the default rule says (the page's demo).
    auto: MethodResult,
}

/// Scan by scan: is `labels`' cluster mapped (as `evaluate` mapped it in
/// `e`) to the scan's true kind, and how far is the scan from a change.
fn tally(
    truth: &[String],
    labels: &[i32],
    e: &Evaluation,
    to_change: &[Option<f64>],
    range: f64,
) -> MethodResult {
    let kind_of = |l: i32| e.confusion.class_of(l).unwrap_or("unassigned").to_string();
    let mut t = Tally::default();
    let mut wrong = vec![];
    for (i, (kind, &l)) in truth.iter().zip(labels).enumerate() {
        let d = to_change[i].unwrap_or(f64::INFINITY);
        let predicted = kind_of(l);
        let is_wrong = predicted != *kind;
        t.scans += 1;
        t.wrong += usize::from(is_wrong);
        t.wrong_near += usize::from(is_wrong && d <= range);
        t.far += usize::from(d > range);
        t.far_wrong += usize::from(is_wrong && d > range);
        if is_wrong {
            wrong.push((i, predicted));
        }
    }
    // The tally and `evaluate` count the same scans right.
    assert!((t.accuracy() - e.accuracy).abs() < 1e-12);
    let mut categories: Vec<i32> = labels.to_vec();
    categories.sort_unstable();
    categories.dedup();
    MethodResult {
        accuracy: e.accuracy,
        categories: categories.len(),
        tally: t,
        wrong,
    }
}

/// Straight-line distance (m, horizontal) from scan i to the nearest scan
/// of another true kind.
fn to_other_kind(positions: &[[f64; 3]], truth: &[String], i: usize) -> f64 {
    let p = positions[i];
    (0..truth.len())
        .filter(|&j| truth[j] != truth[i])
        .map(|j| (positions[j][0] - p[0]).hypot(positions[j][1] - p[1]))
        .fold(f64::INFINITY, f64::min)
}

fn tenth(x: f64) -> f64 {
    (x * 10.0).round() / 10.0
}

fn run(seed: u64, range: f64) -> SeedResult {
    let params = DescriptorParams::outdoor();
    let run = sites::run_site(SceneKind::Outdoor, seed);
    let positions: Vec<[f64; 3]> = (0..run.sim.len())
        .map(|i| run.sim.sensor_pose(i).position)
        .collect();
    let driven = boundary::distance_driven(&positions);
    let to_change = boundary::distance_to_change(&run.truth, &driven);
    let n = run.truth.len();
    // The demo's path: what `placecat cluster --method hkmeans
    // --categories auto --seed 0` does with the same descriptors.
    let names = (0..n).map(|i| format!("scan_{i:04}"));
    // Tree seed 0 is run_site's first tree (the same space from the same
    // descriptors).
    let mut set = Collection::from_parts(params, names.zip(run.descriptors)).unwrap();
    let (tree, hk) = (&run.hk_trees[0], HkMeansParams::new(0));
    let choice = set
        .choose_categories(Clusterer::Tree(tree, &hk), &ChooseKParams::default())
        .unwrap();
    let auto_labels = tree.cut_k(choice.k).unwrap().labels;
    let auto_eval = evaluate(&run.truth, &auto_labels).unwrap();
    SeedResult {
        seed,
        scans: n,
        near: to_change
            .iter()
            .filter(|d| d.is_some_and(|d| d <= range))
            .count(),
        metres_driven: driven[n - 1].round(),
        stretches: (0..n)
            .filter(|&i| i == 0 || run.truth[i] != run.truth[i - 1])
            .map(|i| (i, run.truth[i].clone()))
            .collect(),
        metres_to_change: to_change.iter().map(|d| d.map(tenth)).collect(),
        metres_to_other_kind: (0..n)
            .map(|i| tenth(to_other_kind(&positions, &run.truth, i)))
            .collect(),
        stride: tally(
            &run.truth,
            &run.stride_labels,
            &run.stride,
            &to_change,
            range,
        ),
        hk3: run
            .hk_trees
            .iter()
            .zip(&run.hk)
            .map(|(tree, e)| {
                tally(
                    &run.truth,
                    &tree.cut_k(3).unwrap().labels,
                    e,
                    &to_change,
                    range,
                )
            })
            .collect(),
        auto: tally(&run.truth, &auto_labels, &auto_eval, &to_change, range),
    }
}

fn short(kind: &str) -> &str {
    kind.strip_prefix("forest_")
        .or(kind.strip_prefix("open_"))
        .unwrap_or(kind)
}

fn pct(x: f64) -> String {
    format!("{:.1} %", 100.0 * x)
}

/// One table row: seed, scans near a change, then accuracy, wrong, wrong
/// near a change, accuracy on the scans further than the range (and how
/// many). `t` sums `per` labellings (10 trees): counts are per labelling.
fn row(label: &str, near: usize, scans: usize, t: &Tally, per: usize) -> String {
    assert_eq!(t.far, per * (scans - near));
    let count = |c: usize| {
        if per == 1 {
            c.to_string()
        } else {
            format!("{:.1}", c as f64 / per as f64)
        }
    };
    format!(
        "| {label} | {near} of {scans} ({}) | {} | {} | {} | {} | {} ({}) |",
        pct(near as f64 / scans as f64),
        pct(t.accuracy()),
        count(t.wrong),
        count(t.wrong_near),
        pct(1.0 - t.wrong_near as f64 / (t.scans - t.far) as f64),
        pct(t.far_accuracy()),
        scans - near
    )
}

/// What a method made of one seed: its labellings summed, how many, and
/// a note for the seed's cell (the demo's path: the K chosen).
type Pick = fn(&SeedResult) -> (Tally, usize, String);

/// The methods of the tables, in order.
const METHODS: [(&str, Pick); 3] = [
    ("Stride k-means, K = 3", |r| {
        (r.stride.tally.clone(), 1, String::new())
    }),
    (
        "Hierarchical k-means++ cut at 3, tree seeds 0-9 (wrong scans: mean a tree)",
        |r| {
            let mut t = Tally::default();
            for m in &r.hk3 {
                t.add(&m.tally);
            }
            (t, r.hk3.len(), String::new())
        },
    ),
    (
        "The demo's path: hierarchical k-means++, tree seed 0, cut where the default rule says",
        |r| {
            let k = r.auto.categories;
            (r.auto.tally.clone(), 1, format!(" (K = {k})"))
        },
    ),
];

/// One markdown table a method: a row a seed and a row a group of seeds.
fn tables(results: &[SeedResult], range: f64) -> String {
    let mut out = String::new();
    let groups = [
        ("development seeds", sites::dev_seeds(SceneKind::Outdoor)),
        ("test seeds (seen)", sites::test_seeds(SceneKind::Outdoor)),
    ];
    for (title, pick) in METHODS {
        write!(
            out,
            "{title}:\n\n| seed | scans within {range:.0} m of a change | accuracy | wrong | of them within {range:.0} m | accuracy within {range:.0} m | accuracy further than {range:.0} m (scans) |\n|---|---|---|---|---|---|---|\n"
        )
        .unwrap();
        for (name, members) in &groups {
            let sel: Vec<&SeedResult> = results
                .iter()
                .filter(|r| members.contains(&r.seed))
                .collect();
            if sel.is_empty() {
                continue;
            }
            let (mut sum, mut per, mut near, mut scans) = (Tally::default(), 0, 0, 0);
            for r in &sel {
                let (t, n, note) = pick(r);
                let label = format!("{}{note}", r.seed);
                writeln!(out, "{}", row(&label, r.near, r.scans, &t, n)).unwrap();
                sum.add(&t);
                per = n;
                near += r.near;
                scans += r.scans;
            }
            let (first, last) = (sel[0].seed, sel[sel.len() - 1].seed);
            let label = format!("**{name} {first}-{last}**");
            writeln!(out, "{}", row(&label, near, scans, &sum, per)).unwrap();
        }
        out.push('\n');
    }
    out
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let json = match args.iter().position(|a| a == "--json") {
        Some(i) if i + 1 < args.len() => {
            let path = args.remove(i + 1);
            args.remove(i);
            Some(path)
        }
        Some(_) => return Err("--json needs a file".into()),
        None => None,
    };
    let allowed: Vec<u64> = [
        sites::dev_seeds(SceneKind::Outdoor),
        sites::test_seeds(SceneKind::Outdoor),
    ]
    .concat();
    let seeds: Vec<u64> = if args.is_empty() {
        allowed.clone()
    } else {
        args.iter()
            .map(|a| a.parse().map_err(|_| format!("not a seed: {a}")))
            .collect::<std::result::Result<_, _>>()?
    };
    if let Some(s) = seeds.iter().find(|s| !allowed.contains(s)) {
        return Err(format!(
            "seed {s} has not been run on the outdoor site; this looks only at {allowed:?}"
        )
        .into());
    }
    // The preset's range: its farthest range's outer edge (20 m).
    let range = DescriptorParams::outdoor()
        .ranges
        .iter()
        .filter_map(|r| r.1)
        .fold(0.0, f64::max);
    let mut results = vec![];
    for &seed in &seeds {
        let r = run(seed, range);
        println!(
            "seed {seed}: {} m driven, {} changes of kind, {} of {} scans within {range:.0} m of one",
            r.metres_driven,
            r.stretches.len() - 1,
            r.near,
            r.scans
        );
        let hk_acc: Vec<f64> = r.hk3.iter().map(|m| m.accuracy).collect();
        println!(
            "  stride {} ; hk3 mean {} lowest {} ; auto (K = {}) {}",
            pct(r.stride.accuracy),
            pct(hk_acc.iter().sum::<f64>() / hk_acc.len() as f64),
            pct(hk_acc.iter().copied().fold(1.0, f64::min)),
            r.auto.categories,
            pct(r.auto.accuracy)
        );
        for (name, m) in [
            ("stride", &r.stride),
            ("hk3 tree seed 0", &r.hk3[0]),
            ("auto", &r.auto),
        ] {
            let list: Vec<String> = m
                .wrong
                .iter()
                .map(|(i, given)| {
                    let truth = &r.stretches.iter().rfind(|s| s.0 <= *i).unwrap().1;
                    format!(
                        "{i} {}>{} ({:.1} m; {:.1} m)",
                        short(truth),
                        short(given),
                        r.metres_to_change[*i].unwrap_or(f64::INFINITY),
                        r.metres_to_other_kind[*i]
                    )
                })
                .collect();
            println!(
                "  {name} wrong (truth>given; m along the route to a change; m in a straight line to another kind): {}",
                list.join(", ")
            );
        }
        results.push(r);
    }
    println!("\n{}", tables(&results, range));
    if let Some(path) = json {
        // Compact: pretty-printed, the per-scan lists take a line a number.
        std::fs::write(&path, serde_json::to_string(&results)? + "\n")
            .map_err(|e| format!("{path}: {e}"))?;
    }
    Ok(())
}
