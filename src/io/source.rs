//! Where a recording's bytes come from (a ROS bag, an E57 survey). The
//! readers never hold the file: they ask for byte ranges through
//! [`ByteSource`], so the page can serve them from `File.slice` (a worker's
//! `FileReaderSync`) and the CLI from a file on disk, and memory stays
//! bounded by the largest record (a chunk, a page of points), not the file.
//! [`SourceReader`] makes a source `Read + Seek` for readers built on those
//! traits (the `e57` crate).

use crate::error::{Error, Result};

/// Random access to the bytes of one file (a bag, a survey).
pub trait ByteSource {
    /// Size of the whole file in bytes.
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

/// A [`ByteSource`] as `Read + Seek`, reading ahead a block at a time so
/// that a reader asking for small pieces (the `e57` crate reads 1 KiB pages)
/// calls the source rarely (in the page, each call is a `File.slice` read).
pub struct SourceReader<S> {
    src: S,
    pos: u64,
    start: u64,
    buf: Vec<u8>,
}

impl<S: ByteSource> SourceReader<S> {
    /// Read `src` from its start.
    pub fn new(src: S) -> Self {
        SourceReader {
            src,
            pos: 0,
            start: 0,
            buf: Vec::new(),
        }
    }
}

impl<S: ByteSource> std::io::Read for SourceReader<S> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        let size = self.src.size();
        if out.is_empty() || self.pos >= size {
            return Ok(0);
        }
        let held = self.pos >= self.start && self.pos < self.start + self.buf.len() as u64;
        if !held {
            let want = BLOCK.min((size - self.pos) as usize);
            self.buf.resize(want, 0);
            self.start = self.pos;
            if let Err(e) = self.src.read_at(self.pos, &mut self.buf) {
                self.buf.clear();
                return Err(std::io::Error::other(e.to_string()));
            }
        }
        let at = (self.pos - self.start) as usize;
        let n = out.len().min(self.buf.len() - at);
        out[..n].copy_from_slice(&self.buf[at..at + n]);
        self.pos += n as u64;
        Ok(n)
    }
}

impl<S: ByteSource> std::io::Seek for SourceReader<S> {
    fn seek(&mut self, to: std::io::SeekFrom) -> std::io::Result<u64> {
        use std::io::SeekFrom;
        let (from, by) = match to {
            SeekFrom::Start(o) => (0, i128::from(o)),
            SeekFrom::End(d) => (self.src.size(), i128::from(d)),
            SeekFrom::Current(d) => (self.pos, i128::from(d)),
        };
        let at = i128::from(from) + by;
        self.pos = u64::try_from(at).map_err(|_| {
            std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!("seek to byte {at}, before the start"),
            )
        })?;
        Ok(self.pos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Read, Seek, SeekFrom};

    #[test]
    fn the_reader_gives_the_sources_bytes_wherever_it_seeks() {
        let bytes: Vec<u8> = (0..3 * BLOCK + 17).map(|i| (i * 7 % 251) as u8).collect();
        let mut r = SourceReader::new(bytes.as_slice());
        let mut got = Vec::new();
        r.read_to_end(&mut got).unwrap();
        assert_eq!(got, bytes);
        let mut four = [0u8; 4];
        for at in [5, BLOCK as u64 - 2, 2 * BLOCK as u64 + 1, 0] {
            assert_eq!(r.seek(SeekFrom::Start(at)).unwrap(), at);
            r.read_exact(&mut four).unwrap();
            assert_eq!(four, bytes[at as usize..at as usize + 4]);
        }
        assert_eq!(r.seek(SeekFrom::End(-3)).unwrap(), bytes.len() as u64 - 3);
        assert_eq!(r.read(&mut four).unwrap(), 3, "only three bytes remain");
        assert_eq!(r.read(&mut four).unwrap(), 0, "then the end");
        assert!(r
            .seek(SeekFrom::Current(-(bytes.len() as i64) - 1))
            .is_err());
    }
}
