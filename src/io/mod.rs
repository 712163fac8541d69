//! Readers (and writers, for round trips and the simulator) of point-cloud
//! files. The format is sniffed from the bytes where the format has a header
//! (PLY, PCD, LAS/LAZ, E57), else taken from the file name (`.bin` = KITTI).

pub mod bag;
pub mod csv;
pub mod e57;
pub mod kitti;
pub mod las;
mod lzf_pack;
pub mod pcd;
pub mod ply;
pub mod poses;
pub mod recording;
mod scalar;
pub mod source;
pub mod write;

pub use scalar::Scalar;

use crate::cloud::PointCloud;
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Caps enforced before any large allocation, so a lying header or a huge
/// file fails fast with a clear error instead of eating memory; and how
/// strictly the body must match the header.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ReadLimits {
    /// Largest number of points a scan may have.
    pub max_points: usize,
    /// Largest file size in bytes.
    pub max_bytes: usize,
    /// Read the points the header declares and check nothing after them.
    ///
    /// Strict (the default) refuses a file whose body does not match its
    /// header, since such a file is damaged and its points may be garbage:
    /// bytes after every declared element that are not padding (see
    /// [`MAX_PADDING`]), an element after `vertex` (PLY) that does not parse
    /// to its end, data lines after the last declared one (ascii), and a PCD
    /// header whose WIDTH x HEIGHT is not POINTS (POINTS is then used), a
    /// LAS/LAZ point outside the header's bounding box.
    /// Lenient accepts these, for users who must read such files anyway. A
    /// row of an ascii body with the wrong number of values is an error
    /// either way: it shifts the points, so no reading of it is right.
    pub lenient: bool,
}

impl Default for ReadLimits {
    fn default() -> Self {
        ReadLimits {
            max_points: 50_000_000,
            max_bytes: 2 << 30,
            lenient: false,
        }
    }
}

/// The most bytes after a binary body's declared data that still count as
/// harmless padding, when every one of them is a zero byte or ASCII
/// whitespace (a trailing newline, alignment to a 4 KiB block). Anything
/// else after the data (other bytes, or more of them) means the header does
/// not describe the body: the file is damaged (a text round trip that grew
/// the body, a concatenation) and is refused unless read leniently.
pub const MAX_PADDING: usize = 4096;

/// Check what follows the `declared` bytes of a binary body (`rest`); the
/// error says how much is left over and why it is not padding.
pub(crate) fn check_padding(
    rest: &[u8],
    declared: usize,
    limits: &ReadLimits,
) -> std::result::Result<(), String> {
    let padding =
        rest.len() <= MAX_PADDING && rest.iter().all(|&b| b == 0 || b.is_ascii_whitespace());
    if padding || limits.lenient {
        return Ok(());
    }
    Err(format!(
        "the body does not match the header: {} bytes follow the {declared} bytes it declares \
         (padding is at most {MAX_PADDING} zero or whitespace bytes); the file is damaged",
        rest.len()
    ))
}

/// `a * b` of a header's counts and sizes as a `usize`, or None when it does
/// not fit: the same answer on 64-bit and 32-bit (wasm) targets for every
/// product that is checked against a file's length.
pub(crate) fn checked_len(a: u64, b: usize) -> Option<usize> {
    usize::try_from(a).ok()?.checked_mul(b)
}

