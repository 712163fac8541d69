//! The NDT-histogram appearance descriptor (docs/design.md#descriptor):
//! points -> [`ndt_grid`] -> [`shape`] classes -> [`alignment`] candidates ->
//! [`histogram`] matrices; and optional extra [`parts`] beside it (issue
//! 18): [`height_range`], [`slice`](mod@slice), [`esf`], [`ring`],
//! [`clutter`], [`m2dp`], [`columns`], [`iron`], [`objects`], [`object_types`],
//! [`object_layout`].

pub mod alignment;
pub mod clutter;
pub mod columns;
pub mod directions;
pub mod esf;
pub mod height_range;
pub mod histogram;
pub mod iron;
pub mod m2dp;
pub mod ndt_grid;
pub mod object_layout;
pub mod object_types;
pub mod objects;
pub mod params;
pub mod parts;
pub mod polar;
pub mod ring;
pub mod shape;
pub mod slice;

pub use params::{
    preset_names, preset_note, Alignment, DescriptorParams, Metric, Normalisation, Scale, PRESETS,
    PRESET_NOTES, WITHDRAWN_PRESETS,
};
pub use parts::{Part, PartKind, PartValues};

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// What the descriptor saw of a scan.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Summary {
    /// Finite points used.
    pub points: usize,
    /// Non-finite points dropped.
    pub dropped: usize,
    /// Voxels with enough points.
    pub voxels: usize,
    /// Occupied voxels skipped for having too few points.
    pub sparse_voxels: usize,
    /// Voxels classified spherical (in range or not).
    pub spherical: usize,
    /// Voxels classified planar.
    pub planar: usize,
    /// Voxels classified linear.
    pub linear: usize,
    /// Voxels counted in at least one range interval.
    pub in_range: usize,
    /// Candidate orientations.
    pub alignments: usize,
    /// Fewer classified voxels in range than `min_voxels`: the descriptor
    /// says little; clustering still uses it, but callers should show this.
    pub unreliable: bool,
}

/// A scan's descriptor: one count matrix F per candidate orientation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Descriptor {
    /// Rows of each F: shape classes (ns + np + nl) times height bands.
    pub rows: usize,
    /// Columns of each F: the range intervals.
    pub cols: usize,
    /// Row-major count matrices, one per candidate orientation.
    pub matrices: Vec<Vec<u32>>,
    /// What describing the scan found (points, voxels, classes), for display
    /// and the unreliable flag.
    pub summary: Summary,
    /// The extra parts, in the order of the parameters' `parts` (none for
    /// the paper's descriptor, and then left out of JSON).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub parts: Vec<PartValues>,
}

impl Descriptor {
    /// |F| of the first candidate (all candidates count the same voxels).
    pub fn total(&self) -> u64 {
        self.matrices
            .first()
            .map(|m| m.iter().map(|&v| v as u64).sum())
            .unwrap_or(0)
    }

    /// Check the shape (for descriptors that came from JSON).
    pub fn validate(&self) -> Result<()> {
        if self.matrices.is_empty() {
            return Err(Error::Mismatch("a descriptor has no matrix".into()));
        }
        // Checked: rows and cols come from users' JSON, and a product that
        // wraps round could match a short matrix.
        let cells = self.rows.checked_mul(self.cols).filter(|&c| c > 0);
        if cells.is_none_or(|c| self.matrices.iter().any(|m| m.len() != c)) {
            return Err(Error::Mismatch(format!(
                "a matrix does not have rows x cols = {} x {} entries",
                self.rows, self.cols
            )));
        }
        if self.total() == 0 {
            return Err(Error::NoDescriptor("all counts are zero".into()));
        }
        self.parts.iter().try_for_each(PartValues::validate)
    }

    /// [`validate`](Self::validate), and that `params` make this shape: a
    /// descriptor read back from JSON must match the parameters it is
    /// filed under.
    pub fn validate_for(&self, params: &DescriptorParams) -> Result<()> {
        self.validate()?;
        let (rows, cols) = (params.rows(), params.cols());
        if (self.rows, self.cols) != (rows, cols) {
            return Err(Error::Mismatch(format!(
                "the descriptor is {}x{}, the set's parameters make {rows}x{cols}",
                self.rows, self.cols
            )));
        }
        let have: Vec<PartKind> = self.parts.iter().map(|p| p.kind).collect();
        let want: Vec<PartKind> = params.parts.iter().map(|p| p.kind).collect();
        if have != want {
            return Err(Error::Mismatch(format!(
                "the descriptor has parts {have:?}, the set's parameters make {want:?}"
            )));
        }
        Ok(())
    }
}

/// Describe a scan given its points (sensor frame, sensor at the origin).
pub fn describe(points: &[[f32; 3]], params: &DescriptorParams) -> Result<Descriptor> {
    params.validate()?;
    let grid = ndt_grid::build(points, params.voxel_size, params.min_points_per_voxel);
    let cells: Vec<shape::ShapedCell> = grid
        .cells
        .iter()
        .filter_map(|c| shape::classify(c, params.eigen_threshold))
        .collect();
    let mut summary = Summary {
        points: grid.points,
        dropped: grid.dropped,
        voxels: grid.cells.len(),
        sparse_voxels: grid.sparse_voxels,
        ..Summary::default()
    };
    for c in &cells {
        match c.shape {
            shape::Shape::Spherical => summary.spherical += 1,
            shape::Shape::Planar => summary.planar += 1,
            shape::Shape::Linear => summary.linear += 1,
        }
    }
    let rotations = alignment::candidates(&cells, params);
    let (matrices, in_range) = histogram::histograms(&cells, &rotations, params);
    let total: u64 = matrices[0].iter().map(|&v| v as u64).sum();
    summary.in_range = in_range;
    summary.alignments = matrices.len();
    summary.unreliable = summary.in_range < params.min_voxels;
    if total == 0 {
        return Err(Error::NoDescriptor(format!(
            "no classified voxel in any range interval ({} finite points, {} dropped, {} voxels with >= {} points)",
            grid.points, grid.dropped, grid.cells.len(), params.min_points_per_voxel
        )));
    }
    Ok(Descriptor {
        rows: params.rows(),
        cols: params.cols(),
        matrices,
        summary,
        parts: {
            let kinds: Vec<PartKind> = params.parts.iter().map(|p| p.kind).collect();
            kinds
                .iter()
                .zip(parts::describe_parts_sharing(
                    points,
                    &kinds,
                    params.sensor_height.map(|h| h as f32),
                    // The iron part's grid is this one with the paper's
                    // indoor settings: built once (0.4 m, 5 points, 0.05).
                    iron::shares_grid(
                        params.voxel_size,
                        params.min_points_per_voxel,
                        params.eigen_threshold,
                    )
                    .then_some(cells.as_slice()),
                ))
                .map(|(&kind, values)| PartValues { kind, values })
                .collect()
        },
    })
}
