//! Regenerates docs/experiments.md and its figures: the paper's experiments
//! (Magnusson et al., IROS 2017, Sec. V) repeated on simulated data with
//! known ground truth, and on the real files in tests/data/real.
//!
//!     cargo run --release --example experiments
//!     cargo run --release --example experiments -- --choose-k-only
//!     cargo run --release --example experiments -- --sites-only
//!
//! The second form only replaces section 6 (choosing the number of
//! categories, embedded from the `choose_k` example's tables) in the
//! existing docs/experiments.md; the third only recomputes section 4 (the
//! sites: a fifth of the full run) and replaces it in docs/experiments.md,
//! its `sites` in docs/experiments.json and its four SVGs.
//!
//! The report is computed into plain data, one struct per section
//! (`compute` returns a [`Report`]), written to docs/experiments.json, and
//! the markdown and SVGs are rendered from that data (`render_markdown`,
//! `render_svgs`), so a figure can be read or checked without parsing
//! markdown.
//!
//! Nothing here was tuned on its results: seeds are 0..9 and the simulated
//! data set seed is 1, fixed before the first run.

use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::descriptor::{Metric, Normalisation};
use placecat::eval::{best_score, dbscan_sweep, evaluate};
use placecat::sim::{SceneKind, SimParams, Simulation};
use placecat::*;
use rayon::prelude::*;
use serde::Serialize;
use std::fmt::Write;

#[path = "common/sites.rs"]
mod sites;

#[path = "common/choose_k_section.rs"]
mod choose_k_section;
#[path = "common/real.rs"]
mod real;

/// The example's error: every failure is reported by `main`, none panics.
type Res<T> = Result<T, Box<dyn std::error::Error>>;

/// (name, true kind, points), as examples/common/real.rs reads them.
type Scan = (String, String, Vec<[f32; 3]>);

struct Set {
    truth: Vec<String>,
    descriptors: Vec<Descriptor>,
}

fn simulate_with(sim_params: &SimParams, params: &DescriptorParams) -> Res<Set> {
    let sim = Simulation::new(sim_params)?;
    // Ray casting and describing are most of the report's time; each scan
    // has its own seed, so doing them in parallel changes no figure.
    let described: Vec<(Descriptor, String)> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let s = sim.scan(i);
            describe(&s.points, params).map(|d| (d, s.label))
        })
        .collect::<Result<_, _>>()?;
    let (descriptors, truth) = described.into_iter().unzip();
    Ok(Set { truth, descriptors })
}

fn describe_set(scans: &[Scan], params: &DescriptorParams) -> Res<Set> {
    Ok(Set {
        truth: scans.iter().map(|s| s.1.clone()).collect(),
        descriptors: scans
            .par_iter()
            .map(|s| describe(&s.2, params))
            .collect::<Result<_, _>>()?,
    })
}

struct Results {
    stride: eval::Evaluation,
    hk: Vec<eval::Evaluation>,
    /// The same trees cut at twice as many categories as kinds, each
    /// category named after most of its scans (as a user naming categories
    /// on the page may give two of them one name): not the paper's protocol.
    hk_named: Vec<eval::Evaluation>,
    nn: f64,
    matrix: DistanceMatrix,
    tree: Tree,
}

fn run(set: &Set, params: &DescriptorParams, k: usize) -> Res<Results> {
    let opts = DistanceOptions::from(params);
    let space = Space::new(&set.descriptors, opts)?;
    let m = space.matrix();
    let stride = KMeans::fit(&space, &KMeansParams::new(k).seeding(Seeding::Stride))?;
    let (mut hk, mut hk_named) = (vec![], vec![]);
    let mut tree0 = None;
    for seed in 0..10 {
        let tree = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(seed))?;
        hk.push(evaluate(&set.truth, &tree.cut_k(k)?.labels)?);
        hk_named.push(evaluate(&set.truth, &tree.cut_k(2 * k)?.labels)?);
        tree0.get_or_insert(tree);
    }
    let nn = (0..m.n)
        .filter(|&i| {
            m.nearest_other(i)
                .is_some_and(|j| set.truth[i] == set.truth[j])
        })
        .count() as f64
        / m.n as f64;
    Ok(Results {
        stride: evaluate(&set.truth, &stride.labels)?,
        hk,
        hk_named,
        nn,
        matrix: m,
        tree: tree0.ok_or("no hierarchical tree")?,
    })
}

fn mean_std(v: &[f64]) -> (f64, f64) {
    let m = v.iter().sum::<f64>() / v.len() as f64;
    let var = v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / v.len() as f64;
    (m, var.sqrt())
}

/// Mean and standard deviation of one figure over the clustering seeds.
fn spread(evals: &[eval::Evaluation], f: impl Fn(&eval::Evaluation) -> f64) -> (f64, f64) {
    mean_std(&evals.iter().map(f).collect::<Vec<_>>())
}

fn pct(x: f64) -> String {
    format!("{:.1}", 100.0 * x)
}

// ---- The report as data: one struct per section, written to
// docs/experiments.json and rendered to docs/experiments.md. ----

/// The whole report.
#[derive(Serialize)]
struct Report {
    indoor: IndoorSection,
    seeds: SeedsSection,
    sweep: SweepSection,
    sensitivity: Vec<SensitivityRow>,
    sites: Vec<SiteSection>,
    /// None when tests/data/real is missing.
    real: Option<RealSection>,
    /// Section 6, the markdown embedded from the `choose_k` example's tables.
    choose_k: String,
    /// Wall-clock seconds the computation took.
    seconds: f64,
}

/// Tab. I analogue: hierarchical (10 clustering seeds) and deterministic
/// k-means on one described set.
#[derive(Serialize)]
struct TableOne {
    classes: Vec<ClassRate>,
    hk_accuracy: (f64, f64),
    hk_ari_mean: f64,
    stride_accuracy: f64,
    stride_ari: f64,
    /// The trees cut at twice as many categories, named by majority.
    named_accuracy: (f64, f64),
    nearest_neighbour: f64,
}

/// One class's diagonal rate: hierarchical mean and std, deterministic.
#[derive(Serialize)]
struct ClassRate {
    class: String,
    hk: (f64, f64),
    stride: f64,
}

/// `d[a][b]`: the largest Delta within classes a and b together.
#[derive(Serialize)]
struct Diameters {
    classes: Vec<String>,
    d: Vec<Vec<f32>>,
    widest: usize,
    /// Pairs (a, b) whose union is narrower than the widest class.
    narrower: Vec<(usize, usize)>,
}

/// |F| per class: (class, smallest, median, largest).
#[derive(Serialize)]
struct VoxelCounts {
    what: String,
    rows: Vec<(String, u64, u64, u64)>,
}

/// Section 1.
#[derive(Serialize)]
struct IndoorSection {
    table: TableOne,
    confusion: eval::Evaluation,
    diameters: Diameters,
    voxel_counts: VoxelCounts,
    bands: TableOne,
    #[serde(skip)]
    dendrogram: (Tree, Vec<String>, f32),
}

/// One simulator seed of section 1b.
#[derive(Serialize)]
struct SeedRow {
    seed: u64,
    stride: f64,
    hk: (f64, f64),
    named: f64,
    nearest_neighbour: f64,
}

