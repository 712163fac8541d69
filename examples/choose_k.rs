//! Evaluates the rules that choose the number of categories
//! (`placecat::cluster::choose_k`) on every simulator scene and on the real
//! files, for the hierarchical tree (cut_k) and for k-means (plusplus).
//!
//!     cargo run --release --example choose_k -- [--seeds dev|test] [--indoor-per-kind N] [--scans N] [OUT.md]
//!
//! `--seeds dev`: simulator seeds 1, 2, 3 (the rule was developed on these);
//! `--seeds test`: 101 to 105, indoor also 11 to 20 (run once, to report;
//! docs/seeds.md). `--seeds round2`: the outdoor site as changed in issue
//! 14's second round, each seed on its own row: development seeds 1 to 3
//! and the second round's test seeds 201 to 205 (run once); no real files.
//! `--seeds round3`: the third round's, the outdoor site and the warehouse
//! under the `warehouse` preset (the page's demo): development seeds 1 to
//! 10 and test seeds 401 to 405 (run once; `--dev-only` leaves them out).
//! `--seeds round4`: the fourth round's outdoor site (the vehicle's
//! corridor kept clear): development seeds 1 to 10 and test seeds 501 to
//! 505 (run once; `--dev-only` leaves them out).
//! Clustering seeds 0..9. Indoor: N scans per kind (default
//! 10, two rooms of five); warehouse and outdoor: `--scans` along the
//! trajectory (default: the simulator's own count). Writes a markdown
//! table to stdout and, given a path, to that file.

#[path = "common/real.rs"]
mod real;
use placecat::cluster::choose_k::{best_k, scores, ChooseKParams, Clusterer, Rule, Scores};
use placecat::cluster::hkmeans::HkMeansParams;
use placecat::cluster::*;
use placecat::eval::evaluate;
use placecat::sim::{Buildings, SceneKind, SimParams, Simulation};
use placecat::*;
use rayon::prelude::*;
use std::fmt::Write;

/// A data set with its truth and the category counts that count as found:
/// the true number of kinds and any coarser level of the true hierarchy.
struct Set {
    name: String,
    truth: Vec<String>,
    levels: Vec<usize>,
    descriptors: Vec<Descriptor>,
    params: DescriptorParams,
}

/// Coarser level of the true hierarchy: the outdoor forest road and forest
/// path are both forest (plain vs forest); the warehouse's small and large
/// hall are both halls (halls vs airlock; fixed before the site's first run);
/// other kinds stand alone.
fn coarse(label: &str) -> &str {
    if label.starts_with("forest") {
        "forest"
    } else if label.ends_with("_hall") {
        "hall"
    } else if label.starts_with("kitti00") {
        "kitti00"
    } else {
        label
    }
}

fn distinct<'a>(v: impl Iterator<Item = &'a str>) -> usize {
    let mut v: Vec<&str> = v.collect();
    v.sort_unstable();
    v.dedup();
    v.len()
}

fn levels(truth: &[String]) -> Vec<usize> {
    let mut l = vec![
        distinct(truth.iter().map(|s| s.as_str())),
        distinct(truth.iter().map(|s| coarse(s))),
    ];
    l.dedup();
    l
}

fn simulate(name: String, sp: SimParams, params: DescriptorParams) -> Set {
    let sim = Simulation::new(&sp).unwrap();
    let (descriptors, truth): (Vec<_>, Vec<_>) = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let s = sim.scan(i);
            (describe(&s.points, &params).unwrap(), s.label)
        })
        .unzip();
    Set {
        name,
        levels: levels(&truth),
        truth,
        descriptors,
        params,
    }
}

/// One K chosen: (found?, K, accuracy, ARI).
type Outcome = (bool, usize, f64, f64);

