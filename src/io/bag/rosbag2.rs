//! rosbag2 in MCAP: records of `opcode u8, length u64, body`, decoded with
//! the `mcap` crate's `parse_record`. The framing is walked here rather than
//! by `mcap`'s readers so that bytes come through [`ByteSource`] one record
//! at a time, and a chunk that cannot be read (unknown compression, cut
//! short) is reported and skipped while the walk goes on to the next one.
//! The summary at the end (found through the footer) gives the channels,
//! their message counts and the chunks' contents without reading the data.

use super::compress::decompress;
use super::layout::{Conn, Item, Layout, Walk, WalkState, Want};
use super::msg::Encoding;
use crate::error::{Error, Result};
use crate::io::source::{ByteSource, Window};
use mcap::records::{op, Record};
use std::collections::HashMap;

pub(crate) use mcap::MAGIC;

fn bad(msg: impl Into<String>) -> Error {
    Error::Bag(msg.into())
}

fn mcap_err(at: u64, e: mcap::McapError) -> Error {
    bad(format!("MCAP record at byte {at}: {e}"))
}

/// Opcode and body length of the record at `at`.
fn frame<S: ByteSource>(win: &mut Window<S>, at: u64) -> Result<(u8, u64)> {
    let b = win.get(at, 9, "MCAP record")?;
    Ok((
        b[0],
        u64::from_le_bytes(b[1..9].try_into().expect("8 bytes")),
    ))
}

fn channel(ch: &mcap::records::Channel, schemas: &HashMap<u16, String>) -> Conn {
    Conn {
        id: ch.id as u32,
        topic: ch.topic.clone(),
        msgtype: schemas.get(&ch.schema_id).cloned().unwrap_or_default(),
        enc: if ch.message_encoding == "ros1" {
            Encoding::Ros1
        } else {
            Encoding::Cdr
        },
    }
}

/// Read the summary (when the file has one): channels, counts, chunk
/// contents. Returns the layout and where the data section ends.
pub(crate) fn open<S: ByteSource>(win: &mut Window<S>) -> Result<(Layout, u64)> {
    let size = win.size();
    let mut layout = Layout::default();
    // Footer record (1 + 8 + 20 bytes) then the closing magic.
    let footer_at = size.checked_sub(29 + MAGIC.len() as u64);
    let summary = match footer_at {
        Some(at) if win.get(size - 8, 8, "MCAP end magic")? == MAGIC => {
            let b = win.get(at, 29, "MCAP footer")?;
            (b[0] == op::FOOTER)
                .then(|| u64::from_le_bytes(b[9..17].try_into().expect("8 bytes")))
                .filter(|&s| s > 0 && s < at)
                .map(|s| (s, at))
        }
        _ => None,
    };
    let Some((start, end)) = summary else {
        return Ok((layout, size));
    };
    let mut schemas = HashMap::new();
    let mut at = start;
    let mut has_stats = false;
    while at < end {
        let (opcode, len) = frame(win, at)?;
        let body = win.get(at + 9, len, "MCAP summary record")?;
        match mcap::parse_record(opcode, body).map_err(|e| mcap_err(at, e))? {
            Record::Schema { header, .. } => {
                schemas.insert(header.id, header.name);
            }
            Record::Channel(ch) => layout.add(channel(&ch, &schemas)),
            Record::Statistics(s) => {
                has_stats = true;
                for (id, n) in s.channel_message_counts {
                    layout.counts.insert(id as u32, n);
                }
            }
            Record::ChunkIndex(ci) => {
                let ids = ci.message_index_offsets.keys().map(|&k| k as u32).collect();
                layout.chunk_conns.insert(ci.chunk_start_offset, ids);
            }
            _ => {}
        }
        at += 9 + len;
    }
    layout.indexed = has_stats;
    Ok((layout, start))
}

/// Walks the data section from `pos` to `end`, yielding the records inside
/// chunks and those outside (a file written without chunks).
pub(crate) struct Walker {
    s: WalkState,
    schemas: HashMap<u16, String>,
}

impl Walker {
    pub(crate) fn new(pos: u64, end: u64) -> Self {
        Walker {
            s: WalkState::new(pos, end),
            schemas: HashMap::new(),
        }
    }
    /// Schema, channel or message record `body` found at `base` in `self.s.chunk`.
    fn item(&mut self, opcode: u8, base: usize, len: usize, at: u64) -> Result<Item> {
        let body = &self.s.chunk[base..base + len];
        match opcode {
            op::MESSAGE => {
                // channel u16, sequence u32, log_time u64, publish_time u64, data.
                if len < 22 {
                    return Err(bad(format!("MCAP message at byte {at} is cut")));
                }
                let conn = u16::from_le_bytes([body[0], body[1]]) as u32;
                let log = u64::from_le_bytes(body[6..14].try_into().expect("8 bytes"));
                Ok(Item::Msg {
                    conn,
                    time: log as f64 * 1e-9,
                    range: base + 22..base + len,
                })
            }
            op::SCHEMA | op::CHANNEL => match mcap::parse_record(opcode, body) {
                Ok(Record::Schema { header, .. }) => {
                    self.schemas.insert(header.id, header.name);
                    Ok(Item::Skip)
                }
                Ok(Record::Channel(ch)) => Ok(Item::Conn(channel(&ch, &self.schemas))),
                Ok(_) => Ok(Item::Skip),
                Err(e) => Err(mcap_err(at, e)),
            },
            _ => Ok(Item::Skip),
        }
    }