/// Section 1b: a row per seed, then means over groups of seeds and variants
/// as [deterministic, hierarchical, named by majority, nearest neighbour].
#[derive(Serialize)]
struct SeedsSection {
    rows: Vec<SeedRow>,
    summary: Vec<(String, [f64; 4])>,
}

/// Section 2.
#[derive(Serialize)]
struct SweepSection {
    epsilons: Vec<f32>,
    min_points: Vec<usize>,
    points: Vec<eval::SweepPoint>,
    best: eval::SweepPoint,
}

/// Section 3: one descriptor parameter changed.
#[derive(Serialize)]
struct SensitivityRow {
    parameter: String,
    value: String,
    hk: (f64, f64),
    stride: f64,
}

/// Section 4: one site.
#[derive(Serialize)]
struct SiteSection {
    scene: String,
    name: String,
    preset: String,
    scans: usize,
    /// Every seed's row, rendered by examples/common/sites.rs.
    seed_table: String,
    stride_accuracy: f64,
    stride_ari: f64,
    hk: (f64, f64),
    named: (f64, f64),
    nearest_neighbour: f64,
    /// Planning seconds, seconds a scan, scans (CPU time on one core).
    timing: (f64, f64, usize),
    confusion: eval::Evaluation,
    #[serde(skip)]
    kinds: Vec<&'static str>,
    #[serde(skip)]
    seed1: sites::SiteRun,
}

/// Section 5: a row per preset.
#[derive(Serialize)]
struct RealSection {
    rows: Vec<RealRow>,
    voxel_counts: VoxelCounts,
}

#[derive(Serialize)]
struct RealRow {
    preset: String,
    nearest_neighbour: f64,
    hk: (f64, f64),
    stride: f64,
}

// ---- Compute ----

fn table_one(r: &Results) -> TableOne {
    let classes = r
        .stride
        .confusion
        .rows
        .iter()
        .enumerate()
        .map(|(ci, c)| ClassRate {
            class: c.clone(),
            hk: spread(&r.hk, |e| e.confusion.rates[ci][ci]),
            stride: r.stride.confusion.rates[ci][ci],
        })
        .collect();
    TableOne {
        classes,
        hk_accuracy: spread(&r.hk, |e| e.accuracy),
        hk_ari_mean: spread(&r.hk, |e| e.ari).0,
        stride_accuracy: r.stride.accuracy,
        stride_ari: r.stride.ari,
        named_accuracy: spread(&r.hk_named, |e| e.accuracy),
        nearest_neighbour: r.nn,
    }
}

/// Why a diameter cut can miss: a class wider than the union of two others
/// is split before those two are told apart.
fn diameters(m: &DistanceMatrix, truth: &[String]) -> Res<Diameters> {
    let mut classes: Vec<&str> = truth.iter().map(|s| s.as_str()).collect();
    classes.sort();
    classes.dedup();
    let class = truth
        .iter()
        .map(|t| classes.iter().position(|c| c == t))
        .collect::<Option<Vec<usize>>>()
        .ok_or("a scan without a class")?;
    let k = classes.len();
    // Largest Delta between a member of a and one of b, then unions.
    let mut cross = vec![vec![0f32; k]; k];
    for i in 0..m.n {
        for j in 0..m.n {
            let v = &mut cross[class[i]][class[j]];
            *v = v.max(m.get(i, j));
        }
    }
    let d: Vec<Vec<f32>> = (0..k)
        .map(|a| {
            (0..k)
                .map(|b| cross[a][b].max(cross[a][a]).max(cross[b][b]))
                .collect()
        })
        .collect();
    let widest = (0..k)
        .max_by(|&x, &y| d[x][x].total_cmp(&d[y][y]))
        .ok_or("no classes")?;
    let narrower = (0..k)
        .flat_map(|a| (a + 1..k).map(move |b| (a, b)))
        .filter(|&(a, b)| d[a][b] < d[widest][widest])
        .collect();
    Ok(Diameters {
        classes: classes.iter().map(|c| c.to_string()).collect(),
        d,
        widest,
        narrower,
    })
}

/// How much |F| (the voxel count Delta's size factor divides) varies within
/// each class: the factor max/min |F| alone sets a floor under Delta.
fn voxel_counts(set: &Set, what: &str) -> VoxelCounts {
    let mut per: std::collections::BTreeMap<&str, Vec<u64>> = Default::default();
    for (t, d) in set.truth.iter().zip(&set.descriptors) {
        per.entry(t).or_default().push(d.total());
    }
    let rows = per
        .into_iter()
        .map(|(class, mut v)| {
            v.sort_unstable();
            (class.to_string(), v[0], v[v.len() / 2], v[v.len() - 1])
        })
        .collect();
    VoxelCounts {
        what: what.to_string(),
        rows,
    }
}

fn indoor_scans() -> Res<Vec<Scan>> {
    let sim = Simulation::new(&SimParams::new(SceneKind::Indoor, 1))?;
    Ok((0..sim.len())
        .map(|i| {
            let s = sim.scan(i);
            (s.name, s.label, s.points)
        })
        .collect())
}

/// Section 1, and the matrix and truth section 2 sweeps.
fn indoor_section(scans: &[Scan]) -> Res<(IndoorSection, DistanceMatrix, Vec<String>)> {
    let indoor_p = DescriptorParams::indoor();
    let indoor = describe_set(scans, &indoor_p)?;
    let r = run(&indoor, &indoor_p, 5)?;
    let cut = r.tree.cut_k(5)?;
    let bands_p = DescriptorParams::indoor_bands();
    let rb = run(&describe_set(scans, &bands_p)?, &bands_p, 5)?;
    let section = IndoorSection {
        table: table_one(&r),
        confusion: r.stride.clone(),
        diameters: diameters(&r.matrix, &indoor.truth)?,
        voxel_counts: voxel_counts(&indoor, "class"),
        bands: table_one(&rb),
        dendrogram: (r.tree, indoor.truth.clone(), cut.threshold),
    };
    Ok((section, r.matrix, indoor.truth))
}

/// The indoor figures on data sets that no one chose: the mean over the
/// simulator seeds of (deterministic k-means, hierarchical mean, the same
/// trees cut at 10 categories named by majority, 1-NN), with one row per
/// seed pushed to `rows` if given.
fn seed_rows(
    mut rows: Option<&mut Vec<SeedRow>>,
    seeds: &[u64],
    base: &SimParams,
    params: &DescriptorParams,
) -> Res<[f64; 4]> {
    let mut sums = [0.0; 4];
    for &seed in seeds {
        let set = simulate_with(
            &SimParams {
                seed,
                ..base.clone()
            },
            params,
        )?;
        let r = run(&set, params, 5)?;
        let (m, s) = spread(&r.hk, |e| e.accuracy);
        let (named, _) = spread(&r.hk_named, |e| e.accuracy);
        if let Some(rows) = rows.as_deref_mut() {
            rows.push(SeedRow {
                seed,
                stride: r.stride.accuracy,
                hk: (m, s),
                named,
                nearest_neighbour: r.nn,
            });
        }
        for (sum, v) in sums.iter_mut().zip([r.stride.accuracy, m, named, r.nn]) {
            *sum += v / seeds.len() as f64;
        }
    }
    Ok(sums)
}

