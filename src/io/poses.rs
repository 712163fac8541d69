//! Poses of the scans, for the trajectory map: KITTI (12 numbers a row, a
//! 3x4 [R|t]), TUM (`t tx ty tz qx qy qz qw`) and CSV (`name,x,y[,z]`, with or
//! without a header). The format is recognised from the rows.

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Which poses format a file was in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
#[serde(rename_all = "lowercase")]
pub enum PoseFormat {
    /// KITTI odometry: 12 numbers a row, a 3x4 [R|t] matrix row-major.
    Kitti,
    /// TUM RGB-D: `t tx ty tz qx qy qz qw` a row.
    Tum,
    /// `name,x,y[,z]` a row, with or without a header.
    Csv,
}

/// One pose: position and heading (yaw about z, radians) of the sensor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Pose {
    /// Scan name for CSV rows; None for KITTI and TUM (matched by order).
    pub name: Option<String>,
    /// Timestamp for TUM rows.
    pub time: Option<f64>,
    /// Sensor position x, y, z (m) in the poses file's world frame.
    pub position: [f64; 3],
    /// Heading about z (radians, counter-clockwise from +x).
    pub yaw: f64,
}

/// A parsed poses file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Poses {
    /// The format recognised from the rows.
    pub format: PoseFormat,
    /// One pose a row, in file order.
    pub poses: Vec<Pose>,
}

fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Poses(msg.into()))
}

fn numbers(line: &str, lineno: usize) -> Result<Vec<f64>> {
    line.split_ascii_whitespace()
        .map(|w| {
            w.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| Error::Poses(format!("line {lineno}: {w:?} is not a finite number")))
        })
        .collect()
}

/// Parse a poses file's text.
pub fn parse(text: &str) -> Result<Poses> {
    let rows: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let Some(&(_, first)) = rows.first() else {
        return err("the file has no pose rows");
    };
    if first.contains(',') {
        return parse_csv(&rows);
    }
    let width = first.split_ascii_whitespace().count();
    let format = match width {
        12 => PoseFormat::Kitti,
        8 => PoseFormat::Tum,
        n => {
            return err(format!(
                "line {}: {n} numbers; KITTI rows have 12, TUM rows 8 (t tx ty tz qx qy qz qw), CSV rows name,x,y[,z]",
                rows[0].0
            ))
        }
    };
    let mut poses = Vec::with_capacity(rows.len());
    for &(lineno, line) in &rows {
        let v = numbers(line, lineno)?;
        if v.len() != width {
            return err(format!(
                "line {lineno}: {} numbers, the first row had {width}",
                v.len()
            ));
        }
        poses.push(match format {
            PoseFormat::Kitti => Pose {
                name: None,
                time: None,
                position: [v[3], v[7], v[11]],
                // R = [[r00 r01 r02], [r10 r11 r12], ...]; yaw of the x axis.
                yaw: v[4].atan2(v[0]),
            },
            _ => {
                let (qx, qy, qz, qw) = (v[4], v[5], v[6], v[7]);
                let norm = (qx * qx + qy * qy + qz * qz + qw * qw).sqrt();
                if (norm - 1.0).abs() > 0.05 {
                    return err(format!(
                        "line {lineno}: quaternion has norm {norm:.3}, not 1 (is this a TUM file?)"
                    ));
                }
                Pose {
                    name: None,
                    time: Some(v[0]),
                    position: [v[1], v[2], v[3]],
                    yaw: yaw_from_quaternion(qx, qy, qz, qw),
                }
            }
        });
    }
    Ok(Poses { format, poses })
}

/// Heading (rotation about z, radians) of a unit quaternion, as the map
/// draws it; roll and pitch are left out.
pub fn yaw_from_quaternion(qx: f64, qy: f64, qz: f64, qw: f64) -> f64 {
    (2.0 * (qw * qz + qx * qy)).atan2(1.0 - 2.0 * (qy * qy + qz * qz))
}

fn parse_csv(rows: &[(usize, &str)]) -> Result<Poses> {
    let mut poses = Vec::with_capacity(rows.len());
    for (i, &(lineno, line)) in rows.iter().enumerate() {
        // One CSV module for every CSV: a name may be quoted and hold commas.
        let cells =
            super::csv::parse_line(line, lineno).map_err(|e| Error::Poses(e.to_string()))?;
        let cells: Vec<&str> = cells.iter().map(|c| c.trim()).collect();
        if cells.len() < 3 {
            return err(format!("line {lineno}: CSV rows need name,x,y[,z]"));
        }
        let coords = &cells[1..cells.len().min(4)];
        let nums: Option<Vec<f64>> = coords
            .iter()
            .map(|c| c.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect();
        // A header has words where the numbers go; a row with "NaN" or one
        // number missing is a bad row, not a header.
        let words = coords.iter().all(|c| c.parse::<f64>().is_err());
        match nums {
            Some(v) => poses.push(Pose {
                name: Some(cells[0].to_string()),
                time: None,
                position: [v[0], v[1], v.get(2).copied().unwrap_or(0.0)],
                yaw: 0.0,
            }),
            None if i == 0 && words => {}
            None => return err(format!("line {lineno}: x, y, z must be finite numbers")),
        }
    }
    if poses.is_empty() {
        return err("the CSV file has a header but no pose rows");
    }
    Ok(Poses {
        format: PoseFormat::Csv,
        poses,
    })
}

/// Write poses as KITTI rows (rotation about z by yaw).
pub fn to_kitti(poses: &[Pose]) -> String {
    poses
        .iter()
        .map(|p| {
            let (s, c) = p.yaw.sin_cos();
            let [x, y, z] = p.position;
            format!(
                "{c:.9} {:.9} 0 {x:.6} {s:.9} {c:.9} 0 {y:.6} 0 0 1 {z:.6}\n",
                -s
            )
        })
        .collect()
}

/// Write poses as TUM rows (time = index when absent).
pub fn to_tum(poses: &[Pose]) -> String {
    poses
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let (qz, qw) = ((p.yaw / 2.0).sin(), (p.yaw / 2.0).cos());
            let [x, y, z] = p.position;
            let t = p.time.unwrap_or(i as f64);
            format!("{t:.6} {x:.6} {y:.6} {z:.6} 0 0 {qz:.9} {qw:.9}\n")
        })
        .collect()
}
