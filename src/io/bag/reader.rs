//! [`BagReader`]: the clouds of one topic, in one pass over the chunks.
//!
//! Clouds and poses are read in the same pass. A cloud waits (decoded) until
//! a pose message stamped at or after it has been read, so its pose is
//! interpolated between the two around it; at most [`MAX_WAITING`] clouds
//! wait, so a pose topic that stops early cannot make memory grow.

use super::layout::{Item, Want};
use super::pose::{self, Poses, Series, TfPoses, TfTree};
use super::{cloud, is_cloud, is_odometry, is_tf, message, msg, Bag, BagOptions, ByteSource};
use super::{PoseSource, TopicInfo, Walker};
use crate::error::{invalid, Error, Result};
use crate::io::poses::Pose;
use crate::io::recording::RecordedScan;
use std::collections::{HashSet, VecDeque};

/// Clouds held at most while waiting for the pose after their stamp.
const MAX_WAITING: usize = 8;

/// A decoded cloud waiting for its pose.
struct Waiting {
    index: usize,
    stamp: f64,
    frame: String,
    points: Vec<[f32; 3]>,
}

/// Reads the clouds of one topic of a bag, in recording order; see the
/// module documentation of [`crate::io::bag`]. Iterate it: each item is a
/// cloud, or an error about one cloud, chunk or pose topic, after which the
/// iteration goes on.
pub struct BagReader<S> {
    bag: Bag<S>,
    opts: BagOptions,
    topic: String,
    cloud_ids: Vec<u32>,
    walker: Walker<S>,
    poses: Poses,
    bag_name: String,
    /// Clouds in the topic (before thinning), from the index or a count.
    count: u64,
    width: usize,
    /// Index of the next cloud message of the topic.
    index: usize,
    waiting: VecDeque<Waiting>,
    done: bool,
    /// Path length (metres) at the last emitted cloud, and at the last kept.
    path: f64,
    last_position: Option<[f64; 3]>,
    kept_at: Option<f64>,
    queued: VecDeque<Error>,
    missing_frames: HashSet<String>,
    bad_pose: bool,
}

#[cfg(not(target_arch = "wasm32"))]
impl BagReader<super::FileSource> {
    /// Open a bag on disk; errors name the path.
    pub fn open_path(path: &std::path::Path, opts: BagOptions) -> Result<Self> {
        let file = path.display().to_string();
        let src = super::FileSource::open(path).map_err(|e| e.in_file(&file))?;
        BagReader::open(src, &file, opts)
    }
}

/// The cloud topic: the one asked for, else the only PointCloud2 topic.
fn choose_topic<S: ByteSource + 'static>(bag: &Bag<S>, asked: Option<&str>) -> Result<String> {
    let topics = bag.topics();
    if let Some(t) = asked {
        let info = topics
            .iter()
            .find(|i| i.name == t)
            .ok_or_else(|| Error::Bag(format!("no topic {t} in the bag; {}", bag.list())))?;
        if !is_cloud(&info.msgtype) {
            return Err(Error::Bag(format!(
                "topic {t} is {}, not sensor_msgs/PointCloud2",
                info.msgtype
            )));
        }
        return Ok(t.to_string());
    }
    let clouds: Vec<&TopicInfo> = topics.iter().filter(|i| is_cloud(&i.msgtype)).collect();
    match clouds.as_slice() {
        [one] => Ok(one.name.clone()),
        [] => Err(Error::Bag(format!(
            "no sensor_msgs/PointCloud2 topic; {}",
            bag.list()
        ))),
        many => {
            let names: Vec<&str> = many.iter().map(|i| i.name.as_str()).collect();
            Err(Error::Bag(format!(
                "{} PointCloud2 topics ({}): choose one with --topic",
                many.len(),
                names.join(", ")
            )))
        }
    }
}

/// The pose topics the options choose.
fn choose_poses<S: ByteSource + 'static>(bag: &Bag<S>, source: &PoseSource) -> Result<Poses> {
    let topics = bag.topics();
    let odom: Vec<&TopicInfo> = topics.iter().filter(|t| is_odometry(&t.msgtype)).collect();
    let tf: Vec<&TopicInfo> = topics.iter().filter(|t| is_tf(&t.msgtype)).collect();
    let tf_name = tf
        .iter()
        .find(|t| t.name == "/tf")
        .or(tf.first())
        .map(|t| t.name.clone());
    let (topic, frame, strict) = match source {
        PoseSource::None => return Ok(Poses::None),
        PoseSource::Auto => match (odom.as_slice(), &tf_name) {
            ([one], _) => (one.name.clone(), None, false),
            (_, Some(t)) => (t.clone(), None, false),
            _ => return Ok(Poses::None),
        },
        PoseSource::Topic(t) => {
            let info = topics.iter().find(|i| &i.name == t).ok_or_else(|| {
                Error::Bag(format!("no pose topic {t} in the bag; {}", bag.list()))
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
                    "no tf topic (tf2_msgs/TFMessage) for frame {f:?}, clouds get no pose; {}",
                    bag.list()
                ))
            })?;
            (t, Some(msg::frame(f)), true)
        }
    };
    if odom.iter().any(|t| t.name == topic) {
        return Ok(Poses::Odometry(
            bag.ids(|c| c.topic == topic),
            Series::default(),
        ));
    }
    // Every tf topic together, so /tf_static's fixed sensor mounts chain in.
    let ids = bag
        .layout
        .conns
        .iter()
        .filter(|c| is_tf(&c.msgtype))
        .map(|c| (c.id, c.topic.ends_with("tf_static")))
        .collect();
    Ok(Poses::Tf(TfPoses {
        ids,
        tree: TfTree::default(),
        frame,
        topic,
        strict,
    }))
}