/// Section 1b.
fn seeds_section() -> Res<SeedsSection> {
    let indoor_p = DescriptorParams::indoor();
    let one = SimParams::new(SceneKind::Indoor, 1);
    let mut rows = vec![];
    let range = |a: u64, b: u64| (a..=b).collect::<Vec<u64>>();
    let dev = seed_rows(Some(&mut rows), &range(1, 5), &one, &indoor_p)?;
    let seen = seed_rows(Some(&mut rows), &range(6, 10), &one, &indoor_p)?;
    let held = seed_rows(Some(&mut rows), &range(11, 20), &one, &indoor_p)?;
    let held_after = seed_rows(Some(&mut rows), &range(21, 30), &one, &indoor_p)?;
    let held_last = seed_rows(Some(&mut rows), &range(31, 40), &one, &indoor_p)?;
    let mut summary: Vec<(String, [f64; 4])> = vec![
        ("seeds 1-5 (development)".into(), dev),
        ("seeds 6-10".into(), seen),
        ("seeds 11-20 (held out from the simulator)".into(), held),
        (
            "seeds 21-30 (held out from every change)".into(),
            held_after,
        ),
        ("seeds 31-40 (first run last)".into(), held_last),
        (
            "seeds 11-30 (held out)".into(),
            [0, 1, 2, 3].map(|i| (held[i] + held_after[i]) / 2.0),
        ),
        (
            "**seeds 11-40 (held out)**".into(),
            [0, 1, 2, 3].map(|i| (held[i] + held_after[i] + held_last[i]) / 3.0),
        ),
        (
            "seeds 1-40".into(),
            [0, 1, 2, 3]
                .map(|i| (dev[i] + seen[i] + 2.0 * (held[i] + held_after[i] + held_last[i])) / 8.0),
        ),
    ];
    let all = range(1, 10);
    let many = SimParams {
        buildings: placecat::sim::Buildings::Many,
        ..one.clone()
    };
    summary.push((
        "`--buildings many`, seeds 1-10".into(),
        seed_rows(None, &all, &many, &indoor_p)?,
    ));
    summary.push((
        "preset `indoor_bands`, seeds 1-10".into(),
        seed_rows(None, &all, &one, &DescriptorParams::indoor_bands())?,
    ));
    // The distance options of docs/design.md#variants, with the paper's counts.
    for (name, metric, normalisation) in [
        ("Hellinger", Metric::Hellinger, Normalisation::Total),
        ("chi-squared", Metric::ChiSquared, Normalisation::Total),
        (
            "per-column normalisation",
            Metric::Paper,
            Normalisation::PerColumn,
        ),
    ] {
        let p = DescriptorParams {
            metric,
            normalisation,
            ..DescriptorParams::indoor()
        };
        summary.push((
            format!("{name}, seeds 1-10"),
            seed_rows(None, &all, &one, &p)?,
        ));
    }
    // The first simulator's sensor: 32 beams over +-30 degrees.
    let sparse = SimParams {
        lidar: Some(placecat::sim::LidarParams {
            beams: 32,
            fov_down: -30.0,
            fov_up: 30.0,
            ..placecat::sim::LidarParams::indoor()
        }),
        ..one.clone()
    };
    summary.push((
        "32-beam sensor (+-30 degrees), seeds 1-10".into(),
        seed_rows(None, &all, &sparse, &indoor_p)?,
    ));
    Ok(SeedsSection { rows, summary })
}

/// Section 2 (Fig. 3) on section 1's matrix.
fn sweep_section(matrix: &DistanceMatrix, truth: &[String]) -> Res<SweepSection> {
    // Delta between scans of one kind is mostly below 0.5 (section 1's
    // diameters), so the grid covers 0.025..0.5.
    let epsilons: Vec<f32> = (1..=20).map(|i| i as f32 * 0.025).collect();
    let min_points = placecat::eval::SWEEP_MIN_POINTS.to_vec();
    let points = dbscan_sweep(matrix, Some(truth), &epsilons, &min_points)?;
    let best = best_score(&points).ok_or("no DBSCAN score")?.clone();
    Ok(SweepSection {
        epsilons,
        min_points,
        points,
        best,
    })
}

/// Section 3 (Tab. III): one parameter changed from the `indoor` preset.
fn sensitivity_section(scans: &[Scan]) -> Res<Vec<SensitivityRow>> {
    let base = DescriptorParams::indoor;
    let mut v: Vec<(&str, String, DescriptorParams)> = vec![];
    for te in [0.02, 0.05, 0.1] {
        let mut p = base();
        p.eigen_threshold = te;
        v.push(("te", te.to_string(), p));
    }
    for ta in [0.4, 0.6, 0.8] {
        let mut p = base();
        p.ambiguity_threshold = ta;
        v.push(("ta", ta.to_string(), p));
    }
    for b in [0.3, 0.4, 0.6] {
        let mut p = base();
        p.voxel_size = b;
        v.push(("B", format!("{b} m"), p));
    }
    for ns in [1, 2, 3] {
        let mut p = base();
        p.spherical_classes = ns;
        v.push(("ns", ns.to_string(), p));
    }
    for max in [8.0, 12.0, f64::INFINITY] {
        let mut p = base();
        p.ranges.retain(|(lo, _)| *lo < max);
        let value = if max.is_finite() {
            format!("{max} m")
        } else {
            "none".into()
        };
        v.push(("max range", value, p));
    }
    v.into_iter()
        .map(|(name, value, p)| {
            let rr = run(&describe_set(scans, &p)?, &p, 5)?;
            Ok(SensitivityRow {
                parameter: name.to_string(),
                value,
                hk: spread(&rr.hk, |e| e.accuracy),
                stride: rr.stride.accuracy,
            })
        })
        .collect()
}

/// Section 4: both sites.
fn sites_sections() -> Res<Vec<SiteSection>> {
    [
        (
            SceneKind::Warehouse,
            &placecat::sim::sites::WAREHOUSE_KINDS[..],
            "warehouse",
        ),
        (
            SceneKind::Outdoor,
            &placecat::sim::sites::OUTDOOR_KINDS[..],
            "outdoor",
        ),
    ]
    .into_iter()
    .map(|(scene, kinds, name)| site_section(scene, kinds, name))
    .collect()
}

