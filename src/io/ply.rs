//! PLY reader: ascii, binary_little_endian and binary_big_endian; every
//! scalar type and alias; list properties and other elements (before or after
//! `vertex`) skipped correctly; x, y, z of any type in any position.
//!
//! Binary bodies are read by offset into the record, with no per-vertex map
//! or allocation (the `ply-rs` crate builds a map per vertex, which is what
//! makes it slow; see the benchmarks).

use super::{ascii_text, check_padding, checked_len, split_header, AsciiRows, ReadLimits, Scalar};
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

/// Read a PLY file from its bytes. Strict unless `limits.lenient`: the
/// body must match the header to its end (see [`ReadLimits::lenient`]).
pub fn read(bytes: &[u8], limits: &ReadLimits) -> Result<PointCloud> {
    let header = parse_header(bytes)?;
    let Some(vi) = header.elements.iter().position(|e| e.name == "vertex") else {
        return err("no vertex element in the header");
    };
    let vertex = &header.elements[vi];
    let n = limits.check_points(vertex.count)?;
    let xyz = xyz_indices(vertex)?;
    let (head, body) = bytes.split_at(header.body_offset);
    let (format, points) = match header.encoding {
        Encoding::Ascii => (
            Format::PlyAscii,
            read_ascii(head, body, &header.elements, vi, n, xyz, limits)?,
        ),
        Encoding::Little => (
            Format::PlyBinaryLittleEndian,
            read_binary(body, &header.elements, vi, n, xyz, true, limits)?,
        ),
        Encoding::Big => (
            Format::PlyBinaryBigEndian,
            read_binary(body, &header.elements, vi, n, xyz, false, limits)?,
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
                // try_from, not `as`: a count past 2^32 must fail on wasm32
                // as it does natively, not wrap to a small one.
                pos = end.checked_add(checked_len(n, item.size())?)?;
            }
        }
        if pos > body.len() {
            return None;
        }
    }
    Some(pos)
}

