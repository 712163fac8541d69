//! What the rounds that judge issue 14's sites beside issue 18's families
//! share (round 5, `split_trials.rs`; round 6, `hellinger.rs`): a site
//! simulated and described with its scene's paper preset, trees of tree
//! seeds 0-9, the default rule's choice on each, and one part of a run
//! (sites, then families). Include after `families.rs` and `rounds.rs`.

use crate::families::{Family, Sensor};
use crate::rounds::{every_set, Res, CLUSTER_SEEDS};
use placecat::cluster::choose_k::{choose_k, ChooseKParams, Clusterer, DEFAULT_RULE};
use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::eval::evaluate;
use placecat::sim::{SceneKind, SimParams, Simulation};
use placecat::*;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Trees of tree seeds 0-9, each with the parameters it was built with.
pub type Trees = Vec<(HkMeansParams, Tree)>;

/// Trees of tree seeds 0-9 with `trials` splits per node; `m` is the
/// space's Delta matrix (the caller's, so it is computed once).
pub fn trees(space: &Space, m: &DistanceMatrix, trials: usize) -> Res<Trees> {
    (0..CLUSTER_SEEDS)
        .into_par_iter()
        .map(|s| {
            let params = HkMeansParams::new(s).restarts(trials);
            let tree = HierarchicalKMeans::fit(space, m, &params)?;
            Ok((params, tree))
        })
        .collect::<placecat::Result<_>>()
        .map_err(Into::into)
}

/// The default rule's choice on one tree: K and the accuracy at it.
#[derive(Serialize, Deserialize, Clone, Copy)]
pub struct Chosen {
    pub k: usize,
    pub accuracy: f64,
}

/// The default rule's K on each tree, and the accuracy at it, as the
/// page's first cut.
pub fn choices(
    space: &Space,
    m: &DistanceMatrix,
    trees: &[(HkMeansParams, Tree)],
    truth: &[String],
) -> Res<Vec<Chosen>> {
    trees
        .par_iter()
        .map(|(p, tree)| {
            let c = choose_k(
                space,
                Some(m),
                Clusterer::Tree(tree, p),
                &ChooseKParams::default(),
                DEFAULT_RULE,
            )?;
            let accuracy = evaluate(truth, &tree.cut_k(c.k)?.labels)?.accuracy;
            Ok(Chosen { k: c.k, accuracy })
        })
        .collect::<placecat::Result<_>>()
        .map_err(Into::into)
}

/// K chosen over the trees, e.g. "2x1 3x9".
pub fn ks(c: &[Chosen]) -> String {
    let mut k: Vec<usize> = c.iter().map(|c| c.k).collect();
    k.sort();
    let mut out = vec![];
    for v in k.chunk_by(|a, b| a == b) {
        out.push(format!("{}x{}", v[0], v.len()));
    }
    out.join(" ")
}

/// A site as `placecat simulate --scene S --seed N` makes it, described
/// with the scene's paper preset (as examples/common/sites.rs).
pub struct Site {
    pub name: &'static str,
    pub params: DescriptorParams,
    pub truth: Vec<String>,
    pub descriptors: Vec<Descriptor>,
}

pub fn site(scene: SceneKind, seed: u64) -> Res<Site> {
    let (name, params) = if scene == SceneKind::Outdoor {
        ("outdoor", DescriptorParams::outdoor())
    } else {
        ("warehouse", DescriptorParams::indoor())
    };
    let (truth, mut described) = described_site(scene, seed, std::slice::from_ref(&params))?;
    Ok(Site {
        name,
        params,
        truth,
        descriptors: described.remove(0),
    })
}

/// `placecat simulate --scene S --seed N`'s scans described with each of
/// `params` (simulated once), and their true kinds.
pub fn described_site(
    scene: SceneKind,
    seed: u64,
    params: &[DescriptorParams],
) -> Res<(Vec<String>, Vec<Vec<Descriptor>>)> {
    let sim = Simulation::new(&SimParams::new(scene, seed))?;
    let per_scan: Vec<Vec<Descriptor>> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let points = sim.scan(i).points;
            params.iter().map(|p| describe(&points, p)).collect()
        })
        .collect::<placecat::Result<_>>()?;
    let by_preset = (0..params.len())
        .map(|j| per_scan.iter().map(|s| s[j].clone()).collect())
        .collect();
    let truth: Vec<String> = (0..sim.len()).map(|i| sim.label(i).to_string()).collect();
    Ok((truth, by_preset))
}