/// Section 4 (Fig. 1, 4, 6): one site over its seeds, seed 1 in detail.
fn site_section(scene: SceneKind, kinds: &[&'static str], name: &str) -> Res<SiteSection> {
    let preset = sites::preset(scene);
    let (seed_table, runs) = sites::seed_table(scene, kinds, true);
    let seed1 = runs
        .into_iter()
        .find(|(s, _)| *s == 1)
        .ok_or("no site run for seed 1")?
        .1;
    let set = Set {
        truth: seed1.truth.clone(),
        descriptors: seed1.descriptors.clone(),
    };
    let rr = run(&set, &preset, 3)?;
    Ok(SiteSection {
        scene: format!("{scene:?}"),
        name: name.to_string(),
        preset: preset.preset.to_string(),
        scans: seed1.sim.len(),
        seed_table,
        stride_accuracy: rr.stride.accuracy,
        stride_ari: rr.stride.ari,
        hk: spread(&rr.hk, |e| e.accuracy),
        named: spread(&rr.hk_named, |e| e.accuracy),
        nearest_neighbour: rr.nn,
        timing: sites::timing(scene, 1, 30),
        confusion: rr.stride,
        kinds: kinds.to_vec(),
        seed1,
    })
}

/// Section 5: the real files, if present.
fn real_section() -> Res<Option<RealSection>> {
    let scans = real::real_scans();
    if scans.is_empty() {
        return Ok(None);
    }
    let mut rows = vec![];
    let mut counts = None;
    for p in [DescriptorParams::indoor(), DescriptorParams::outdoor()] {
        let set = describe_set(&scans, &p)?;
        if p.preset == "indoor" {
            counts = Some(voxel_counts(&set, "place"));
        }
        let rr = run(&set, &p, 4)?;
        rows.push(RealRow {
            preset: p.preset.to_string(),
            nearest_neighbour: rr.nn,
            hk: spread(&rr.hk, |e| e.accuracy),
            stride: rr.stride.accuracy,
        });
    }
    Ok(Some(RealSection {
        rows,
        voxel_counts: counts.ok_or("no indoor preset")?,
    }))
}

fn compute(docs: &std::path::Path) -> Res<Report> {
    let t0 = std::time::Instant::now();
    let scans = indoor_scans()?;
    let (indoor, matrix, truth) = indoor_section(&scans)?;
    let seeds = seeds_section()?;
    let sweep = sweep_section(&matrix, &truth)?;
    let sensitivity = sensitivity_section(&scans)?;
    let sites = sites_sections()?;
    let real = real_section()?;
    Ok(Report {
        indoor,
        seeds,
        sweep,
        sensitivity,
        sites,
        real,
        choose_k: choose_k_section::section(docs),
        seconds: t0.elapsed().as_secs_f64(),
    })
}

// ---- Render ----

const PALETTE: [&str; 8] = [
    "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
];

/// S against epsilon, one line per c, and the inlier ratio dashed (paper
/// Fig. 3).
fn sweep_svg(sweep: &[eval::SweepPoint], eps: &[f32], cs: &[usize]) -> String {
    let (w, h, left, top, plot_w, plot_h) = (560.0, 280.0, 50.0, 15.0, 380.0, 220.0);
    let e_max = eps.iter().copied().fold(0f32, f32::max) as f64;
    let x = |e: f32| left + plot_w * e as f64 / e_max;
    let y = |v: f64| top + plot_h * (1.0 - v);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#
    );
    s += &format!(
        r##"<rect x="{left}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#888"/>"##
    );
    for t in [0.0, 0.25, 0.5, 0.75, 1.0] {
        s += &format!(
            r#"<text x="{}" y="{}" text-anchor="end">{t}</text>"#,
            left - 4.0,
            y(t) + 4.0
        );
    }
    for e in [0.0, e_max / 2.0, e_max] {
        s += &format!(
            r#"<text x="{}" y="{}" text-anchor="middle">{e:.3}</text>"#,
            x(e as f32),
            top + plot_h + 14.0
        );
    }
    s += &format!(
        r#"<text x="{}" y="{}" text-anchor="middle">epsilon</text>"#,
        left + plot_w / 2.0,
        top + plot_h + 28.0
    );
    for (i, &c) in cs.iter().enumerate() {
        let colour = PALETTE[i % 8];
        let points: Vec<&eval::SweepPoint> = eps
            .iter()
            .filter_map(|&e| sweep.iter().find(|p| p.epsilon == e && p.min_points == c))
            .collect();
        let line = |v: &dyn Fn(&eval::SweepPoint) -> f64| {
            points
                .iter()
                .map(|p| format!("{:.1},{:.1}", x(p.epsilon), y(v(p))))
                .collect::<Vec<_>>()
                .join(" ")
        };
        s += &format!(
            r#"<polyline fill="none" stroke="{colour}" stroke-width="2" points="{}"/>"#,
            line(&|p| p.score.unwrap_or(0.0))
        );
        s += &format!(
            r#"<polyline fill="none" stroke="{colour}" stroke-width="1" stroke-dasharray="4 3" points="{}"/>"#,
            line(&|p| p.inlier_ratio)
        );
        let ly = top + 10.0 + 16.0 * i as f64;
        s += &format!(
            r#"<line x1="{}" y1="{ly}" x2="{}" y2="{ly}" stroke="{colour}" stroke-width="2"/><text x="{}" y="{}">c = {c}</text>"#,
            left + plot_w + 15.0,
            left + plot_w + 35.0,
            left + plot_w + 40.0,
            ly + 4.0
        );
    }
    let ly = top + 20.0 + 16.0 * cs.len() as f64;
    s += &format!(
        r##"<text x="{}" y="{ly}">solid: S</text><text x="{}" y="{}">dashed: inliers</text>"##,
        left + plot_w + 15.0,
        left + plot_w + 15.0,
        ly + 14.0
    );
    s + "</svg>"
}

/// The dendrogram (paper Fig. 1b, 2) from the linkage matrix.
fn dendrogram_svg(tree: &Tree, truth: &[String], cut: f32) -> String {
    let z = tree.linkage();
    let n = tree.n;
    let classes: Vec<String> = truth
        .iter()
        .cloned()
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    // Leaf order by an in-order walk of the linkage.
    let mut order = Vec::new();
    let mut stack = vec![(2 * n - 2) as f64];
    while let Some(id) = stack.pop() {
        if (id as usize) < n {
            order.push(id as usize);
        } else {
            let row = z[id as usize - n];
            stack.push(row[1]);
            stack.push(row[0]);
        }
    }
    let (w, h, top) = (900.0, 320.0, 20.0);
    let hmax = z.last().map_or(1.0, |r| r[2]).max(1e-9);
    // x of each leaf, indexed by scan (a Vec, so the SVG is written in the
    // same order every run).
    let mut xs_of_leaf = vec![0f64; n];
    for (i, &leaf) in order.iter().enumerate() {
        xs_of_leaf[leaf] = 40.0 + i as f64 * (w - 60.0) / n as f64;
    }
    let y = |hgt: f64| top + (1.0 - hgt / hmax) * (h - 60.0);
    let mut pos: Vec<(f64, f64)> = xs_of_leaf.iter().map(|&x| (x, y(0.0))).collect();
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#
    );
    for row in &z {
        let (a, b) = (pos[row[0] as usize], pos[row[1] as usize]);
        let yy = y(row[2]);
        s += &format!(
            r##"<path d="M{} {} V{yy} H{} V{}" fill="none" stroke="#555" stroke-width="0.7"/>"##,
            a.0, a.1, b.0, b.1
        );
        pos.push(((a.0 + b.0) / 2.0, yy));
    }
    for (leaf, &x) in xs_of_leaf.iter().enumerate() {
        let ci = classes.iter().position(|c| *c == truth[leaf]).unwrap_or(0);
        s += &format!(
            r#"<rect x="{}" y="{}" width="3" height="10" fill="{}"/>"#,
            x - 1.5,
            h - 38.0,
            PALETTE[ci % 8]
        );
    }
    let yc = y(cut as f64);
    s += &format!(
        r##"<line x1="30" x2="{}" y1="{yc}" y2="{yc}" stroke="#e15759" stroke-dasharray="4 3"/><text x="{}" y="{}" fill="#e15759">cut {cut:.2}</text>"##,
        w - 10.0,
        w - 80.0,
        yc - 4.0
    );
    for (i, c) in classes.iter().enumerate() {
        let x = 40.0 + i as f64 * 120.0;
        s += &format!(
            r#"<rect x="{x}" y="{}" width="12" height="12" fill="{}"/><text x="{}" y="{}">{c}</text>"#,
            h - 20.0,
            PALETTE[i % 8],
            x + 16.0,
            h - 10.0
        );
    }
    s += &format!(r#"<text x="4" y="14">height (diameter, max {hmax:.2})</text>"#);
    s + "</svg>"
}