/// Skip whole elements; returns the bytes they take, or what ran past the end.
fn skip_binary_elements(
    body: &[u8],
    elements: &[Element],
    little: bool,
) -> std::result::Result<usize, String> {
    let mut pos = 0usize;
    for el in elements {
        if let Some(stride) = el.fixed_stride() {
            let left = body.len() - pos;
            match checked_len(el.count, stride) {
                Some(len) if len <= left => pos += len,
                _ => {
                    return Err(format!(
                    "element {} claims {} records of {stride} bytes but only {left} bytes remain",
                    el.name, el.count
                ))
                }
            }
        } else {
            for r in 0..el.count {
                match walk_record(&body[pos..], el, little) {
                    Some(len) => pos += len,
                    None => {
                        return Err(format!(
                            "element {} runs past the end of the file in record {r} of {}",
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
    elements: &[Element],
    vi: usize,
    n: usize,
    xyz: [usize; 3],
    little: bool,
    limits: &ReadLimits,
) -> Result<Vec<[f32; 3]>> {
    let vertex = &elements[vi];
    let start = skip_binary_elements(body, &elements[..vi], little)
        .or_else(|e| err(format!("truncated: {e}")))?;
    let (points, len) = read_binary_vertices(&body[start..], vertex, n, xyz, little)?;
    if limits.lenient {
        return Ok(points);
    }
    // What follows the vertices must be exactly the elements declared after
    // them, then at most padding: a body that does not parse to its end is
    // damaged, and its vertices may be too (a text round trip that replaced
    // bytes grows the body and shifts every record).
    let end = start + len;
    let after = skip_binary_elements(&body[end..], &elements[vi + 1..], little).or_else(|e| {
        err(format!(
            "the body does not match the header: {e} (the file is truncated or damaged)"
        ))
    })?;
    check_padding(&body[end + after..], end + after, limits).map_err(Error::Ply)?;
    Ok(points)
}

/// Read `n` vertex records at the start of `data`; the points and the bytes
/// they take.
fn read_binary_vertices(
    data: &[u8],
    vertex: &Element,
    n: usize,
    xyz: [usize; 3],
    little: bool,
) -> Result<(Vec<[f32; 3]>, usize)> {
    let scalar_of = |i: usize| match vertex.props[i].kind {
        PropKind::Scalar(s) => s,
        PropKind::List { .. } => unreachable!("xyz_indices rejects lists"),
    };
    let types = [scalar_of(xyz[0]), scalar_of(xyz[1]), scalar_of(xyz[2])];

    if let Some(stride) = vertex.fixed_stride() {
        let need = match n.checked_mul(stride) {
            Some(need) if need <= data.len() => need,
            _ => {
                return err(format!(
                    "truncated: the header claims {n} vertices of {stride} bytes ({} bytes) but the body holds {} bytes",
                    n as u128 * stride as u128,
                    data.len()
                ))
            }
        };
        let offsets = xyz.map(|i| {
            vertex.props[..i]
                .iter()
                .map(|p| match p.kind {
                    PropKind::Scalar(s) => s.size(),
                    PropKind::List { .. } => 0,
                })
                .sum::<usize>()
        });
        let records = data[..need].chunks_exact(stride);
        let mut points = Vec::with_capacity(n);
        let packed = stride == 12 && offsets == [0, 4, 8];
        // One float32 LE at offset o of a record.
        let f = |r: &[u8], o: usize| f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]]);
        if little && types == [Scalar::F32; 3] && packed {
            // x, y, z as float32 LE and nothing else (placecat's own files,
            // the page's benchmark set): the same loop as below with the
            // offsets known, so the compiler copies each record whole.
            // Through the loop below this took 12 instructions per point
            // natively and 19 in wasm (docs/wasm-floor.md). Not one memcpy
            // of the body: glibc's copy of 12 MB (1M points) took 8 ms in
            // criterion on this machine's Zen 4, against 0.8 ms for the loop.
            points.extend(records.map(|r| [f(r, 0), f(r, 4), f(r, 8)]));
            return Ok((points, need));
        }
        if little && types == [Scalar::F32; 3] {
            // The common case (lidar data as float32 LE): a tight loop the
            // compiler can unroll, no dispatch on the type per value.
            points.extend(records.map(|r| [f(r, offsets[0]), f(r, offsets[1]), f(r, offsets[2])]));
        } else {
            points.extend(
                records.map(|r| [0, 1, 2].map(|k| types[k].read(&r[offsets[k]..], little) as f32)),
            );
        }
        return Ok((points, need));
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
                    // walk_record has checked this count and its items.
                    let c = count
                        .read_count(&rec[off..], little)
                        .and_then(|c| usize::try_from(c).ok())
                        .unwrap_or(0);
                    off += count.size() + c * item.size();
                }
            }
        }
        points.push(p);
        pos += len;
    }
    Ok((points, pos))
}

/// Read an ascii body line by line: each record of each element is one line
/// with exactly the values its properties declare (a list: its length, then
/// that many items), as the PLY format defines it and as PCL reads it.
/// Reading the values as one stream instead would take a row of 2 values
/// and the next row's first as one point, and shift every point after it.
fn read_ascii(
    head: &[u8],
    body: &[u8],
    elements: &[Element],
    vi: usize,
    n: usize,
    xyz: [usize; 3],
    limits: &ReadLimits,
) -> Result<Vec<[f32; 3]>> {
    let text = ascii_text(head, body, limits).map_err(Error::Ply)?;
    let mut rows = AsciiRows::new(head, text);
    let mut values = Vec::new();
    // Each vertex needs at least two bytes per property ("0 "), so this bounds
    // the allocation by the file size even when the header lies.
    let vertex = &elements[vi];
    let mut points = Vec::with_capacity(n.min(body.len() / (2 * vertex.props.len().max(1)) + 1));
    // Read leniently, nothing after the vertices is looked at.
    let last = if limits.lenient {
        vi
    } else {
        elements.len() - 1
    };
    for (ei, el) in elements[..=last].iter().enumerate() {
        // A record of no properties is a line of no values, which the rows
        // skip as blank: skipping a claimed 10^13 of them must not loop
        // (found by the fuzzer).
        if el.props.is_empty() {
            continue;
        }
        for r in 0..el.count {
            let Some(line) = rows.next_row(&mut values) else {
                return err(format!(
                    "truncated: the body ends in element {} record {r} of {}",
                    el.name, el.count
                ));
            };
            let p = ascii_record(&values, el, xyz).map_err(|(e, short)| {
                // A short last row is where a cut file ends.
                let cut = if short && rows.at_end() {
                    "truncated: "
                } else {
                    ""
                };
                Error::Ply(format!(
                    "{cut}line {line}: {e} (element {} record {r} of {})",
                    el.name, el.count
                ))
            })?;
            if ei == vi {
                points.push(p);
            }
        }
    }
    rows.check_end("the last element the header declares", limits)
        .map_err(Error::Ply)?;
    Ok(points)
}

/// One ascii record: checks the number of values against the properties;
/// the x, y, z found (meaningful for vertices only), or what is wrong and
/// whether the row was short.
fn ascii_record(
    values: &[&str],
    el: &Element,
    xyz: [usize; 3],
) -> std::result::Result<[f32; 3], (String, bool)> {
    // The values a short row needed: `at` taken, one per property from
    // `from` on (a list: its length at least; exact when none is left).
    let short = |at: usize, from: usize| {
        let rest = &el.props[from..];
        let lists = rest.iter().any(|p| matches!(p.kind, PropKind::List { .. }));
        let want = at.saturating_add(rest.len());
        let want = if lists {
            format!("at least {want}")
        } else {
            want.to_string()
        };
        (
            format!("{} values where the header declares {want}", values.len()),
            true,
        )
    };
    let mut p = [0f32; 3];
    let mut at = 0usize;
    for (i, prop) in el.props.iter().enumerate() {
        let Some(&t) = values.get(at) else {
            return Err(short(at, i));
        };
        at += 1;
        match prop.kind {
            PropKind::Scalar(_) => {
                if let Some(k) = xyz.iter().position(|&x| x == i) {
                    p[k] = parse_f32(t).ok_or_else(|| (format!("{t:?} is not a number"), false))?;
                }
            }
            PropKind::List { .. } => {
                let len =
                    parse_count(t).ok_or_else(|| (format!("bad list length {t:?}"), false))?;
                at = at.saturating_add(len);
                if at > values.len() {
                    return Err(short(at, i + 1));
                }
            }
        }
    }
    if at != values.len() {
        return Err((
            format!("{} values where the header declares {at}", values.len()),
            false,
        ));
    }
    Ok(p)
}

/// A list length written in ascii ("3", or "3.0" by some writers).
fn parse_count(t: &str) -> Option<usize> {
    let v = t.parse::<f64>().ok()?;
    if v >= 0.0 && v.fract() == 0.0 && v < 1e9 {
        usize::try_from(v as u64).ok()
    } else {
        None
    }
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
