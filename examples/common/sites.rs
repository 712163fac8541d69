//! The sequence sites' figures, shared by `examples/sites.rs` (the seed
//! table alone, fast) and `examples/experiments.rs` (the whole report):
//! simulate a site, describe it, cluster it into 3 with deterministic
//! k-means and with hierarchical k-means++ (clustering seeds 0-9), and draw
//! the site top-down.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::eval::{evaluate, Evaluation};
use placecat::sim::geometry::Shape;
use placecat::sim::{SceneKind, SimParams, Simulation};
use placecat::*;
use rayon::prelude::*;
use std::fmt::Write;

/// Development seeds (looked at while building the sites), fixed in
/// docs/seeds.md before the first run: 1-3; the outdoor site's third round
/// (issue 14) looked at 4-10 too.
pub fn dev_seeds(scene: SceneKind) -> &'static [u64] {
    match scene {
        SceneKind::Outdoor => &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10],
        _ => &[1, 2, 3],
    }
}

/// The test seeds of a site (run once at the end): the outdoor site's
/// second and third rounds' (201-205, 401-405) were seen before its fourth
/// round changed it, so it is judged on the fourth round's (501-505); the
/// warehouse site is as it was.
pub fn test_seeds(scene: SceneKind) -> &'static [u64] {
    match scene {
        SceneKind::Outdoor => &[501, 502, 503, 504, 505],
        _ => &[101, 102, 103, 104, 105],
    }
}

#[allow(dead_code)] // experiments.rs reads the descriptors, boundary_errors.rs the trees' labels, sites.rs neither
pub struct SiteRun {
    pub sim: Simulation,
    pub truth: Vec<String>,
    pub descriptors: Vec<Descriptor>,
    pub stride: Evaluation,
    pub stride_labels: Vec<i32>,
    /// Hierarchical k-means++ cut at 3, clustering seeds 0-9.
    pub hk: Vec<Evaluation>,
    /// Their trees (tree seeds 0-9), for other cuts of the same trees.
    pub hk_trees: Vec<Tree>,
}

pub fn preset(scene: SceneKind) -> DescriptorParams {
    if scene == SceneKind::Outdoor {
        DescriptorParams::outdoor()
    } else {
        DescriptorParams::indoor()
    }
}

/// `placecat simulate --scene S --seed N` (default scans), described with
/// the scene's preset and clustered into 3.
pub fn run_site(scene: SceneKind, seed: u64) -> SiteRun {
    let params = preset(scene);
    let sim = Simulation::new(&SimParams::new(scene, seed)).unwrap();
    // Each scan has its own RNG stream: parallel casting changes nothing.
    let descriptors: Vec<Descriptor> = (0..sim.len())
        .into_par_iter()
        .map(|i| describe(&sim.scan(i).points, &params).unwrap())
        .collect();
    let truth: Vec<String> = (0..sim.len()).map(|i| sim.label(i).to_string()).collect();
    let space = Space::new(&descriptors, DistanceOptions::from(&params)).unwrap();
    let m = space.matrix();
    let stride_labels = KMeans::fit(&space, &KMeansParams::new(3).seeding(Seeding::Stride))
        .unwrap()
        .labels;
    let hk_trees: Vec<Tree> = (0..10)
        .map(|s| HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(s)).unwrap())
        .collect();
    let hk = hk_trees
        .iter()
        .map(|tree| evaluate(&truth, &tree.cut_k(3).unwrap().labels).unwrap())
        .collect();
    SiteRun {
        stride: evaluate(&truth, &stride_labels).unwrap(),
        sim,
        truth,
        descriptors,
        stride_labels,
        hk,
        hk_trees,
    }
}

fn mean(v: impl Iterator<Item = f64>) -> f64 {
    let v: Vec<f64> = v.collect();
    v.iter().sum::<f64>() / v.len() as f64
}

/// One table row: seed, scans per kind, then accuracy and ARI of both
/// methods (hierarchical: mean and lowest over the 10 clustering seeds).
pub fn row(seed: u64, run: &SiteRun, kinds: &[&str]) -> String {
    let counts: Vec<String> = kinds
        .iter()
        .map(|k| run.truth.iter().filter(|t| t == k).count().to_string())
        .collect();
    let hk_acc = mean(run.hk.iter().map(|e| e.accuracy));
    let hk_min = run.hk.iter().map(|e| e.accuracy).fold(1.0, f64::min);
    format!(
        "| {seed} | {} | {:.1} % | {:.3} | {:.1} % (lowest {:.1} %) | {:.3} |",
        counts.join(" / "),
        100.0 * run.stride.accuracy,
        run.stride.ari,
        100.0 * hk_acc,
        100.0 * hk_min,
        mean(run.hk.iter().map(|e| e.ari)),
    )
}