/// How the sites were made, for the report.
const SITES_TEXT: &str = "Both sites are routes through places, like the paper's data sets, not the straight strips of earlier versions (a 294 m strip outdoors, 82 m in the warehouse, 150 scans each). **Outdoor** (like EskilstunaField, the paper's Fig. 1): a field of 130-160 m by 90-120 m ringed by forest; on it 3-6 gravel heaps, 2-5 parked machines (excavator, wheel loader, truck, tractor with trailer), 4-10 single deciduous trees, 15-35 rocks, a power line, sometimes a row of round bales or a container. On development seeds 1-3, 97-100 % of the field scans have something (a field object or the forest edge) within the `outdoor` preset's 20 m, 50-80 % within 10 m. The vehicle loops over the field, leaves by a forest road (gravel, shoulders and verges: the stand begins 5-7.5 m from the centre line; timber piles; the road goes on past the junction with the path), comes back by a narrower forest path (stand from 1.1-1.6 m, undergrowth) and crosses the field again. The forest is mixed as Swedish production forest is: about 40 % spruce, whose cone of branches (living or dead) reaches down to 0.3-2 m above the ground, 40 % pine and 20 % birch with clean trunks and crowns above head height, and 200-600 young spruces (1-4 m) a hectare under the canopy. The ground is a gentle slope (up to 1 %) plus three waves (field swells of 80-160 m and 0.3-1 m, undulation of 30-60 m and 0.1-0.4 m, bumps of 8-16 m and up to 0.1 m); the sensor rides 1.6-1.95 m above the plane through the ground under the four wheels and tilts with it (roll and pitch). Drawn per seed: field size, waypoints within 5 m of a plan, terrain, stand density (500-900 stems a hectare), undergrowth, object counts and places, the vehicle. Scans are taken at a fixed rate, the vehicle slower on the path (0.6) and the road (0.9) than on the field, so the kinds get about 107 / 90 / 103 scans of 300. A scan's true kind is the place the vehicle stands in: on the field inside its (wavy) forest edge, in the road's clearing (up to where its stand begins, past the junction too), else on the path. **Warehouse** (like ArlaWarehouse): an AGV goes round a small hall, through an airlock (slowly: doors), down the main aisle of a large hall, back along one aisle between loaded pallet racks, out along another, and home through the airlock; rack fill, aisle widths and rack lengths are drawn per seed; the floor is flat, so the sensor stays level. Most of its time is in the large hall (about 50 / 30 / 220 scans). **How the sites were developed:** built and checked on simulator seeds 1, 2 and 3 only (the development seeds of docs/seeds.md); their figures were looked at while building. In the first round one change followed a look at them: the forest road first had its stand 3.5-5 m from the centre line and ended at the path; it was given the width of a real forest road with verges and continued past the junction, which lowered deterministic k-means on seeds 1-3 from 93.0 / 96.3 / 94.3 % to 91.3 / 95.7 / 94.0 %, and was kept. The first round's test seeds 101-105 then gave deterministic k-means 92.7 / 95.3 / 93.0 / 91.3 / 95.0 % and hierarchical k-means++ 89.4 / 91.3 / 92.3 / 91.3 / 90.2 %. **Second round (issue 14):** `examples/site_errors.rs` lists every misclassified scan with where it stands. On seeds 1-3 the errors were road scans in the middle of the road taken for path (seed 1: 13 of them), path scans within 15 m of the road junction or 10 m of the field taken for road, and scans where the route's leg changes kind. Two causes, both of realism: (1) the forest was see-through at the sensor's height. Its conifers had crowns from half their height up, and the sensor (+2 to -24.8 degrees) sees below about 2.5 m within 20 m, so it saw bare trunks (a mean free path of some 35 m at 700 stems a hectare) where a spruce stand is a wall of branches; a road and a path then differ only in a few trunks. (2) The labels were the kind of the route's leg, and a leg's kind changes at its waypoint, not where the place changes: the path leaves from the road's centre line, so its first scans stood on the road, and the field's edge is wavy, up to 6 m beyond the waypoint. The forest got its spruces and young spruces (seeds 1/2/3, deterministic k-means 91.3 / 95.7 / 94.0 -> 94.7 / 96.7 / 95.0 %, hierarchical 91.2 / 92.1 / 93.7 -> 94.4 / 96.8 / 94.6 %) and the labels became the place the vehicle stands in (-> 96.7 / 97.7 / 97.0 % and 96.4 / 97.8 / 96.6 %; 4 to 6 labels changed a seed). Each change alone helps: the labels alone, with the see-through forest, give 92.7 / 96.7 / 95.7 % and 92.5 / 93.1 / 95.7 % (a check run afterwards, on the same seeds). The remaining errors on seed 1 are path scans 9-17 m from the road junction, which see the road's clearing behind them, path scans in the last 9 m before the field, and two in the middle of the path. The second round's test seeds 201-205 (docs/seeds.md, fixed before any of its runs) were run once, after both changes, and are the outdoor test rows below. No descriptor, clustering or sensor parameter was changed; the warehouse site and its labels are as they were (its rows are the same); indoor scans are bit-identical to before (the indoor sections are unchanged).";

/// Issue 14's third round (section 4), after SITES_TEXT.
const THIRD_ROUND_TEXT: &str = include_str!("common/sites_third_round.md");

/// Issue 14's fourth round (section 4): why two of the third round's test
/// seeds fell short, and the change of the site that followed (the
/// vehicle's corridor kept clear) with its test seeds 501-505.
const FOURTH_ROUND_TEXT: &str = include_str!("common/sites_fourth_round.md");

/// Issue 14, after the fourth round's test seeds: where the outdoor
/// errors lie along the route (`examples/boundary_errors.rs`' tables, on
/// seeds already run; nothing changed).
const BOUNDARY_ERRORS_TEXT: &str = include_str!("common/sites_boundary_errors.md");

/// Issues 14 and 18's fifth round: the tree's trial splits
/// (`examples/split_trials.rs`, docs/split-trials.md); the tables of
/// section 4 stay the paper's tree.
const FIFTH_ROUND_TEXT: &str = include_str!("common/sites_fifth_round.md");

/// Issues 14 and 18's sixth round: the Hellinger distance
/// (`examples/hellinger.rs`, docs/hellinger.md); the tables of section 4
/// stay the paper's distance.
const SIXTH_ROUND_TEXT: &str = include_str!("common/sites_sixth_round.md");

/// Issues 14 and 18's seventh round: range intervals from 2 m
/// (`examples/near_ranges.rs`, docs/near-ranges.md); the tables of section
/// 4 stay the paper's outdoor preset.
const SEVENTH_ROUND_TEXT: &str = include_str!("common/sites_seventh_round.md");

