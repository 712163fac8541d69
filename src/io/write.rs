//! Writers for the formats placecat reads: used by the simulator, by tests
//! (round trips) and by anyone converting scans.

use crate::error::Result;

/// PLY encodings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlyEncoding {
    /// `ascii`: one vertex a line.
    Ascii,
    /// `binary_little_endian`: the compact form most tools write.
    BinaryLittleEndian,
    /// `binary_big_endian`.
    BinaryBigEndian,
}

/// Write points as a PLY file with x, y, z of float32 (`double = false`) or
/// float64.
pub fn ply(points: &[[f32; 3]], encoding: PlyEncoding, double: bool) -> Vec<u8> {
    let fmt = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::BinaryBigEndian => "binary_big_endian",
    };
    let t = if double { "double" } else { "float" };
    let mut out = format!(
        "ply\nformat {fmt} 1.0\ncomment written by placecat\nelement vertex {}\nproperty {t} x\nproperty {t} y\nproperty {t} z\nend_header\n",
        points.len()
    )
    .into_bytes();
    let width = if double { 24 } else { 12 };
    out.reserve(points.len() * width);
    for p in points {
        match encoding {
            PlyEncoding::Ascii => {
                out.extend_from_slice(format!("{} {} {}\n", p[0], p[1], p[2]).as_bytes())
            }
            PlyEncoding::BinaryLittleEndian => {
                for v in p {
                    if double {
                        out.extend_from_slice(&(*v as f64).to_le_bytes())
                    } else {
                        out.extend_from_slice(&v.to_le_bytes())
                    }
                }
            }
            PlyEncoding::BinaryBigEndian => {
                for v in p {
                    if double {
                        out.extend_from_slice(&(*v as f64).to_be_bytes())
                    } else {
                        out.extend_from_slice(&v.to_be_bytes())
                    }
                }
            }
        }
    }
    out
}

/// PCD DATA kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PcdData {
    /// `DATA ascii`: one point a line.
    Ascii,
    /// `DATA binary`: packed records.
    Binary,
    /// `DATA binary_compressed`: LZF over the columns.
    BinaryCompressed,
}

/// Write points as a PCD v0.7 file with float32 x, y, z.
pub fn pcd(points: &[[f32; 3]], data: PcdData) -> Result<Vec<u8>> {
    let kind = match data {
        PcdData::Ascii => "ascii",
        PcdData::Binary => "binary",
        PcdData::BinaryCompressed => "binary_compressed",
    };
    let n = points.len();
    let mut out = format!(
        "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH {n}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA {kind}\n"
    )
    .into_bytes();
    match data {
        PcdData::Ascii => {
            for p in points {
                out.extend_from_slice(format!("{} {} {}\n", p[0], p[1], p[2]).as_bytes());
            }
        }
        PcdData::Binary => {
            for p in points {
                for v in p {
                    out.extend_from_slice(&v.to_le_bytes());
                }
            }
        }
        PcdData::BinaryCompressed => {
            let mut raw = Vec::with_capacity(n * 12);
            for k in 0..3 {
                for p in points {
                    raw.extend_from_slice(&p[k].to_le_bytes());
                }
            }
            let packed = super::lzf_pack::compress(&raw);
            out.extend_from_slice(&(packed.len() as u32).to_le_bytes());
            out.extend_from_slice(&(raw.len() as u32).to_le_bytes());
            out.extend_from_slice(&packed);
        }
    }
    Ok(out)
}

/// Write points as a KITTI `.bin` (intensity 0).
pub fn kitti(points: &[[f32; 3]]) -> Vec<u8> {
    let mut out = Vec::with_capacity(points.len() * 16);
    for p in points {
        for v in p {
            out.extend_from_slice(&v.to_le_bytes());
        }
        out.extend_from_slice(&0f32.to_le_bytes());
    }
    out
}
