//! Scalar types of binary point-cloud records, read at a byte offset.

/// A numeric type of a PLY property or PCD field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    /// Signed 8-bit integer (PLY `char`/`int8`, PCD `I 1`).
    I8,
    /// Unsigned 8-bit integer (PLY `uchar`/`uint8`, PCD `U 1`).
    U8,
    /// Signed 16-bit integer.
    I16,
    /// Unsigned 16-bit integer.
    U16,
    /// Signed 32-bit integer.
    I32,
    /// Unsigned 32-bit integer.
    U32,
    /// Signed 64-bit integer (PCD only).
    I64,
    /// Unsigned 64-bit integer (PCD only).
    U64,
    /// IEEE 754 single (PLY `float`/`float32`, PCD `F 4`).
    F32,
    /// IEEE 754 double (PLY `double`/`float64`, PCD `F 8`).
    F64,
}

impl Scalar {
    /// Size in bytes.
    pub fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::I64 | Scalar::U64 | Scalar::F64 => 8,
        }
    }

    /// Read one value at `bytes[0..size]`; the caller guarantees the length.
    #[inline(always)]
    pub fn read(self, b: &[u8], little: bool) -> f64 {
        macro_rules! get {
            ($t:ty, $n:expr) => {{
                let mut a = [0u8; $n];
                a.copy_from_slice(&b[..$n]);
                if little {
                    <$t>::from_le_bytes(a) as f64
                } else {
                    <$t>::from_be_bytes(a) as f64
                }
            }};
        }
        match self {
            Scalar::I8 => b[0] as i8 as f64,
            Scalar::U8 => b[0] as f64,
            Scalar::I16 => get!(i16, 2),
            Scalar::U16 => get!(u16, 2),
            Scalar::I32 => get!(i32, 4),
            Scalar::U32 => get!(u32, 4),
            Scalar::I64 => get!(i64, 8),
            Scalar::U64 => get!(u64, 8),
            Scalar::F32 => get!(f32, 4),
            Scalar::F64 => get!(f64, 8),
        }
    }

    /// Read a non-negative integer (a PLY list length); None if negative or not integral.
    pub fn read_count(self, b: &[u8], little: bool) -> Option<u64> {
        let v = self.read(b, little);
        if v >= 0.0 && v.fract() == 0.0 && v.is_finite() {
            Some(v as u64)
        } else {
            None
        }
    }
}
