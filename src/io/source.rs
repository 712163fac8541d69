//! Where a bag's bytes come from. The readers never hold the file: they ask
//! for byte ranges through [`ByteSource`], so the page can serve them from
//! `File.slice` (a worker's `FileReaderSync`) and the CLI from a file on disk,
//! and memory stays bounded by the largest record (a chunk), not the file.

use crate::error::{Error, Result};

/// Random access to the bytes of one bag.
pub trait ByteSource {
    /// Size of the whole bag in bytes.
    fn size(&self) -> u64;
    /// Fill `buf` with the bytes at `offset..offset + buf.len()`. Callers never
    /// ask past [`size`](Self::size).
    fn read_at(&mut self, offset: u64, buf: &mut [u8]) -> Result<()>;
}

impl ByteSource for &[u8] {
    fn size(&self) -> u64 {
        self.len() as u64
    }
    fn read_at(&mut self, offset: u64, buf: &mut [u8]) -> Result<()> {
        let start = offset as usize;
        buf.copy_from_slice(&self[start..start + buf.len()]);
        Ok(())
    }
}

impl ByteSource for Vec<u8> {
    fn size(&self) -> u64 {
        self.len() as u64
    }
    fn read_at(&mut self, offset: u64, buf: &mut [u8]) -> Result<()> {
        self.as_slice().read_at(offset, buf)
    }
}

/// A bag on disk, read through a buffered reader (native only).
#[cfg(not(target_arch = "wasm32"))]
pub struct FileSource {
    reader: std::io::BufReader<std::fs::File>,
    size: u64,
    pos: u64,
}

#[cfg(not(target_arch = "wasm32"))]
impl FileSource {
    /// Open the file at `path` for reading by byte ranges.
    pub fn open(path: &std::path::Path) -> Result<FileSource> {
        let file = std::fs::File::open(path)?;
        let size = file.metadata()?.len();
        Ok(FileSource {
            reader: std::io::BufReader::with_capacity(1 << 20, file),
            size,
            pos: 0,
        })
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl ByteSource for FileSource {
    fn size(&self) -> u64 {
        self.size
    }
    fn read_at(&mut self, offset: u64, buf: &mut [u8]) -> Result<()> {
        use std::io::Read;
        if offset != self.pos {
            // Relative seeks keep the buffer when the target is inside it.
            self.reader
                .seek_relative(offset as i64 - self.pos as i64)
                .map_err(Error::from)?;
        }
        self.reader.read_exact(buf)?;
        self.pos = offset + buf.len() as u64;
        Ok(())
    }
}

/// A read-ahead window over a [`ByteSource`]: small records (record headers,
/// index entries) are served from one block fetched at a time, so a source
/// with a costly call (a `File.slice` in the page) is asked rarely.
pub(crate) struct Window<S> {
    pub(crate) src: S,
    start: u64,
    buf: Vec<u8>,
}

/// Bytes fetched at once when a smaller range is asked for.
const BLOCK: usize = 1 << 20;

impl<S: ByteSource> Window<S> {
    pub(crate) fn new(src: S) -> Self {
        Window {
            src,
            start: 0,
            buf: Vec::new(),
        }
    }

    pub(crate) fn size(&self) -> u64 {
        self.src.size()
    }

    /// The bytes at `offset..offset + len`, or an error saying the file ends
    /// before them (a truncated record).
    pub(crate) fn get(&mut self, offset: u64, len: u64, what: &str) -> Result<&[u8]> {
        let size = self.src.size();
        let end = offset.checked_add(len).filter(|&e| e <= size);
        let Some(end) = end else {
            return Err(Error::Bag(format!(
                "{what} at byte {offset} needs {len} bytes, but the file ends at byte {size} \
                 (truncated?)"
            )));
        };
        let have = offset >= self.start && end <= self.start + self.buf.len() as u64;
        if !have {
            let want = (len as usize).max(BLOCK).min((size - offset) as usize);
            // A big record replaces the window instead of growing it, so at
            // most one record (chunk) is held.
            self.buf = vec![0; want];
            self.start = offset;
            self.src.read_at(offset, &mut self.buf)?;
        }
        let at = (offset - self.start) as usize;
        Ok(&self.buf[at..at + len as usize])
    }

    /// Drop a large window after use so a huge chunk is not kept alive.
    pub(crate) fn shrink(&mut self) {
        if self.buf.len() > BLOCK {
            self.buf = Vec::new();
            self.start = 0;
        }
    }
}