/// Per clusterer ("tree", "k-means"), per rule, the outcomes over the
/// clustering seeds, plus the oracle (K = true kinds).
fn run(set: &Set, seeds: &[u64]) -> Vec<(String, String, Vec<Outcome>)> {
    let space = Space::new(&set.descriptors, DistanceOptions::from(&set.params)).unwrap();
    let matrix = space.matrix();
    let truth_k = set.levels[0].min(set.truth.len());
    let per_seed: Vec<Vec<(String, String, Outcome)>> = seeds
        .par_iter()
        .map(|&seed| {
            let cp = ChooseKParams {
                seed,
                ..Default::default()
            };
            let hk = HkMeansParams::new(seed);
            let tree = HierarchicalKMeans::fit(&space, &matrix, &hk).unwrap();
            let km = KMeansParams::new(1).seed(seed);
            let mut out = Vec::new();
            for (cname, clusterer) in [
                ("tree", Clusterer::Tree(&tree, &hk)),
                ("k-means", Clusterer::KMeans(&km)),
            ] {
                let s: Scores = scores(&space, Some(&matrix), clusterer, &cp).unwrap();
                let outcome = |k: usize| -> Outcome {
                    let e = evaluate(&set.truth, &s.labels[k - 1]).unwrap();
                    (set.levels.contains(&k), k, e.accuracy, e.ari)
                };
                for rule in Rule::ALL {
                    if let Ok(c) = s.choose(rule) {
                        out.push((cname.into(), rule.name().into(), outcome(c.k)));
                    }
                }
                // Other K = 1 tests: Kaufman & Rousseeuw's silhouette bounds.
                let sil_best = s.best_silhouette();
                for bound in [0.25, 0.5] {
                    for rule in [Rule::GapSilhouette, Rule::HeightGap, Rule::CalinskiHarabasz] {
                        if let Ok(c) = s.choose(rule) {
                            let k = if sil_best < bound {
                                1
                            } else {
                                best_k(&c.scores).unwrap_or(1)
                            };
                            let name =
                                format!("{} (K=1: sil<{bound})", rule.name().replace("gap_", ""));
                            out.push((cname.into(), name, outcome(k)));
                        }
                    }
                }
                if seed == 0 {
                    eprintln!(
                        "  {} {cname}: sil {:?} gap-margin {:.3}",
                        set.name,
                        s.silhouette
                            .iter()
                            .map(|x| x.map(|v| (v * 100.0).round() / 100.0))
                            .collect::<Vec<_>>(),
                        s.one_category_margin().unwrap_or(f64::NAN)
                    );
                }
                out.push((
                    cname.into(),
                    "oracle (true K)".into(),
                    outcome(truth_k.min(s.labels.len())),
                ));
            }
            out
        })
        .collect();
    let mut rows: Vec<(String, String, Vec<Outcome>)> = Vec::new();
    for (c, r, o) in per_seed.into_iter().flatten() {
        match rows.iter_mut().find(|x| x.0 == c && x.1 == r) {
            Some(x) => x.2.push(o),
            None => rows.push((c, r, vec![o])),
        }
    }
    rows
}

fn table(out: &mut String, title: &str, sets: &[Set], seeds: &[u64]) {
    writeln!(out, "\n### {title}\n").unwrap();
    writeln!(out, "| data | scans | true K (levels) | clusterer | rule | found | K chosen | accuracy % | ARI |").unwrap();
    writeln!(out, "|---|---|---|---|---|---|---|---|---|").unwrap();
    // Aggregate over the sets of one scene name (several simulator seeds).
    let mut names: Vec<&str> = sets.iter().map(|s| s.name.as_str()).collect();
    names.dedup();
    for name in names {
        let group: Vec<&Set> = sets.iter().filter(|s| s.name == name).collect();
        let mut agg: Vec<(String, String, Vec<Outcome>)> = Vec::new();
        for set in &group {
            for (c, r, o) in run(set, seeds) {
                match agg.iter_mut().find(|x| x.0 == c && x.1 == r) {
                    Some(x) => x.2.extend(o),
                    None => agg.push((c, r, o)),
                }
            }
        }
        let lv = group[0]
            .levels
            .iter()
            .map(|l| l.to_string())
            .collect::<Vec<_>>()
            .join(", ");
        let scans = group
            .iter()
            .map(|s| s.truth.len().to_string())
            .collect::<Vec<_>>();
        let scans = if scans.iter().all(|s| *s == scans[0]) {
            scans[0].clone()
        } else {
            scans.join("/")
        };
        for (c, r, o) in agg {
            let n = o.len() as f64;
            let found = o.iter().filter(|x| x.0).count();
            let mut ks: Vec<usize> = o.iter().map(|x| x.1).collect();
            ks.sort_unstable();
            let kdesc = summarise(&ks);
            writeln!(
                out,
                "| {name} | {scans} | {lv} | {c} | {r} | {found}/{} | {kdesc} | {:.1} | {:.2} |",
                o.len(),
                100.0 * o.iter().map(|x| x.2).sum::<f64>() / n,
                o.iter().map(|x| x.3).sum::<f64>() / n,
            )
            .unwrap();
        }
    }
}

