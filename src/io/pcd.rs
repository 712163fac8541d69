//! PCD v0.7 reader: DATA ascii, binary and binary_compressed (LZF, column
//! major after decompression); any field order, sizes, types and counts.

use super::{ascii_text, check_padding, split_header, AsciiRows, ReadLimits, Scalar};
use crate::cloud::{Format, PointCloud};
use crate::error::{Error, Result};

fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Pcd(msg.into()))
}

const MAX_HEADER_BYTES: usize = 1 << 16;

/// True when the bytes start like a PCD header (a comment or a known keyword).
pub fn looks_like_pcd(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(64)];
    [&b"# .PCD"[..], b"VERSION", b"FIELDS", b"#.PCD"]
        .iter()
        .any(|k| head.starts_with(k))
}

#[derive(Debug, Clone)]
struct Field {
    name: String,
    scalar: Scalar,
    count: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Data {
    Ascii,
    Binary,
    Compressed,
}

struct Header {
    fields: Vec<Field>,
    /// Bytes of one point: the sum of SIZE x COUNT.
    record: usize,
    points: u64,
    data: Data,
    body_offset: usize,
}

fn parse_header(bytes: &[u8], limits: &ReadLimits) -> Result<Header> {
    let Some((lines, body_offset)) =
        split_header(bytes, MAX_HEADER_BYTES, |l| l.starts_with("DATA"))
    else {
        return err("no DATA line in the header (truncated or not a PCD file)");
    };
    let mut names: Vec<String> = Vec::new();
    // SIZE and COUNT stay u64 until checked, never cast with `as`: SIZE
    // 4294967300 must fail on wasm32 as it does natively, not wrap to 4.
    let mut sizes: Vec<u64> = Vec::new();
    let mut types: Vec<char> = Vec::new();
    let mut counts: Vec<u64> = Vec::new();
    let (mut width, mut height, mut points) = (None::<u64>, None::<u64>, None::<u64>);
    let mut data = None;
    for (i, line) in lines.iter().enumerate() {
        let lineno = i + 1;
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let mut words = line.split_ascii_whitespace();
        let key = words.next().unwrap_or("");
        let rest: Vec<&str> = words.collect();
        let num = |w: &str| -> Result<u64> {
            w.parse::<u64>()
                .map_err(|_| Error::Pcd(format!("line {lineno}: {w:?} is not a whole number")))
        };
        match key {
            "VERSION" | "VIEWPOINT" => {}
            "FIELDS" | "COLUMNS" => names = rest.iter().map(|s| s.to_string()).collect(),
            "SIZE" => sizes = rest.iter().map(|w| num(w)).collect::<Result<_>>()?,
            "TYPE" => {
                types = rest
                    .iter()
                    .map(|w| match w.as_bytes() {
                        [t] => Ok(*t as char),
                        _ => err(format!("line {lineno}: TYPE {w:?} is not one of F, I, U")),
                    })
                    .collect::<Result<_>>()?
            }
            "COUNT" => counts = rest.iter().map(|w| num(w)).collect::<Result<_>>()?,
            "WIDTH" => width = Some(num(rest.first().unwrap_or(&""))?),
            "HEIGHT" => height = Some(num(rest.first().unwrap_or(&""))?),
            "POINTS" => points = Some(num(rest.first().unwrap_or(&""))?),
            "DATA" => {
                data = Some(match rest.first().copied() {
                    Some("ascii") => Data::Ascii,
                    Some("binary") => Data::Binary,
                    Some("binary_compressed") => Data::Compressed,
                    other => return err(format!("line {lineno}: unknown DATA kind {other:?}")),
                })
            }
            other => return err(format!("line {lineno}: unknown header keyword {other:?}")),
        }
    }
    if names.is_empty() {
        return err("no FIELDS line in the header");
    }
    if counts.is_empty() {
        counts = vec![1; names.len()];
    }
    if sizes.len() != names.len() || types.len() != names.len() || counts.len() != names.len() {
        return err(format!(
            "FIELDS has {} entries but SIZE {}, TYPE {}, COUNT {}",
            names.len(),
            sizes.len(),
            types.len(),
            counts.len()
        ));
    }
    let mut fields = Vec::with_capacity(names.len());
    for i in 0..names.len() {
        let scalar = match (types[i], sizes[i]) {
            ('F', 4) => Scalar::F32,
            ('F', 8) => Scalar::F64,
            ('I', 1) => Scalar::I8,
            ('I', 2) => Scalar::I16,
            ('I', 4) => Scalar::I32,
            ('I', 8) => Scalar::I64,
            ('U', 1) => Scalar::U8,
            ('U', 2) => Scalar::U16,
            ('U', 4) => Scalar::U32,
            ('U', 8) => Scalar::U64,
            (t, s) => {
                return err(format!(
                    "field {}: unknown TYPE {t} with SIZE {s}",
                    names[i]
                ))
            }
        };
        let count = match usize::try_from(counts[i]) {
            Ok(c) if (1..=1 << 20).contains(&c) => c,
            _ => {
                return err(format!(
                    "field {}: COUNT {} is not valid",
                    names[i], counts[i]
                ))
            }
        };
        fields.push(Field {
            name: names[i].clone(),
            scalar,
            count,
        });
    }
    let points = match (points, width, height) {
        (Some(p), Some(w), Some(h)) => {
            // PCL refuses such a header; which of the three is wrong cannot
            // be told, so only a lenient read goes on (with POINTS).
            if w.checked_mul(h) != Some(p) && !limits.lenient {
                return err(format!(
                    "the header does not add up: WIDTH {w} x HEIGHT {h} is not POINTS {p}"
                ));
            }
            p
        }
        (Some(p), _, _) => p,
        (None, Some(w), Some(h)) => match w.checked_mul(h) {
            Some(p) => p,
            None => return err(format!("WIDTH {w} x HEIGHT {h} is too large")),
        },
        (None, Some(w), None) => w,
        _ => return err("no POINTS (or WIDTH and HEIGHT) in the header"),
    };
    let Some(data) = data else {
        return err("no DATA line in the header");
    };
    // Checked: fields x COUNT (up to 2^20) x 8 bytes overflows 32 bits.
    let record = fields
        .iter()
        .try_fold(0usize, |sum, f| {
            f.scalar.size().checked_mul(f.count)?.checked_add(sum)
        })
        .ok_or_else(|| Error::Pcd("the fields' SIZE x COUNT is too large".into()))?;
    Ok(Header {
        record,
        fields,
        points,
        data,
        body_offset,
    })
}

/// Read a PCD file from its bytes. Strict unless `limits.lenient`: the
/// header must add up and the body match it (see [`ReadLimits::lenient`]).
pub fn read(bytes: &[u8], limits: &ReadLimits) -> Result<PointCloud> {
    let h = parse_header(bytes, limits)?;
    let n = limits.check_points(h.points)?;
    // (field index, element offset within the record)
    let mut xyz = [usize::MAX; 3];
    for (i, f) in h.fields.iter().enumerate() {
        match f.name.as_str() {
            "x" => xyz[0] = i,
            "y" => xyz[1] = i,
            "z" => xyz[2] = i,
            _ => {}
        }
    }
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        if xyz[k] == usize::MAX {
            return err(format!("no field {name}"));
        }
    }
    let (head, body) = bytes.split_at(h.body_offset);
    let record = h.record;
    let (format, points) = match h.data {
        Data::Ascii => (
            Format::PcdAscii,
            read_ascii(head, body, &h, n, xyz, limits)?,
        ),
        Data::Binary => {
            let need = match n.checked_mul(record) {
                Some(need) if need <= body.len() => need,
                _ => {
                    return err(format!(
                        "truncated: the header claims {n} points of {record} bytes ({} bytes) but the body holds {} bytes",
                        n as u128 * record as u128,
                        body.len()
                    ))
                }
            };
            check_padding(&body[need..], need, limits).map_err(Error::Pcd)?;
            let offs = xyz.map(|i| field_offset(&h.fields, i));
            let types = xyz.map(|i| h.fields[i].scalar);
            let mut pts = Vec::with_capacity(n);
            if record > 0 {
                if types == [Scalar::F32; 3] {
                    let f = |r: &[u8], o: usize| {
                        f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]])
                    };
                    pts.extend(
                        body[..need]
                            .chunks_exact(record)
                            .map(|r| [f(r, offs[0]), f(r, offs[1]), f(r, offs[2])]),
                    );
                } else {
                    pts.extend(
                        body[..need]
                            .chunks_exact(record)
                            .map(|r| [0, 1, 2].map(|k| types[k].read(&r[offs[k]..], true) as f32)),
                    );
                }
            }
            (Format::PcdBinary, pts)
        }
        Data::Compressed => (
            Format::PcdBinaryCompressed,
            read_compressed(body, &h, n, xyz, limits)?,
        ),
    };
    Ok(PointCloud { format, points })
}