    fn load_chunk<S: ByteSource>(
        &mut self,
        win: &mut Window<S>,
        at: u64,
        len: u64,
        max_chunk: usize,
    ) -> Result<()> {
        if len > max_chunk as u64 {
            return Err(bad(format!(
                "chunk at byte {at} has {len} bytes, over the limit"
            )));
        }
        let body = win.get(at + 9, len, "MCAP chunk")?;
        let Record::Chunk { header, data } =
            mcap::parse_record(op::CHUNK, body).map_err(|e| mcap_err(at, e))?
        else {
            return Err(bad(format!("MCAP chunk at byte {at} does not parse")));
        };
        let size = header.uncompressed_size;
        if size > max_chunk as u64 {
            return Err(bad(format!(
                "chunk at byte {at} claims {size} bytes, over the limit"
            )));
        }
        decompress(&header.compression, &data, size as usize, &mut self.s.chunk)
            .map_err(|e| bad(format!("chunk at byte {at}: {}", super::message(e))))?;
        self.s.in_chunk = 0;
        self.s.chunk_at = at;
        Ok(())
    }
}

impl<S: ByteSource> Walk<S> for Walker {
    fn next(&mut self, win: &mut Window<S>, want: &Want) -> Option<Result<Item>> {
        loop {
            if self.s.in_chunk < self.s.chunk.len() {
                let at = self.s.chunk_at;
                let b = &self.s.chunk[self.s.in_chunk..];
                let Some(len) = b
                    .get(1..9)
                    .map(|l| u64::from_le_bytes(l.try_into().expect("8")))
                else {
                    self.s.in_chunk = usize::MAX;
                    return Some(Err(bad(format!("truncated chunk at byte {at}"))));
                };
                if len > (b.len() - 9) as u64 {
                    self.s.in_chunk = usize::MAX;
                    return Some(Err(bad(format!(
                        "truncated chunk at byte {at}: a record inside runs past its end"
                    ))));
                }
                let (opcode, base) = (b[0], self.s.in_chunk + 9);
                self.s.in_chunk = base + len as usize;
                return Some(self.item(opcode, base, len as usize, at));
            }
            if self.s.pos >= self.s.end {
                return None;
            }
            let at = self.s.pos;
            let (opcode, len) = match frame(win, at) {
                Ok(f) => f,
                Err(e) => {
                    self.s.pos = self.s.end;
                    return Some(Err(e));
                }
            };
            self.s.pos = at.saturating_add(9).saturating_add(len);
            match opcode {
                op::DATA_END | op::FOOTER => {
                    self.s.pos = self.s.end;
                    return None;
                }
                op::CHUNK if !want.layout.chunk_may_hold(at, want.wanted) => {
                    self.s.failed = false;
                }
                op::CHUNK => {
                    let res = self.load_chunk(win, at, len, want.max_chunk);
                    win.shrink();
                    self.s.failed = res.is_err();
                    if let Err(e) = res {
                        self.s.chunk.clear();
                        return Some(Err(e));
                    }
                }
                // channel u16, then the (time u64, offset u64) entries' byte length u32.
                op::MESSAGE_INDEX if self.s.failed => {
                    if let Ok(b) = win.get(at + 9, len.min(6), "MCAP message index") {
                        if b.len() == 6 {
                            let conn = u16::from_le_bytes([b[0], b[1]]) as u32;
                            let n = u32::from_le_bytes(b[2..6].try_into().expect("4 bytes"));
                            return Some(Ok(Item::Lost {
                                conn,
                                count: n as u64 / 16,
                            }));
                        }
                    }
                }
                op::MESSAGE | op::SCHEMA | op::CHANNEL => {
                    // Outside chunks: copy the record to the chunk buffer so
                    // messages are read from one place.
                    let body = match win.get(at + 9, len, "MCAP record") {
                        Ok(b) => b,
                        Err(e) => {
                            self.s.pos = self.s.end;
                            return Some(Err(e));
                        }
                    };
                    self.s.chunk.clear();
                    self.s.chunk.extend_from_slice(body);
                    self.s.in_chunk = usize::MAX;
                    return Some(self.item(opcode, 0, len as usize, at));
                }
                _ => {}
            }
        }
    }
    fn chunk(&self) -> &[u8] {
        &self.s.chunk
    }
}
