//! LAS and LAZ (ASPRS LAS 1.0-1.4, LASzip): one scan per file.
//!
//! Coordinates are integers with a scale and an offset per axis, often
//! georeferenced (UTM northings of 6e6 m), where a float32 has a step of
//! 0.5 m. So each point is taken to float64 (`i * scale + offset`), the
//! sensor position is subtracted in float64, and only the sensor-centred
//! result becomes float32: centimetres survive.
//!
//! Where the sensor was: LAS headers carry no sensor position (the header
//! has scale, offset and the points' bounding box; the offset is a
//! quantisation anchor, usually a round number, and the bounding box centre
//! at ground level is where the points are, not where the scanner stood). So:
//! - a given `origin` is the sensor position, in the file's coordinates;
//! - without one, the file's own origin (0, 0, 0) is taken as the sensor when
//!   it lies inside the x-y bounding box grown by [`SENSOR_MARGIN`] (a scan
//!   exported in its scanner's frame surrounds its scanner);
//! - otherwise the file is refused with the bounding box and a hint, rather
//!   than described around a made-up centre.
//!
//! The header's bounding box is also a check of the points: LAZ has no
//! checksums, and a damaged chunk decodes to points far outside it. Read
//! leniently ([`ReadLimits::lenient`]) the box is not checked, for files
//! whose writer left it stale.
//!
//! Bytes are read in place (no copy of the file); LAZ is decompressed a
//! batch of points at a time.

use super::ReadLimits;
use crate::cloud::{Format, PointCloud};
use crate::error::{Error, Result};
use std::io::Cursor;

/// How far (m) outside the x-y bounding box the file's origin may lie and
/// still be taken as the sensor: a forward-looking scanner sees nothing in
/// its first metres.
pub const SENSOR_MARGIN: f64 = 5.0;

/// LAZ points decompressed per batch.
const BATCH: usize = 65_536;

fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Las(msg.into()))
}

fn las_err(e: impl std::fmt::Display) -> Error {
    Error::Las(e.to_string())
}

/// True when the bytes start with the LAS signature.
pub fn looks_like_las(bytes: &[u8]) -> bool {
    bytes.starts_with(b"LASF")
}