/// The outdoor site's rows of the second round, as measured then: the
/// third round changed the site, so they cannot be computed again.
const SECOND_ROUND_OUTDOOR: &str = include_str!("common/sites_second_round_outdoor.md");

/// The outdoor site's rows of the third round, as measured then: the
/// fourth round changed the site.
const THIRD_ROUND_OUTDOOR: &str = include_str!("common/sites_third_round_outdoor.md");

type Fmt = std::fmt::Result;

fn render_table_one(out: &mut String, t: &TableOne) -> Fmt {
    writeln!(
        out,
        "| class | hierarchical k-means++ (10 seeds) | deterministic k-means |"
    )?;
    writeln!(out, "|---|---|---|")?;
    for c in &t.classes {
        let ((m, s), class) = (c.hk, &c.class);
        writeln!(
            out,
            "| {class} | {} ± {} | {} |",
            pct(m),
            pct(s),
            pct(c.stride)
        )?;
    }
    let (m, s) = t.hk_accuracy;
    writeln!(
        out,
        "| **overall accuracy** | **{} ± {}** | **{}** |",
        pct(m),
        pct(s),
        pct(t.stride_accuracy)
    )?;
    writeln!(out, "| ARI | {:.3} | {:.3} |", t.hk_ari_mean, t.stride_ari)?;
    let (nm, ns) = t.named_accuracy;
    writeln!(
        out,
        "\nThe same trees cut at twice as many categories as kinds, each named after most of its scans (two may share a name, as when a user names categories on the page; not the paper's protocol): {} ± {} %.",
        pct(nm),
        pct(ns)
    )?;
    writeln!(
        out,
        "\nLeave-one-out nearest-neighbour accuracy (no clustering): {}%.\n",
        pct(t.nearest_neighbour)
    )
}

fn render_diameters(out: &mut String, t: &Diameters) -> Fmt {
    let (classes, k) = (&t.classes, t.classes.len());
    writeln!(out, "| | {} |", classes.join(" | "))?;
    writeln!(out, "|---|{}", "---|".repeat(k))?;
    for (a, name) in classes.iter().enumerate() {
        let row: Vec<String> = t.d[a].iter().map(|v| format!("{v:.2}")).collect();
        writeln!(out, "| {name} | {} |", row.join(" | "))?;
    }
    let w = t.widest;
    let narrower: Vec<String> = t
        .narrower
        .iter()
        .map(|&(a, b)| format!("{} + {} ({:.2})", classes[a], classes[b], t.d[a][b]))
        .collect();
    writeln!(
        out,
        "\nThe widest class is {0} (diameter {1:.2}). Pairs of classes whose union is narrower: {2}. A tree node holding just such a pair is no wider than {0}, so any threshold that keeps {0} whole keeps that node whole too; the two can be told apart only where the tree puts other scans with them.\n",
        classes[w],
        t.d[w][w],
        if narrower.is_empty() { "none".to_string() } else { narrower.join(", ") }
    )
}

fn render_voxel_counts(out: &mut String, t: &VoxelCounts) -> Fmt {
    let what = &t.what;
    writeln!(out, "| {what} | smallest \\|F\\| | median | largest | largest / smallest |\n|---|---|---|---|---|")?;
    for (class, lo, median, hi) in &t.rows {
        let ratio = *hi as f64 / *lo as f64;
        writeln!(out, "| {class} | {lo} | {median} | {hi} | {ratio:.2} |")?;
    }
    writeln!(out)
}

fn render_confusion(out: &mut String, e: &eval::Evaluation) -> Fmt {
    let c = &e.confusion;
    writeln!(out, "| truth \\ predicted | {} |", c.cols.join(" | "))?;
    writeln!(out, "|---|{}", "---|".repeat(c.cols.len()))?;
    for (r, row) in c.rows.iter().zip(&c.rates) {
        let cells: Vec<String> = row.iter().map(|v| format!("{v:.2}")).collect();
        writeln!(out, "| {r} | {} |", cells.join(" | "))?;
    }
    out.push('\n');
    Ok(())
}

fn render_indoor(out: &mut String, s: &IndoorSection) -> Fmt {
    writeln!(out, "## 1. Indoor categories (paper Tab. I, KyushuIndoor)\n\nPaper: hierarchical k-means++ 88.0 ± 5.6 % over 10 seeds, deterministic k-means 93.3 %.\n\n### Preset `indoor` (the paper's descriptor)\n")?;
    render_table_one(out, &s.table)?;
    writeln!(
        out,
        "Confusion of deterministic k-means (rows: truth, row-normalised):\n"
    )?;
    render_confusion(out, &s.confusion)?;
    writeln!(out, "![dendrogram](indoor_dendrogram.svg)\n\nThe hierarchical tree (seed 0), leaves coloured by true kind, cut at 5 categories.\n")?;
    writeln!(out, "Diameters (largest Delta within a class, and within the union of two classes; hierarchical k-means++ cuts by diameter):\n")?;
    render_diameters(out, &s.diameters)?;
    writeln!(out, "Voxel counts |F| per class. Delta multiplies the histogram distance by max/min |F|, so two scans of one class can be as far apart as the last column says on that factor alone. Where the sensor stands changes |F|: in a corridor, scans from near the middle have more voxels than scans from near an end, and hierarchical k-means++ tends to split the corridors that way.\n")?;
    render_voxel_counts(out, &s.voxel_counts)?;
    writeln!(
        out,
        "### Preset `indoor_bands` ([design](design.md#variants): height bands, no far ranges, te = 0.1)\n"
    )?;
    render_table_one(out, &s.bands)
}

fn render_seeds(out: &mut String, s: &SeedsSection) -> Fmt {
    writeln!(out, "## 1b. Indoor over simulator seeds\n\nThe same protocol on forty simulated data sets (preset `indoor`). Seeds 1 to 5 were looked at while the simulator was developed. Seeds 6 to 10 were first run when the room kinds were fixed, with the 32-beam sensor; the sensor was changed after that. Seeds 11 to 20 were first run for the previous version of this report, after the last change to the simulator. Since then the cut at K categories has changed: it used to cut at the K-th highest node height, and where two splits share one height (a child that keeps its parent's diameter pair has the parent's diameter) that gave fewer than K categories, e.g. 4 instead of 5 in 6 of the 10 trees of seed 9; it now makes the K - 1 highest splits, a parent's before its child's. With the old cut the hierarchical column read 82.6, 82.3 and 80.6 % for seeds 1-5, 6-10 and 11-20. Seeds 21 to 30 were first run after that change (once in a throwaway check, then here), so they are held out from every change. Seeds 31 to 40 were added later and first run here, after changes that do not touch the simulator, the descriptor or the clustering (a DBSCAN sweep command, model and typing work). The column of 10 categories named by majority cuts the same trees at twice as many categories as kinds and names each after most of its scans, as a user naming categories on the page may give one name to two of them; it is not the paper's protocol and was added after the other columns had been seen. Deterministic k-means starts from scans i·n/k, and the simulator lists these sets kind by kind, so it starts from one scan of each kind; on the same scans in random orders the held-out seeds 11 to 40 give 81.8 % against 94.5 % as listed (docs/stride-order.md, a later look; the order of the paper's data is not known).\n\n| simulator seed | deterministic k-means | hierarchical k-means++ (10 seeds) | hierarchical, 10 categories named by majority | nearest neighbour |\n|---|---|---|---|---|")?;
    for r in &s.rows {
        writeln!(
            out,
            "| {} | {} | {} ± {} | {} | {} |",
            r.seed,
            pct(r.stride),
            pct(r.hk.0),
            pct(r.hk.1),
            pct(r.named),
            pct(r.nearest_neighbour)
        )?;
    }
    writeln!(out, "\n| data sets | deterministic k-means | hierarchical k-means++ | hierarchical, 10 categories named by majority | nearest neighbour |\n|---|---|---|---|---|")?;
    for (name, v) in &s.summary {
        let [a, b, c, d] = v.map(pct);
        writeln!(out, "| {name} | {a} | {b} | {c} | {d} |")?;
    }
    writeln!(out)
}

