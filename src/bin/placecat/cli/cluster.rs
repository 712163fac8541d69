//! `placecat cluster`, `placecat evaluate`, `placecat sweep`, `placecat simulate`.

use super::describe::DescriptorsFile;
use super::names::Labels;
use super::progress;
use placecat::cluster::choose_k::{ChooseKParams, Clusterer};
use placecat::cluster::{
    hkmeans::HkMeansParams, DbscanParams, KMeansParams, KMedoidsParams, Seeding, SpectralParams,
};
use placecat::io::csv;
use placecat::io::write::{self, PlyEncoding};
use placecat::sim::{LidarParams, SceneKind, SimParams, Simulation};
use placecat::{Error, Result};
use rayon::prelude::*;
use serde_json::{json, Value};
use std::path::Path;
use std::process::ExitCode;

/// Options of `placecat cluster`.
#[derive(clap::Args)]
pub struct ClusterArgs {
    /// kmeans, hkmeans, dbscan, kmedoids, spectral.
    #[arg(long)]
    pub method: String,
    /// kmeans, kmedoids, spectral: the number of categories; `auto`
    /// (kmeans, the default there, but not with --seeding spectral)
    /// chooses it from the data (see `categories` in OUT.json).
    #[arg(long)]
    pub k: Option<Count>,
    /// k-means seeding: random, stride, plusplus, spectral. Stride (the
    /// paper's deterministic seeding) starts from scans i*n/k of the input's
    /// order, so its result depends on that order: along a recording the
    /// route's, for room scans the files'. Spectral starts each centre at
    /// the mean of one group of spectral clustering (--seed seeds it; one
    /// run; at most 2000 scans); recommended for sets of room scans
    /// described with indoor_searched or indoor_objects
    /// (docs/spectral-seeding-round.md), not along a route; it needs --k.
    #[arg(long, default_value = "plusplus")]
    pub seeding: String,
    /// kmeans: runs of k-means, each from its own seeding, keeping the one
    /// of lowest cost (1: the paper's single run; more needs random or
    /// plusplus seeding; at most 1000). With --k auto every k tried is
    /// clustered so. hkmeans: 2-means++ trials at every split of the tree,
    /// the cheapest kept (1: the paper's tree; at most 1000); with
    /// --categories auto the rule's reference trees are built so too.
    /// spectral: runs of k-means on the embedded scans. Default: 1 for
    /// kmeans and hkmeans, 10 for spectral.
    #[arg(long)]
    pub restarts: Option<usize>,
    /// Seeds k-means, k-medoids, spectral clustering's k-means, the tree's
    /// 2-means splits and the choice of K (its reference sets).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// hkmeans: cut the tree at this height.
    #[arg(long, allow_negative_numbers = true)]
    pub threshold: Option<f32>,
    /// hkmeans: cut the tree where it gives this many categories (its K - 1
    /// highest splits; of two at one height, the parent's first); `auto`
    /// (the default when no --threshold is given) chooses K from the data.
    #[arg(long)]
    pub categories: Option<Count>,
    /// dbscan: neighbourhood radius (Delta <= eps).
    #[arg(long, allow_negative_numbers = true)]
    pub eps: Option<f32>,
    /// dbscan: neighbours of a core scan, itself included.
    #[arg(long = "min-points")]
    pub min_points: Option<usize>,
    /// spectral: which nearest neighbour sets a scan's local scale
    /// (Zelnik-Manor and Perona's 7 unless given).
    #[arg(long)]
    pub neighbours: Option<usize>,
}

/// A number of categories given, or `auto`: chosen from the data by the
/// core's default rule (`placecat::cluster::choose_k`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Count {
    /// Chosen from the data.
    Auto,
    /// As given.
    Exactly(usize),
}

impl std::str::FromStr for Count {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "auto" => Ok(Count::Auto),
            n => n
                .parse()
                .map(Count::Exactly)
                .map_err(|_| format!("expected a whole number or auto, got {n:?}")),
        }
    }
}

/// The choice's fields that OUT.json carries when K was chosen.
fn choice_json(choice: &placecat::cluster::choose_k::Choice) -> Value {
    json!({
        "rule": choice.rule,
        "scores": choice.scores,
        "one_category": choice.one_category,
    })
}