/// Byte offset of field `i` inside one (row-major) record.
fn field_offset(fields: &[Field], i: usize) -> usize {
    fields[..i].iter().map(|f| f.scalar.size() * f.count).sum()
}

fn read_compressed(
    body: &[u8],
    h: &Header,
    n: usize,
    xyz: [usize; 3],
    limits: &ReadLimits,
) -> Result<Vec<[f32; 3]>> {
    if body.len() < 8 {
        return err("truncated: binary_compressed data has no size words");
    }
    let word = |i: usize| {
        let w = u32::from_le_bytes(body[i..i + 4].try_into().unwrap());
        usize::try_from(w).unwrap_or(usize::MAX)
    };
    let (compressed, uncompressed) = (word(0), word(4));
    let record = h.record;
    let need = n as u128 * record as u128;
    if uncompressed as u128 != need {
        return err(format!(
            "binary_compressed: the header claims {n} points of {record} bytes ({need} bytes) but the data says {uncompressed} bytes uncompressed"
        ));
    }
    if compressed > body.len() - 8 {
        return err(format!(
            "truncated: binary_compressed claims {compressed} compressed bytes but {} remain",
            body.len() - 8
        ));
    }
    check_padding(&body[8 + compressed..], 8 + compressed, limits).map_err(Error::Pcd)?;
    // LZF expands at most ~ 264/3 times (a back reference of 264 bytes in 3),
    // so a larger claim is a lie; check before allocating the output.
    if uncompressed > compressed.saturating_mul(90) + 64 {
        return err(format!(
            "binary_compressed: {uncompressed} bytes cannot come from {compressed} compressed bytes"
        ));
    }
    if n == 0 {
        return Ok(Vec::new());
    }
    let raw = lzf::decompress(&body[8..8 + compressed], uncompressed)
        .map_err(|e| Error::Pcd(format!("binary_compressed: LZF data is corrupt ({e:?})")))?;
    if raw.len() != uncompressed {
        return err(format!(
            "binary_compressed: LZF data gave {} bytes, not {uncompressed}",
            raw.len()
        ));
    }
    // Column major: all of field 0 (n * size * count bytes), then field 1, ...
    let col = |i: usize| -> (usize, usize, Scalar) {
        let start: usize = h.fields[..i]
            .iter()
            .map(|f| n * f.scalar.size() * f.count)
            .sum();
        let f = &h.fields[i];
        (start, f.scalar.size() * f.count, f.scalar)
    };
    let cols = xyz.map(col);
    Ok((0..n)
        .map(|j| {
            [0, 1, 2].map(|k| {
                let (start, step, s) = cols[k];
                s.read(&raw[start + j * step..], true) as f32
            })
        })
        .collect())
}

