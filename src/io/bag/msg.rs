//! Decoding the few ROS messages placecat needs from their two wire forms:
//! ROS 1 serialisation (little-endian, packed) and ROS 2 CDR (a 4-byte
//! encapsulation header saying the byte order, then each primitive aligned to
//! its size, counted from the end of that header).

use crate::error::{Error, Result};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};

/// How a connection's messages are serialised.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Encoding {
    Ros1,
    Cdr,
}

/// A reader over one serialised message.
pub(crate) struct Cursor<'a> {
    buf: &'a [u8],
    pos: usize,
    /// Offset that alignment counts from (after the CDR header); None = packed.
    align_base: Option<usize>,
    little: bool,
    enc: Encoding,
}

fn short(what: &str) -> Error {
    Error::Bag(format!("message too short: it ends inside {what}"))
}

impl<'a> Cursor<'a> {
    pub(crate) fn new(buf: &'a [u8], enc: Encoding) -> Result<Self> {
        match enc {
            Encoding::Ros1 => Ok(Cursor {
                buf,
                pos: 0,
                align_base: None,
                little: true,
                enc,
            }),
            Encoding::Cdr => {
                // Byte 1 of the encapsulation: even = big-endian, odd = little
                // (CDR_BE 0, CDR_LE 1, PL_CDR_BE 2, PL_CDR_LE 3, ...).
                if buf.len() < 4 {
                    return Err(short("the CDR encapsulation header"));
                }
                Ok(Cursor {
                    buf,
                    pos: 4,
                    align_base: Some(4),
                    little: buf[1] & 1 == 1,
                    enc,
                })
            }
        }
    }

    fn align(&mut self, n: usize) {
        if let Some(base) = self.align_base {
            let rel = self.pos - base;
            self.pos += (n - rel % n) % n;
        }
    }

    pub(crate) fn bytes(&mut self, n: usize, what: &str) -> Result<&'a [u8]> {
        let end = self.pos.checked_add(n).filter(|&e| e <= self.buf.len());
        let end = end.ok_or_else(|| short(what))?;
        let b = &self.buf[self.pos..end];
        self.pos = end;
        Ok(b)
    }

    fn fixed<const N: usize>(&mut self, what: &str) -> Result<[u8; N]> {
        self.align(N);
        let mut a: [u8; N] = self.bytes(N, what)?.try_into().expect("N bytes");
        if !self.little {
            a.reverse();
        }
        Ok(a)
    }

    pub(crate) fn u8(&mut self, what: &str) -> Result<u8> {
        Ok(self.bytes(1, what)?[0])
    }
    pub(crate) fn u32(&mut self, what: &str) -> Result<u32> {
        Ok(u32::from_le_bytes(self.fixed(what)?))
    }
    fn f64(&mut self, what: &str) -> Result<f64> {
        Ok(f64::from_le_bytes(self.fixed(what)?))
    }

    pub(crate) fn string(&mut self, what: &str) -> Result<String> {
        let n = self.u32(what)? as usize;
        let b = self.bytes(n, what)?;
        // CDR strings carry their terminating NUL in the length.
        let b = b.strip_suffix(&[0]).unwrap_or(b);
        Ok(String::from_utf8_lossy(b).into_owned())
    }

    /// `std_msgs/Header`: (stamp in seconds, frame_id). ROS 1 has a `seq`
    /// first; ROS 2 does not, and its seconds are signed.
    pub(crate) fn header(&mut self) -> Result<(f64, String)> {
        if self.enc == Encoding::Ros1 {
            self.u32("header.seq")?;
        }
        let sec = self.u32("header.stamp")?;
        let sec = match self.enc {
            Encoding::Ros1 => sec as f64,
            Encoding::Cdr => sec as i32 as f64,
        };
        let nsec = self.u32("header.stamp")?;
        let frame = self.string("header.frame_id")?;
        Ok((sec + nsec as f64 * 1e-9, frame))
    }

    /// Position (Point / Vector3) then orientation (Quaternion x y z w).
    fn isometry(&mut self, what: &str) -> Result<Isometry3<f64>> {
        let mut v = [0.0; 7];
        for x in &mut v {
            *x = self.f64(what)?;
        }
        let q = Quaternion::new(v[6], v[3], v[4], v[5]);
        if !v.iter().all(|x| x.is_finite()) || q.norm() < 1e-9 {
            return Err(Error::Bag(format!("{what} is not a finite pose")));
        }
        Ok(Isometry3::from_parts(
            Translation3::new(v[0], v[1], v[2]),
            UnitQuaternion::from_quaternion(q),
        ))
    }
}

/// One timed transform: `parent -> child` at `stamp`.
#[derive(Debug, Clone)]
pub(crate) struct Transform {
    pub(crate) stamp: f64,
    pub(crate) parent: String,
    pub(crate) child: String,
    pub(crate) iso: Isometry3<f64>,
}

/// `nav_msgs/Odometry`: the pose of `child_frame_id` in `header.frame_id`.
pub(crate) fn odometry(data: &[u8], enc: Encoding) -> Result<Transform> {
    let mut c = Cursor::new(data, enc)?;
    let (stamp, parent) = c.header()?;
    let child = c.string("child_frame_id")?;
    let iso = c.isometry("pose.pose")?;
    Ok(Transform {
        stamp,
        parent: frame(&parent),
        child: frame(&child),
        iso,
    })
}

/// tf frame names without the leading slash that ROS 1 allowed.
pub(crate) fn frame(name: &str) -> String {
    name.trim_start_matches('/').to_string()
}

/// `tf2_msgs/TFMessage` (ROS 1 `tf/tfMessage` too): its transforms.
pub(crate) fn tf_message(data: &[u8], enc: Encoding) -> Result<Vec<Transform>> {
    let mut c = Cursor::new(data, enc)?;
    let n = c.u32("transforms")? as usize;
    // Each transform takes at least 60 bytes: a lying count fails here.
    if n > data.len() / 60 + 1 {
        return Err(Error::Bag(format!(
            "TFMessage claims {n} transforms in {} bytes",
            data.len()
        )));
    }
    (0..n)
        .map(|_| {
            let (stamp, parent) = c.header()?;
            let child = c.string("child_frame_id")?;
            let iso = c.isometry("transform")?;
            Ok(Transform {
                stamp,
                parent: frame(&parent),
                child: frame(&child),
                iso,
            })
        })
        .collect()
}