/// The number given to `--k` of a method that cannot choose it.
fn exact_k(k: Option<Count>, method: &str) -> Result<usize> {
    match need(k, "--k", method)? {
        Count::Exactly(k) => Ok(k),
        Count::Auto => Err(Error::InvalidParameter(format!(
            "--method {method} needs a number for --k (auto is for kmeans and hkmeans)"
        ))),
    }
}

fn need<T>(v: Option<T>, flag: &str, method: &str) -> Result<T> {
    v.ok_or_else(|| Error::InvalidParameter(format!("--method {method} needs {flag}")))
}

/// The form of `placecat cluster`'s output.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// OUT.json: files, labels and the method's fields (the default).
    Json,
    /// `file,category` rows under that header: the scan's name and its
    /// category number (-1: DBSCAN noise).
    Csv,
}

impl Format {
    /// The format asked for, else CSV for an output named `*.csv` (JSON
    /// in a .csv file would be read as one odd cell), else JSON.
    pub fn for_output(asked: Option<Format>, output: &Path) -> Format {
        let csv_name = output
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
        asked.unwrap_or(if csv_name { Format::Csv } else { Format::Json })
    }
}

/// `file,category` rows with their header, RFC 4180 quoted.
fn categories_csv(files: &[String], labels: &[i32]) -> String {
    let mut s = String::from("file,category\n");
    for (f, l) in files.iter().zip(labels) {
        s += &csv::record([f.as_str(), &l.to_string()]);
        s.push('\n');
    }
    s
}

