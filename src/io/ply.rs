//! PLY reader: ascii, binary_little_endian and binary_big_endian; every
//! scalar type and alias; list properties and other elements (before or after
//! `vertex`) skipped correctly; x, y, z of any type in any position.
//!
//! Binary bodies are read by offset into the record, with no per-vertex map
//! or allocation (the `ply-rs` crate builds a map per vertex, which is what
//! makes it slow; see the benchmarks).

use super::{split_header, ReadLimits, Scalar};
use crate::cloud::{Format, PointCloud};
use crate::error::{Error, Result};

fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Ply(msg.into()))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Encoding {
    Ascii,
    Little,
    Big,
}

#[derive(Debug, Clone)]
enum PropKind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug, Clone)]
struct Property {
    name: String,
    kind: PropKind,
}

#[derive(Debug, Clone)]
struct Element {
    name: String,
    count: u64,
    props: Vec<Property>,
}

impl Element {
    /// Record size when every property is a scalar.
    fn fixed_stride(&self) -> Option<usize> {
        self.props
            .iter()
            .map(|p| match p.kind {
                PropKind::Scalar(s) => Some(s.size()),
                PropKind::List { .. } => None,
            })
            .sum()
    }
}

fn scalar_type(name: &str) -> Option<Scalar> {
    Some(match name {
        "char" | "int8" => Scalar::I8,
        "uchar" | "uint8" => Scalar::U8,
        "short" | "int16" => Scalar::I16,
        "ushort" | "uint16" => Scalar::U16,
        "int" | "int32" => Scalar::I32,
        "uint" | "uint32" => Scalar::U32,
        "float" | "float32" => Scalar::F32,
        "double" | "float64" => Scalar::F64,
        _ => return None,
    })
}

struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    body_offset: usize,
}

/// Headers longer than this are treated as missing their `end_header`.
const MAX_HEADER_BYTES: usize = 1 << 20;