/// Read an ascii body line by line: one point a line, with exactly the
/// values the fields declare (the sum of their COUNTs), as PCL reads it.
fn read_ascii(
    head: &[u8],
    body: &[u8],
    h: &Header,
    n: usize,
    xyz: [usize; 3],
    limits: &ReadLimits,
) -> Result<Vec<[f32; 3]>> {
    let text = ascii_text(head, body, limits).map_err(Error::Pcd)?;
    // Column index of x, y, z within a line (fields may have COUNT > 1).
    let cols = xyz.map(|i| h.fields[..i].iter().map(|f| f.count).sum::<usize>());
    let per_line: usize = h.fields.iter().map(|f| f.count).sum();
    let mut pts = Vec::with_capacity(n.min(body.len() / (2 * per_line) + 1));
    let mut rows = AsciiRows::new(head, text);
    let mut words = Vec::new();
    for r in 0..n {
        let Some(line) = rows.next_row(&mut words) else {
            return err(format!(
                "truncated: the header claims {n} points but the data has {r}"
            ));
        };
        if words.len() != per_line {
            // A short last row is where a cut file ends.
            let cut = words.len() < per_line && rows.at_end();
            return err(format!(
                "{}line {line}: {} values where the fields declare {per_line} (point {r} of {n})",
                if cut { "truncated: " } else { "" },
                words.len()
            ));
        }
        let mut p = [0f32; 3];
        for k in 0..3 {
            let w = words[cols[k]];
            p[k] = super::ply::parse_f32(w).ok_or_else(|| {
                Error::Pcd(format!(
                    "line {line}: {w:?} is not a number (point {r} of {n})"
                ))
            })?;
        }
        pts.push(p);
    }
    rows.check_end(&format!("the {n} points the header declares"), limits)
        .map_err(Error::Pcd)?;
    Ok(pts)
}
