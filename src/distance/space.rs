//! The space clustering works in: prepared descriptors, their metric, and
//! centres (element-wise means of normalised matrices,
//! docs/design.md#clustering).

use super::{
    delta_prepared, matrix_distance, prepare_all, size_factor, DistanceMatrix, DistanceOptions,
    Prepared,
};
use crate::descriptor::{Descriptor, Metric};
use crate::error::Result;

/// Prepared descriptors and the metric to compare them with.
#[derive(Debug, Clone)]
pub struct Space {
    /// One prepared descriptor per scan, in scan order.
    pub items: Vec<Prepared>,
    /// The metric every Delta here uses.
    pub metric: Metric,
    /// The options the items were prepared with: the ones given, with
    /// [`Scale::Median`](crate::descriptor::Scale::Median) resolved into
    /// weights (`distance::scale`), so a model built here compares new
    /// scans as the space does.
    pub options: DistanceOptions,
}

/// A cluster centre: one normalised matrix and the members' mean |F|.
#[derive(Debug, Clone, PartialEq)]
pub struct Centre {
    /// Column-major and padded as [`Prepared::padded`] (`stride` rows).
    pub matrix: Vec<f32>,
    /// The members' mean |F|, the centre's size in Delta's size factor.
    pub total: f32,
    /// The members' mean extra parts, in the form of [`Prepared::parts`]
    /// (empty without parts).
    pub parts: Vec<f32>,
}

impl Space {
    /// Prepare every descriptor once with `opts` (its median scale, if
    /// any, taken over these descriptors). Descriptors of different shapes,
    /// or an invalid one (named by its index), are an error.
    pub fn new(descriptors: &[Descriptor], opts: DistanceOptions) -> Result<Space> {
        let options = super::scale::resolve(descriptors, opts)?;
        Ok(Space {
            items: prepare_all(descriptors, options)?,
            metric: options.metric,
            options,
        })
    }

    /// Number of scans.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// True when there is no scan.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Padded rows (`stride`) and columns of every item's matrices.
    fn shape(&self) -> (usize, usize) {
        self.items
            .first()
            .map(|p| (p.stride, p.cols))
            .unwrap_or((0, 0))
    }

    /// The full Delta matrix of the items (parallel natively), from the
    /// descriptors already prepared here.
    pub fn matrix(&self) -> DistanceMatrix {
        DistanceMatrix::from_fn(self.len(), |i, j| self.delta(i, j))
    }

    /// Delta between items i and j.
    pub fn delta(&self, i: usize, j: usize) -> f32 {
        delta_prepared(&self.items[i], &self.items[j], self.metric)
    }

    /// Delta from a centre to item i, and the candidate of i that attains it.
    pub fn to_centre(&self, c: &Centre, i: usize) -> (f32, usize) {
        let (stride, cols) = self.shape();
        let item = &self.items[i];
        // The candidate stays 0 when the NDT histogram has weight 0 (not compared).
        let mut candidate = 0;
        let ndt = || {
            let mut best = (f32::INFINITY, 0);
            for (k, m) in item.candidates().enumerate() {
                let d = matrix_distance(&c.matrix, m, stride, cols, self.metric);
                if d < best.0 {
                    best = (d, k);
                }
            }
            candidate = best.1;
            best.0 * size_factor(c.total, item.total)
        };
        (item.combined(ndt, &c.parts), candidate)
    }

    /// An error unless `c` has the shape of this space's centres (as
    /// [`Space::centre_of`] makes them; a centre of another space would be
    /// compared element by element with matrices of another size), finite
    /// values and a size above 0.
    pub(crate) fn check_centre(&self, c: &Centre, which: usize) -> Result<()> {
        let Some(item) = self.items.first() else {
            return Ok(());
        };
        let (matrix, parts) = (item.candidate(0).len(), item.parts.len());
        if c.matrix.len() != matrix || c.parts.len() != parts {
            return Err(crate::Error::InvalidParameter(format!(
                "centre {which} has {} matrix values and {} part values; this space's centres have {matrix} and {parts}",
                c.matrix.len(),
                c.parts.len()
            )));
        }
        // A NaN or infinite value, or a size of 0, would put every scan at
        // an infinite or NaN distance and label them all alike.
        if let Some(v) = (c.matrix.iter().chain(&c.parts)).find(|v| !v.is_finite()) {
            return Err(crate::Error::InvalidParameter(format!(
                "centre {which} holds the value {v}; a centre's values must be finite"
            )));
        }
        if !(c.total.is_finite() && c.total > 0.0) {
            return Err(crate::Error::InvalidParameter(format!(
                "centre {which} has size (total) {}; it must be a finite number above 0",
                c.total
            )));
        }
        Ok(())
    }

    /// A centre at item i (its first candidate).
    pub fn centre_of(&self, i: usize) -> Centre {
        Centre {
            matrix: self.items[i].candidate(0).to_vec(),
            total: self.items[i].total,
            parts: self.items[i].parts.clone(),
        }
    }

    /// Mean of the members, each contributing its candidate nearest to
    /// `near` (the current centre). None for no members.
    pub fn mean(&self, members: &[usize], near: &Centre) -> Option<Centre> {
        if members.is_empty() {
            return None;
        }
        let mut matrix = vec![0f32; near.matrix.len()];
        let mut parts = vec![0f32; near.parts.len()];
        let mut total = 0f64;
        for &i in members {
            let (_, k) = self.to_centre(near, i);
            for (a, b) in matrix.iter_mut().zip(self.items[i].candidate(k)) {
                *a += b;
            }
            for (a, b) in parts.iter_mut().zip(&self.items[i].parts) {
                *a += b;
            }
            total += self.items[i].total as f64;
        }
        let n = members.len() as f32;
        matrix.iter_mut().for_each(|v| *v /= n);
        parts.iter_mut().for_each(|v| *v /= n);
        Some(Centre {
            matrix,
            total: (total / members.len() as f64) as f32,
            parts,
        })
    }
}