fn parse_header(bytes: &[u8]) -> Result<Header> {
    let (lines, body_offset) = match split_header(bytes, MAX_HEADER_BYTES, |l| l == "end_header") {
        Some(h) => h,
        None => return err("no end_header line in the header (truncated or not a PLY file)"),
    };
    if lines.first().map(|l| l.trim()) != Some("ply") {
        return err("the file does not start with the line \"ply\"");
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for (i, line) in lines.iter().enumerate().skip(1) {
        let lineno = i + 1;
        let mut words = line.split_ascii_whitespace();
        match words.next() {
            None | Some("comment") | Some("obj_info") | Some("end_header") => {}
            Some("format") => {
                encoding = Some(match (words.next(), words.next()) {
                    (Some("ascii"), _) => Encoding::Ascii,
                    (Some("binary_little_endian"), _) => Encoding::Little,
                    (Some("binary_big_endian"), _) => Encoding::Big,
                    (other, _) => return err(format!("line {lineno}: unknown format {other:?}")),
                })
            }
            Some("element") => {
                let name = words.next();
                let count = words.next().and_then(|c| c.parse::<u64>().ok());
                match (name, count) {
                    (Some(n), Some(c)) => elements.push(Element {
                        name: n.to_string(),
                        count: c,
                        props: Vec::new(),
                    }),
                    _ => return err(format!("line {lineno}: bad element line {line:?}")),
                }
            }
            Some("property") => {
                let Some(el) = elements.last_mut() else {
                    return err(format!("line {lineno}: property before any element"));
                };
                let t = words.next().unwrap_or("");
                let kind = if t == "list" {
                    let c = words.next().unwrap_or("");
                    let it = words.next().unwrap_or("");
                    match (scalar_type(c), scalar_type(it)) {
                        (Some(count), Some(item)) => PropKind::List { count, item },
                        _ => {
                            return err(format!(
                                "line {lineno}: unknown type in list property {line:?}"
                            ))
                        }
                    }
                } else {
                    match scalar_type(t) {
                        Some(s) => PropKind::Scalar(s),
                        None => return err(format!("line {lineno}: unknown property type {t:?}")),
                    }
                };
                let Some(name) = words.next() else {
                    return err(format!("line {lineno}: property without a name"));
                };
                el.props.push(Property {
                    name: name.to_string(),
                    kind,
                });
            }
            Some(other) => return err(format!("line {lineno}: unknown header keyword {other:?}")),
        }
    }
    let Some(encoding) = encoding else {
        return err("no format line in the header");
    };
    Ok(Header {
        encoding,
        elements,
        body_offset,
    })
}

/// Position of x, y, z among the vertex element's properties.
fn xyz_indices(el: &Element) -> Result<[usize; 3]> {
    let mut idx = [usize::MAX; 3];
    for (i, p) in el.props.iter().enumerate() {
        let slot = match p.name.as_str() {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => continue,
        };
        if let PropKind::List { .. } = p.kind {
            return err(format!("vertex property {} is a list", p.name));
        }
        idx[slot] = i;
    }
    for (slot, n) in ["x", "y", "z"].iter().enumerate() {
        if idx[slot] == usize::MAX {
            return err(format!("the vertex element has no property {n}"));
        }
    }
    Ok(idx)
}

/// Read a PLY file from its bytes.
pub fn read(bytes: &[u8], limits: &ReadLimits) -> Result<PointCloud> {
    let header = parse_header(bytes)?;
    let Some(vi) = header.elements.iter().position(|e| e.name == "vertex") else {
        return err("no vertex element in the header");
    };
    let vertex = &header.elements[vi];
    let n = limits.check_points(vertex.count)?;
    let xyz = xyz_indices(vertex)?;
    let body = &bytes[header.body_offset..];
    let (format, points) = match header.encoding {
        Encoding::Ascii => (
            Format::PlyAscii,
            read_ascii(body, &header.elements[..vi], vertex, n, xyz)?,
        ),
        Encoding::Little => (
            Format::PlyBinaryLittleEndian,
            read_binary(body, &header.elements[..vi], vertex, n, xyz, true)?,
        ),
        Encoding::Big => (
            Format::PlyBinaryBigEndian,
            read_binary(body, &header.elements[..vi], vertex, n, xyz, false)?,
        ),
    };
    Ok(PointCloud { format, points })
}

/// Walk one record with list properties; returns its length in bytes.
fn walk_record(body: &[u8], el: &Element, little: bool) -> Option<usize> {
    let mut pos = 0usize;
    for p in &el.props {
        match p.kind {
            PropKind::Scalar(s) => pos = pos.checked_add(s.size())?,
            PropKind::List { count, item } => {
                let end = pos.checked_add(count.size())?;
                let n = count.read_count(body.get(pos..end)?, little)?;
                pos = end.checked_add((n as usize).checked_mul(item.size())?)?;
            }
        }
        if pos > body.len() {
            return None;
        }
    }
    Some(pos)
}

/// Skip the elements before `vertex`; returns the offset where vertex data starts.
fn skip_binary_elements(body: &[u8], before: &[Element], little: bool) -> Result<usize> {
    let mut pos = 0usize;
    for el in before {
        if let Some(stride) = el.fixed_stride() {
            let len = (el.count as u128) * (stride as u128);
            if len > (body.len() - pos) as u128 {
                return err(format!(
                    "truncated: element {} claims {} records of {stride} bytes but only {} bytes remain",
                    el.name,
                    el.count,
                    body.len() - pos
                ));
            }
            pos += len as usize;
        } else {
            for r in 0..el.count {
                match walk_record(&body[pos..], el, little) {
                    Some(len) => pos += len,
                    None => {
                        return err(format!(
                            "truncated: element {} ends in record {r} of {}",
                            el.name, el.count
                        ))
                    }
                }
            }
        }
    }
    Ok(pos)
}

fn read_binary(
    body: &[u8],
    before: &[Element],
    vertex: &Element,
    n: usize,
    xyz: [usize; 3],
    little: bool,
) -> Result<Vec<[f32; 3]>> {
    let start = skip_binary_elements(body, before, little)?;
    let data = &body[start..];
    let scalar_of = |i: usize| match vertex.props[i].kind {
        PropKind::Scalar(s) => s,
        PropKind::List { .. } => unreachable!("xyz_indices rejects lists"),
    };
    let types = [scalar_of(xyz[0]), scalar_of(xyz[1]), scalar_of(xyz[2])];

    if let Some(stride) = vertex.fixed_stride() {
        let need = (n as u128) * (stride as u128);
        if need > data.len() as u128 {
            return err(format!(
                "truncated: the header claims {n} vertices of {stride} bytes ({need} bytes) but the body holds {} bytes",
                data.len()
            ));
        }
        let offsets = xyz.map(|i| {
            vertex.props[..i]
                .iter()
                .map(|p| match p.kind {
                    PropKind::Scalar(s) => s.size(),
                    PropKind::List { .. } => 0,
                })
                .sum::<usize>()
        });
        let records = data[..n * stride].chunks_exact(stride);
        let mut points = Vec::with_capacity(n);
        if little && types == [Scalar::F32; 3] {
            // The common case (lidar data as float32 LE): a tight loop the
            // compiler can unroll, no dispatch on the type per value.
            let f = |r: &[u8], o: usize| f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]]);
            points.extend(records.map(|r| [f(r, offsets[0]), f(r, offsets[1]), f(r, offsets[2])]));
        } else {
            points.extend(
                records.map(|r| [0, 1, 2].map(|k| types[k].read(&r[offsets[k]..], little) as f32)),
            );
        }
        return Ok(points);
    }

    // Vertex records with list properties: walk each record.
    let mut points = Vec::with_capacity(n.min(data.len() / vertex.props.len().max(1)));
    let mut pos = 0usize;
    for r in 0..n {
        let rec = &data[pos..];
        let Some(len) = walk_record(rec, vertex, little) else {
            return err(format!(
                "truncated: vertex {r} of {n} runs past the end of the file"
            ));
        };
        let mut p = [0f32; 3];
        let mut off = 0usize;
        for (i, prop) in vertex.props.iter().enumerate() {
            match prop.kind {
                PropKind::Scalar(s) => {
                    if let Some(k) = xyz.iter().position(|&x| x == i) {
                        p[k] = s.read(&rec[off..], little) as f32;
                    }
                    off += s.size();
                }
                PropKind::List { count, item } => {
                    let c = count.read_count(&rec[off..], little).unwrap_or(0) as usize;
                    off += count.size() + c * item.size();
                }
            }
        }
        points.push(p);
        pos += len;
    }
    Ok(points)
}