pub fn cluster(
    descriptors: &Path,
    a: &ClusterArgs,
    output: &Path,
    format: Option<Format>,
) -> Result<ExitCode> {
    let mut set = DescriptorsFile::load(descriptors)?;
    if set.is_empty() {
        return Err(Error::InvalidParameter(format!(
            "{}: no described files",
            descriptors.display()
        )));
    }
    if a.restarts.is_some_and(|r| r != 1)
        && !matches!(a.method.as_str(), "kmeans" | "hkmeans" | "spectral")
    {
        return Err(Error::InvalidParameter(format!(
            "--restarts is for --method kmeans, hkmeans or spectral, not {}",
            a.method
        )));
    }
    if a.neighbours.is_some() && a.method != "spectral" {
        return Err(Error::InvalidParameter(format!(
            "--neighbours is for --method spectral, not {}",
            a.method
        )));
    }
    let restarts = a.restarts.unwrap_or(1);
    let files = set.names().to_vec();
    let mut out = json!({ "files": files, "method": a.method });
    match a.method.as_str() {
        "kmeans" => {
            let seeding: Seeding = a.seeding.parse()?;
            let params = |k| {
                KMeansParams::new(k)
                    .seeding(seeding)
                    .seed(a.seed)
                    .restarts(restarts)
            };
            let k = match a.k.unwrap_or(Count::Auto) {
                Count::Exactly(k) => k,
                // The library refuses it too; this names the option.
                Count::Auto if seeding == Seeding::Spectral => {
                    return Err(Error::InvalidParameter(
                        "--seeding spectral needs a number for --k: auto, the default for \
                         kmeans, is not offered with it (on room sets it said one category; \
                         docs/spectral-seeding-k-dev.md)"
                            .into(),
                    ));
                }
                Count::Auto => {
                    let choice = set.choose_categories(
                        Clusterer::KMeans(&params(1)),
                        &ChooseKParams::default(),
                    )?;
                    out["choice"] = choice_json(&choice);
                    choice.k
                }
            };
            let r = set.kmeans(&params(k))?;
            out["labels"] = json!(r.labels);
            out["k"] = json!(k);
            out["categories"] = json!(k);
            out["seeding"] = json!(seeding);
            out["seed"] = json!(a.seed);
            out["iterations"] = json!(r.iterations);
            out["converged"] = json!(r.converged);
            out["cost"] = json!(r.cost);
            out["restarts"] = json!(restarts);
            out["restart"] = json!(r.restart);
        }
        "kmedoids" => {
            let k = exact_k(a.k, "kmedoids")?;
            let r = set.kmedoids(&KMedoidsParams::new(k).seed(a.seed))?;
            out["labels"] = json!(r.labels);
            out["medoids"] = json!(r.medoids.iter().map(|&i| &files[i]).collect::<Vec<_>>());
        }
        "hkmeans" => {
            // Above the matrix limit the tree is built without the matrix.
            let hk = HkMeansParams::new(a.seed).restarts(restarts);
            let tree = set.hkmeans(&hk)?;
            let cut = match (a.threshold, a.categories) {
                (Some(t), None) => tree.cut(t)?,
                (None, Some(Count::Exactly(k))) => tree.cut_k(k)?,
                (None, None | Some(Count::Auto)) => {
                    let choice = set.choose_categories(
                        Clusterer::Tree(&tree, &hk),
                        &ChooseKParams::default(),
                    )?;
                    out["choice"] = choice_json(&choice);
                    tree.cut_k(choice.k)?
                }
                (Some(_), Some(_)) => return Err(Error::InvalidParameter(
                    "--method hkmeans takes one of --threshold T or --categories K|auto, not both"
                        .into(),
                )),
            };
            out["labels"] = json!(cut.labels);
            out["threshold"] = json!(cut.threshold);
            out["categories"] = json!(cut.nodes.len());
            out["seed"] = json!(a.seed);
            out["restarts"] = json!(restarts);
            out["tree"] = json!({
                "nodes": tree.nodes.iter().map(|n| json!({"members": n.members, "height": n.height, "children": n.children})).collect::<Vec<Value>>(),
                "linkage": tree.linkage(),
            });
        }
        "dbscan" => {
            let eps = need(a.eps, "--eps", "dbscan")?;
            let c = need(a.min_points, "--min-points", "dbscan")?;
            let labels = set.dbscan(&DbscanParams::new(eps, c))?;
            out["noise"] = json!(labels.iter().filter(|&&l| l < 0).count());
            out["labels"] = json!(labels);
            out["eps"] = json!(eps);
            out["min_points"] = json!(c);
        }
        "spectral" => {
            let k = exact_k(a.k, "spectral")?;
            let mut params = SpectralParams::new(k).seed(a.seed);
            if let Some(r) = a.restarts {
                params = params.restarts(r);
            }
            if let Some(nb) = a.neighbours {
                params = params.neighbours(nb);
            }
            let r = set.spectral(&params)?;
            out["labels"] = json!(r.labels);
            out["k"] = json!(k);
            out["categories"] = json!(k);
            out["seed"] = json!(a.seed);
            out["neighbours"] = json!(params.neighbours);
            out["restarts"] = json!(params.restarts);
            out["restart"] = json!(r.restart);
            out["eigenvalues"] = json!(r.eigenvalues);
            out["cost"] = json!(r.cost);
        }
        other => {
            return Err(Error::InvalidParameter(format!(
                "unknown --method {other:?} (kmeans, hkmeans, dbscan, kmedoids, spectral)"
            )))
        }
    }
    let text = match Format::for_output(format, output) {
        Format::Json => serde_json::to_string(&out)?,
        Format::Csv => {
            let labels: Vec<i32> = serde_json::from_value(out["labels"].take())?;
            categories_csv(&files, &labels)
        }
    };
    super::write_out(Some(output), &text)?;
    Ok(ExitCode::SUCCESS)
}

/// Read a `file,label` CSV (header optional) into (file, label) pairs,
/// with the core's CSV reader (RFC 4180: the page's export, spreadsheets).
pub fn read_truth(path: &Path) -> Result<Vec<(String, String)>> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&name))?;
    let mut rows = Vec::new();
    for rec in csv::parse(&text).map_err(|e| e.in_file(&name))? {
        // A header: labels.csv's file,label or the page's file,category.
        let first = rec.cells[0].trim().to_ascii_lowercase();
        if rec.line == 1 && first == "file" && rec.cells.len() > 1 {
            continue;
        }
        let Ok([f, l]) = <[String; 2]>::try_from(rec.cells) else {
            return Err(Error::Csv(format!(
                "line {}: expected two cells, file,label (quote a name that holds a comma)",
                rec.line
            ))
            .in_file(&name));
        };
        rows.push((f.trim().to_string(), l.trim().to_string()));
    }
    Ok(rows)
}

/// The labels of a `file,label` CSV for these scan names (see
/// [`Labels`] for how rows match names).
pub fn read_labels(path: &Path) -> Result<Labels> {
    Labels::new(read_truth(path)?, path)
}

