//! E57 (ASTM E2807) surveys: many scans to a file, one per scanner station,
//! each with its own pose. Every scan becomes a [`RecordedScan`] with its
//! points in the scan's own (scanner) frame, as the descriptor needs, and
//! its pose (position, and yaw for the map) from the scan's rigid-body
//! transform, so a building survey can be categorised room by room.
//!
//! Points are Cartesian, or spherical (range, azimuth, elevation) converted
//! to Cartesian. A point the scanner marks invalid (no return, or a
//! direction only) is kept as NaN, as the other readers keep non-finite
//! points: the descriptor drops them and `info` counts them.
//!
//! The scanner's tilt (roll, pitch of the pose) is not taken out: the
//! points stay in the frame the scanner recorded them in.

use super::poses::{yaw_from_quaternion, Pose};
use super::recording::RecordedScan;
use super::ReadLimits;
use crate::cloud::{Format, PointCloud};
use crate::error::{Error, Result};
use std::collections::HashSet;
use std::io::{Cursor, Read, Seek};

/// True when the bytes start with the E57 signature.
pub fn looks_like_e57(bytes: &[u8]) -> bool {
    bytes.starts_with(b"ASTM-E57")
}

/// Every scan of an E57 file, from its bytes, in file order. `name` (the
/// file's name) prefixes the scans' names; errors name the file and scan.
pub fn read_scans(bytes: &[u8], name: &str, limits: &ReadLimits) -> Result<Vec<RecordedScan>> {
    let mut scans = Vec::new();
    for_each_scan(bytes, name, limits, |s| {
        scans.push(s);
        Ok(())
    })?;
    Ok(scans)
}

/// [`read_scans`] one scan at a time, so that a survey of many large
/// stations need not be held whole: `f` gets each scan in file order, and
/// its error stops the reading.
pub fn for_each_scan(
    bytes: &[u8],
    name: &str,
    limits: &ReadLimits,
    f: impl FnMut(RecordedScan) -> Result<()>,
) -> Result<()> {
    limits
        .check_bytes(bytes.len())
        .and_then(|()| Survey::open(Cursor::new(bytes), name)?.each(limits, f))
        .map_err(|e| e.in_file(name))
}

/// Every scan of an E57 file on disk (native only), read through a buffer
/// rather than whole; errors name the path and scan.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_scans_path(path: &std::path::Path, limits: &ReadLimits) -> Result<Vec<RecordedScan>> {
    let mut scans = Vec::new();
    for_each_scan_path(path, limits, |s| {
        scans.push(s);
        Ok(())
    })?;
    Ok(scans)
}

/// [`for_each_scan`] for a file on disk (native only). The file is read a
/// page at a time, so its size is not held to `limits.max_bytes` (surveys
/// run to tens of gigabytes); each scan's point count is held to
/// `limits.max_points`.
#[cfg(not(target_arch = "wasm32"))]
pub fn for_each_scan_path(
    path: &std::path::Path,
    limits: &ReadLimits,
    f: impl FnMut(RecordedScan) -> Result<()>,
) -> Result<()> {
    let name = path.display().to_string();
    std::fs::File::open(path)
        .map_err(Error::from)
        .and_then(|file| Survey::open(std::io::BufReader::new(file), &name)?.each(limits, f))
        .map_err(|e| e.in_file(&name))
}

/// The scans of a survey one at a time, in file order, from any `Read +
/// Seek` (in the page: a [`super::source::SourceReader`] over `File.slice`),
/// so that only the scan being read is held. A scan that cannot be read is
/// an `Err` naming the file and the scan; the next call reads the next one.
pub struct SurveyScans<R: Read + Seek> {
    survey: Survey<R>,
    next: usize,
    limits: ReadLimits,
    file: String,
}

impl<R: Read + Seek> SurveyScans<R> {
    /// Open the survey in `reader`; `file` names it (and prefixes the scans'
    /// names). Reads the file's header and XML section, no points.
    pub fn open(reader: R, file: &str, limits: ReadLimits) -> Result<Self> {
        Self::open_as(reader, file, file, limits)
    }

    /// [`open`](Self::open), the scans named after `prefix` (e.g. the
    /// file's base name, `site.e57:hall`) while errors name `file`.
    pub fn open_as(reader: R, file: &str, prefix: &str, limits: ReadLimits) -> Result<Self> {
        Ok(SurveyScans {
            survey: Survey::open(reader, prefix).map_err(|e| e.in_file(file))?,
            next: 0,
            limits,
            file: file.to_string(),
        })
    }

    /// How many scans the survey holds.
    pub fn len(&self) -> usize {
        self.survey.clouds.len()
    }

    /// Never: a survey with no scans is refused when opened.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// How many scans were read so far (failed ones included).
    pub fn met(&self) -> usize {
        self.next
    }
}

impl<R: Read + Seek> Iterator for SurveyScans<R> {
    type Item = Result<RecordedScan>;

    fn next(&mut self) -> Option<Result<RecordedScan>> {
        let i = self.next;
        if i >= self.len() {
            return None;
        }
        self.next += 1;
        Some(
            self.survey
                .scan(i, &self.limits)
                .map_err(|e| e.in_file(&self.file)),
        )
    }
}