fn read_ascii(
    body: &[u8],
    before: &[Element],
    vertex: &Element,
    n: usize,
    xyz: [usize; 3],
) -> Result<Vec<[f32; 3]>> {
    let text = match std::str::from_utf8(body) {
        Ok(t) => t,
        Err(e) => {
            // Allow trailing garbage only after a valid prefix; report where it broke.
            return err(format!(
                "ascii body is not text (invalid byte at offset {})",
                e.valid_up_to()
            ));
        }
    };
    let mut tokens = text.split_ascii_whitespace();
    let mut next = |what: &dyn Fn() -> String| -> Result<&str> {
        tokens
            .next()
            .ok_or_else(|| Error::Ply(format!("truncated: the body ends in {}", what())))
    };
    let parse_count = |t: &str, what: &dyn Fn() -> String| -> Result<usize> {
        t.parse::<f64>()
            .ok()
            .filter(|v| *v >= 0.0 && v.fract() == 0.0 && *v < 1e9)
            .map(|v| v as usize)
            .ok_or_else(|| Error::Ply(format!("bad list length {t:?} in {}", what())))
    };
    for el in before {
        // A record of no properties takes no tokens: skipping a claimed
        // 10^13 of them must not loop (found by the fuzzer).
        if el.props.is_empty() {
            continue;
        }
        for r in 0..el.count {
            let what = || format!("element {} record {r}", el.name);
            for p in &el.props {
                let t = next(&what)?;
                if let PropKind::List { .. } = p.kind {
                    for _ in 0..parse_count(t, &what)? {
                        next(&what)?;
                    }
                }
            }
        }
    }
    // Each vertex needs at least two bytes per property ("0 "), so this bounds
    // the allocation by the file size even when the header lies.
    let mut points = Vec::with_capacity(n.min(body.len() / (2 * vertex.props.len().max(1)) + 1));
    for r in 0..n {
        let what = || format!("vertex {r} of {n}");
        let mut p = [0f32; 3];
        for (i, prop) in vertex.props.iter().enumerate() {
            let t = next(&what)?;
            match prop.kind {
                PropKind::Scalar(_) => {
                    if let Some(k) = xyz.iter().position(|&x| x == i) {
                        p[k] = parse_f32(t).ok_or_else(|| {
                            Error::Ply(format!("vertex {r}: {t:?} is not a number"))
                        })?;
                    }
                }
                PropKind::List { .. } => {
                    for _ in 0..parse_count(t, &what)? {
                        next(&what)?;
                    }
                }
            }
        }
        points.push(p);
    }
    Ok(points)
}

/// Parse an ascii number as f32, accepting "nan" and "inf" spellings.
pub(crate) fn parse_f32(t: &str) -> Option<f32> {
    t.parse::<f32>().ok().or_else(
        || match t.to_ascii_lowercase().trim_start_matches(['+', '-']) {
            "nan" | "-nan" | "nan(ind)" => Some(f32::NAN),
            "inf" | "infinity" if t.starts_with('-') => Some(f32::NEG_INFINITY),
            "inf" | "infinity" => Some(f32::INFINITY),
            _ => None,
        },
    )
}