/// The files and labels of a `cluster` OUT.json, errors naming it.
pub fn read_clusters(clusters: &Path) -> Result<(Vec<String>, Vec<i32>)> {
    let name = clusters.display().to_string();
    let text = std::fs::read_to_string(clusters).map_err(|e| Error::from(e).in_file(&name))?;
    let v: Value = serde_json::from_str(&text).map_err(|e| Error::from(e).in_file(&name))?;
    // Say what was expected: a DESCRIPTORS.json given by mistake has
    // "files" too, but as objects.
    let not_clusters = |e: serde_json::Error| {
        Error::Mismatch(format!(
            "not the output of placecat cluster (\"files\": names, \"labels\": integers): {e}"
        ))
        .in_file(&name)
    };
    let files: Vec<String> = serde_json::from_value(v["files"].clone()).map_err(not_clusters)?;
    let labels: Vec<i32> = serde_json::from_value(v["labels"].clone()).map_err(not_clusters)?;
    if files.len() != labels.len() {
        return Err(
            Error::Mismatch(format!("{} files but {} labels", files.len(), labels.len()))
                .in_file(&name),
        );
    }
    Ok((files, labels))
}

/// `placecat evaluate`: the clustering against `file,label` ground truth.
pub fn evaluate(clusters: &Path, truth: &Path) -> Result<ExitCode> {
    let (files, labels) = read_clusters(clusters)?;
    let t = truth_for(&files, truth)?;
    let ev = placecat::eval::evaluate(&t, &labels)?;
    super::write_out(None, &format!("{}\n", serde_json::to_string_pretty(&ev)?))?;
    Ok(ExitCode::SUCCESS)
}

/// The ground-truth label of each file from a `file,label` CSV, matched
/// on the relative path, or on the base name where only one scan has it;
/// an error naming the CSV if a file has none.
fn truth_for(files: &[impl AsRef<str>], truth: &Path) -> Result<Vec<String>> {
    let labels = read_labels(truth)?;
    let found = labels.for_names(files);
    let missing: Vec<&str> = files
        .iter()
        .zip(&found)
        .filter(|(_, l)| l.is_none())
        .map(|(f, _)| f.as_ref())
        .collect();
    if let Some(first) = missing.first() {
        return Err(Error::Mismatch(format!(
            "{} files have no ground-truth label (first: {first}; rows match a scan's \
             path relative to the inputs' common root, or its base name where no other \
             scan has it)",
            missing.len(),
        ))
        .in_file(truth.display().to_string()));
    }
    Ok(found.into_iter().flatten().map(str::to_string).collect())
}

/// Options of `placecat sweep`.
#[derive(clap::Args)]
pub struct SweepArgs {
    /// `file,label` CSV (matched to the scans as `evaluate --truth` is):
    /// adds the ARI and S = ARI x inliers / all.
    #[arg(long)]
    pub truth: Option<std::path::PathBuf>,
    /// Epsilons, comma-separated (default: quantiles 0.5 % to 50 % of the
    /// Delta between two different scans, rounded up to 3 significant digits).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub eps: Vec<f32>,
    /// Min points (the scan itself included), comma-separated.
    #[arg(long = "min-points", value_delimiter = ',', default_values_t = placecat::eval::SWEEP_MIN_POINTS)]
    pub min_points: Vec<usize>,
}

