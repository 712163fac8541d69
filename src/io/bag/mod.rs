//! ROS bags: ROS 1 `.bag` (format 2.0, chunks uncompressed, bz2 or lz4) and
//! rosbag2 MCAP (chunks uncompressed, lz4 or zstd). A bag holds many clouds;
//! [`BagReader`] yields each cloud of one `sensor_msgs/PointCloud2` topic as
//! a [`RecordedScan`], with its stamp and, where the bag records one, its
//! pose (from `nav_msgs/Odometry` or the tf tree), thinned on request.
//!
//! Streaming: the bag is never read whole. Bytes come through a
//! [`ByteSource`] (a file on disk, or `File.slice` in the page), one record at
//! a time, and at most one decompressed chunk is held beside the connection
//! list, the chunk index and the poses. Poses are read in a first pass over
//! the chunks that hold them, so each cloud gets its pose, interpolated at
//! its stamp, as soon as its chunk is read in the second.
//!
//! Cloud names say where a cloud came from: `BAGNAME:TOPIC:INDEX`, e.g.
//! `run.bag:/points:000042`, where BAGNAME is the bag's file name (no
//! folders), TOPIC the cloud topic and INDEX the cloud's position among all
//! the clouds of that topic (from 0, before thinning, so a name stays the
//! same whatever the thinning), zero-padded to 6 digits or more so that
//! names sort in recording order.
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
mod ros1;
mod rosbag2;
mod source;

pub use source::ByteSource;
#[cfg(not(target_arch = "wasm32"))]
pub use source::FileSource;

use super::poses::Pose;
use super::recording::RecordedScan;
use super::ReadLimits;
use crate::error::{Error, Result};
use layout::{is_type, Item, Layout, Walk, Want};
use pose::{Series, TfTree};
use serde::{Deserialize, Serialize};
use source::Window;
use std::collections::{HashSet, VecDeque};

/// One topic of a bag.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct TopicInfo {
    pub name: String,
    /// The message type as the bag writes it (`sensor_msgs/PointCloud2`,
    /// `sensor_msgs/msg/PointCloud2`).
    #[serde(rename = "type")]
    pub msgtype: String,
    /// Number of messages.
    pub count: u64,
}

/// Where the clouds' poses come from.
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
    Ok(Bag::open(src, file).map_err(|e| e.in_file(file))?.topics())
}

/// Where poses come from once the first pass is done.
enum Poses {
    None,
    Odometry(Series),
    /// The tree, the frame asked for (None: each cloud's frame), the tf
    /// topic (for messages), and whether a missing frame is an error.
    Tf(TfTree, Option<String>, String, bool),
}

/// Reads the clouds of one topic of a bag, in recording order; see the
/// module documentation. Iterate it: each item is a cloud, or an error
/// about one cloud or chunk, after which the iteration goes on.
pub struct BagReader<S> {
    bag: Bag<S>,
    opts: BagOptions,
    topic: String,
    cloud_ids: Vec<u32>,
    walker: Walker<S>,
    poses: Poses,
    bag_name: String,
    width: usize,
    index: usize,
    /// Path length (metres) at the last cloud, and at the last kept one.
    path: f64,
    last_position: Option<[f64; 3]>,
    kept_at: Option<f64>,
    queued: VecDeque<Error>,
    missing_frames: HashSet<String>,
}

#[cfg(not(target_arch = "wasm32"))]
impl BagReader<FileSource> {
    /// Open a bag on disk; errors name the path.
    pub fn open_path(path: &std::path::Path, opts: BagOptions) -> Result<Self> {
        let file = path.display().to_string();
        let src = FileSource::open(path).map_err(|e| e.in_file(&file))?;
        BagReader::open(src, &file, opts)
    }
}

/// [`topics`] of a bag on disk.
#[cfg(not(target_arch = "wasm32"))]
pub fn topics_path(path: &std::path::Path) -> Result<Vec<TopicInfo>> {
    let file = path.display().to_string();
    topics(FileSource::open(path).map_err(|e| e.in_file(&file))?, &file)
}

