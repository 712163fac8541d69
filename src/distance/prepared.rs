//! Descriptors prepared once for many comparisons: normalised, column-major
//! and padded.

use super::{check_parts, check_shape, DistanceOptions};
use crate::descriptor::parts::{cumulative, parts_distance};
use crate::descriptor::{Descriptor, Metric, Normalisation, PartKind};
use crate::error::Result;

/// A descriptor with its matrices normalised once, for many comparisons.
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared {
    /// Rows of each matrix (classes times height bands), before padding.
    pub rows: usize,
    /// Columns of each matrix (range intervals).
    pub cols: usize,
    /// |F|.
    pub total: f32,
    /// The normalised matrices of every candidate orientation, one after
    /// another in one buffer, column-major (each range interval's class
    /// counts contiguous, so the per-column norm of Eq. 2 reads memory in
    /// order; measured in benches/stages.rs, delta_matrix), each column
    /// padded with zeros to `stride` (a multiple of 4) rows: the Delta
    /// matrix's inner loop then runs on whole SIMD lanes and one allocation
    /// (measured: see [`delta_prepared`](super::delta_prepared)). Every metric gives the same
    /// value with or without the zero rows, so no unpadded copy is kept
    /// (Hellinger keeps one more buffer, [`roots`](Self::roots)).
    pub padded: Vec<f32>,
    /// Rows of each padded column: `rows` rounded up to a multiple of 4.
    pub stride: usize,
    /// The square roots of `padded`, entry by entry, for the Hellinger
    /// metric only (else empty): taken once here rather than twice per
    /// entry and pair (the Delta matrix of 1,000 outdoor scans: 2.0 s of
    /// CPU taking them in the kernel, see `distance/kernel.rs`). `padded`
    /// stays: centres are means of it and take their roots in the kernel
    /// (the same value to the bit), and reference scans copy both.
    pub roots: Vec<f32>,
    /// Weight of Delta in the distance (1: the paper's).
    pub ndt_weight: f32,
    /// The extra parts, weighted, in the form they are compared in
    /// ([`cumulative`]), one after another; empty without parts.
    pub parts: Vec<f32>,
    /// The kinds of those parts, in order.
    pub part_kinds: Vec<PartKind>,
}

/// A column-major rows x cols matrix with each column padded with zeros to
/// `stride` rows.
pub fn pad(m: &[f32], rows: usize, stride: usize) -> Vec<f32> {
    let cols = m.len() / rows.max(1);
    let mut out = vec![0f32; stride * cols];
    for (col, to) in m.chunks_exact(rows).zip(out.chunks_exact_mut(stride)) {
        to[..rows].copy_from_slice(col);
    }
    out
}

/// The inverse of [`pad`]: the first `rows` of every `stride`.
pub fn unpad(m: &[f32], rows: usize, stride: usize) -> Vec<f32> {
    m.chunks_exact(stride)
        .flat_map(|col| &col[..rows])
        .copied()
        .collect()
}

/// Row-major rows x cols to column-major with each column padded with
/// zeros to `stride` rows, appended to `out`.
fn extend_column_major_padded(
    out: &mut Vec<f32>,
    m: &[f32],
    rows: usize,
    cols: usize,
    stride: usize,
) {
    let start = out.len();
    out.resize(start + stride * cols, 0.0);
    for r in 0..rows {
        for c in 0..cols {
            out[start + c * stride + r] = m[r * cols + c];
        }
    }
}

impl Prepared {
    /// Check `d` (a matrix of rows x cols entries each) and normalise and
    /// pad its matrices as `opts` says; an invalid descriptor is an error
    /// here, not a NaN later.
    pub fn new(d: &Descriptor, opts: DistanceOptions) -> Result<Prepared> {
        d.validate()?;
        // DescriptorParams checks its weights; DistanceOptions' fields are
        // public, so a NaN or negative weight made by hand stops here, not
        // as a NaN Delta.
        let mut weights = std::iter::once(opts.ndt_weight).chain(opts.part_weights.iter().copied());
        if let Some(w) = weights.find(|w| !w.is_finite() || *w < 0.0) {
            return Err(crate::Error::InvalidParameter(format!(
                "distance weights must be finite and not negative, got {w}"
            )));
        }
        let total = d.total() as f32;
        let stride = d.rows.next_multiple_of(4);
        let mut padded = Vec::with_capacity(stride * d.cols * d.matrices.len());
        for m in &d.matrices {
            let normalised = normalise(m, d.rows, d.cols, opts.normalisation);
            extend_column_major_padded(&mut padded, &normalised, d.rows, d.cols, stride);
        }
        let mut parts = Vec::new();
        for p in &d.parts {
            cumulative(p, opts.part_weights[p.kind.index()], &mut parts);
        }
        let roots = match opts.metric {
            Metric::Hellinger => padded.iter().map(|v| v.sqrt()).collect(),
            Metric::Paper | Metric::ChiSquared => Vec::new(),
        };
        Ok(Prepared {
            rows: d.rows,
            cols: d.cols,
            total,
            padded,
            stride,
            roots,
            ndt_weight: opts.ndt_weight,
            parts,
            part_kinds: d.parts.iter().map(|p| p.kind).collect(),
        })
    }