/// "3 x8, 4 x2": how often each K was chosen.
fn summarise(ks: &[usize]) -> String {
    let mut parts = Vec::new();
    let mut i = 0;
    while i < ks.len() {
        let j = ks[i..].iter().take_while(|&&k| k == ks[i]).count();
        parts.push(format!("{}×{j}", ks[i]));
        i += j;
    }
    parts.join(" ")
}

fn real_sets() -> Vec<Set> {
    let scans = real::real_scans();
    if scans.is_empty() {
        return vec![];
    }
    let mut folders: Vec<&str> = scans
        .iter()
        .map(|s| s.0.split('/').next().unwrap())
        .collect();
    folders.dedup();
    let mut sets = Vec::new();
    for params in [DescriptorParams::indoor(), DescriptorParams::outdoor()] {
        let mut subsets: Vec<(String, Vec<usize>)> =
            vec![("all 18 files".into(), (0..scans.len()).collect())];
        for f in &folders {
            subsets.push((
                f.to_string(),
                (0..scans.len())
                    .filter(|&i| scans[i].0.starts_with(&format!("{f}/")))
                    .collect(),
            ));
        }
        for (name, idx) in subsets {
            let truth: Vec<String> = idx.iter().map(|&i| scans[i].1.clone()).collect();
            sets.push(Set {
                name: format!("real: {name}, preset {}", params.preset),
                levels: levels(&truth),
                truth,
                descriptors: idx
                    .par_iter()
                    .map(|&i| describe(&scans[i].2, &params).unwrap())
                    .collect(),
                params: params.clone(),
            });
        }
    }
    sets
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut which: Option<String> = None;
    let mut dev_only = false;
    let mut per_kind = 10;
    let mut scans: Option<usize> = None;
    let mut path = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--seeds" => which = it.next().cloned(),
            "--dev-only" => dev_only = true,
            "--indoor-per-kind" => {
                per_kind = it.next().and_then(|s| s.parse().ok()).expect("a number")
            }
            "--scans" => scans = it.next().and_then(|s| s.parse().ok()),
            p => path = Some(p.to_string()),
        }
    }
    let test = which.as_deref() == Some("test");
    let (sim_seeds, indoor_extra): (Vec<u64>, Vec<u64>) = if test {
        ((101..=105).collect(), (11..=20).collect())
    } else {
        (vec![1, 2, 3], vec![])
    };
    let clustering: Vec<u64> = (0..10).collect();
    let start = std::time::Instant::now();
    let later = match which.as_deref() {
        Some("round2") => Some(Round {
            title: "the outdoor site of issue 14's second round",
            dev: (1..=3).collect(),
            test: (201..=205).collect(),
            scenes: vec![("outdoor", SceneKind::Outdoor, DescriptorParams::outdoor())],
        }),
        Some("round3") => Some(Round {
            title: "the outdoor site and the warehouse demo of issue 14's third round",
            dev: (1..=10).collect(),
            test: if dev_only {
                vec![]
            } else {
                (401..=405).collect()
            },
            scenes: vec![
                ("outdoor", SceneKind::Outdoor, DescriptorParams::outdoor()),
                (
                    "warehouse, preset warehouse",
                    SceneKind::Warehouse,
                    DescriptorParams::warehouse(),
                ),
            ],
        }),
        Some("round4") => Some(Round {
            title:
                "the outdoor site of issue 14's fourth round (the vehicle's corridor kept clear)",
            dev: (1..=10).collect(),
            test: if dev_only {
                vec![]
            } else {
                (501..=505).collect()
            },
            scenes: vec![("outdoor", SceneKind::Outdoor, DescriptorParams::outdoor())],
        }),
        _ => None,
    };
    if let Some(r) = later {
        return round(r, &clustering, scans, path, start);
    }
    let mut sets = Vec::new();
    for (label, scene, buildings, preset) in [
        (
            "indoor (one building)",
            SceneKind::Indoor,
            Buildings::One,
            DescriptorParams::indoor(),
        ),
        (
            "indoor (many buildings)",
            SceneKind::Indoor,
            Buildings::Many,
            DescriptorParams::indoor(),
        ),
        (
            "warehouse",
            SceneKind::Warehouse,
            Buildings::One,
            DescriptorParams::indoor(),
        ),
        (
            "outdoor",
            SceneKind::Outdoor,
            Buildings::One,
            DescriptorParams::outdoor(),
        ),
    ] {
        let mut seeds = sim_seeds.clone();
        if scene == SceneKind::Indoor && buildings == Buildings::One {
            seeds.extend(&indoor_extra);
        }
        for &seed in &seeds {
            let mut sp = SimParams::new(scene, seed);
            sp.buildings = buildings;
            if scene == SceneKind::Indoor {
                sp.scans = per_kind;
            } else if let Some(n) = scans {
                sp.scans = n;
            }
            eprintln!(
                "{label} seed {seed} ({:.0} s)",
                start.elapsed().as_secs_f64()
            );
            sets.push(simulate(label.to_string(), sp, preset.clone()));
        }
    }
    let mut out = String::new();
    writeln!(
        out,
        "## Choosing the number of categories: {} seeds\n\nSimulator seeds {:?}{}; clustering seeds 0 to 9 (tree: hierarchical k-means++ cut with `cut_k`; k-means: plusplus seeding). \"found\": the K chosen is the true number of kinds or a coarser level of the true hierarchy (outdoor: plain vs forest; warehouse: halls vs airlock; real files: KITTI's two places as one). Accuracy and ARI at the K chosen (`eval::evaluate`). Indoor: {per_kind} scans per kind.",
        if test { "test" } else { "development" },
        sim_seeds,
        if test { ", indoor (one building) also 11 to 20" } else { "" },
    )
    .unwrap();
    table(&mut out, "Simulated scenes", &sets, &clustering);
    table(
        &mut out,
        "Real files (`tests/data/real`)",
        &real_sets(),
        &clustering,
    );
    writeln!(out, "\n(took {:.0} s)", start.elapsed().as_secs_f64()).unwrap();
    print!("{out}");
    if let Some(p) = path {
        std::fs::write(&p, &out).unwrap_or_else(|e| panic!("{p}: {e}"));
    }
}