impl<S: ByteSource + 'static> BagReader<S> {
    /// Open a bag: read its index or summary, choose the cloud topic and the
    /// pose topics. `file` names the bag in errors and (its last component)
    /// in cloud names. Fails when no cloud topic can be chosen; everything
    /// after that is reported per cloud by the iterator.
    pub fn open(src: S, file: &str, opts: BagOptions) -> Result<Self> {
        if let Some(e) = super::unsupported_storage(file) {
            return Err(e);
        }
        Self::open_inner(src, file, opts).map_err(|e| e.in_file(file))
    }

    fn open_inner(src: S, file: &str, opts: BagOptions) -> Result<Self> {
        if opts.every == 0 {
            return invalid("every must be at least 1 (1 keeps every cloud)");
        }
        if let Some(d) = opts.every_metres {
            if !(d.is_finite() && d > 0.0) {
                return invalid(format!("every-metres must be a distance > 0, not {d}"));
            }
        }
        let bag = Bag::open(src, file)?;
        let topic = choose_topic(&bag, opts.topic.as_deref())?;
        let mut queued = VecDeque::new();
        let poses = match choose_poses(&bag, &opts.pose) {
            Ok(p) => p,
            // Like a tf tree without the frame: said, and the clouds read.
            Err(e) if matches!(opts.pose, PoseSource::TfFrame(_)) => {
                queued.push_back(e);
                Poses::None
            }
            Err(e) => return Err(e),
        };
        if opts.every_metres.is_some() && matches!(poses, Poses::None) {
            return invalid(format!(
                "--every-metres needs poses, and the bag has none to use (no \
                 nav_msgs/Odometry or tf topic chosen); {}",
                bag.list()
            ));
        }
        let count = bag
            .topics()
            .iter()
            .find(|i| i.name == topic)
            .map_or(0, |i| i.count);
        Ok(BagReader {
            cloud_ids: bag.ids(|c| c.topic == topic),
            walker: bag.walker(),
            bag_name: crate::io::base_name(file).to_string(),
            width: count.saturating_sub(1).to_string().len().max(6),
            count,
            bag,
            opts,
            topic,
            poses,
            index: 0,
            waiting: VecDeque::new(),
            done: false,
            path: 0.0,
            last_position: None,
            kept_at: None,
            queued,
            missing_frames: HashSet::new(),
            bad_pose: false,
        })
    }

    /// The cloud topic being read.
    pub fn topic(&self) -> &str {
        &self.topic
    }

    /// How many clouds the topic holds, before thinning (for progress).
    pub fn topic_len(&self) -> u64 {
        self.count
    }

    /// Name the clouds (and their poses, and the clouds in errors) after
    /// `prefix`, e.g. the bag's path under a folder, in place of the bag's
    /// base name; errors still name the file.
    pub fn with_prefix(mut self, prefix: &str) -> Self {
        self.bag_name = prefix.to_string();
        self
    }

    /// Clouds of the topic met so far, kept or not (for progress).
    pub fn clouds_met(&self) -> u64 {
        self.index as u64
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

    /// The pose at `stamp` of a cloud in `frame_id`.
    fn pose_at(&mut self, stamp: f64, frame_id: &str) -> Option<nalgebra::Isometry3<f64>> {
        match &self.poses {
            Poses::None => None,
            Poses::Odometry(_, s) => s.at(stamp),
            Poses::Tf(tf) => {
                let f = tf.frame.clone().unwrap_or_else(|| msg::frame(frame_id));
                if tf.tree.has(&f) {
                    return tf.tree.at(&f, stamp);
                }
                if tf.strict && self.missing_frames.insert(f.clone()) {
                    let e = Error::Bag(format!(
                        "topic {}: the tf tree has no frame {f:?} (frames: {}); clouds get no pose",
                        tf.topic,
                        tf.tree.frames().join(", ")
                    ));
                    self.queued.push_back(e);
                }
                None
            }
        }
    }

    /// A cloud message: thinned by count, else decoded and set waiting.
    fn cloud(
        &mut self,
        range: std::ops::Range<usize>,
        enc: msg::Encoding,
        time: f64,
    ) -> Result<()> {
        let index = self.index;
        self.index += 1;
        if index % self.opts.every != 0 {
            return Ok(());
        }
        let decoded = cloud::header(&self.walker.chunk()[range], enc).and_then(|m| {
            let (stamp, frame) = (m.stamp, m.frame_id.clone());
            Ok((stamp, frame, m.points(&self.opts.limits)?))
        });
        let (stamp, frame, points) = decoded.map_err(|e| self.cloud_error(index, e))?;
        // Some drivers leave the header stamp at 0: the log time stands in.
        let stamp = if stamp > 0.0 { stamp } else { time };
        self.waiting.push_back(Waiting {
            index,
            stamp,
            frame,
            points,
        });
        Ok(())
    }

    /// A waiting cloud with its pose, or None when the path thinning drops it.
    fn finish(&mut self, w: Waiting) -> Option<RecordedScan> {
        let iso = self.pose_at(w.stamp, &w.frame);
        let position: Option<[f64; 3]> = iso.map(|i| i.translation.vector.into());
        if let (Some(p), Some(q)) = (position, self.last_position) {
            self.path +=
                ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
        }
        if position.is_some() {
            self.last_position = position;
        }
        if let (Some(d), Some(_)) = (self.opts.every_metres, position) {
            if self.kept_at.is_some_and(|k| self.path - k < d) {
                return None;
            }
            self.kept_at = Some(self.path);
        }
        let name = self.name(w.index);
        let pose = iso.map(|i| Pose {
            name: Some(name.clone()),
            time: Some(w.stamp),
            position: i.translation.vector.into(),
            yaw: pose::yaw(&i),
        });
        Some(RecordedScan {
            name,
            points: w.points,
            stamp: Some(w.stamp),
            pose,
        })
    }

    /// Read the next item of the walk; false at the end of the data.
    fn step(&mut self) -> Result<bool> {
        let max = self.opts.limits.max_bytes;
        let (ids, poses) = (&self.cloud_ids, &self.poses);
        let want = Want {
            layout: &self.bag.layout,
            wanted: &|id| ids.contains(&id) || poses.wants(id),
            max_chunk: max,
        };
        let Some(item) = self.walker.next(&mut self.bag.win, &want) else {
            return Ok(false);
        };
        let item = item.map_err(|e| {
            Error::Bag(format!("topic {}: {}", self.topic, message(e))).in_file(&self.bag.file)
        })?;
        match item {
            Item::Conn(c) => {
                if c.topic == self.topic && !self.cloud_ids.contains(&c.id) {
                    self.cloud_ids.push(c.id);
                }
                self.bag.layout.add(c);
            }
            Item::Lost { conn, count } if self.cloud_ids.contains(&conn) => {
                self.index += count as usize;
            }
            Item::Msg { conn, time, range } => {
                let enc = self
                    .bag
                    .layout
                    .conn(conn)
                    .map_or(msg::Encoding::Ros1, |c| c.enc);
                if self.cloud_ids.contains(&conn) {
                    self.cloud(range, enc, time)?;
                } else if self.poses.wants(conn) {
                    let res = self.poses.add(conn, &self.walker.chunk()[range], enc);
                    if let (Err(e), false) = (res, self.bad_pose) {
                        // The first bad pose message is reported, not each.
                        self.bad_pose = true;
                        let topic = self.bag.layout.conn(conn).map_or("", |c| &c.topic);
                        let e = Error::Bag(format!("topic {topic}: pose message: {}", message(e)));
                        return Err(e.in_file(&self.bag.file));
                    }
                }
            }
            _ => {}
        }
        Ok(true)
    }
}

impl<S: ByteSource + 'static> Iterator for BagReader<S> {
    type Item = Result<RecordedScan>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(e) = self.queued.pop_front() {
                return Some(Err(e.in_file(&self.bag.file)));
            }
            let ready = self.waiting.front().is_some_and(|w| {
                self.done || w.stamp <= self.poses.horizon() || self.waiting.len() > MAX_WAITING
            });
            if ready {
                let w = self.waiting.pop_front().expect("a waiting cloud");
                if let Some(scan) = self.finish(w) {
                    return Some(Ok(scan));
                }
                continue;
            }
            if self.done {
                return None;
            }
            match self.step() {
                Ok(true) => {}
                Ok(false) => {
                    self.done = true;
                    self.bag.win.shrink();
                }
                Err(e) => return Some(Err(e)),
            }
        }
    }
}
