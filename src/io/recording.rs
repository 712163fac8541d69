//! Scans that come many to a file: ROS bags (a cloud topic), E57 surveys (a
//! scan per station). Each carries a name that says where it came from and,
//! where the recording holds one, its time stamp and pose, so that the map
//! and the thinning along the path need no separate poses file.

use super::poses::Pose;
#[cfg(not(target_arch = "wasm32"))]
use crate::error::{Error, Result};

/// One scan taken out of a recording.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordedScan {
    /// Where the scan came from, unique within the recording: e.g.
    /// `run.bag:/points:000042` or `survey.e57:scan 3`.
    pub name: String,
    /// Points in the sensor frame (as the descriptor needs), file order,
    /// non-finite points included as in [`crate::PointCloud`].
    pub points: Vec<[f32; 3]>,
    /// Time stamp in seconds, where the recording has one.
    pub stamp: Option<f64>,
    /// Pose of the sensor in the recording's world frame, where known.
    pub pose: Option<Pose>,
}

/// A recording on disk opened for reading one scan at a time: a ROS bag's
/// cloud topic or an E57 survey's stations (native only; the page reads
/// both through [`super::source::ByteSource`]s of its own). Iterate it:
/// each item is a scan, or an error naming the file and the scan, after
/// which the iteration goes on.
#[cfg(not(target_arch = "wasm32"))]
pub enum Recording {
    /// A ROS 1 `.bag` or rosbag2 `.mcap`, one cloud topic.
    Bag(Box<super::bag::BagReader<super::bag::FileSource>>),
    /// An E57 survey, read through a buffer.
    Survey(Box<super::e57::SurveyScans<std::io::BufReader<std::fs::File>>>),
}

#[cfg(not(target_arch = "wasm32"))]
impl Recording {
    /// Open `path`: an E57 survey by its signature (whatever its name), a
    /// bag by its name (`.bag`, `.mcap`). `opts` chooses a bag's topic and
    /// thinning; a survey is read station by station, so a topic or a
    /// thinning for it is an error, as is a file that is neither, or
    /// rosbag2's SQLite storage. Errors name the path; the scans are named
    /// after the file's base name, a bag's clouds `run.bag:/points:000042`
    /// and a survey's stations `site.e57:hall`.
    pub fn open_path(path: &std::path::Path, opts: super::bag::BagOptions) -> Result<Self> {
        Self::open_path_as(path, None, opts)
    }

    /// [`open_path`](Self::open_path), the scans (and their poses) named
    /// after `prefix` in place of the file's base name when it is given,
    /// e.g. the recording's path under a folder, so that recordings of one
    /// name in different folders keep apart; errors still name the path.
    pub fn open_path_as(
        path: &std::path::Path,
        prefix: Option<&str>,
        opts: super::bag::BagOptions,
    ) -> Result<Self> {
        use std::io::{Read, Seek};
        let name = path.display().to_string();
        let in_file = |e: std::io::Error| Error::from(e).in_file(&name);
        let mut file = std::fs::File::open(path).map_err(in_file)?;
        let mut head = [0u8; 8];
        let is_e57 = file.read_exact(&mut head).is_ok() && super::e57::looks_like_e57(&head);
        if is_e57 {
            if opts.topic.is_some() || opts.every != 1 || opts.every_metres.is_some() {
                return Err(Error::InvalidParameter(
                    "an E57 survey is read station by station; a topic, every and \
                     every_metres are a bag's"
                        .into(),
                )
                .in_file(&name));
            }
            // The sniff moved the file on; the survey's header is read from byte 0.
            file.rewind().map_err(in_file)?;
            let reader = std::io::BufReader::with_capacity(1 << 20, file);
            let prefix = prefix.unwrap_or_else(|| super::base_name(&name));
            let scans = super::e57::SurveyScans::open_as(reader, &name, prefix, opts.limits)?;
            return Ok(Recording::Survey(Box::new(scans)));
        }
        // A .db3 too: opening refuses it with the core's message.
        if super::bag::is_bag_name(&name) {
            let mut reader = super::bag::BagReader::open_path(path, opts)?;
            if let Some(prefix) = prefix {
                reader = reader.with_prefix(prefix);
            }
            return Ok(Recording::Bag(Box::new(reader)));
        }
        if name.to_ascii_lowercase().ends_with(".e57") {
            return Err(
                Error::E57("not an E57 file (no E57 signature at its start)".into()).in_file(&name),
            );
        }
        Err(Error::InvalidParameter(
            "not a recording (an E57 survey, a ROS .bag or a rosbag2 .mcap: a rosbag2 folder \
             is read through its .mcap files); a scan file is read whole"
                .into(),
        )
        .in_file(&name))
    }

    /// Scans in the recording: a bag's clouds on its topic (before
    /// thinning), a survey's stations.
    pub fn total(&self) -> u64 {
        match self {
            Recording::Bag(b) => b.topic_len(),
            Recording::Survey(s) => s.len() as u64,
        }
    }

    /// Scans met so far, kept or not, read or not.
    pub fn met(&self) -> u64 {
        match self {
            Recording::Bag(b) => b.clouds_met(),
            Recording::Survey(s) => s.met() as u64,
        }
    }

    /// The cloud topic read (a bag), or None (a survey).
    pub fn topic(&self) -> Option<&str> {
        match self {
            Recording::Bag(b) => Some(b.topic()),
            Recording::Survey(_) => None,
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl Iterator for Recording {
    type Item = Result<RecordedScan>;

    fn next(&mut self) -> Option<Self::Item> {
        match self {
            Recording::Bag(b) => b.next(),
            Recording::Survey(s) => s.next(),
        }
    }
}
