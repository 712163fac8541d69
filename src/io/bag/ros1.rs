//! ROS 1 bag format 2.0: after the line `#ROSBAG V2.0`, records of
//! `header_len, header, data_len, data`, the header being `len, name=value`
//! fields with an `op` code: 0x03 bag header (where the index starts), 0x05
//! chunk (compression none/bz2/lz4, uncompressed `size`; holds 0x02 message
//! and 0x07 connection records), 0x04 index data after each chunk, then at
//! `index_pos` the 0x07 connection and 0x06 chunk-info records.

use super::compress::decompress;
use super::layout::{Conn, Item, Layout, Walk, WalkState, Want};
use super::msg::Encoding;
use crate::error::{Error, Result};
use crate::io::source::{ByteSource, Window};

pub(crate) const MAGIC: &[u8] = b"#ROSBAG V2.0\n";

const OP_MSG: u8 = 0x02;
const OP_INDEX_DATA: u8 = 0x04;
const OP_BAG_HEADER: u8 = 0x03;
const OP_CHUNK: u8 = 0x05;
const OP_CHUNK_INFO: u8 = 0x06;
const OP_CONNECTION: u8 = 0x07;

fn bad(msg: impl Into<String>) -> Error {
    Error::Bag(msg.into())
}

fn le_u32(b: &[u8]) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(..4)?.try_into().ok()?))
}
fn le_u64(b: &[u8]) -> Option<u64> {
    Some(u64::from_le_bytes(b.get(..8)?.try_into().ok()?))
}

/// The `name=value` fields of a record header.
struct Fields<'a>(Vec<(&'a [u8], &'a [u8])>);

impl<'a> Fields<'a> {
    fn parse(mut b: &'a [u8], at: u64) -> Result<Self> {
        let mut v = Vec::new();
        while !b.is_empty() {
            let n = le_u32(b).ok_or_else(|| bad(format!("record header at byte {at} is cut")))?;
            // Checked: on wasm32 a lying u32 length would overflow usize.
            let end = (n as usize).checked_add(4).filter(|&e| e <= b.len());
            let f = end.map(|e| &b[4..e]).ok_or_else(|| {
                bad(format!(
                    "record header field at byte {at} runs past its end"
                ))
            })?;
            let eq = f
                .iter()
                .position(|&c| c == b'=')
                .ok_or_else(|| bad(format!("record header field at byte {at} has no '='")))?;
            v.push((&f[..eq], &f[eq + 1..]));
            b = &b[4 + f.len()..];
        }
        Ok(Fields(v))
    }
    fn get(&self, name: &str) -> Option<&'a [u8]> {
        self.0
            .iter()
            .find(|(k, _)| *k == name.as_bytes())
            .map(|f| f.1)
    }
    fn need(&self, name: &str, at: u64) -> Result<&'a [u8]> {
        self.get(name)
            .ok_or_else(|| bad(format!("record at byte {at} has no header field {name:?}")))
    }
    fn op(&self, at: u64) -> Result<u8> {
        Ok(self.need("op", at)?.first().copied().unwrap_or(0))
    }
    fn u32(&self, name: &str, at: u64) -> Result<u32> {
        le_u32(self.need(name, at)?)
            .ok_or_else(|| bad(format!("field {name:?} at byte {at} is short")))
    }
    fn u64(&self, name: &str, at: u64) -> Result<u64> {
        le_u64(self.need(name, at)?)
            .ok_or_else(|| bad(format!("field {name:?} at byte {at} is short")))
    }
    fn string(&self, name: &str) -> String {
        String::from_utf8_lossy(self.get(name).unwrap_or_default()).into_owned()
    }
}

/// A top-level record read from the file: its header and where its data is.
struct Record {
    op: u8,
    header: Vec<u8>,
    data_at: u64,
    data_len: u64,
    next: u64,
}

fn record<S: ByteSource>(win: &mut Window<S>, at: u64) -> Result<Record> {
    let hl = le_u32(win.get(at, 4, "record")?).expect("4 bytes") as u64;
    // Record headers are a few fields; a huge length is a corrupt file.
    if hl > 1 << 20 {
        return Err(bad(format!(
            "record at byte {at} claims a {hl}-byte header"
        )));
    }
    let header = win.get(at + 4, hl, "record header")?.to_vec();
    let data_at = at + 4 + hl + 4;
    let data_len = le_u32(win.get(at + 4 + hl, 4, "record")?).expect("4 bytes") as u64;
    let op = Fields::parse(&header, at)?.op(at)?;
    Ok(Record {
        op,
        header,
        data_at,
        data_len,
        next: data_at + data_len,
    })
}

/// A connection record's topic and type (the type is in its data, which is
/// itself laid out as header fields).
fn connection(header: &Fields, data: &[u8], at: u64) -> Result<Conn> {
    let id = header.u32("conn", at)?;
    let fields = Fields::parse(data, at)?;
    Ok(Conn {
        id,
        topic: header.string("topic"),
        msgtype: fields.string("type"),
        enc: Encoding::Ros1,
    })
}