/// The one scan of a single-station E57, for [`super::read_scan`]; a survey
/// of several is refused, before any is read, with the advice to read its
/// scans one by one.
pub(crate) fn read_single(bytes: &[u8], limits: &ReadLimits) -> Result<PointCloud> {
    let mut survey = Survey::open(Cursor::new(bytes), "")?;
    if survey.clouds.len() > 1 {
        return Err(Error::E57(format!(
            "the survey holds {} scans; read them one by one (e57::read_scans; placecat describe and info do)",
            survey.clouds.len()
        )));
    }
    Ok(PointCloud {
        format: Format::E57,
        points: survey.scan(0, limits)?.points,
    })
}

/// The E57 crate's message (its Display already carries the cause, such as
/// "File appears to be truncated ...").
fn e57_err(e: ::e57::Error) -> Error {
    Error::E57(e.to_string())
}

/// An open survey: the scans' headers (from the XML section) and their
/// unique names, the points read on demand.
struct Survey<R: Read + Seek> {
    reader: ::e57::E57Reader<R>,
    clouds: Vec<::e57::PointCloud>,
    names: Vec<String>,
}

impl<R: Read + Seek> Survey<R> {
    fn open(reader: R, file: &str) -> Result<Self> {
        let reader = ::e57::E57Reader::new(reader).map_err(e57_err)?;
        let clouds = reader.pointclouds();
        if clouds.is_empty() {
            return Err(Error::E57(
                "the file holds no scans (data3D is empty)".into(),
            ));
        }
        let mut seen = HashSet::new();
        let names = clouds
            .iter()
            .enumerate()
            .map(|(i, pc)| unique_name(file, i, pc.name.as_deref(), &mut seen))
            .collect();
        Ok(Survey {
            reader,
            clouds,
            names,
        })
    }

    fn each(
        &mut self,
        limits: &ReadLimits,
        mut f: impl FnMut(RecordedScan) -> Result<()>,
    ) -> Result<()> {
        (0..self.clouds.len()).try_for_each(|i| f(self.scan(i, limits)?))
    }

    /// Scan `i`: points in its own frame, invalid ones as NaN.
    fn scan(&mut self, i: usize, limits: &ReadLimits) -> Result<RecordedScan> {
        let pc = &self.clouds[i];
        let label = match &pc.name {
            Some(n) if !n.trim().is_empty() => format!("scan {i} ({})", n.trim()),
            _ => format!("scan {i}"),
        };
        let in_scan = |e: String| Error::E57(format!("{label}: {e}"));
        let n = limits
            .check_points(pc.records)
            .map_err(|e| in_scan(e.to_string()))?;
        if !pc.has_cartesian() && !pc.has_spherical() {
            return Err(in_scan(
                "neither Cartesian nor spherical coordinates".into(),
            ));
        }
        let mut reader = self
            .reader
            .pointcloud_simple(pc)
            .map_err(|e| in_scan(e.to_string()))?;
        // The scanner's frame, not the survey's: the pose goes with the scan.
        reader.apply_pose(false);
        reader.spherical_to_cartesian(true);
        reader.intensity_to_color(false);
        reader.normalize_intensity(false);
        reader.normalize_color(false);
        let mut points = Vec::with_capacity(n);
        for p in reader {
            let p = p.map_err(|e| in_scan(e.to_string()))?;
            points.push(match p.cartesian {
                ::e57::CartesianCoordinate::Valid { x, y, z } => [x as f32, y as f32, z as f32],
                _ => [f32::NAN; 3],
            });
        }
        if points.len() != n {
            return Err(in_scan(format!(
                "{} points read, the scan declares {n}",
                points.len()
            )));
        }
        let name = self.names[i].clone();
        let stamp = pc.acquisition_start.as_ref().map(|d| d.gps_time);
        let pose = pc.transform.as_ref().map(|t| Pose {
            name: Some(name.clone()),
            time: stamp,
            position: [t.translation.x, t.translation.y, t.translation.z],
            yaw: yaw_from_quaternion(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w),
        });
        Ok(RecordedScan {
            name,
            points,
            stamp,
            pose,
        })
    }
}

/// `FILE:NAME` with the scan's own name, `FILE:scan N` (N from 0, the
/// file's order) without one, and `FILE:NAME (scan N)` for a name already
/// taken: surveys often call every station "Scan".
fn unique_name(file: &str, index: usize, own: Option<&str>, seen: &mut HashSet<String>) -> String {
    let base = match own.map(str::trim) {
        Some(n) if !n.is_empty() => format!("{file}:{n}"),
        _ => format!("{file}:scan {index}"),
    };
    let name = if seen.contains(&base) {
        format!("{base} (scan {index})")
    } else {
        base
    };
    seen.insert(name.clone());
    name
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_say_where_the_scan_came_from() {
        let mut seen = HashSet::new();
        let names: Vec<String> = [Some("hall"), None, Some("hall"), Some("  "), Some("scan 1")]
            .iter()
            .enumerate()
            .map(|(i, n)| unique_name("s.e57", i, *n, &mut seen))
            .collect();
        assert_eq!(
            names,
            [
                "s.e57:hall",
                "s.e57:scan 1",
                "s.e57:hall (scan 2)",
                "s.e57:scan 3",
                "s.e57:scan 1 (scan 4)"
            ]
        );
    }
}
