//! A scan as read from a file: points in the sensor frame, in file order.

use serde::{Deserialize, Serialize};

/// Which format a scan was read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Format {
    /// PLY, `format ascii 1.0`.
    PlyAscii,
    /// PLY, `format binary_little_endian 1.0`.
    PlyBinaryLittleEndian,
    /// PLY, `format binary_big_endian 1.0`.
    PlyBinaryBigEndian,
    /// PCD v0.7, `DATA ascii`.
    PcdAscii,
    /// PCD v0.7, `DATA binary`.
    PcdBinary,
    /// PCD v0.7, `DATA binary_compressed` (LZF).
    PcdBinaryCompressed,
    /// KITTI velodyne `.bin`: float32 x, y, z, intensity, no header.
    KittiBin,
    /// LAS (ASPRS 1.0-1.4), uncompressed.
    Las,
    /// LAZ: LAS compressed with LASzip.
    Laz,
    /// One scan of an E57 (ASTM E2807) survey.
    E57,
}

impl Format {
    /// The name used in `placecat info` output.
    pub fn name(self) -> &'static str {
        match self {
            Format::PlyAscii => "ply_ascii",
            Format::PlyBinaryLittleEndian => "ply_binary_little_endian",
            Format::PlyBinaryBigEndian => "ply_binary_big_endian",
            Format::PcdAscii => "pcd_ascii",
            Format::PcdBinary => "pcd_binary",
            Format::PcdBinaryCompressed => "pcd_binary_compressed",
            Format::KittiBin => "kitti_bin",
            Format::Las => "las",
            Format::Laz => "laz",
            Format::E57 => "e57",
        }
    }
}

/// Points exactly as the file holds them (non-finite ones included, so that
/// `info` can show the file as it is); the descriptor drops non-finite points.
#[derive(Debug, Clone, PartialEq)]
pub struct PointCloud {
    /// The format the bytes were read as (sniffed, or from the file name).
    pub format: Format,
    /// x, y, z of each point in the sensor frame (m), in file order.
    pub points: Vec<[f32; 3]>,
}

impl PointCloud {
    /// Number of points whose three coordinates are all finite.
    pub fn finite_count(&self) -> usize {
        self.points.iter().filter(|p| is_finite(p)).count()
    }
}

/// True when x, y and z are all finite.
#[inline]
pub fn is_finite(p: &[f32; 3]) -> bool {
    p[0].is_finite() && p[1].is_finite() && p[2].is_finite()
}

/// At most `max` finite points, evenly strided through the scan (for maps
/// and thumbnails), as interleaved x, y, z.
pub fn decimate(points: &[[f32; 3]], max: usize) -> Vec<f32> {
    if max == 0 {
        return Vec::new();
    }
    decimate_counted(points, points.iter().filter(|p| is_finite(p)).count(), max)
}

/// [`decimate`] when the number of finite points is known (a descriptor's
/// summary counts them): one pass over the points instead of two (the
/// counting pass was 4 % of describing a KITTI scan in wasm).
pub fn decimate_counted(points: &[[f32; 3]], finite: usize, max: usize) -> Vec<f32> {
    if max == 0 || finite == 0 {
        return Vec::new();
    }
    let step = finite.div_ceil(max);
    points
        .iter()
        .filter(|p| is_finite(p))
        .step_by(step)
        .flat_map(|p| p.iter().copied())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimate_strides_through_the_finite_points_and_the_counted_form_agrees() {
        let nan = f32::NAN;
        let points: Vec<[f32; 3]> = (0..10)
            .map(|i| {
                if i % 3 == 1 {
                    [nan, 0.0, 0.0]
                } else {
                    [i as f32, 0.0, 1.0]
                }
            })
            .collect();
        // Finite: 0, 2, 3, 5, 6, 8, 9 (7 points); at most 3 -> every 3rd.
        let d = decimate(&points, 3);
        assert_eq!(d, vec![0.0, 0.0, 1.0, 5.0, 0.0, 1.0, 9.0, 0.0, 1.0]);
        assert_eq!(decimate_counted(&points, 7, 3), d);
        assert!(decimate(&points, 0).is_empty());
        assert!(decimate_counted(&points, 0, 3).is_empty());
    }
}
