//! Argument parsing and dispatch.

mod cluster;
mod describe;
mod info;
mod model;
mod progress;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "placecat",
    version,
    about = "Unsupervised place categorisation of 3D lidar scans"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Show what a scan file holds.
    Info {
        file: PathBuf,
        /// Print one JSON object (format, count, first, last, sum).
        #[arg(long)]
        json: bool,
    },
    /// Compute the NDT-histogram descriptor of every scan.
    Describe {
        /// Parameter preset: indoor, outdoor, indoor_bands, perception_oru.
        #[arg(long, default_value = "indoor")]
        preset: String,
        /// JSON file of parameters (fields not given keep the preset's values).
        #[arg(long)]
        params: Option<PathBuf>,
        /// Files or folders (folders: every scan inside, sorted by name).
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        #[arg(short, long)]
        output: PathBuf,
        #[command(flatten)]
        limits: Limits,
    },
    /// Cluster described scans into categories.
    Cluster {
        descriptors: PathBuf,
        #[command(flatten)]
        args: cluster::ClusterArgs,
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Compare cluster labels with ground truth (file,label CSV).
    Evaluate {
        clusters: PathBuf,
        #[arg(long)]
        truth: PathBuf,
    },
    /// DBSCAN over a grid of epsilon x min points (paper Fig. 3): CSV
    /// epsilon,min_points,clusters,inlier_ratio,ari,score.
    Sweep {
        descriptors: PathBuf,
        #[command(flatten)]
        args: cluster::SweepArgs,
        /// CSV file to write (default: stdout).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Simulate lidar scans with ground truth: PLY scans, poses, labels.csv.
    Simulate {
        /// indoor, warehouse, outdoor.
        #[arg(long)]
        scene: String,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// indoor: scans per kind (default 40); others: scans along the route (default 300).
        #[arg(long)]
        scans: Option<usize>,
        /// indoor: `one` building (rooms of a kind share a plan, the
        /// default) or `many` (every room drawn over its kind's whole size
        /// range; harder).
        #[arg(long, default_value = "one")]
        buildings: String,
        #[arg(short, long)]
        output: PathBuf,
    },
    /// A named model from described scans and a file,name CSV (the page's
    /// "Export CSV" or a labels.csv): one category per name.
    Model {
        descriptors: PathBuf,
        #[arg(long)]
        names: PathBuf,
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Put new scans into the named categories of a model (the page's
    /// "Export model"): CSV file,category,distance,relative.
    Classify {
        model: PathBuf,
        /// Files or folders (folders: every scan inside, sorted by name).
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// CSV file to write (default: stdout).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        limits: Limits,
    },
    /// The Delta matrix of described scans, as CSV.
    Distances {
        descriptors: PathBuf,
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
}

/// How large a scan file may be (checked before allocating).
#[derive(clap::Args)]
struct Limits {
    /// Refuse scans with more points (checked before allocating).
    #[arg(long, default_value_t = placecat::io::ReadLimits::default().max_points)]
    max_points: usize,
    /// Refuse files larger than this many bytes.
    #[arg(long, default_value_t = placecat::io::ReadLimits::default().max_bytes)]
    max_bytes: usize,
}

impl From<Limits> for placecat::io::ReadLimits {
    fn from(l: Limits) -> Self {
        placecat::io::ReadLimits {
            max_points: l.max_points,
            max_bytes: l.max_bytes,
        }
    }
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Info { file, json } => info::run(&file, json),
        Command::Describe {
            preset,
            params,
            inputs,
            output,
            limits,
        } => describe::run(&preset, params.as_deref(), &inputs, &output, &limits.into()),
        Command::Cluster {
            descriptors,
            args,
            output,
        } => cluster::cluster(&descriptors, &args, &output),
        Command::Evaluate { clusters, truth } => cluster::evaluate(&clusters, &truth),
        Command::Sweep {
            descriptors,
            args,
            output,
        } => cluster::sweep(&descriptors, &args, output.as_deref()),
        Command::Simulate {
            scene,
            seed,
            scans,
            buildings,
            output,
        } => cluster::simulate(&scene, seed, scans, &buildings, &output),
        Command::Distances {
            descriptors,
            output,
        } => describe::distances(&descriptors, output.as_deref()),
        Command::Model {
            descriptors,
            names,
            output,
        } => model::build(&descriptors, &names, &output),
        Command::Classify {
            model,
            inputs,
            output,
            limits,
        } => model::classify(&model, &inputs, output.as_deref(), &limits.into()),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("placecat: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Write text to a file, or to stdout when no path is given.
pub(crate) fn write_out(path: Option<&std::path::Path>, text: &str) -> placecat::Result<()> {
    match path {
        Some(p) => std::fs::write(p, text)
            .map_err(|e| placecat::Error::from(e).in_file(p.display().to_string())),
        None => {
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
                // The reader went away (`placecat ... | head`): stop
                // quietly, as Unix tools do, instead of panicking in print!.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
                other => other.map_err(|e| placecat::Error::from(e).in_file("standard output")),
            }
        }
    }
}