/// `placecat sweep`: DBSCAN over a grid of epsilon x min points, as CSV
/// `epsilon,min_points,clusters,inlier_ratio,ari,score` (the last two empty
/// without `--truth`); the best S goes to stderr.
pub fn sweep(descriptors: &Path, a: &SweepArgs, output: Option<&Path>) -> Result<ExitCode> {
    let mut set = DescriptorsFile::load(descriptors)?;
    let truth = a
        .truth
        .as_deref()
        .map(|t| truth_for(set.names(), t))
        .transpose()?;
    if set.len() < 2 {
        return Err(Error::InvalidParameter(format!(
            "{}: a sweep needs at least two described files, it has {}",
            descriptors.display(),
            set.len()
        )));
    }
    let eps = if a.eps.is_empty() {
        set.epsilon_grid()?
    } else {
        a.eps.clone()
    };
    let points = set.dbscan_sweep(truth.as_deref(), &eps, &a.min_points)?;
    let cell = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.4}"));
    let mut out = String::from("epsilon,min_points,clusters,inlier_ratio,ari,score\n");
    for p in &points {
        out += &format!(
            "{},{},{},{:.4},{},{}\n",
            p.epsilon,
            p.min_points,
            p.clusters,
            p.inlier_ratio,
            cell(p.ari),
            cell(p.score)
        );
    }
    super::write_out(output, &out)?;
    if let Some(b) = placecat::eval::best_score(&points) {
        eprintln!(
            "best S {:.3} at --eps {} --min-points {} ({} clusters, {:.0} % inliers, ARI {:.3})",
            b.score.unwrap_or(0.0),
            b.epsilon,
            b.min_points,
            b.clusters,
            100.0 * b.inlier_ratio,
            b.ari.unwrap_or(0.0)
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Sensor and sampling options of `placecat simulate`.
#[derive(clap::Args)]
pub struct SensorArgs {
    /// The sensor by beam count: 16 (VLP-16, +-15 deg), 32 (HDL-32E,
    /// -30.7..+10.7 deg), 64 (OS1-64, +-22.5 deg) or 128 (OS0-128, +-45
    /// deg). Default: the scene's own (128 indoors, a 64-beam KITTI-like
    /// one outdoors).
    #[arg(long)]
    beams: Option<usize>,
    /// The sensor's height above the floor or ground (m), e.g. 0.3 for a
    /// small robot, 1.8 for a car roof. Default: the scene's own.
    #[arg(long)]
    sensor_height: Option<f64>,
    /// indoor, office-floor, school, hospital, hotel, mall, home,
    /// institute, gym: scans taken in each room (default 5 indoor, 3 on
    /// office, school, hospital, hotel, mall, home, institute and gym
    /// floors).
    #[arg(long)]
    scans_per_room: Option<usize>,
}

pub fn simulate(
    scene: &str,
    seed: u64,
    scans: Option<usize>,
    buildings: &str,
    shuffle: bool,
    sensor: &SensorArgs,
    dir: &Path,
) -> Result<ExitCode> {
    if super::is_stdout(dir) {
        return Err(Error::InvalidParameter(
            "simulate writes a folder of files: -o needs a folder, not -".into(),
        ));
    }
    let kind: SceneKind = scene.parse()?;
    let mut p = SimParams::new(kind, seed);
    p.buildings = buildings.parse()?;
    p.shuffle = shuffle;
    if let Some(n) = scans {
        p.scans = n;
    }
    if let Some(n) = sensor.scans_per_room {
        p.scans_per_room = n;
    }
    p.lidar = sensor.beams.map(LidarParams::with_beams).transpose()?;
    p.sensor_height = sensor.sensor_height;
    let sim = Simulation::new(&p)?;
    std::fs::create_dir_all(dir).map_err(|e| Error::from(e).in_file(dir.display().to_string()))?;
    let bar = progress::bar(sim.len() as u64, "simulating");
    let meta: Vec<Result<(String, String, placecat::io::poses::Pose)>> = (0..sim.len())
        .into_par_iter()
        .map(|i| {
            let s = sim.scan(i);
            let path = dir.join(&s.name);
            std::fs::write(
                &path,
                write::ply(&s.points, PlyEncoding::BinaryLittleEndian, false),
            )
            .map_err(|e| Error::from(e).in_file(path.display().to_string()))?;
            bar.inc(1);
            Ok((s.name, s.label, s.pose))
        })
        .collect();
    bar.finish_and_clear();
    let meta: Vec<_> = meta.into_iter().collect::<Result<_>>()?;
    let poses: Vec<_> = meta.iter().map(|m| m.2.clone()).collect();
    let mut labels = String::from("file,label\n");
    for (f, l, _) in &meta {
        labels.push_str(&format!("{f},{l}\n"));
    }
    for (file, text) in [
        ("poses.txt", placecat::io::poses::to_kitti(&poses)),
        ("poses_tum.txt", placecat::io::poses::to_tum(&poses)),
        ("labels.csv", labels),
    ] {
        super::write_out(Some(&dir.join(file)), &text)?;
    }
    eprintln!(
        "simulated {} {scene} scans (seed {seed}) -> {}",
        meta.len(),
        dir.display()
    );
    Ok(ExitCode::SUCCESS)
}