impl<S: ByteSource + 'static> BagReader<S> {
    /// Open a bag: read its index or summary, choose the cloud topic, read
    /// the poses. `file` names the bag in errors and (its last component) in
    /// cloud names. Fails when no cloud topic can be chosen; everything
    /// after that is reported per cloud by the iterator.
    pub fn open(src: S, file: &str, opts: BagOptions) -> Result<Self> {
        Self::open_inner(src, file, opts).map_err(|e| e.in_file(file))
    }

    fn open_inner(src: S, file: &str, opts: BagOptions) -> Result<Self> {
        if opts.every == 0 {
            return crate::error::invalid("every must be at least 1 (1 keeps every cloud)");
        }
        if let Some(d) = opts.every_metres {
            if !(d.is_finite() && d > 0.0) {
                return crate::error::invalid(format!(
                    "every-metres must be a distance > 0, not {d}"
                ));
            }
        }
        let bag = Bag::open(src, file)?;
        let topics = bag.topics();
        let topic = match &opts.topic {
            Some(t) => {
                let info = topics.iter().find(|i| &i.name == t).ok_or_else(|| {
                    Error::Bag(format!("no topic {t} in the bag; {}", bag.list()))
                })?;
                if !is_cloud(&info.msgtype) {
                    return Err(Error::Bag(format!(
                        "topic {t} is {}, not sensor_msgs/PointCloud2",
                        info.msgtype
                    )));
                }
                t.clone()
            }
            None => {
                let clouds: Vec<&TopicInfo> =
                    topics.iter().filter(|i| is_cloud(&i.msgtype)).collect();
                match clouds.as_slice() {
                    [one] => one.name.clone(),
                    [] => {
                        return Err(Error::Bag(format!(
                            "no sensor_msgs/PointCloud2 topic; {}",
                            bag.list()
                        )))
                    }
                    many => {
                        let names: Vec<&str> = many.iter().map(|i| i.name.as_str()).collect();
                        return Err(Error::Bag(format!(
                            "{} PointCloud2 topics ({}): choose one with --topic",
                            many.len(),
                            names.join(", ")
                        )));
                    }
                }
            }
        };
        let count = topics
            .iter()
            .find(|i| i.name == topic)
            .map_or(0, |i| i.count);
        let cloud_ids = bag.ids(|c| c.topic == topic);
        let bag_name = file.rsplit(['/', '\\']).next().unwrap_or(file).to_string();
        let walker = bag.walker();
        let mut reader = BagReader {
            bag,
            opts,
            topic,
            cloud_ids,
            walker,
            poses: Poses::None,
            bag_name,
            width: count.saturating_sub(1).to_string().len().max(6),
            index: 0,
            path: 0.0,
            last_position: None,
            kept_at: None,
            queued: VecDeque::new(),
            missing_frames: HashSet::new(),
        };
        reader.read_poses()?;
        if reader.opts.every_metres.is_some() && matches!(reader.poses, Poses::None) {
            return crate::error::invalid(format!(
                "--every-metres needs poses, and the bag has none to use (no \
                 nav_msgs/Odometry or tf topic chosen); {}",
                reader.bag.list()
            ));
        }
        Ok(reader)
    }

    /// The cloud topic being read.
    pub fn topic(&self) -> &str {
        &self.topic
    }

    /// The pose topics chosen by the options, and the first pass over them.
    fn read_poses(&mut self) -> Result<()> {
        let topics = self.bag.topics();
        let odom: Vec<&TopicInfo> = topics.iter().filter(|t| is_odometry(&t.msgtype)).collect();
        let tf: Vec<&TopicInfo> = topics.iter().filter(|t| is_tf(&t.msgtype)).collect();
        let tf_name = tf
            .iter()
            .find(|t| t.name == "/tf")
            .or(tf.first())
            .map(|t| t.name.clone());
        let (pose_topic, tf_frame, strict) = match &self.opts.pose {
            PoseSource::None => return Ok(()),
            PoseSource::Auto => match (odom.as_slice(), &tf_name) {
                ([one], _) => (one.name.clone(), None, false),
                (_, Some(t)) => (t.clone(), None, false),
                _ => return Ok(()),
            },
            PoseSource::Topic(t) => {
                let info = topics.iter().find(|i| &i.name == t).ok_or_else(|| {
                    Error::Bag(format!("no pose topic {t} in the bag; {}", self.bag.list()))
                })?;
                if !is_odometry(&info.msgtype) && !is_tf(&info.msgtype) {
                    return Err(Error::Bag(format!(
                        "pose topic {t} is {}, not nav_msgs/Odometry or tf2_msgs/TFMessage",
                        info.msgtype
                    )));
                }
                (t.clone(), None, true)
            }
            PoseSource::TfFrame(f) => {
                let t = tf_name.clone().ok_or_else(|| {
                    Error::Bag(format!(
                        "no tf topic (tf2_msgs/TFMessage) for frame {f:?}; {}",
                        self.bag.list()
                    ))
                })?;
                (t, Some(msg::frame(f)), true)
            }
        };
        let is_odom = odom.iter().any(|t| t.name == pose_topic);
        // tf: every tf topic together, so /tf_static's fixed sensor mounts chain in.
        let ids = if is_odom {
            self.bag.ids(|c| c.topic == pose_topic)
        } else {
            self.bag.ids(|c| is_tf(&c.msgtype))
        };
        let mut series = Series::default();
        let mut tree = TfTree::default();
        let mut walker = self.bag.walker();
        let max = self.bag.max_chunk();
        let mut bad = 0usize;
        let mut first_bad = None;
        while let Some(item) = walker.next(
            &mut self.bag.win,
            &Want {
                layout: &self.bag.layout,
                wanted: &|id| ids.contains(&id),
                max_chunk: max,
            },
        ) {
            // Chunk errors are reported by the cloud pass, not twice.
            let Ok(Item::Msg { conn, range, .. }) = item else {
                continue;
            };
            let Some(c) = self.bag.layout.conn(conn).filter(|_| ids.contains(&conn)) else {
                continue;
            };
            let data = &walker.chunk()[range];
            let res = if is_odom {
                msg::odometry(data, c.enc).map(|t| series.push(t.stamp, t.iso))
            } else {
                msg::tf_message(data, c.enc).map(|ts| ts.into_iter().for_each(|t| tree.add(t)))
            };
            if let Err(e) = res {
                bad += 1;
                first_bad.get_or_insert((c.topic.clone(), message(e)));
            }
        }
        self.bag.win.shrink();
        if let Some((topic, e)) = first_bad {
            self.queued.push_back(Error::Bag(format!(
                "topic {topic}: {bad} pose message(s) cannot be read, the first: {e}"
            )));
        }
        series.finish();
        tree.finish();
        self.poses = if is_odom {
            Poses::Odometry(series)
        } else {
            if let (Some(f), true) = (&tf_frame, strict) {
                self.check_frame(&tree, f, &pose_topic);
            }
            Poses::Tf(tree, tf_frame, pose_topic, strict)
        };
        Ok(())
    }

    /// Queue (once per frame) the error of a tf tree without `frame`.
    fn check_frame(&mut self, tree: &TfTree, frame: &str, topic: &str) -> bool {
        if tree.has(frame) {
            return true;
        }
        if self.missing_frames.insert(frame.to_string()) {
            self.queued.push_back(Error::Bag(format!(
                "topic {topic}: the tf tree has no frame {frame:?} (frames: {}); clouds get no pose",
                tree.frames().join(", ")
            )));
        }
        false
    }

    /// The pose at `stamp` of the cloud in `frame_id`.
    fn pose_at(&mut self, stamp: f64, frame_id: &str) -> Option<nalgebra::Isometry3<f64>> {
        let poses = std::mem::replace(&mut self.poses, Poses::None);
        let iso = match &poses {
            Poses::None => None,
            Poses::Odometry(s) => s.at(stamp),
            Poses::Tf(tree, frame, topic, strict) => {
                let f = frame.clone().unwrap_or_else(|| msg::frame(frame_id));
                if *strict && !self.check_frame(tree, &f, topic) {
                    None
                } else {
                    tree.at(&f, stamp)
                }
            }
        };
        self.poses = poses;
        iso
    }

    fn cloud_error(&self, index: usize, e: Error) -> Error {
        Error::Bag(format!(
            "topic {}: cloud {} ({}): {}",
            self.topic,
            index,
            self.name(index),
            message(e)
        ))
        .in_file(&self.bag.file)
    }

    fn name(&self, index: usize) -> String {
        format!(
            "{}:{}:{:0w$}",
            self.bag_name,
            self.topic,
            index,
            w = self.width
        )
    }

    /// One cloud message: thin, then decode. None when thinned out.
    fn cloud(
        &mut self,
        range: std::ops::Range<usize>,
        enc: msg::Encoding,
        time: f64,
    ) -> Option<Result<RecordedScan>> {
        let index = self.index;
        self.index += 1;
        let head = match cloud::header(&self.walker.chunk()[range.clone()], enc) {
            Ok(h) => (h.stamp, h.frame_id),
            Err(e) => return Some(Err(self.cloud_error(index, e))),
        };
        // Some drivers leave the header stamp at 0: fall back to the log time.
        let stamp = if head.0 > 0.0 { head.0 } else { time };
        let iso = self.pose_at(stamp, &head.1);
        let position = iso.map(|i| i.translation.vector.into());
        if let (Some(p), Some(q)) = (position, self.last_position) {
            let d: [f64; 3] = p;
            self.path +=
                ((d[0] - q[0]).powi(2) + (d[1] - q[1]).powi(2) + (d[2] - q[2]).powi(2)).sqrt();
        }
        if position.is_some() {
            self.last_position = position;
        }
        if index % self.opts.every != 0 {
            return None;
        }
        if let (Some(d), Some(_)) = (self.opts.every_metres, position) {
            if self.kept_at.is_some_and(|k| self.path - k < d) {
                return None;
            }
            self.kept_at = Some(self.path);
        }
        let name = self.name(index);
        let msg = cloud::header(&self.walker.chunk()[range], enc).expect("decoded above");
        let points = match msg.points(&self.opts.limits) {
            Ok(p) => p,
            Err(e) => return Some(Err(self.cloud_error(index, e))),
        };
        let pose = iso.map(|i| Pose {
            name: Some(name.clone()),
            time: Some(stamp),
            position: i.translation.vector.into(),
            yaw: pose::yaw(&i),
        });
        Some(Ok(RecordedScan {
            name,
            points,
            stamp: Some(stamp),
            pose,
        }))
    }
}

