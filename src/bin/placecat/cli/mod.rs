//! Argument parsing and dispatch.

mod bag;
mod cluster;
mod describe;
mod info;
mod map;
mod model;
mod names;
mod progress;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// `--preset`'s help, naming every preset of the table with its note.
fn preset_help() -> String {
    let notes: Vec<String> = placecat::descriptor::PRESET_NOTES
        .iter()
        .map(|(name, note)| format!("{name} ({note})"))
        .collect();
    format!(
        "Parameter preset: {}. Default: the preset the --params file names, else indoor",
        notes.join("; ")
    )
}

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
        /// The scan file (PLY, PCD, KITTI .bin, LAS/LAZ, E57).
        file: PathBuf,
        /// Print one JSON object (format, count, first, last, sum; for an
        /// E57 survey also scans: name, count, finite, sum, pose of each).
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        lenient: Lenient,
        #[command(flatten)]
        origin: Origin,
    },
    /// Compute the NDT-histogram descriptor of every scan.
    Describe {
        /// Parameter preset (the names come from the one preset table).
        #[arg(long, help = preset_help())]
        preset: Option<String>,
        /// JSON file of parameters (fields not given keep the preset's
        /// values: --preset's, else the preset the file names, else indoor).
        #[arg(long)]
        params: Option<PathBuf>,
        /// The sensor's height above the floor in metres, a constant of the
        /// robot: the clutter, columns and objects parts then measure
        /// heights from a floor that far below the sensor instead of each
        /// scan's own estimate (as "sensor_height" in --params; this flag
        /// wins).
        #[arg(long, value_name = "M")]
        sensor_height: Option<f64>,
        /// Files or folders, and ROS bags (.bag, .mcap). Folders are
        /// searched with all their subfolders (hidden ones skipped) for
        /// .ply .pcd .bin .las .laz .e57 .bag .mcap, sorted by name. Each
        /// scan is named by its path relative to the common folder of the
        /// inputs (`describe sequences` names `00/velodyne/000000.bin`;
        /// loose files of one folder keep their base names). Each cloud of
        /// a bag's PointCloud2 topic is one scan, named PATH:TOPIC:INDEX
        /// (e.g. run.bag:/points:000042, INDEX counted before thinning),
        /// each station of an E57 survey PATH:scan N.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// The descriptors file (JSON) to write; `-` for standard output.
        #[arg(short, long)]
        output: PathBuf,
        #[command(flatten)]
        limits: Limits,
        #[command(flatten)]
        bag: bag::BagArgs,
    },
    /// List the topics of a ROS bag (.bag or rosbag2 .mcap): name, message
    /// type and message count.
    Topics {
        /// The bag: a ROS 1 .bag file, or the .mcap file of a rosbag2 bag.
        bag: PathBuf,
        /// Print a JSON array of {name, type, count}.
        #[arg(long)]
        json: bool,
    },
    /// Cluster described scans into categories.
    Cluster {
        /// The output of `placecat describe`.
        descriptors: PathBuf,
        #[command(flatten)]
        args: cluster::ClusterArgs,
        /// The file to write; `-` for standard output.
        #[arg(short, long)]
        output: PathBuf,
        /// json (OUT.json: files, labels and the method's fields) or csv
        /// (`file,category` rows under that header). Default: csv for an
        /// output named *.csv, else json.
        #[arg(long, value_enum)]
        format: Option<cluster::Format>,
    },
    /// Compare cluster labels with ground truth (file,label CSV).
    Evaluate {
        /// The OUT.json of `placecat cluster`.
        clusters: PathBuf,
        /// `file,label` CSV (header optional). A row matches the scan whose
        /// name (path relative to the inputs' common folder) is its file,
        /// else the scan with its base name when no other scan has that
        /// base name.
        #[arg(long)]
        truth: PathBuf,
    },
    /// DBSCAN over a grid of epsilon x min points (paper Fig. 3): CSV
    /// epsilon,min_points,clusters,inlier_ratio,ari,score.
    Sweep {
        /// The output of `placecat describe`.
        descriptors: PathBuf,
        #[command(flatten)]
        args: cluster::SweepArgs,
        /// CSV file to write (default, or `-`: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Simulate lidar scans with ground truth: PLY scans, poses, labels.csv.
    Simulate {
        /// indoor, warehouse, outdoor, office-floor, school, hospital, hotel,
        /// mall, home, institute, gym.
        #[arg(long)]
        scene: String,
        /// Seeds the scene, the route and the sensor noise.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// indoor: scans per kind (default 40); others: scans along the route (default 300).
        #[arg(long)]
        scans: Option<usize>,
        /// indoor: `one` building (rooms of a kind share a plan, the
        /// default) or `many` (every room drawn over its kind's whole size
        /// range; harder) or `varied` (as many, with mirrored layouts and
        /// L-shaped rooms).
        #[arg(long, default_value = "one")]
        buildings: String,
        /// Scenes of rooms: list the scans in a random order (from the
        /// seed) instead of kind by kind; the same rooms, poses and points.
        /// Order-dependent methods, such as stride seeding, then do not
        /// start from one scan of each kind. Refused for warehouse and
        /// outdoor, whose routes keep their order.
        #[arg(long)]
        shuffle: bool,
        #[command(flatten)]
        sensor: cluster::SensorArgs,
        /// The folder to write the scans, poses.txt, poses_tum.txt and
        /// labels.csv into (created if missing).
        #[arg(short, long)]
        output: PathBuf,
    },
    /// A named model from described scans and a file,name CSV (the page's
    /// "Export CSV" or a labels.csv): one category per name.
    Model {
        /// The output of `placecat describe`.
        descriptors: PathBuf,
        /// `file,name` CSV, matched to the scans as `evaluate --truth` is.
        #[arg(long)]
        names: PathBuf,
        /// The model file (JSON) to write; `-` for standard output.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Put new scans into the named categories of a model (the page's
    /// "Export model"): CSV file,category,distance,relative.
    Classify {
        /// The model: `placecat model`'s output or the page's "Export model".
        model: PathBuf,
        /// Files, folders (searched with their subfolders) and bags, named
        /// as `describe` names them.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// CSV file to write (default, or `-`: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        limits: Limits,
    },
    /// The Delta matrix of described scans, as CSV.
    Distances {
        /// The output of `placecat describe`.
        descriptors: PathBuf,
        /// CSV file to write (default, or `-`: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Draw the trajectory coloured by category, top-down, as SVG (the
    /// page's map): over the scans' points when --scans is given.
    Map {
        #[command(flatten)]
        args: map::MapArgs,
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
    #[command(flatten)]
    lenient: Lenient,
    #[command(flatten)]
    origin: Origin,
}

/// Where the sensor stood, for files whose points are not centred on it.
#[derive(clap::Args)]
struct Origin {
    /// Sensor position X,Y,Z in the files' own coordinates, subtracted from
    /// every point (in float64 for LAS/LAZ, so georeferenced coordinates
    /// keep their millimetres). LAS headers do not record it: a
    /// georeferenced LAS/LAZ is refused without it. Not for E57, whose
    /// scans are each in their scanner's frame.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_origin, allow_hyphen_values = true)]
    origin: Option<[f64; 3]>,
}

fn parse_origin(s: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|c| c.trim().parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(|| format!("{s:?}: X,Y,Z must be three finite numbers"))?;
    v.try_into()
        .map_err(|_| format!("{s:?}: X,Y,Z must be three numbers, comma-separated"))
}

/// How strictly a file's body must match its header.
#[derive(clap::Args)]
struct Lenient {
    /// Read files whose body does not match their header (bytes after the
    /// data that are not padding, PLY elements after the vertices that do
    /// not parse, a PCD WIDTH x HEIGHT that is not POINTS): the points the
    /// header declares are read and nothing after them is checked. Such
    /// files are damaged; their points may be wrong.
    #[arg(long)]
    lenient: bool,
}

impl From<Limits> for describe::ReadOptions {
    fn from(l: Limits) -> Self {
        describe::ReadOptions {
            limits: placecat::io::ReadLimits {
                max_points: l.max_points,
                max_bytes: l.max_bytes,
                lenient: l.lenient.lenient,
            },
            origin: l.origin.origin,
        }
    }
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Info {
            file,
            json,
            lenient,
            origin,
        } => info::run(&file, json, lenient.lenient, origin.origin),
        Command::Describe {
            preset,
            params,
            sensor_height,
            inputs,
            output,
            limits,
            bag,
        } => describe::run(
            preset.as_deref(),
            params.as_deref(),
            sensor_height,
            &inputs,
            &output,
            &limits.into(),
            &bag,
        ),
        Command::Topics { bag, json } => bag::topics(&bag, json),
        Command::Cluster {
            descriptors,
            args,
            output,
            format,
        } => cluster::cluster(&descriptors, &args, &output, format),
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
            shuffle,
            sensor,
            output,
        } => cluster::simulate(&scene, seed, scans, &buildings, shuffle, &sensor, &output),
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
        Command::Map { args } => map::run(&args),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("placecat: {e}");
            ExitCode::FAILURE
        }
    }
}

/// True for the output name `-`: standard output.
pub(crate) fn is_stdout(path: &std::path::Path) -> bool {
    path.as_os_str() == "-"
}

/// How messages name an output: its path, or "standard output" for `-`.
pub(crate) fn shown(path: &std::path::Path) -> String {
    if is_stdout(path) {
        "standard output".into()
    } else {
        path.display().to_string()
    }
}

/// Write text to a file, or to stdout when no path is given or it is `-`.
pub(crate) fn write_out(path: Option<&std::path::Path>, text: &str) -> placecat::Result<()> {
    match path.filter(|p| !is_stdout(p)) {
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

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;

    /// Every subcommand and every argument says what it is in `--help`.
    #[test]
    fn every_argument_has_help_text() {
        let cli = Cli::command();
        let mut missing = Vec::new();
        for sub in cli.get_subcommands() {
            if sub.get_about().is_none() {
                missing.push(sub.get_name().to_string());
            }
            for arg in sub.get_arguments() {
                let id = arg.get_id().as_str();
                if id != "help" && id != "version" && arg.get_help().is_none() {
                    missing.push(format!("{} {id}", sub.get_name()));
                }
            }
        }
        assert!(missing.is_empty(), "no help text: {missing:?}");
    }
}
