//! What both bag formats tell about themselves: connections (ROS 1) or
//! channels (MCAP) with their topic and type, message counts, and which
//! connections each chunk holds (so a pass can skip chunks it has no use for).

use super::msg::Encoding;
use std::collections::HashMap;

/// One connection (ROS 1) or channel (MCAP).
#[derive(Debug, Clone)]
pub(crate) struct Conn {
    pub(crate) id: u32,
    pub(crate) topic: String,
    /// As the bag writes it: `sensor_msgs/PointCloud2` (ROS 1) or
    /// `sensor_msgs/msg/PointCloud2` (ROS 2).
    pub(crate) msgtype: String,
    pub(crate) enc: Encoding,
}

/// True when `msgtype` is `pkg/Name`, in its ROS 1 or ROS 2 spelling.
pub(crate) fn is_type(msgtype: &str, pkg: &str, name: &str) -> bool {
    let short = msgtype.replace("/msg/", "/");
    short == format!("{pkg}/{name}")
}

#[derive(Debug, Default)]
pub(crate) struct Layout {
    pub(crate) conns: Vec<Conn>,
    /// Message counts per connection id, from the index or summary.
    pub(crate) counts: HashMap<u32, u64>,
    /// Connection ids each chunk holds, by the chunk's byte offset.
    pub(crate) chunk_conns: HashMap<u64, Vec<u32>>,
    /// The counts above are complete (the bag has an index or summary).
    pub(crate) indexed: bool,
}

impl Layout {
    pub(crate) fn add(&mut self, c: Conn) {
        if !self.conns.iter().any(|k| k.id == c.id) {
            self.conns.push(c);
        }
    }

    pub(crate) fn conn(&self, id: u32) -> Option<&Conn> {
        self.conns.iter().find(|c| c.id == id)
    }

    /// False only when the index says the chunk at `at` holds nothing wanted.
    pub(crate) fn chunk_may_hold(&self, at: u64, wanted: &dyn Fn(u32) -> bool) -> bool {
        match self.chunk_conns.get(&at) {
            Some(ids) => ids.iter().any(|&id| wanted(id)),
            None => true,
        }
    }
}

/// What a walk over the chunks yields.
#[derive(Debug)]
pub(crate) enum Item {
    /// A message of connection `conn`, logged at `time` (seconds); its bytes
    /// are `range` in the walker's current chunk.
    Msg {
        conn: u32,
        time: f64,
        range: std::ops::Range<usize>,
    },
    /// A connection (channel) declared inside the data.
    Conn(Conn),
    /// `count` messages of connection `conn` were in a chunk that could not
    /// be read (from the index records after it), so indices stay true.
    Lost { conn: u32, count: u64 },
    /// A record of no interest.
    Skip,
}