/// Read a LAS or LAZ file from its bytes. `origin` is the sensor position in
/// the file's (scaled, offset) coordinates; see the module notes for `None`.
pub fn read(bytes: &[u8], limits: &ReadLimits, origin: Option<[f64; 3]>) -> Result<PointCloud> {
    // The raw header first: its point count goes through the limit before
    // anything trusts it (the las crate multiplies it unchecked).
    let raw = ::las::raw::Header::read_from(Cursor::new(bytes)).map_err(las_err)?;
    // LAS 1.4 readers take the legacy 32-bit count when it is not zero.
    let count = match (raw.number_of_point_records, &raw.large_file) {
        (0, Some(large)) => large.number_of_point_records,
        (legacy, _) => u64::from(legacy),
    };
    let n = limits.check_points(count)?;
    let record = usize::from(raw.point_data_record_length);
    let mut cursor = Cursor::new(bytes);
    let header = ::las::Header::new(&mut cursor).map_err(las_err)?;
    let start = cursor.position() as usize;
    let t = header.transforms();
    let scale = [t.x.scale, t.y.scale, t.z.scale];
    let offset = [t.x.offset, t.y.offset, t.z.offset];
    if scale.iter().any(|s| !s.is_finite() || *s == 0.0) || offset.iter().any(|o| !o.is_finite()) {
        return err(format!(
            "the header's scale {scale:?} / offset {offset:?} is not usable"
        ));
    }
    let bounds = header.bounds();
    let (lo, hi) = (
        [bounds.min.x, bounds.min.y, bounds.min.z],
        [bounds.max.x, bounds.max.y, bounds.max.z],
    );
    let origin = match origin {
        Some(o) if o.iter().all(|v| v.is_finite()) => o,
        Some(o) => return err(format!("the sensor position {o:?} is not finite")),
        None => file_origin(lo, hi)?,
    };
    let compressed = header.point_format().is_compressed;

    // A point outside the declared box (by more than a quantisation step) is
    // damage, or a header that does not describe its points: refuse both.
    let mut points = Vec::with_capacity(n);
    let mut push = |i: usize, raw: [i32; 3]| -> Result<()> {
        let mut p = [0f32; 3];
        for a in 0..3 {
            let v = f64::from(raw[a]) * scale[a] + offset[a];
            let outside = v < lo[a] - scale[a].abs() || v > hi[a] + scale[a].abs();
            if outside && !limits.lenient {
                return err(format!(
                    "point {i} has {} = {v} outside the header's bounding box [{}, {}]: the point data is damaged or the header does not describe it",
                    ["x", "y", "z"][a],
                    lo[a],
                    hi[a]
                ));
            }
            p[a] = (v - origin[a]) as f32;
        }
        points.push(p);
        Ok(())
    };

    if compressed {
        let vlr = header.laz_vlr().map_err(las_err)?;
        let record = vlr.items_size() as usize;
        // The laz crate asserts on some damaged input instead of returning
        // an error (in debug builds; release ones decode garbage, which the
        // bounding box catches). Natively the panic becomes this error; in
        // wasm, where panics abort, release builds have no such assertions.
        let decoded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let mut decoder = ::laz::LasZipDecompressor::new(cursor, vlr).map_err(las_err)?;
            let mut buf = vec![0u8; BATCH.min(n.max(1)) * record];
            let mut done = 0;
            while done < n {
                let m = BATCH.min(n - done);
                let chunk = &mut buf[..m * record];
                decoder.decompress_many(chunk).map_err(|e| {
                    Error::Las(format!(
                        "LAZ data damaged or cut short in points {done}..{} of {n}: {e}",
                        done + m
                    ))
                })?;
                for (j, r) in chunk.chunks_exact(record).enumerate() {
                    push(done + j, xyz(r))?;
                }
                done += m;
            }
            Ok(())
        }));
        decoded.unwrap_or_else(|_| err("LAZ data damaged: the decompressor failed"))?;
    } else {
        let end = n
            .checked_mul(record)
            .and_then(|len| len.checked_add(start))
            .filter(|&end| end <= bytes.len());
        let Some(end) = end else {
            return err(format!(
                "the header declares {n} points of {record} bytes from byte {start}, but the file has {} bytes (truncated?)",
                bytes.len()
            ));
        };
        for (i, r) in bytes[start..end].chunks_exact(record).enumerate() {
            push(i, xyz(r))?;
        }
    }
    Ok(PointCloud {
        format: if compressed { Format::Laz } else { Format::Las },
        points,
    })
}

/// X, Y, Z: the first 12 bytes of every LAS point record (formats 0-10).
fn xyz(record: &[u8]) -> [i32; 3] {
    let f = |o: usize| i32::from_le_bytes([record[o], record[o + 1], record[o + 2], record[o + 3]]);
    [f(0), f(4), f(8)]
}

/// The sensor position when none is given: the file's origin if the points
/// surround it, else an error that says what the header offers.
fn file_origin(lo: [f64; 3], hi: [f64; 3]) -> Result<[f64; 3]> {
    let inside = (0..2).all(|a| lo[a] - SENSOR_MARGIN <= 0.0 && 0.0 <= hi[a] + SENSOR_MARGIN);
    if inside {
        return Ok([0.0; 3]);
    }
    let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, lo[2]];
    err(format!(
        "no sensor position: the points span x {:.3}..{:.3}, y {:.3}..{:.3}, z {:.3}..{:.3}, away from the file's origin (georeferenced?), and LAS headers do not record where the scanner stood. Give the sensor position in the file's coordinates (placecat --origin x,y,z). The bounding box centre at ground level, {:.3},{:.3},{:.3}, is not a sensor position: pass it only if the scanner stood near there",
        lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], centre[0], centre[1], centre[2]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_origin_is_taken_only_when_the_points_surround_it() {
        assert_eq!(
            file_origin([-3.0, -2.0, -1.2], [4.0, 2.0, 1.4]).unwrap(),
            [0.0; 3]
        );
        // A forward-looking scanner: nothing behind it, nothing in its first metres.
        assert_eq!(
            file_origin([2.0, -8.0, -1.0], [30.0, 8.0, 3.0]).unwrap(),
            [0.0; 3]
        );
        let e = file_origin([512337.0, 6123451.0, 97.5], [512353.0, 6123461.0, 100.2])
            .unwrap_err()
            .to_string();
        assert!(e.contains("no sensor position"), "{e}");
        assert!(e.contains("512345.000,6123456.000,97.500"), "{e}");
        assert!(e.contains("is not a sensor position"), "{e}");
    }
}
