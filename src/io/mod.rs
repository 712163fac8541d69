//! Readers (and writers, for round trips and the simulator) of point-cloud
//! files. The format is sniffed from the bytes where the format has a header
//! (PLY, PCD), else taken from the file name (`.bin` = KITTI).

pub mod kitti;
pub mod pcd;
pub mod ply;
pub mod poses;
pub mod recording;
mod scalar;
pub mod write;

pub use scalar::Scalar;

use crate::cloud::PointCloud;
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Caps enforced before any large allocation, so a lying header or a huge
/// file fails fast with a clear error instead of eating memory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ReadLimits {
    /// Largest number of points a scan may have.
    pub max_points: usize,
    /// Largest file size in bytes.
    pub max_bytes: usize,
}

impl Default for ReadLimits {
    fn default() -> Self {
        ReadLimits {
            max_points: 50_000_000,
            max_bytes: 2 << 30,
        }
    }
}

impl ReadLimits {
    pub(crate) fn check_points(&self, claimed: u64) -> Result<usize> {
        if claimed > self.max_points as u64 {
            return Err(Error::Limit(format!(
                "the file claims {claimed} points, more than the limit of {}",
                self.max_points
            )));
        }
        Ok(claimed as usize)
    }

    pub(crate) fn check_bytes(&self, len: usize) -> Result<()> {
        if len > self.max_bytes {
            return Err(Error::Limit(format!(
                "the file has {len} bytes, more than the limit of {}",
                self.max_bytes
            )));
        }
        Ok(())
    }
}

/// The kinds of point-cloud file placecat reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    Ply,
    Pcd,
    KittiBin,
}

/// Decide the format: from the bytes when they start like a PLY or PCD
/// header, else from the name's extension.
pub fn sniff(bytes: &[u8], name: &str) -> Result<FileKind> {
    if bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n") {
        return Ok(FileKind::Ply);
    }
    if pcd::looks_like_pcd(bytes) {
        return Ok(FileKind::Pcd);
    }
    let lower = name.to_ascii_lowercase();
    if lower.ends_with(".bin") {
        return Ok(FileKind::KittiBin);
    }
    if lower.ends_with(".ply") {
        return Err(Error::Ply(
            "the file does not start with the line \"ply\"".into(),
        ));
    }
    if lower.ends_with(".pcd") {
        return Err(Error::Pcd(
            "the file does not start with a PCD header (VERSION / FIELDS ...)".into(),
        ));
    }
    if bytes.is_empty() {
        return Err(Error::UnknownFormat("the file is empty".into()));
    }
    Err(Error::UnknownFormat(
        "not PLY or PCD, and the name does not end in .bin (KITTI)".into(),
    ))
}

/// True when the name looks like a scan placecat can read (for folder walks).
pub fn is_scan_name(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    lower.ends_with(".ply") || lower.ends_with(".pcd") || lower.ends_with(".bin")
}

/// Read a scan from its bytes. Errors are not yet wrapped with the file
/// name; [`read_scan_named`] does that.
pub fn read_scan(bytes: &[u8], name: &str, limits: &ReadLimits) -> Result<PointCloud> {
    limits.check_bytes(bytes.len())?;
    match sniff(bytes, name)? {
        FileKind::Ply => ply::read(bytes, limits),
        FileKind::Pcd => pcd::read(bytes, limits),
        FileKind::KittiBin => kitti::read(bytes, limits),
    }
}

/// [`read_scan`] with the error naming the file.
pub fn read_scan_named(bytes: &[u8], name: &str, limits: &ReadLimits) -> Result<PointCloud> {
    read_scan(bytes, name, limits).map_err(|e| e.in_file(name))
}

/// Read a scan from disk (native only), errors naming the path.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_path(path: &std::path::Path, limits: &ReadLimits) -> Result<PointCloud> {
    let name = path.display().to_string();
    let meta = std::fs::metadata(path).map_err(|e| Error::from(e).in_file(&name))?;
    limits
        .check_bytes(meta.len() as usize)
        .map_err(|e| e.in_file(&name))?;
    let bytes = std::fs::read(path).map_err(|e| Error::from(e).in_file(&name))?;
    read_scan_named(&bytes, &name, limits)
}

/// Split off the header: returns (header lines, offset of the body). The
/// header ends with the line that `is_last` accepts; at most `max_len` bytes
/// are searched, so a file with no end of header fails fast.
pub(crate) fn split_header(
    bytes: &[u8],
    max_len: usize,
    is_last: impl Fn(&str) -> bool,
) -> Option<(Vec<&str>, usize)> {
    let mut lines = Vec::new();
    let mut pos = 0;
    while pos < bytes.len() && pos < max_len {
        let end = bytes[pos..].iter().position(|&b| b == b'\n');
        let (line_end, next) = match end {
            Some(e) => (pos + e, pos + e + 1),
            None => (bytes.len(), bytes.len()),
        };
        let raw = &bytes[pos..line_end];
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let line = std::str::from_utf8(raw).ok()?;
        lines.push(line);
        pos = next;
        if is_last(line.trim()) {
            return Some((lines, pos));
        }
    }
    None
}
