//! What both bag formats tell about themselves: connections (ROS 1) or
//! channels (MCAP) with their topic and type, message counts, and which
//! connections each chunk holds (so a pass can skip chunks it has no use for).

use super::msg::Encoding;
use crate::error::Result;
use crate::io::source::{ByteSource, Window};
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

/// Where a walk over the data of a bag is: the next top-level record, the
/// end of the data, and the chunk being read (decompressed) with the
/// position inside it.
pub(crate) struct WalkState {
    pub(crate) pos: u64,
    pub(crate) end: u64,
    pub(crate) chunk: Vec<u8>,
    /// Position in `chunk`; past its end when no chunk is being read.
    pub(crate) in_chunk: usize,
    /// Byte offset of the chunk record in the file (for messages).
    pub(crate) chunk_at: u64,
    /// The last chunk could not be read: the index records after it say
    /// what it held ([`Item::Lost`]).
    pub(crate) failed: bool,
}

impl WalkState {
    pub(crate) fn new(pos: u64, end: u64) -> Self {
        WalkState {
            pos,
            end,
            chunk: Vec::new(),
            in_chunk: usize::MAX,
            chunk_at: 0,
            failed: false,
        }
    }
}

/// What a walk is for: the layout it reads by, the connections it wants
/// (chunks the index says hold none of them are skipped unread), and the
/// largest decompressed chunk it accepts.
pub(crate) struct Want<'a> {
    pub(crate) layout: &'a Layout,
    pub(crate) wanted: &'a dyn Fn(u32) -> bool,
    pub(crate) max_chunk: usize,
}

/// A walk over the chunks of one bag format, record by record.
pub(crate) trait Walk<S: ByteSource> {
    /// The next item, reading through `win`; None at the end of the data.
    fn next(&mut self, win: &mut Window<S>, want: &Want) -> Option<Result<Item>>;
    /// The current chunk, into which [`Item::Msg`] ranges point.
    fn chunk(&self) -> &[u8];
}