pub const HEADER: &str = "| seed | scans per kind | deterministic k-means, accuracy | ARI | hierarchical k-means++, accuracy (10 seeds) | ARI |\n|---|---|---|---|---|---|";

/// The seed table of a scene: development seeds, then test seeds, then the
/// means of each group (the test seeds left out unless `test`). Returns
/// the markdown and the runs (in seed order).
pub fn seed_table(scene: SceneKind, kinds: &[&str], test: bool) -> (String, Vec<(u64, SiteRun)>) {
    let mut out = format!("Scans per kind: {}.\n\n{HEADER}\n", kinds.join(" / "));
    let mut runs = vec![];
    let test_seeds: &[u64] = if test { test_seeds(scene) } else { &[] };
    for (group, seeds) in [("development", dev_seeds(scene)), ("test", test_seeds)] {
        if seeds.is_empty() {
            continue;
        }
        let list = format!("{}-{}", seeds[0], seeds[seeds.len() - 1]);
        writeln!(out, "| **{group} seeds ({list})** | | | | | |").unwrap();
        let start = runs.len();
        for &seed in seeds {
            let run = run_site(scene, seed);
            writeln!(out, "{}", row(seed, &run, kinds)).unwrap();
            runs.push((seed, run));
        }
        let group_runs = &runs[start..];
        writeln!(
            out,
            "| mean ({group}) | | {:.1} % | {:.3} | {:.1} % | {:.3} |",
            100.0 * mean(group_runs.iter().map(|(_, r)| r.stride.accuracy)),
            mean(group_runs.iter().map(|(_, r)| r.stride.ari)),
            100.0
                * mean(
                    group_runs
                        .iter()
                        .map(|(_, r)| mean(r.hk.iter().map(|e| e.accuracy)))
                ),
            mean(
                group_runs
                    .iter()
                    .map(|(_, r)| mean(r.hk.iter().map(|e| e.ari)))
            ),
        )
        .unwrap();
    }
    (out, runs)
}

const PALETTE: [&str; 8] = [
    "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
];

/// A label strip along the sequence (paper Fig. 4 and 6): truth above,
/// clusters (mapped to classes) below.
pub fn strip_svg(truth: &[String], e: &Evaluation, labels: &[i32]) -> String {
    let classes = &e.confusion.rows;
    let n = truth.len();
    let w = 4.0;
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="110" font-family="sans-serif" font-size="11">"#,
        n as f64 * w + 90.0
    );
    let color = |name: Option<&str>| {
        name.and_then(|nm| classes.iter().position(|c| c == nm))
            .map_or("#999999", |i| PALETTE[i % 8])
    };
    s += r#"<text x="0" y="22">truth</text><text x="0" y="52">clusters</text>"#;
    for i in 0..n {
        let x = 80.0 + i as f64 * w;
        s += &format!(
            r#"<rect x="{x}" y="10" width="{w}" height="18" fill="{}"/>"#,
            color(Some(&truth[i]))
        );
        let mapped = e.confusion.class_of(labels[i]);
        s += &format!(
            r#"<rect x="{x}" y="40" width="{w}" height="18" fill="{}"/>"#,
            color(mapped)
        );
    }
    for (i, c) in classes.iter().enumerate() {
        let x = 80.0 + i as f64 * 120.0;
        s += &format!(
            r#"<rect x="{x}" y="75" width="12" height="12" fill="{}"/><text x="{}" y="85">{c}</text>"#,
            PALETTE[i % 8],
            x + 16.0
        );
    }
    s + "</svg>"
}