impl ReadLimits {
    pub(crate) fn check_points(&self, claimed: u64) -> Result<usize> {
        match usize::try_from(claimed) {
            Ok(n) if n <= self.max_points => Ok(n),
            _ => Err(Error::Limit(format!(
                "the file claims {claimed} points, more than the limit of {}",
                self.max_points
            ))),
        }
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
    /// PLY (the first line is `ply`).
    Ply,
    /// PCD v0.7 (a PCD header: comments, `VERSION`, `FIELDS` ...).
    Pcd,
    /// KITTI `.bin` (no header: known by the file name only).
    KittiBin,
    /// LAS or LAZ (the header says which).
    Las,
    /// E57 (starts with `ASTM-E57`).
    E57,
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
    if self::las::looks_like_las(bytes) {
        return Ok(FileKind::Las);
    }
    if self::e57::looks_like_e57(bytes) {
        return Ok(FileKind::E57);
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
    if lower.ends_with(".las") || lower.ends_with(".laz") {
        return Err(Error::Las("the file does not start with \"LASF\"".into()));
    }
    if lower.ends_with(".e57") {
        return Err(Error::E57(
            "the file does not start with \"ASTM-E57\"".into(),
        ));
    }
    if bytes.is_empty() {
        return Err(Error::UnknownFormat("the file is empty".into()));
    }
    Err(Error::UnknownFormat(
        "not PLY, PCD, LAS/LAZ or E57, and the name does not end in .bin (KITTI)".into(),
    ))
}

/// The last part of a path given as text (`a/b/run.bag` -> `run.bag`), by
/// either separator, as scans of a recording are named.
pub(crate) fn base_name(file: &str) -> &str {
    file.rsplit(['/', '\\']).next().unwrap_or(file)
}

/// True when the name looks like a scan placecat can read (for folder walks).
pub fn is_scan_name(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    [".ply", ".pcd", ".bin", ".las", ".laz", ".e57"]
        .iter()
        .any(|ext| lower.ends_with(ext))
}

/// Read a scan from its bytes. Errors are not yet wrapped with the file
/// name; [`read_scan_named`] does that.
pub fn read_scan(bytes: &[u8], name: &str, limits: &ReadLimits) -> Result<PointCloud> {
    read_scan_at(bytes, name, limits, None)
}

/// [`read_scan`] with the sensor position, in the file's coordinates,
/// subtracted from every point (in float64 for LAS/LAZ, whose coordinates
/// are often georeferenced; see [`las`] for LAS without one).
pub fn read_scan_at(
    bytes: &[u8],
    name: &str,
    limits: &ReadLimits,
    origin: Option<[f64; 3]>,
) -> Result<PointCloud> {
    limits.check_bytes(bytes.len())?;
    if let Some(o) = origin.filter(|o| o.iter().any(|v| !v.is_finite())) {
        return crate::error::invalid(format!("the sensor position {o:?} is not finite"));
    }
    let mut cloud = match sniff(bytes, name)? {
        FileKind::Ply => ply::read(bytes, limits),
        FileKind::Pcd => pcd::read(bytes, limits),
        FileKind::KittiBin => kitti::read(bytes, limits),
        FileKind::Las => return self::las::read(bytes, limits, origin),
        FileKind::E57 => self::e57::read_single(bytes, limits),
    }?;
    if let Some(o) = origin {
        for p in &mut cloud.points {
            *p = std::array::from_fn(|a| (f64::from(p[a]) - o[a]) as f32);
        }
    }
    Ok(cloud)
}

/// [`read_scan`] with the error naming the file.
pub fn read_scan_named(bytes: &[u8], name: &str, limits: &ReadLimits) -> Result<PointCloud> {
    read_scan(bytes, name, limits).map_err(|e| e.in_file(name))
}

/// Read a scan from disk (native only), errors naming the path.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_path(path: &std::path::Path, limits: &ReadLimits) -> Result<PointCloud> {
    read_path_at(path, limits, None)
}

/// [`read_path`] with a sensor position, as [`read_scan_at`].
#[cfg(not(target_arch = "wasm32"))]
pub fn read_path_at(
    path: &std::path::Path,
    limits: &ReadLimits,
    origin: Option<[f64; 3]>,
) -> Result<PointCloud> {
    let name = path.display().to_string();
    let meta = std::fs::metadata(path).map_err(|e| Error::from(e).in_file(&name))?;
    limits
        .check_bytes(usize::try_from(meta.len()).unwrap_or(usize::MAX))
        .map_err(|e| e.in_file(&name))?;
    let bytes = std::fs::read(path).map_err(|e| Error::from(e).in_file(&name))?;
    read_scan_at(&bytes, &name, limits, origin).map_err(|e| e.in_file(&name))
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

/// The rows of an ascii body: its non-blank lines, split into values, each
/// with its line number in the file (for errors a user can look up). Blank
/// lines carry no values, so skipping them shifts nothing.
#[derive(Clone)]
pub(crate) struct AsciiRows<'a> {
    lines: std::iter::Enumerate<std::str::Lines<'a>>,
    /// Lines before the body (the header).
    first: usize,
}

impl<'a> AsciiRows<'a> {
    /// `header` is the bytes before `body`, to count its lines.
    pub(crate) fn new(header: &[u8], body: &'a str) -> Self {
        AsciiRows {
            lines: body.lines().enumerate(),
            first: header.iter().filter(|&&b| b == b'\n').count(),
        }
    }

    /// True when no row is left: a short row there is where a cut file ends.
    pub(crate) fn at_end(&self) -> bool {
        self.clone().next_row(&mut Vec::new()).is_none()
    }

    /// After the declared rows, a strict read wants none left: else the
    /// line of the first extra one, after `what` (the rows declared).
    pub(crate) fn check_end(
        &mut self,
        what: &str,
        limits: &ReadLimits,
    ) -> std::result::Result<(), String> {
        match self.next_row(&mut Vec::new()) {
            Some(line) if !limits.lenient => Err(format!(
                "line {line}: data after {what} (the file is damaged, or its header's counts are wrong)"
            )),
            _ => Ok(()),
        }
    }

    /// Fill `values` with the next non-blank line's values; its line number.
    pub(crate) fn next_row(&mut self, values: &mut Vec<&'a str>) -> Option<usize> {
        for (i, line) in self.lines.by_ref() {
            values.clear();
            values.extend(line.split_ascii_whitespace());
            if !values.is_empty() {
                return Some(self.first + i + 1);
            }
        }
        None
    }
}

/// The text of an ascii body. Bytes that are not UTF-8 are an error naming
/// their line; read leniently, the text before them is used (the rows there
/// are still checked, and a row that needs more text fails as truncated).
pub(crate) fn ascii_text<'a>(
    header: &[u8],
    body: &'a [u8],
    limits: &ReadLimits,
) -> std::result::Result<&'a str, String> {
    match std::str::from_utf8(body) {
        Ok(t) => Ok(t),
        Err(e) => {
            let valid = &body[..e.valid_up_to()];
            if limits.lenient {
                return Ok(std::str::from_utf8(valid).expect("valid up to here"));
            }
            let line = header.iter().chain(valid).filter(|&&b| b == b'\n').count() + 1;
            Err(format!(
                "line {line}: the ascii data is not text (a byte that is not UTF-8 at body offset {})",
                e.valid_up_to()
            ))
        }
    }
}