/// Read the bag header and, when the bag is indexed (closed cleanly), the
/// connections and chunk infos at its end. Returns the layout and where the
/// chunks end.
pub(crate) fn open<S: ByteSource>(win: &mut Window<S>) -> Result<(Layout, u64, u64)> {
    let start = MAGIC.len() as u64;
    let head = record(win, start)?;
    if head.op != OP_BAG_HEADER {
        return Err(bad("no bag header record after the #ROSBAG V2.0 line"));
    }
    let fields = Fields::parse(&head.header, start)?;
    let index_pos = fields.u64("index_pos", start)?;
    let size = win.size();
    if head.next > size {
        return Err(bad(format!(
            "the file ends at byte {size}, inside the bag header record (truncated?)"
        )));
    }
    let mut layout = Layout::default();
    if index_pos < head.next || index_pos >= size {
        // Not closed cleanly (index_pos 0): connections come from the chunks.
        return Ok((layout, head.next, size));
    }
    layout.indexed = true;
    let mut at = index_pos;
    while at < size {
        let r = record(win, at)?;
        let data = win.get(r.data_at, r.data_len, "index record")?;
        let f = Fields::parse(&r.header, at)?;
        match r.op {
            OP_CONNECTION => layout.add(connection(&f, data, at)?),
            OP_CHUNK_INFO => {
                let pos = f.u64("chunk_pos", at)?;
                let mut ids = Vec::new();
                for e in data.chunks_exact(8) {
                    let (id, n) = (le_u32(e).expect("4"), le_u32(&e[4..]).expect("4"));
                    *layout.counts.entry(id).or_default() += n as u64;
                    ids.push(id);
                }
                layout.chunk_conns.insert(pos, ids);
            }
            _ => {}
        }
        at = r.next;
    }
    Ok((layout, head.next, index_pos))
}

/// Walks the chunks from `pos` to `end`, yielding the records inside.
pub(crate) struct Walker {
    s: WalkState,
}

impl Walker {
    pub(crate) fn new(pos: u64, end: u64) -> Self {
        Walker {
            s: WalkState::new(pos, end),
        }
    }

    /// The next record inside the current chunk.
    fn inner(&mut self) -> Result<Item> {
        let b = &self.s.chunk[self.s.in_chunk..];
        let at = self.s.chunk_at;
        let cut = || {
            bad(format!(
                "truncated chunk at byte {at}: a record inside runs past its end"
            ))
        };
        let parsed = (|| {
            let hl = le_u32(b)? as usize;
            let header = b.get(4..hl.checked_add(4)?)?;
            let dl = le_u32(b.get(4 + hl..)?)? as usize;
            let data_start = 4 + hl + 4;
            b.get(data_start..data_start.checked_add(dl)?)?;
            Some((header, data_start, dl))
        })();
        let Some((header, data_start, dl)) = parsed else {
            self.s.in_chunk = usize::MAX;
            return Err(cut());
        };
        let base = self.s.in_chunk;
        self.s.in_chunk += data_start + dl;
        let f = Fields::parse(header, at)?;
        match f.op(at)? {
            OP_MSG => {
                let time = f.need("time", at)?;
                let (s, ns) = (
                    le_u32(time).unwrap_or(0),
                    le_u32(&time[4.min(time.len())..]).unwrap_or(0),
                );
                Ok(Item::Msg {
                    conn: f.u32("conn", at)?,
                    time: s as f64 + ns as f64 * 1e-9,
                    range: base + data_start..base + data_start + dl,
                })
            }
            OP_CONNECTION => {
                let data = &self.s.chunk[base + data_start..base + data_start + dl];
                Ok(Item::Conn(connection(&f, data, at)?))
            }
            _ => Ok(Item::Skip),
        }
    }
}

impl<S: ByteSource> Walk<S> for Walker {
    fn next(&mut self, win: &mut Window<S>, want: &Want) -> Option<Result<Item>> {
        loop {
            if self.s.in_chunk < self.s.chunk.len() {
                return Some(self.inner());
            }
            if self.s.pos >= self.s.end {
                return None;
            }
            let at = self.s.pos;
            let r = match record(win, at) {
                Ok(r) => r,
                Err(e) => {
                    self.s.pos = self.s.end;
                    return Some(Err(e));
                }
            };
            self.s.pos = r.next;
            if r.op == OP_INDEX_DATA && self.s.failed {
                let f = Fields::parse(&r.header, at);
                let lost = f.and_then(|f| Ok((f.u32("conn", at)?, f.u32("count", at)?)));
                if let Ok((conn, count)) = lost {
                    return Some(Ok(Item::Lost {
                        conn,
                        count: count as u64,
                    }));
                }
            }
            if r.op == OP_CONNECTION {
                // Top-level connections are the index's; a bag whose header
                // lost its index_pos still has them after the chunks.
                let conn = win
                    .get(r.data_at, r.data_len, "connection record")
                    .and_then(|data| connection(&Fields::parse(&r.header, at)?, data, at));
                return Some(conn.map(Item::Conn));
            }
            if r.op != OP_CHUNK {
                continue;
            }
            self.s.failed = false;
            if !want.layout.chunk_may_hold(at, want.wanted) {
                continue;
            }
            let res = (|| {
                let f = Fields::parse(&r.header, at)?;
                let size = f.u32("size", at)? as usize;
                if size > want.max_chunk {
                    return Err(bad(format!(
                        "chunk at byte {at} claims {size} bytes, over the limit"
                    )));
                }
                let compression = f.string("compression");
                if r.data_len > want.max_chunk as u64 {
                    return Err(bad(format!(
                        "chunk at byte {at} has {} bytes, over the limit",
                        r.data_len
                    )));
                }
                let data = win.get(r.data_at, r.data_len, "chunk")?;
                decompress(&compression, data, size, &mut self.s.chunk)
                    .map_err(|e| bad(format!("chunk at byte {at}: {}", super::message(e))))
            })();
            win.shrink();
            if let Err(e) = res {
                self.s.chunk.clear();
                self.s.failed = true;
                return Some(Err(e));
            }
            self.s.in_chunk = 0;
            self.s.chunk_at = at;
        }
    }
    fn chunk(&self) -> &[u8] {
        &self.s.chunk
    }
}
