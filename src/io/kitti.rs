//! KITTI velodyne `.bin`: float32 x, y, z, intensity per point, little endian,
//! no header. Ouster and other tools write the same layout.

use super::ReadLimits;
use crate::cloud::{Format, PointCloud};
use crate::error::{Error, Result};

/// Bytes per point: four float32.
pub const RECORD: usize = 16;

/// Read a KITTI `.bin` from its bytes.
pub fn read(bytes: &[u8], limits: &ReadLimits) -> Result<PointCloud> {
    if bytes.is_empty() {
        return Err(Error::Kitti("the file is empty".into()));
    }
    if bytes.len() % RECORD != 0 {
        return Err(Error::Kitti(format!(
            "{} bytes is not a whole number of 16-byte points (truncated, or not a KITTI scan)",
            bytes.len()
        )));
    }
    let n = limits.check_points((bytes.len() / RECORD) as u64)?;
    let f = |r: &[u8], o: usize| f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]]);
    let mut points = Vec::with_capacity(n);
    points.extend(
        bytes
            .chunks_exact(RECORD)
            .map(|r| [f(r, 0), f(r, 4), f(r, 8)]),
    );
    Ok(PointCloud {
        format: Format::KittiBin,
        points,
    })
}