impl<S: ByteSource + 'static> Iterator for BagReader<S> {
    type Item = Result<RecordedScan>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(e) = self.queued.pop_front() {
                return Some(Err(e.in_file(&self.bag.file)));
            }
            let max = self.opts.limits.max_bytes;
            let ids = &self.cloud_ids;
            let item = self.walker.next(
                &mut self.bag.win,
                &Want {
                    layout: &self.bag.layout,
                    wanted: &|id| ids.contains(&id),
                    max_chunk: max,
                },
            )?;
            match item {
                Err(e) => {
                    return Some(Err(Error::Bag(format!(
                        "topic {}: {}",
                        self.topic,
                        message(e)
                    ))
                    .in_file(&self.bag.file)))
                }
                Ok(Item::Conn(c)) => {
                    if c.topic == self.topic && !self.cloud_ids.contains(&c.id) {
                        self.cloud_ids.push(c.id);
                    }
                    self.bag.layout.add(c);
                }
                Ok(Item::Lost { conn, count }) if self.cloud_ids.contains(&conn) => {
                    self.index += count as usize;
                }
                Ok(Item::Msg { conn, time, range }) if self.cloud_ids.contains(&conn) => {
                    let enc = self
                        .bag
                        .layout
                        .conn(conn)
                        .map_or(msg::Encoding::Ros1, |c| c.enc);
                    if let Some(r) = self.cloud(range, enc, time) {
                        return Some(r);
                    }
                }
                Ok(_) => {}
            }
        }
    }
}