/// A later round of the outdoor site (and, from the third, the warehouse
/// under the `warehouse` preset, as the page's demo describes it), one row
/// per seed: its development seeds, then its test seeds (none with
/// `--dev-only`).
struct Round {
    title: &'static str,
    dev: Vec<u64>,
    test: Vec<u64>,
    scenes: Vec<(&'static str, SceneKind, DescriptorParams)>,
}

fn round(
    r: Round,
    clustering: &[u64],
    scans: Option<usize>,
    path: Option<String>,
    start: std::time::Instant,
) {
    let mut sets = Vec::new();
    for (label, scene, params) in &r.scenes {
        for (group, seeds) in [("development", &r.dev), ("test", &r.test)] {
            for &seed in seeds {
                let mut sp = SimParams::new(*scene, seed);
                if let Some(n) = scans {
                    sp.scans = n;
                }
                eprintln!(
                    "{label} seed {seed} ({:.0} s)",
                    start.elapsed().as_secs_f64()
                );
                let name = format!("{label}, {group} seed {seed}");
                sets.push(simulate(name, sp, params.clone()));
            }
        }
    }
    let seeds = |v: &[u64]| match v {
        [] => "none".to_string(),
        [a] => a.to_string(),
        [a, .., b] => format!("{a} to {b}"),
    };
    let mut out = String::new();
    writeln!(out, "## Choosing the number of categories: {}\n\nSimulator seeds {} (development) and {} (test, run once), one row per seed; clustering seeds 0 to 9 (tree: hierarchical k-means++ cut with `cut_k`; k-means: plusplus seeding). \"found\": the K chosen is 3 or 2 (outdoor: plain vs forest; warehouse: halls vs airlock). Accuracy and ARI at the K chosen (`eval::evaluate`).", r.title, seeds(&r.dev), seeds(&r.test)).unwrap();
    table(&mut out, r.title, &sets, clustering);
    writeln!(out, "\n(took {:.0} s)", start.elapsed().as_secs_f64()).unwrap();
    print!("{out}");
    if let Some(p) = path {
        std::fs::write(&p, &out).unwrap_or_else(|e| panic!("{p}: {e}"));
    }
}