    /// The distance of this descriptor to another (a scan's, a centre's or
    /// a category's) whose NDT Delta `ndt` gives and whose parts are
    /// `parts`: Delta itself for the paper's descriptor, else `ndt_weight`
    /// x Delta + [`parts_distance`]. `ndt` is not called when the weight is
    /// 0. The one place the combined distance is made (pairs, centres and
    /// a model's categories use it), so the three cannot drift apart.
    pub(crate) fn combined(&self, ndt: impl FnOnce() -> f32, parts: &[f32]) -> f32 {
        if self.parts.is_empty() && self.ndt_weight == 1.0 {
            return ndt();
        }
        let weighted = if self.ndt_weight == 0.0 {
            0.0
        } else {
            self.ndt_weight * ndt()
        };
        weighted + parts_distance(parts, &self.parts)
    }

    /// The candidate orientations' padded matrices (`stride` x `cols`).
    pub fn candidates(&self) -> std::slice::ChunksExact<'_, f32> {
        self.padded.chunks_exact(self.stride * self.cols)
    }

    /// Candidate k's padded matrix (`stride` x `cols`).
    pub fn candidate(&self, k: usize) -> &[f32] {
        let size = self.stride * self.cols;
        &self.padded[k * size..(k + 1) * size]
    }

    /// The candidates' [`roots`](Self::roots) (none without them).
    pub(crate) fn root_candidates(&self) -> std::slice::ChunksExact<'_, f32> {
        self.roots.chunks_exact(self.stride * self.cols)
    }

    /// Column `col` of candidate `to` becomes column `col` of `src`'s
    /// candidate `from` (their roots too): how a reference scan of the gap
    /// statistic is drawn (cluster/choose_k/gap.rs).
    pub(crate) fn copy_column(&mut self, to: usize, col: usize, src: &Prepared, from: usize) {
        let size = self.stride * self.cols;
        let (t, f) = (
            to * size + col * self.stride,
            from * size + col * self.stride,
        );
        self.padded[t..t + self.stride].copy_from_slice(&src.padded[f..f + self.stride]);
        if !self.roots.is_empty() {
            self.roots[t..t + self.stride].copy_from_slice(&src.roots[f..f + self.stride]);
        }
    }

    /// Bytes this item holds on the heap; `examples/scaling.rs` reports it
    /// beside the Delta matrix's size.
    pub fn heap_bytes(&self) -> usize {
        (self.padded.capacity() + self.roots.capacity() + self.parts.capacity())
            * std::mem::size_of::<f32>()
    }
}

/// Normalise one count matrix.
pub fn normalise(m: &[u32], rows: usize, cols: usize, how: Normalisation) -> Vec<f32> {
    match how {
        Normalisation::Total => {
            let t: u64 = m.iter().map(|&v| v as u64).sum();
            let inv = if t > 0 { 1.0 / t as f32 } else { 0.0 };
            m.iter().map(|&v| v as f32 * inv).collect()
        }
        Normalisation::PerColumn => {
            let mut out = vec![0f32; m.len()];
            for c in 0..cols {
                let t: u64 = (0..rows).map(|r| m[r * cols + c] as u64).sum();
                if t > 0 {
                    for r in 0..rows {
                        out[r * cols + c] = m[r * cols + c] as f32 / t as f32;
                    }
                }
            }
            out
        }
    }
}

/// Prepare many descriptors, checking they share one shape.
pub fn prepare_all(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<Vec<Prepared>> {
    if let Some(first) = descriptors.first() {
        for d in descriptors {
            check_shape((d.rows, d.cols), (first.rows, first.cols))?;
        }
    }
    let prepared: Vec<Prepared> = descriptors
        .iter()
        .enumerate()
        .map(|(i, d)| Prepared::new(d, opts).map_err(|e| e.in_file(format!("descriptor {i}"))))
        .collect::<Result<_>>()?;
    if let Some(first) = prepared.first() {
        for (i, p) in prepared.iter().enumerate() {
            check_parts(p, first).map_err(|e| e.in_file(format!("descriptor {i}")))?;
        }
    }
    Ok(prepared)
}