fn render_sweep(out: &mut String, s: &SweepSection) -> Res<()> {
    writeln!(out, "## 2. DBSCAN sweep (paper Fig. 3)\n\nS = ARI(inliers) x inliers / all. Paper: best S 0.70. Rows epsilon, columns c (min points, the scan itself counted). `placecat sweep DESCRIPTORS.json --truth labels.csv` gives the same figures for any described set, by default on a grid from quantiles of its own Delta.\n")?;
    let heads: Vec<String> = s
        .min_points
        .iter()
        .map(|c| format!("c={c}: S (inliers)"))
        .collect();
    writeln!(out, "| epsilon | {} |", heads.join(" | "))?;
    writeln!(out, "|---|{}", "---|".repeat(s.min_points.len()))?;
    for e in &s.epsilons {
        let mut row = vec![];
        for &c in &s.min_points {
            let p = s
                .points
                .iter()
                .find(|p| p.epsilon == *e && p.min_points == c)
                .ok_or("a sweep point is missing")?;
            let score = p.score.ok_or("a sweep point has no score")?;
            row.push(format!("{score:.2} ({:.0}%)", 100.0 * p.inlier_ratio));
        }
        writeln!(out, "| {e:.3} | {} |", row.join(" | "))?;
    }
    writeln!(out, "\n![DBSCAN sweep](dbscan_sweep.svg)\n\nS (solid) and the share of scans in a cluster (dashed) against epsilon, one colour per c, as in the paper's Fig. 3.")?;
    let best = &s.best;
    writeln!(
        out,
        "\nBest S = {:.2} at epsilon {:.3}, c = {} ({} clusters, {:.0}% inliers, ARI {:.2}).\n",
        best.score.ok_or("the best point has no score")?,
        best.epsilon,
        best.min_points,
        best.clusters,
        100.0 * best.inlier_ratio,
        best.ari.ok_or("the best point has no ARI")?
    )?;
    Ok(())
}

fn render_sensitivity(out: &mut String, rows: &[SensitivityRow]) -> Fmt {
    writeln!(out, "## 3. Sensitivity (paper Tab. III)\n\nPaper: accuracy changes little with te, ta, B, ns. Same indoor scans, one parameter changed from the `indoor` preset.\n\n| parameter | value | hierarchical (mean of 10 seeds) | deterministic k-means |\n|---|---|---|---|")?;
    for r in rows {
        let (name, value, (m, s)) = (&r.parameter, &r.value, r.hk);
        writeln!(
            out,
            "| {name} | {value} | {} ± {} | {} |",
            pct(m),
            pct(s),
            pct(r.stride)
        )?;
    }
    Ok(())
}

/// Section 4's heading, text and both sites.
fn render_sites(out: &mut String, sites: &[SiteSection]) -> Fmt {
    writeln!(
        out,
        "\n{SITES_HEADING}\n\n{SITES_TEXT}\n\n{}\n\n{}\n\n{}\n\n{}\n\n{}\n\n{}\n",
        THIRD_ROUND_TEXT.trim(),
        FOURTH_ROUND_TEXT.trim(),
        BOUNDARY_ERRORS_TEXT.trim(),
        FIFTH_ROUND_TEXT.trim(),
        SIXTH_ROUND_TEXT.trim(),
        SEVENTH_ROUND_TEXT.trim()
    )?;
    for site in sites {
        render_site(out, site)?;
    }
    Ok(())
}

const SITES_HEADING: &str =
    "## 4. Sites (paper: ArlaWarehouse 99.8 % for two categories, EskilstunaField 97.5 %)";

fn render_site(out: &mut String, s: &SiteSection) -> Fmt {
    let (scene, name, table) = (&s.scene, &s.name, &s.seed_table);
    writeln!(out, "### {scene} (preset `{}`, 3 categories)\n\nEvery seed: `placecat simulate --scene {name} --seed S` ({} scans), described with the preset, deterministic (stride) k-means at k = 3 and hierarchical k-means++ cut at 3 categories, clustering seeds 0-9. The test seeds were run once, after the site was fixed; their figures stand as they came.\n\n{table}\nSeed 1 in detail:\n\n- deterministic k-means: {} % (ARI {:.3})\n- hierarchical k-means++: {} ± {} % over 10 seeds\n- the same trees cut at 6 categories named by majority: {} ± {} %\n- nearest neighbour: {} %\n", s.preset, s.scans, pct(s.stride_accuracy), s.stride_ari, pct(s.hk.0), pct(s.hk.1), pct(s.named.0), pct(s.named.1), pct(s.nearest_neighbour))?;
    let (plan, per_scan, n) = s.timing;
    writeln!(out, "Simulating seed 1 natively (release, CPU time on one core): planning the site {:.0} ms, {:.0} ms a scan, {:.1} s for all {n} scans.\n", 1e3 * plan, 1e3 * per_scan, plan + per_scan * n as f64)?;
    let strip = format!("{name}_strip.svg");
    writeln!(out, "![{name} site]({name}_map.svg)\n\nThe site from above (seed 1): what stands there in grey, one dot per scan along the route, filled with the category deterministic k-means gave it (named after most of its scans) and ringed with its true kind.\n\n![{strip}]({strip})\n\nThe same along the route in scan order (like the paper's Fig. 4 and 6).\n")?;
    render_confusion(out, &s.confusion)?;
    if name == "outdoor" {
        writeln!(out, "\n{}", THIRD_ROUND_OUTDOOR.trim())?;
        writeln!(out, "\n{}", SECOND_ROUND_OUTDOOR.trim())?;
    }
    Ok(())
}

fn render_real(out: &mut String, s: &RealSection) -> Fmt {
    writeln!(out, "## 5. Real scans (`tests/data/real`, 18 files, 4 places)\n\n| preset | nearest neighbour | hierarchical, 4 categories (10 seeds) | deterministic k-means k=4 |\n|---|---|---|---|")?;
    for r in &s.rows {
        writeln!(
            out,
            "| {} | {} % | {} ± {} % | {} % |",
            r.preset,
            pct(r.nearest_neighbour),
            pct(r.hk.0),
            pct(r.hk.1),
            pct(r.stride)
        )?;
    }
    writeln!(out, "\nVoxel counts |F| per place (preset `indoor`). The two scans of one room (`pcl_room`, taken from two positions) differ by the factor in the last column, as simulated scans of one kind do (section 1); the other places' scans are consecutive ones, taken close together.\n")?;
    render_voxel_counts(out, &s.voxel_counts)
}

