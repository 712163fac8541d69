//! ROS bags: ROS 1 `.bag` (format 2.0, chunks uncompressed, bz2 or lz4) and
//! rosbag2 MCAP (chunks uncompressed, lz4 or zstd). A bag holds many clouds;
//! [`BagReader`] yields each cloud of one `sensor_msgs/PointCloud2` topic as
//! a [`RecordedScan`](crate::io::recording::RecordedScan), with its stamp and, where the bag records one, its
//! pose (from `nav_msgs/Odometry` or the tf tree), thinned on request.
//!
//! Streaming: the bag is never read whole. Bytes come through a
//! [`ByteSource`] (a file on disk, or `File.slice` in the page), one record at
//! a time, and at most one decompressed chunk is held beside the connection
//! list, the chunk index, the poses and the few clouds waiting for the pose
//! message after their stamp (clouds and poses come in one pass).
//!
//! Cloud names say where a cloud came from: `BAGNAME:TOPIC:INDEX`, e.g.
//! `run.bag:/points:000042`, where BAGNAME is the bag's file name (no
//! folders), TOPIC the cloud topic and INDEX the cloud's position among all
//! the clouds of that topic (from 0, before thinning, so a name stays the
//! same whatever the thinning), zero-padded to 6 digits or more so that
//! names sort in recording order.
//!
//! In the page, a [`ByteSource`] over a `File` is a worker's
//! `FileReaderSync.readAsArrayBuffer(file.slice(offset, offset + len))`:
//! reads are at most one chunk record or 1 MiB, in file order but for the
//! index or summary read first at the end of the file.
//!
//! Report and skip: a chunk that is cut short or compressed in an unknown
//! way, a cloud without x/y/z, a tf tree without the chosen frame, each comes
//! out of the iterator as an `Err` naming the file and the topic, and the
//! iteration goes on with the other clouds.

mod cloud;
mod compress;
mod layout;
mod msg;
mod pose;
mod reader;
mod ros1;
mod rosbag2;

pub use super::source::ByteSource;
#[cfg(not(target_arch = "wasm32"))]
pub use super::source::FileSource;
pub use reader::BagReader;

use super::source::Window;
use super::ReadLimits;
use crate::error::{Error, Result};
use layout::{is_type, Item, Layout, Walk, Want};
use serde::{Deserialize, Serialize};

/// True for a file name of a ROS bag: ROS 1 `.bag`, rosbag2 `.mcap`, and
/// rosbag2's SQLite `.db3`, which opening refuses with
/// [`unsupported_storage`]'s message (so a folder of them is said to hold
/// bags placecat cannot read, not passed over as holding no scans).
pub fn is_bag_name(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    [".bag", ".mcap", ".db3"]
        .iter()
        .any(|ext| lower.ends_with(ext))
}

/// Why a bag cannot be read before it is opened: rosbag2's SQLite storage
/// (`.db3`), named by `name`. A rosbag2 folder (metadata.yaml and its
/// storage files) is read through its `.mcap` files; `.db3` files would
/// need SQLite, which placecat does not carry.
pub fn unsupported_storage(name: &str) -> Option<Error> {
    name.to_ascii_lowercase().ends_with(".db3").then(|| {
        Error::Bag(
            "rosbag2 SQLite storage (.db3) is not read, only MCAP: convert the bag \
             (`ros2 bag convert` with storage_id: mcap) and read its .mcap files"
                .into(),
        )
        .in_file(name)
    })
}

/// One topic of a bag.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct TopicInfo {
    /// The topic name, e.g. `/os_cloud_node/points`.
    pub name: String,
    /// The message type as the bag writes it (`sensor_msgs/PointCloud2`,
    /// `sensor_msgs/msg/PointCloud2`).
    #[serde(rename = "type")]
    pub msgtype: String,
    /// Number of messages.
    pub count: u64,
}

/// Where the clouds' poses come from. The points stay in the cloud's own
/// frame (the sensor's, as the descriptor needs); the pose says where that
/// frame was (with tf: the cloud's `frame_id` unless a frame is chosen; with
/// odometry: its child frame, usually `base_link`), for the map and the
/// thinning along the path.
#[derive(Debug, Clone, Default, PartialEq)]
pub enum PoseSource {
    /// The only `nav_msgs/Odometry` topic if there is exactly one, else the
    /// tf tree at each cloud's frame when the tree has that frame, else none.
    #[default]
    Auto,
    /// No poses.
    None,
    /// This topic: a `nav_msgs/Odometry` topic, or a tf topic (then the pose
    /// of each cloud's `frame_id`).
    Topic(String),
    /// The tf tree (every `tf2_msgs/TFMessage` topic, `/tf` and `/tf_static`)
    /// chained from its root to this frame, e.g. `base_link`.
    TfFrame(String),
}

/// What to read from a bag.
#[derive(Debug, Clone, PartialEq)]
pub struct BagOptions {
    /// The cloud topic; by default the bag's only PointCloud2 topic.
    pub topic: Option<String>,
    /// Keep every Nth cloud (1 = all).
    pub every: usize,
    /// Keep one cloud every this many metres along the path (needs poses;
    /// a cloud without a pose is kept).
    pub every_metres: Option<f64>,
    /// Where each cloud's pose comes from (odometry, tf, or none).
    pub pose: PoseSource,
    /// `max_points` caps each cloud; `max_bytes` each chunk (not the bag).
    pub limits: ReadLimits,
}