/// One part of a round (development or test seeds): the sites, then the
/// families, and the seconds it took.
#[derive(Serialize, Deserialize)]
pub struct Part<F, S> {
    pub families: Vec<F>,
    pub sites: Vec<S>,
    pub seconds: f64,
}

impl<F, S> Default for Part<F, S> {
    fn default() -> Self {
        Part {
            families: vec![],
            sites: vec![],
            seconds: 0.0,
        }
    }
}

/// Every site seed of both sites with `site_set`, then every family set
/// with `family_set`.
pub fn run<F, S>(
    presets: &[(String, Vec<String>)],
    family_seeds: &[u64],
    site_seeds: &[u64],
    what: &str,
    site_set: impl FnMut(SceneKind, u64) -> Res<S>,
    family_set: impl FnMut(&Family, Sensor, u64, &[String]) -> Res<F>,
) -> Res<Part<F, S>> {
    let scenes = [SceneKind::Outdoor, SceneKind::Warehouse];
    run_on(
        &scenes,
        presets,
        family_seeds,
        site_seeds,
        what,
        site_set,
        family_set,
    )
}

/// [`run`] on the sites of `scenes` only.
pub fn run_on<F, S>(
    scenes: &[SceneKind],
    presets: &[(String, Vec<String>)],
    family_seeds: &[u64],
    site_seeds: &[u64],
    what: &str,
    mut site_set: impl FnMut(SceneKind, u64) -> Res<S>,
    family_set: impl FnMut(&Family, Sensor, u64, &[String]) -> Res<F>,
) -> Res<Part<F, S>> {
    let t0 = std::time::Instant::now();
    let mut sites = vec![];
    for &scene in scenes {
        for &seed in site_seeds {
            eprintln!(
                "{what} site {scene:?} seed {seed} ({:.0} s)",
                t0.elapsed().as_secs_f64()
            );
            sites.push(site_set(scene, seed)?);
        }
    }
    let (families, _) = every_set(presets, family_seeds, what, family_set)?;
    Ok(Part {
        families,
        sites,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// The files of a round in docs/: its development run, its test report and
/// the report rendered.
pub struct RoundFiles {
    pub dev: &'static str,
    pub report: &'static str,
    pub md: &'static str,
}

/// The command line every round shares. `--render` renders the report to
/// its markdown again; `--dev` makes the development report with `dev`,
/// writes it and prints `dev_tables` of it; with neither, the test seeds
/// run once: `test` gets the development report (`--dev` must have run)
/// and its report is written and rendered. A test report that exists is
/// never overwritten.
pub fn round_main<R: Serialize + serde::de::DeserializeOwned>(
    files: &RoundFiles,
    dev: impl FnOnce() -> Res<R>,
    dev_tables: impl Fn(&R) -> Res<String>,
    test: impl FnOnce(R) -> Res<R>,
    render: impl Fn(&R) -> Res<String>,
) -> Res<()> {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let has = |a: &str| std::env::args().skip(1).any(|x| x == a);
    if has("--render") {
        let r: R = crate::families::read_json(&docs.join(files.report))?;
        std::fs::write(docs.join(files.md), render(&r)?)?;
        return Ok(());
    }
    if has("--dev") {
        // The decision was read from the development run before the test
        // run: once that has run, its development report stays as it was.
        if docs.join(files.report).exists() {
            return Err(format!(
                "docs/{} exists: the test seeds have run, so docs/{} is not written again",
                files.report, files.dev
            )
            .into());
        }
        let r = dev()?;
        std::fs::write(docs.join(files.dev), serde_json::to_string_pretty(&r)?)?;
        println!("{}", dev_tables(&r)?);
        return Ok(());
    }
    let report = files.report;
    if docs.join(report).exists() {
        return Err(format!(
            "docs/{report} exists: the test seeds run once (--render renders it again)"
        )
        .into());
    }
    let t0 = std::time::Instant::now();
    let dev: R = crate::families::read_json(&docs.join(files.dev))
        .map_err(|e| format!("{e} (run with --dev first)"))?;
    let r = test(dev)?;
    std::fs::write(docs.join(report), serde_json::to_string_pretty(&r)?)?;
    std::fs::write(docs.join(files.md), render(&r)?)?;
    eprintln!(
        "wrote docs/{report} and docs/{} ({:.0} s)",
        files.md,
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
