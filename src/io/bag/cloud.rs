//! `sensor_msgs/PointCloud2` of any field layout: x, y, z found by name as
//! float32 or float64 at any offset, points `point_step` apart in rows
//! `row_step` apart (padding allowed), either byte order, organised clouds
//! (height > 1) kept whole, NaN included, as the other readers do.

use super::msg::{Cursor, Encoding};
use crate::error::{Error, Result};
use crate::io::ReadLimits;

/// The header of a cloud and where its point bytes are.
pub(crate) struct CloudMsg<'a> {
    pub(crate) stamp: f64,
    pub(crate) frame_id: String,
    cursor: Cursor<'a>,
}

/// Read the header only: enough to decide whether to keep the cloud
/// (thinning) before paying for its points.
pub(crate) fn header(data: &[u8], enc: Encoding) -> Result<CloudMsg<'_>> {
    let mut cursor = Cursor::new(data, enc)?;
    let (stamp, frame_id) = cursor.header()?;
    Ok(CloudMsg {
        stamp,
        frame_id,
        cursor,
    })
}

const FLOAT32: u8 = 7;
const FLOAT64: u8 = 8;

struct Field {
    name: String,
    offset: u32,
    datatype: u8,
}

impl CloudMsg<'_> {
    /// The points as f32 (float64 coordinates are narrowed, as the
    /// descriptor works in f32), in file order, non-finite ones included.
    pub(crate) fn points(mut self, limits: &ReadLimits) -> Result<Vec<[f32; 3]>> {
        let c = &mut self.cursor;
        let height = c.u32("height")? as u64;
        let width = c.u32("width")? as u64;
        let nfields = c.u32("fields")? as usize;
        if nfields > 1024 {
            return Err(Error::Bag(format!("PointCloud2 claims {nfields} fields")));
        }
        let mut fields = Vec::with_capacity(nfields);
        for _ in 0..nfields {
            let name = c.string("fields.name")?;
            let offset = c.u32("fields.offset")?;
            let datatype = c.u8("fields.datatype")?;
            c.u32("fields.count")?;
            fields.push(Field {
                name,
                offset,
                datatype,
            });
        }
        let big = c.u8("is_bigendian")? != 0;
        let point_step = c.u32("point_step")? as u64;
        let row_step = c.u32("row_step")? as u64;
        let len = c.u32("data")? as usize;
        let data = c.bytes(len, "data")?;

        let names: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
        let mut xyz = [(0usize, false); 3];
        for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
            let f = fields.iter().find(|f| f.name == axis).ok_or_else(|| {
                Error::Bag(format!(
                    "PointCloud2 has no field {axis:?} (fields: {}); placecat needs x, y, z",
                    names.join(", ")
                ))
            })?;
            let wide = match f.datatype {
                FLOAT32 => false,
                FLOAT64 => true,
                t => {
                    return Err(Error::Bag(format!(
                        "PointCloud2 field {axis:?} has datatype {t}; placecat reads float32 (7) \
                         and float64 (8)"
                    )))
                }
            };
            let size = if wide { 8 } else { 4 };
            if f.offset as u64 + size > point_step {
                return Err(Error::Bag(format!(
                    "PointCloud2 field {axis:?} at offset {} does not fit in point_step \
                     {point_step}",
                    f.offset
                )));
            }
            xyz[k] = (f.offset as usize, wide);
        }
        let n = limits.check_points(height.saturating_mul(width))?;
        if width > 0 && height > 0 {
            // The bytes the last x/y/z of a row reach; trailing padding may be absent.
            let end = xyz
                .iter()
                .map(|&(o, w)| o as u64 + if w { 8 } else { 4 })
                .max();
            let row_len = (width - 1) * point_step + end.unwrap_or(0);
            let need = (height - 1)
                .saturating_mul(row_step)
                .saturating_add(row_len);
            if (height > 1 && row_step < row_len) || need > data.len() as u64 {
                return Err(Error::Bag(format!(
                    "PointCloud2 of {height} x {width} points (point_step {point_step}, \
                     row_step {row_step}) needs {need} data bytes, it has {}",
                    data.len()
                )));
            }
        }
        let read = |at: usize, wide: bool| -> f32 {
            if wide {
                let b: [u8; 8] = data[at..at + 8].try_into().expect("8 bytes");
                (if big {
                    f64::from_be_bytes(b)
                } else {
                    f64::from_le_bytes(b)
                }) as f32
            } else {
                let b: [u8; 4] = data[at..at + 4].try_into().expect("4 bytes");
                if big {
                    f32::from_be_bytes(b)
                } else {
                    f32::from_le_bytes(b)
                }
            }
        };
        let mut points = Vec::with_capacity(n);
        for r in 0..height as usize {
            let row = r * row_step as usize;
            for i in 0..width as usize {
                let p = row + i * point_step as usize;
                points.push(xyz.map(|(off, wide)| read(p + off, wide)));
            }
        }
        Ok(points)
    }
}