const INTRO: &str = "# Experiments\n\nRegenerate with `cargo run --release --example experiments` (writes this file and the SVGs beside it).\n\nData: `placecat simulate` scenes (indoor: 5 kinds x 40 scans, 8 rooms per kind, 5 scans per room at free spots with a random heading, a 128-beam sensor with a 90 degree vertical field like an Ouster OS0-128; warehouse and outdoor: 300 scans along a route through a site, section 4). Sections 1 to 3 use simulator seed 1, section 1b the seeds 1 to 40. Clustering seeds 0..9. No descriptor or clustering parameter was tuned on these results.\n\n**How the indoor simulator came to be.** Its first version drew every room's size over a wide range, and its kinds overlapped in size (kitchens and study rooms of 8 to 25 m2; offices and labs overlapping too). On it the paper's descriptor gave deterministic k-means 84.0 % and hierarchical k-means++ 81.7 % (means over simulator seeds 1 to 5), with office/lab and kitchen/study room confused. The present version (`src/sim/scenes.rs`) gives each kind the floor area and furniture of its use (a kitchenette, a group study room lined with bookcases round a large table, an open-plan office with desk islands behind partitions, a lab with island benches, fume cupboards and ducts under a high ceiling, corridors with doors and notice boards; chairs at any angle) and, by default, builds the rooms of a kind to one plan (sides within ±10 %), as in a survey of one building; `--buildings many` draws every room afresh. Its sensor was first a 32-beam one (32k rays a scan); it is now a 128-beam one (131k rays), as dense as the real room scans in `tests/data/real` (112k points). That change was made after a 128-beam variant had raised the hierarchical figure on seeds 1 to 5 (the 32-beam figures are the last row of section 1b). The simulator was developed while looking at seeds 1 to 5; seeds 6 to 10 were first run once the room kinds were fixed (with the 32-beam sensor), and seeds 11 to 40 only after the last change.\n";

/// docs/experiments.md from the report's data.
fn render_markdown(r: &Report) -> Res<String> {
    let mut out = String::new();
    writeln!(out, "{INTRO}")?;
    render_indoor(&mut out, &r.indoor)?;
    render_seeds(&mut out, &r.seeds)?;
    render_sweep(&mut out, &r.sweep)?;
    render_sensitivity(&mut out, &r.sensitivity)?;
    render_sites(&mut out, &r.sites)?;
    if let Some(real) = &r.real {
        render_real(&mut out, real)?;
    }
    // 6. Choosing the number of categories (the choose_k example's tables).
    writeln!(out, "\n{}", r.choose_k)?;
    writeln!(out, "\n_Generated in {:.0} s._", r.seconds)?;
    Ok(out)
}

/// The figures beside the report: (file name, SVG).
fn render_svgs(r: &Report) -> Vec<(String, String)> {
    let (tree, truth, cut) = &r.indoor.dendrogram;
    let mut svgs = vec![
        (
            "indoor_dendrogram.svg".to_string(),
            dendrogram_svg(tree, truth, *cut),
        ),
        (
            "dbscan_sweep.svg".to_string(),
            sweep_svg(&r.sweep.points, &r.sweep.epsilons, &r.sweep.min_points),
        ),
    ];
    for s in &r.sites {
        let run = &s.seed1;
        svgs.push((format!("{}_map.svg", s.name), sites::map_svg(run, &s.kinds)));
        svgs.push((
            format!("{}_strip.svg", s.name),
            sites::strip_svg(&run.truth, &run.stride, &run.stride_labels),
        ));
    }
    svgs
}

fn write(path: &std::path::Path, text: &str) -> Res<()> {
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()).into())
}

fn main() -> Res<()> {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    std::fs::create_dir_all(&docs)?;
    if std::env::args().any(|a| a == "--choose-k-only") {
        return replace_choose_k_section(&docs);
    }
    if std::env::args().any(|a| a == "--sites-only") {
        return replace_sites_section(&docs);
    }
    let report = compute(&docs)?;
    write(
        &docs.join("experiments.json"),
        &serde_json::to_string_pretty(&report)?,
    )?;
    for (name, svg) in render_svgs(&report) {
        write(&docs.join(name), &svg)?;
    }
    let md = render_markdown(&report)?;
    write(&docs.join("experiments.md"), &md)?;
    println!("{md}");
    Ok(())
}

/// Recomputes section 4 and replaces it in docs/experiments.md (up to
/// section 5's heading), in docs/experiments.json (`sites`) and its SVGs,
/// leaving the rest of the report as it was.
fn replace_sites_section(docs: &std::path::Path) -> Res<()> {
    let t0 = std::time::Instant::now();
    let sites = sites_sections()?;
    let json_path = docs.join("experiments.json");
    let json =
        std::fs::read_to_string(&json_path).map_err(|e| format!("{}: {e}", json_path.display()))?;
    // Spliced as text: a serde_json::Value would sort the report's keys.
    let (Some(a), Some(b)) = (json.find("\n  \"sites\": "), json.find("\n  \"real\": ")) else {
        return Err(format!("{}: no sites or real", json_path.display()).into());
    };
    let value = serde_json::to_string_pretty(&sites)?.replace('\n', "\n  ");
    let json = format!("{}\n  \"sites\": {value},{}", &json[..a], &json[b..]);
    serde_json::from_str::<serde_json::Value>(&json)?;
    write(&json_path, &json)?;
    for s in &sites {
        let run = &s.seed1;
        write(
            &docs.join(format!("{}_map.svg", s.name)),
            &sites::map_svg(run, &s.kinds),
        )?;
        write(
            &docs.join(format!("{}_strip.svg", s.name)),
            &sites::strip_svg(&run.truth, &run.stride, &run.stride_labels),
        )?;
    }
    let path = docs.join("experiments.md");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let begin = text
        .find(SITES_HEADING)
        .ok_or("no section 4 in experiments.md")?;
    // Section 4 ends where section 5's heading begins, as in the full render.
    let end = 1 + text
        .find("\n## 5. ")
        .ok_or("no section 5 in experiments.md")?;
    let mut new = String::new();
    render_sites(&mut new, &sites)?;
    let new = new.trim_start_matches('\n');
    write(&path, &format!("{}{new}{}", &text[..begin], &text[end..]))?;
    println!("{new}\n(section 4 in {:.0} s)", t0.elapsed().as_secs_f64());
    Ok(())
}

/// Replaces section 6 in docs/experiments.md (or puts it before the closing
/// "_Generated in" line), leaving the rest of the report as it was.
fn replace_choose_k_section(docs: &std::path::Path) -> Res<()> {
    use choose_k_section::{section, BEGIN, END};
    let path = docs.join("experiments.md");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let new = section(docs);
    let text = match (text.find(BEGIN), text.find(END)) {
        (Some(b), Some(e)) => format!("{}{}{}", &text[..b], new.trim_end(), &text[e + END.len()..]),
        _ => {
            let at = text.rfind("\n_Generated in").unwrap_or(text.len());
            format!("{}{}\n{}", &text[..at], new, &text[at..])
        }
    };
    write(&path, &text)
}
