//! ROS bags on the command line: `placecat topics BAG` and the bag inputs of
//! `placecat describe` (each cloud of the chosen topic is one scan, named
//! `BAG:TOPIC:INDEX` by the bag's path relative to the inputs' root).

use super::describe::{DescribedFile, DescriptorsFile, FileError, ScanPose};
use super::names::Input;
use super::progress;
use placecat::descriptor::DescriptorParams;
use placecat::io::bag::{topics_path, BagOptions, BagReader, PoseSource};
use placecat::io::ReadLimits;
use placecat::Result;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// How `describe` reads ROS bags (`.bag`, `.mcap`); no effect on other files.
#[derive(clap::Args, Debug, Default)]
pub struct BagArgs {
    /// Bags: the sensor_msgs/PointCloud2 topic to read (default: the bag's
    /// only PointCloud2 topic; `placecat topics BAG` lists them).
    #[arg(long)]
    pub topic: Option<String>,
    /// Bags: keep every Nth cloud of the topic (1 = all).
    #[arg(long, default_value_t = 1, conflicts_with = "every_metres")]
    pub every: usize,
    /// Bags: keep one cloud every D metres along the recorded path (needs
    /// poses: an odometry or tf topic).
    #[arg(long, value_name = "D")]
    pub every_metres: Option<f64>,
    /// Bags: poses from this nav_msgs/Odometry or tf topic (default: the
    /// only odometry topic, else /tf at each cloud's frame).
    #[arg(long, value_name = "T", conflicts_with_all = ["tf_frame", "no_poses"])]
    pub pose_topic: Option<String>,
    /// Bags: poses of this tf frame (e.g. base_link), chained through /tf and
    /// /tf_static; a tree without it is reported and the clouds kept.
    #[arg(long, value_name = "F", conflicts_with = "no_poses")]
    pub tf_frame: Option<String>,
    /// Bags: read no poses.
    #[arg(long)]
    pub no_poses: bool,
    /// Bags and E57 surveys: write the poses of the described clouds and
    /// stations (name,x,y,z CSV, the form the map reads) to this file.
    /// OUT.json holds them too, as each scan's `pose`.
    #[arg(long, value_name = "FILE")]
    pub poses_out: Option<PathBuf>,
}

impl BagArgs {
    fn options(&self, limits: &ReadLimits) -> BagOptions {
        let pose = match (&self.pose_topic, &self.tf_frame, self.no_poses) {
            (_, _, true) => PoseSource::None,
            (Some(t), _, _) => PoseSource::Topic(t.clone()),
            (_, Some(f), _) => PoseSource::TfFrame(f.clone()),
            _ => PoseSource::Auto,
        };
        BagOptions {
            topic: self.topic.clone(),
            every: self.every,
            every_metres: self.every_metres,
            pose,
            limits: *limits,
        }
    }
}

/// True for the names `describe` reads as bags (and `.db3`, which it
/// refuses with [`unsupported`]: so a rosbag2 folder of SQLite storage is
/// said to be one, not passed over as holding no scans).
pub fn is_bag(path: &Path) -> bool {
    placecat::io::bag::is_bag_name(&path.to_string_lossy())
}

/// Why a bag cannot be read before it is opened (the core's rule).
fn unsupported(path: &Path) -> Option<placecat::Error> {
    placecat::io::bag::unsupported_storage(&path.to_string_lossy())
}

/// `placecat topics BAG`: one line per topic (name, type, count), or JSON.
pub fn topics(bag: &Path, json: bool) -> Result<ExitCode> {
    if let Some(e) = unsupported(bag) {
        return Err(e);
    }
    let list = topics_path(bag)?;
    let text = if json {
        serde_json::to_string_pretty(&list)? + "\n"
    } else {
        let w = list.iter().map(|t| t.name.len()).max().unwrap_or(5).max(5);
        let v = list
            .iter()
            .map(|t| t.msgtype.len())
            .max()
            .unwrap_or(4)
            .max(4);
        let mut s = format!("{:w$}  {:v$}  count\n", "topic", "type");
        for t in &list {
            s += &format!("{:w$}  {:v$}  {}\n", t.name, t.msgtype, t.count);
        }
        s
    };
    super::write_out(None, &text)?;
    Ok(ExitCode::SUCCESS)
}

/// Describe the clouds of each bag into `set`, a few at a time in
/// parallel (memory holds a batch of clouds, not the bag). A bag that
/// cannot be opened, a cloud or chunk that cannot be read, and a cloud
/// without descriptor each go to `set.errors` and stderr.
pub fn describe(
    bags: &[Input],
    args: &BagArgs,
    limits: &ReadLimits,
    set: &mut DescriptorsFile,
) -> Result<()> {
    let opts = args.options(limits);
    for input in bags {
        let bag = input.path.as_path();
        let shown = bag.display().to_string();
        let opened = match unsupported(bag) {
            Some(e) => Err(e),
            // Clouds are named `RELATIVE_PATH:TOPIC:INDEX` (their poses
            // and errors too), so two `run.bag` in different folders keep
            // apart.
            None => BagReader::open_path(bag, opts.clone()).map(|r| r.with_prefix(&input.name)),
        };
        let mut reader = match opened {
            Ok(r) => r,
            Err(e) => {
                eprintln!("skipped {e}");
                set.errors.push(FileError {
                    file: shown,
                    error: e.to_string(),
                });
                continue;
            }
        };
        let bar = progress::bar(reader.topic_len(), "describing bag clouds");
        let batch_len = 2 * rayon::current_num_threads();
        loop {
            let mut batch = Vec::with_capacity(batch_len);
            for item in reader.by_ref() {
                match item {
                    Ok(scan) => batch.push(scan),
                    Err(e) => {
                        eprintln!("skipped {e}");
                        set.errors.push(FileError {
                            file: shown.clone(),
                            error: e.to_string(),
                        });
                    }
                }
                if batch.len() == batch_len {
                    break;
                }
            }
            if batch.is_empty() {
                break;
            }
            let params: &DescriptorParams = &set.params;
            let described: Vec<_> = batch
                .into_par_iter()
                .map(|scan| {
                    placecat::describe(&scan.points, params)
                        .map(|descriptor| DescribedFile {
                            name: scan.name.clone(),
                            path: shown.clone(),
                            descriptor,
                            pose: scan.pose.as_ref().map(ScanPose::from),
                        })
                        .map_err(|e| FileError {
                            file: shown.clone(),
                            error: e.in_file(&scan.name).to_string(),
                        })
                })
                .collect();
            for d in described {
                match d {
                    Ok(f) => set.files.push(f),
                    Err(e) => {
                        eprintln!("skipped {}", e.error);
                        set.errors.push(e);
                    }
                }
            }
            bar.set_position(reader.clouds_met());
        }
        bar.finish_and_clear();
    }
    Ok(())
}