/// The site top-down (like the paper's Fig. 1a): what stands there in grey
/// (tree crowns and trunks as dots, boxes as outlines), the route as one
/// dot per scan, filled with the kind k-means put it in (mapped to the
/// true kinds) and ringed with its true kind.
pub fn map_svg(run: &SiteRun, kinds: &[&str]) -> String {
    let sim = &run.sim;
    let shapes = sim.shapes(0);
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for i in 0..sim.len() {
        let p = sim.sensor_pose(i).position;
        for k in 0..2 {
            lo[k] = lo[k].min(p[k] - 25.0);
            hi[k] = hi[k].max(p[k] + 25.0);
        }
    }
    let scale = (760.0 / (hi[0] - lo[0])).min(560.0 / (hi[1] - lo[1]));
    let (w, h) = ((hi[0] - lo[0]) * scale, (hi[1] - lo[1]) * scale);
    // North up: y grows upwards.
    let xy = |x: f64, y: f64| ((x - lo[0]) * scale, (hi[1] - y) * scale);
    let inside = |x: f64, y: f64| x > lo[0] && x < hi[0] && y > lo[1] && y < hi[1];
    let mut s = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{:.0}" height="{:.0}" font-family="sans-serif" font-size="11"><rect width="100%" height="100%" fill="#ffffff"/>"##,
        w,
        h + 40.0
    );
    s += r##"<g fill="#c8c8c8" stroke="none">"##;
    let mut boxes = String::new();
    for shape in shapes {
        match *shape {
            Shape::Sphere { centre, radius } if inside(centre[0], centre[1]) => {
                let (x, y) = xy(centre[0], centre[1]);
                write!(
                    s,
                    r#"<circle cx="{x:.1}" cy="{y:.1}" r="{:.1}"/>"#,
                    (radius * scale).max(0.6)
                )
                .unwrap();
            }
            Shape::Cuboid { .. } | Shape::OrientedBox { .. } => {
                let c = shape.footprint_corners().unwrap();
                if c.iter().any(|p| inside(p[0], p[1])) {
                    let pts: Vec<String> = [c[0], c[1], c[3], c[2]]
                        .iter()
                        .map(|p| {
                            let (x, y) = xy(p[0], p[1]);
                            format!("{x:.1},{y:.1}")
                        })
                        .collect();
                    write!(boxes, r#"<polygon points="{}"/>"#, pts.join(" ")).unwrap();
                }
            }
            _ => {}
        }
    }
    s += "</g>";
    write!(
        s,
        r##"<g fill="none" stroke="#808080" stroke-width="0.6">{boxes}</g>"##
    )
    .unwrap();
    let colour = |name: Option<&str>| {
        name.and_then(|n| kinds.iter().position(|k| *k == n))
            .map_or("#999999", |i| PALETTE[i % 8])
    };
    for i in 0..sim.len() {
        let p = sim.sensor_pose(i).position;
        let (x, y) = xy(p[0], p[1]);
        let mapped = run.stride.confusion.class_of(run.stride_labels[i]);
        write!(
            s,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="3.2" fill="{}" stroke="{}" stroke-width="1.6"/>"#,
            colour(mapped),
            colour(Some(&run.truth[i]))
        )
        .unwrap();
    }
    for (i, k) in kinds.iter().enumerate() {
        let x = 10.0 + i as f64 * 150.0;
        write!(
            s,
            r#"<rect x="{x}" y="{:.0}" width="12" height="12" fill="{}"/><text x="{}" y="{:.0}">{k}</text>"#,
            h + 12.0,
            PALETTE[i % 8],
            x + 16.0,
            h + 22.0
        )
        .unwrap();
    }
    write!(
        s,
        r#"<text x="{:.0}" y="{:.0}" text-anchor="end">{:.0} m across</text>"#,
        w - 10.0,
        h + 22.0,
        hi[0] - lo[0]
    )
    .unwrap();
    s + "</svg>"
}

/// CPU time of this thread (s): the machine is shared, so wall time says
/// more about the neighbours than about the simulator. Linux only.
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/thread-self/stat").unwrap_or_default();
    let fields: Vec<&str> = stat
        .rsplit(')')
        .next()
        .unwrap_or("")
        .split_whitespace()
        .collect();
    let tick = |i: usize| {
        fields
            .get(i)
            .and_then(|f| f.parse::<f64>().ok())
            .unwrap_or(0.0)
    };
    (tick(11) + tick(12)) / 100.0
}

/// Native CPU time to plan a site and cast `scans` of its scans (spread
/// along the route) one after another, as the page does: (plan seconds,
/// seconds a scan, scans in the site).
pub fn timing(scene: SceneKind, seed: u64, scans: usize) -> (f64, f64, usize) {
    let t = cpu_seconds();
    let sim = Simulation::new(&SimParams::new(scene, seed)).unwrap();
    let plan = cpu_seconds() - t;
    let n = scans.min(sim.len());
    let step = sim.len() / n;
    let t = cpu_seconds();
    for i in 0..n {
        std::hint::black_box(sim.scan(i * step));
    }
    (plan, (cpu_seconds() - t) / n as f64, sim.len())
}