impl Default for BagOptions {
    fn default() -> Self {
        BagOptions {
            topic: None,
            every: 1,
            every_metres: None,
            pose: PoseSource::Auto,
            limits: ReadLimits::default(),
        }
    }
}

/// The text of a bag error without its "ROS bag:" prefix, for nesting.
pub(crate) fn message(e: Error) -> String {
    match e {
        Error::Bag(m) => m,
        other => other.to_string(),
    }
}

type Walker<S> = Box<dyn Walk<S>>;

/// An opened bag: its bytes, format and layout.
struct Bag<S> {
    file: String,
    win: Window<S>,
    ros1: bool,
    layout: Layout,
    data: (u64, u64),
}

impl<S: ByteSource + 'static> Bag<S> {
    fn open(src: S, file: &str) -> Result<Self> {
        let mut win = Window::new(src);
        let size = win.size();
        let head = win.get(0, size.min(13), "file start")?;
        let (ros1, (layout, data)) = if head.starts_with(ros1::MAGIC) {
            let (layout, start, end) = ros1::open(&mut win)?;
            (true, (layout, (start, end)))
        } else if head.starts_with(rosbag2::MAGIC) {
            let (layout, end) = rosbag2::open(&mut win)?;
            (false, (layout, (rosbag2::MAGIC.len() as u64, end)))
        } else {
            return Err(Error::Bag(
                "not a ROS bag: neither \"#ROSBAG V2.0\" (ROS 1) nor the MCAP magic \
                 (rosbag2) at the start"
                    .into(),
            ));
        };
        let mut bag = Bag {
            file: file.to_string(),
            win,
            ros1,
            layout,
            data,
        };
        if !bag.layout.indexed {
            bag.count_messages();
        }
        Ok(bag)
    }

    fn walker(&self) -> Walker<S> {
        let (start, end) = self.data;
        if self.ros1 {
            Box::new(ros1::Walker::new(start, end))
        } else {
            Box::new(rosbag2::Walker::new(start, end))
        }
    }

    /// A bag without index or summary: one pass over the chunks to learn the
    /// connections and count their messages. Unreadable chunks are skipped
    /// here; the pass that reads clouds reports them.
    fn count_messages(&mut self) {
        let mut w = self.walker();
        let max = self.max_chunk();
        let mut layout = std::mem::take(&mut self.layout);
        layout.counts.clear();
        while let Some(item) = w.next(
            &mut self.win,
            &Want {
                layout: &layout,
                wanted: &|_| true,
                max_chunk: max,
            },
        ) {
            match item {
                Ok(Item::Conn(c)) => layout.add(c),
                Ok(Item::Msg { conn, .. }) => *layout.counts.entry(conn).or_default() += 1,
                _ => {}
            }
        }
        self.layout = layout;
    }

    fn max_chunk(&self) -> usize {
        ReadLimits::default().max_bytes
    }

    fn topics(&self) -> Vec<TopicInfo> {
        let mut v: Vec<TopicInfo> = Vec::new();
        for c in &self.layout.conns {
            let n = self.layout.counts.get(&c.id).copied().unwrap_or(0);
            match v.iter_mut().find(|t| t.name == c.topic) {
                Some(t) => t.count += n,
                None => v.push(TopicInfo {
                    name: c.topic.clone(),
                    msgtype: c.msgtype.clone(),
                    count: n,
                }),
            }
        }
        v.sort_by(|a, b| a.name.cmp(&b.name));
        v
    }

    fn ids(&self, keep: impl Fn(&layout::Conn) -> bool) -> Vec<u32> {
        self.layout
            .conns
            .iter()
            .filter(|c| keep(c))
            .map(|c| c.id)
            .collect()
    }

    fn list(&self) -> String {
        let t = self.topics();
        if t.is_empty() {
            return "the bag has no topics".into();
        }
        let v: Vec<String> = t
            .iter()
            .map(|t| format!("{} ({})", t.name, t.msgtype))
            .collect();
        format!("topics: {}", v.join(", "))
    }
}

fn is_cloud(t: &str) -> bool {
    is_type(t, "sensor_msgs", "PointCloud2")
}
fn is_odometry(t: &str) -> bool {
    is_type(t, "nav_msgs", "Odometry")
}
fn is_tf(t: &str) -> bool {
    is_type(t, "tf2_msgs", "TFMessage") || is_type(t, "tf", "tfMessage")
}

/// The topics of a bag, sorted by name, with their types and message counts.
/// Reads only the index (ROS 1) or summary (MCAP) when the bag has one.
pub fn topics<S: ByteSource + 'static>(src: S, file: &str) -> Result<Vec<TopicInfo>> {
    if let Some(e) = unsupported_storage(file) {
        return Err(e);
    }
    Ok(Bag::open(src, file).map_err(|e| e.in_file(file))?.topics())
}

/// [`topics`] of a bag on disk.
#[cfg(not(target_arch = "wasm32"))]
pub fn topics_path(path: &std::path::Path) -> Result<Vec<TopicInfo>> {
    let file = path.display().to_string();
    topics(FileSource::open(path).map_err(|e| e.in_file(&file))?, &file)
}
