//! Extra parts of a descriptor beside the NDT histogram (issue 18): each
//! part is a few 1-D histograms ("channels"), each of unit sum, computed
//! from the points alone (no training). Two parts are compared channel by
//! channel with the 1-D earth mover's distance divided by its largest
//! value (bins - 1), averaged over the channels: a part's distance lies in
//! [0, 1] whatever the scene, so weights mean the same everywhere, and a
//! channel that holds one scalar feature (soft-binned, see [`soft_bin`])
//! compares as the absolute difference of the feature over its range.
//!
//! The parts: [`height_range`], [`slice`](mod@slice), [`esf`], [`ring`],
//! [`clutter`], [`m2dp`], [`columns`], [`iron`], [`objects`],
//! [`object_types`], [`object_layout`].

use super::polar::PolarScan;
use super::shape::ShapedCell;
use super::{
    clutter, columns, esf, height_range, iron, m2dp, object_layout, object_types, objects, ring,
    slice,
};
use crate::cloud::is_finite;
use rustc_hash::{FxHashMap, FxHashSet};
use serde::{Deserialize, Serialize};

/// Most parts one descriptor may have (one of each kind).
pub const MAX_PARTS: usize = 11;

/// Which extra part.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
#[serde(rename_all = "snake_case")]
pub enum PartKind {
    /// Distributions of horizontal range and of height ([`height_range`]).
    HeightRange,
    /// Geometry of the free-space polygon around the sensor ([`slice`](mod@slice)).
    Slice,
    /// Shape-function histograms of point pairs and triples ([`esf`]).
    Esf,
    /// Ring statistics of a polar height grid ([`ring`]).
    Ring,
    /// Virtual horizontal scans at several heights above the floor, and
    /// the height profile of what stands in the room ([`clutter`]).
    Clutter,
    /// The first singular vectors of a scan's projections onto 64 planes
    /// (M2DP, He et al. 2016; [`m2dp`]).
    M2dp,
    /// What stands in each azimuth sector, from the floor up: top, extent
    /// and bottom of the room's contents ([`columns`]).
    Columns,
    /// How the scan's planar NDT cells stand to each other: separations
    /// and angles of nearby pairs (after IRON, Schmiedel et al. 2015;
    /// [`iron`]).
    Iron,
    /// What stands in the room, object by object: footprints, tops,
    /// roundness and number of connected pieces (after object-based place
    /// models, Vasudevan et al. 2007; [`objects`]).
    Objects,
    /// The same pieces by footprint class and top together (a joint
    /// histogram, after Pass and Zabih 1999; [`object_types`]).
    ObjectTypes,
    /// How the same pieces are laid out: spacing to the nearest, angles
    /// between long axes ([`object_layout`]).
    ObjectLayout,
}

impl PartKind {
    /// Every kind, in the order of [`DistanceOptions`](crate::DistanceOptions)'s weights.
    pub const ALL: [PartKind; MAX_PARTS] = [
        PartKind::HeightRange,
        PartKind::Slice,
        PartKind::Esf,
        PartKind::Ring,
        PartKind::Clutter,
        PartKind::M2dp,
        PartKind::Columns,
        PartKind::Iron,
        PartKind::Objects,
        PartKind::ObjectTypes,
        PartKind::ObjectLayout,
    ];

    /// Position in [`PartKind::ALL`].
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The kind's name, as in JSON (`"height_range"`, `"iron"`, ...).
    pub fn name(self) -> &'static str {
        match self {
            PartKind::HeightRange => "height_range",
            PartKind::Slice => "slice",
            PartKind::Esf => "esf",
            PartKind::Ring => "ring",
            PartKind::Clutter => "clutter",
            PartKind::M2dp => "m2dp",
            PartKind::Columns => "columns",
            PartKind::Iron => "iron",
            PartKind::Objects => "objects",
            PartKind::ObjectTypes => "object_types",
            PartKind::ObjectLayout => "object_layout",
        }
    }

    /// Bins of each channel.
    pub fn channels(self) -> &'static [usize] {
        match self {
            PartKind::HeightRange => &height_range::CHANNELS,
            PartKind::Slice => &slice::CHANNELS,
            PartKind::Esf => &esf::CHANNELS,
            PartKind::Ring => &ring::CHANNELS,
            PartKind::Clutter => &clutter::CHANNELS,
            PartKind::M2dp => &m2dp::CHANNELS,
            PartKind::Columns => &columns::CHANNELS,
            PartKind::Iron => &iron::CHANNELS,
            PartKind::Objects => &objects::CHANNELS,
            PartKind::ObjectTypes => &object_types::CHANNELS,
            PartKind::ObjectLayout => &object_layout::CHANNELS,
        }
    }

    /// Whether the part measures heights from the floor, and so reads a
    /// given `sensor_height` in place of each scan's estimate.
    pub fn measures_from_floor(self) -> bool {
        matches!(
            self,
            PartKind::Clutter
                | PartKind::Columns
                | PartKind::Objects
                | PartKind::ObjectTypes
                | PartKind::ObjectLayout
        )
    }

    /// Values of the part: the sum of [`channels`](Self::channels).
    pub fn len(self) -> usize {
        self.channels().iter().sum()
    }

    /// Always false: every part has values (for clippy's `len` rule).
    pub fn is_empty(self) -> bool {
        false
    }

    /// Compute the part from a scan's points (sensor frame, z up).
    pub fn describe(self, points: &[[f32; 3]]) -> Vec<f32> {
        describe_parts(points, &[self]).pop().unwrap_or_default()
    }

    /// Compute the part from a scan whose ranges and azimuths are
    /// computed once for all its parts.
    pub fn describe_scan(self, scan: &PolarScan) -> Vec<f32> {
        let points = scan.points;
        let v = match self {
            PartKind::HeightRange => height_range::describe(points),
            PartKind::Slice => slice::describe_scan(scan),
            PartKind::Esf => esf::describe(points),
            PartKind::Ring => ring::describe_scan(scan),
            PartKind::Clutter => clutter::describe_scan(scan),
            PartKind::M2dp => m2dp::describe(points),
            PartKind::Columns => columns::describe_scan(scan),
            PartKind::Iron => iron::describe(points),
            PartKind::Objects => objects::describe_scan(scan),
            PartKind::ObjectTypes => object_types::describe_scan(scan),
            PartKind::ObjectLayout => object_layout::describe_scan(scan),
        };
        debug_assert_eq!(v.len(), self.len());
        v
    }
}

/// The values of each of `kinds` for a scan's points. The points' ranges
/// and azimuths ([`PolarScan`]) are computed once, and only when a part
/// that reads them is asked for: `height_range` and `esf` alone cost no
/// `hypot` or `atan2` pass.
/// The floor of the parts that measure from it is each scan's estimate.
pub fn describe_parts(points: &[[f32; 3]], kinds: &[PartKind]) -> Vec<Vec<f32>> {
    describe_parts_with(points, kinds, None)
}

/// [`describe_parts`] with the floor `sensor_height` (m) below the sensor
/// where it is given ([`PolarScan::with_sensor_height`]).
pub fn describe_parts_with(
    points: &[[f32; 3]],
    kinds: &[PartKind],
    sensor_height: Option<f32>,
) -> Vec<Vec<f32>> {
    describe_parts_sharing(points, kinds, sensor_height, None)
}

/// [`describe_parts_with`], the `iron` part from `ndt_cells` where given:
/// the scan's classified NDT cells, built as that part builds them
/// (`iron::shares_grid`), so that `describe` builds the grid once.
pub(crate) fn describe_parts_sharing(
    points: &[[f32; 3]],
    kinds: &[PartKind],
    sensor_height: Option<f32>,
    ndt_cells: Option<&[ShapedCell]>,
) -> Vec<Vec<f32>> {
    let scan = std::cell::OnceCell::new();
    let polar = || scan.get_or_init(|| PolarScan::with_sensor_height(points, sensor_height));
    // The objects' pieces, cut once for the three parts that describe them.
    let contents = std::cell::OnceCell::new();
    let pieces = || {
        contents
            .get_or_init(|| objects::contents_of(polar()))
            .as_ref()
    };
    kinds
        .iter()
        .map(|&kind| {
            let v = match kind {
                PartKind::Objects => objects::of_contents(pieces()),
                PartKind::ObjectTypes => object_types::of_contents(pieces()),
                PartKind::ObjectLayout => object_layout::of_contents(pieces()),
                PartKind::HeightRange => height_range::describe(points),
                PartKind::Esf => esf::describe(points),
                PartKind::M2dp => m2dp::describe(points),
                PartKind::Iron => match ndt_cells {
                    Some(cells) => iron::describe_cells(cells),
                    None => iron::describe(points),
                },
                _ => kind.describe_scan(polar()),
            };
            debug_assert_eq!(v.len(), kind.len());
            v
        })
        .collect()
}

/// One extra part and its weight in the distance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
#[serde(deny_unknown_fields)]
pub struct Part {
    /// Which part.
    pub kind: PartKind,
    /// Its weight: the part's distance (in [0, 1]) times this is added to
    /// the NDT histogram's Delta times `ndt_weight`.
    pub weight: f64,
}

/// A described part as stored in a descriptor: its kind and values
/// (channel after channel, each of unit sum).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PartValues {
    /// Which part.
    pub kind: PartKind,
    /// The channels' histograms, one after another.
    pub values: Vec<f32>,
}

impl PartValues {
    /// Check the length and that each channel is a histogram (finite,
    /// non-negative, unit sum): values from JSON must not make a NaN later.
    pub fn validate(&self) -> crate::Result<()> {
        let bad = |why: &str| {
            Err(crate::Error::Mismatch(format!(
                "a {:?} part {why}",
                self.kind
            )))
        };
        if self.values.len() != self.kind.len() {
            return bad(&format!(
                "has {} values, not {}",
                self.values.len(),
                self.kind.len()
            ));
        }
        let mut at = 0;
        for &bins in self.kind.channels() {
            let ch = &self.values[at..at + bins];
            at += bins;
            if ch.iter().any(|v| !v.is_finite() || *v < 0.0) {
                return bad("has a negative or non-finite value");
            }
            if (ch.iter().sum::<f32>() - 1.0).abs() > 1e-3 {
                return bad("has a channel that does not sum to 1");
            }
        }
        Ok(())
    }
}

/// Add unit mass at position `x` (in bins, clamped to [0, bins - 1]) to
/// `hist`, split linearly between the two nearest bins: the earth mover's
/// distance between two such masses is then exactly |x - y| in bins.
pub fn soft_bin(hist: &mut [f32], x: f64, mass: f32) {
    let top = (hist.len() - 1) as f64;
    // An infinite position (a distance overflowing from a wild but finite
    // point) belongs in the top bin, as any value beyond the range does.
    let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, top) };
    let lo = x.floor() as usize;
    let frac = (x - lo as f64) as f32;
    hist[lo] += mass * (1.0 - frac);
    if frac > 0.0 {
        hist[lo + 1] += mass * frac;
    }
}

/// One channel holding one scalar: `x` mapped linearly from [lo, hi] onto
/// the bins (clamped).
pub fn scalar_channel(bins: usize, x: f64, lo: f64, hi: f64) -> Vec<f32> {
    let mut h = vec![0f32; bins];
    soft_bin(&mut h, (x - lo) / (hi - lo) * (bins - 1) as f64, 1.0);
    h
}

/// Scale `hist` to unit sum; an empty histogram puts its mass in bin 0
/// (for every part, bin 0 means "nothing there").
pub fn unit_sum(hist: &mut [f32]) {
    let s: f32 = hist.iter().sum();
    if s > 0.0 {
        hist.iter_mut().for_each(|v| *v /= s);
    } else {
        hist[0] = 1.0;
    }
}

/// Channels of the given bins with every mass in bin 0 ("nothing
/// there"): a part of a scan with no usable return.
pub fn empty_channels(channels: &[usize]) -> Vec<f32> {
    let mut v = Vec::with_capacity(channels.iter().sum());
    for &b in channels {
        let mut h = vec![0f32; b];
        h[0] = 1.0;
        v.extend(h);
    }
    v
}

/// The azimuth sector (of `sectors` equal ones, counted from -pi) that a
/// point lies in.
pub fn sector_of(p: &[f32; 3], sectors: usize) -> usize {
    let a = p[1].atan2(p[0]) + std::f32::consts::PI;
    ((a / std::f32::consts::TAU * sectors as f32) as usize).min(sectors - 1)
}

/// One point per occupied voxel of edge `size` (the first point seen in
/// it), finite points only, in a fixed order. A lidar samples near
/// surfaces far more densely than far ones; statistics of these points
/// weigh surfaces by area instead. The point kept depends on the points'
/// order (used by `height_range`, which is in no preset;
/// [`voxel_lowest`] does not).
pub fn voxel_sample(points: &[[f32; 3]], size: f32) -> Vec<[f32; 3]> {
    let inv = 1.0 / size;
    let mut seen = FxHashSet::default();
    points
        .iter()
        .filter(|p| is_finite(p))
        .filter(|p| {
            let k = p.map(|v| (v * inv).floor() as i32);
            seen.insert(k)
        })
        .copied()
        .collect()
}

/// One point per occupied voxel of edge `size`, finite points only: the
/// lowest of the voxel's points (least by z, then x, then y, in
/// `f32::total_cmp`). Which points are kept does not depend on the order
/// of `points`; the order of the list does (it is a hash map's), so a
/// part summing floats over them sorts what it sums first (sorting every
/// voxel by key cost the clutter part 1.8x on a 100k-point outdoor scan).
pub fn voxel_lowest(points: &[[f32; 3]], size: f32) -> Vec<[f32; 3]> {
    let inv = 1.0 / size;
    let below = |a: &[f32; 3], b: &[f32; 3]| {
        (a[2].total_cmp(&b[2]))
            .then(a[0].total_cmp(&b[0]))
            .then(a[1].total_cmp(&b[1]))
            .is_lt()
    };
    let mut lowest: FxHashMap<[i32; 3], [f32; 3]> = FxHashMap::default();
    for p in points.iter().filter(|p| is_finite(p)) {
        let k = p.map(|v| (v * inv).floor() as i32);
        lowest
            .entry(k)
            .and_modify(|q| {
                if below(p, q) {
                    *q = *p
                }
            })
            .or_insert(*p);
    }
    lowest.into_values().collect()
}

/// The form parts are compared in: each channel's cumulative sums, scaled
/// so that the L1 distance of two of them is the part's distance times
/// `weight` (channel EMD / (bins - 1), averaged over channels). Linear, so
/// means of these are the form of the mean histogram (cluster centres).
pub fn cumulative(p: &PartValues, weight: f32, out: &mut Vec<f32>) {
    let channels = p.kind.channels();
    let mut at = 0;
    for &bins in channels {
        let scale = weight / ((bins.max(2) - 1) * channels.len()) as f32;
        let mut sum = 0f32;
        // The last cumulative sum is 1 for every histogram: left out.
        for v in &p.values[at..at + bins - 1] {
            sum += v;
            out.push(sum * scale);
        }
        at += bins;
    }
}

/// Length of the [`cumulative`] form of a part.
pub fn cumulative_len(kind: PartKind) -> usize {
    kind.channels().iter().map(|b| b - 1).sum()
}

/// The L1 distance of two cumulative forms: the weighted sum of part
/// distances.
#[inline]
pub fn parts_distance(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kinds_name_is_its_json_name() {
        for kind in PartKind::ALL {
            assert_eq!(serde_json::to_value(kind).unwrap(), kind.name());
        }
    }

    /// Soft binning makes the EMD of two scalars their distance in bins.
    #[test]
    fn soft_binned_scalars_compare_as_their_difference() {
        let pv = |x: f64| PartValues {
            kind: PartKind::HeightRange,
            values: {
                let mut v = Vec::new();
                for &b in PartKind::HeightRange.channels() {
                    v.extend(scalar_channel(b, x, 0.0, (b - 1) as f64));
                }
                v
            },
        };
        let (mut a, mut b) = (Vec::new(), Vec::new());
        cumulative(&pv(0.3), 1.0, &mut a);
        cumulative(&pv(1.6), 1.0, &mut b);
        let channels = PartKind::HeightRange.channels();
        let want: f32 = channels
            .iter()
            .map(|&bins| 1.3 / ((bins - 1) * channels.len()) as f32)
            .sum();
        assert!((parts_distance(&a, &b) - want).abs() < 1e-5);
        assert_eq!(a.len(), cumulative_len(PartKind::HeightRange));
    }

    /// `height_range` and `esf` never build a [`PolarScan`] (a `hypot`
    /// and `atan2` pass over every point that they do not read); slice,
    /// ring and clutter together build one.
    #[test]
    fn polar_coordinates_are_made_once_and_only_when_read() {
        let pts: Vec<[f32; 3]> = (0..400)
            .map(|i| {
                let a = i as f32 * 0.05;
                [3.0 * a.cos(), 2.0 * a.sin(), (i % 7) as f32 * 0.3 - 1.0]
            })
            .collect();
        let built = |kinds: &[PartKind]| {
            let before = super::super::polar::built();
            let v = describe_parts(&pts, kinds);
            assert_eq!(v.len(), kinds.len());
            super::super::polar::built() - before
        };
        assert_eq!(built(&[PartKind::HeightRange]), 0);
        assert_eq!(built(&[PartKind::Esf]), 0);
        assert_eq!(built(&[PartKind::HeightRange, PartKind::Esf]), 0);
        assert_eq!(built(&PartKind::ALL), 1);
        let before = super::super::polar::built();
        PartKind::Esf.describe(&pts);
        PartKind::HeightRange.describe(&pts);
        assert_eq!(super::super::polar::built(), before);
        PartKind::Ring.describe(&pts);
        assert_eq!(super::super::polar::built(), before + 1);
    }

    /// The lowest point of each voxel, whatever the order: reversing the
    /// points keeps the same points (the first point seen did not).
    #[test]
    fn voxel_lowest_does_not_depend_on_the_order() {
        let pts = vec![
            [0.05, 0.05, 0.07],
            [0.02, 0.01, 0.03],
            [0.5, 0.5, 0.5],
            [0.04, 0.08, 0.03],
        ];
        let mut rev = pts.clone();
        rev.reverse();
        let sorted = |mut v: Vec<[f32; 3]>| {
            v.sort_by(|a, b| a[2].total_cmp(&b[2]));
            v
        };
        let a = sorted(voxel_lowest(&pts, 0.1));
        assert_eq!(a, sorted(voxel_lowest(&rev, 0.1)));
        assert_eq!(a, vec![[0.02, 0.01, 0.03], [0.5, 0.5, 0.5]]);
    }

    /// The whole mass at opposite ends is the largest distance: 1.
    #[test]
    fn a_part_distance_is_at_most_one() {
        let end = |last: bool| {
            let mut v = Vec::new();
            for &b in PartKind::Slice.channels() {
                let mut h = vec![0f32; b];
                h[if last { b - 1 } else { 0 }] = 1.0;
                v.extend(h);
            }
            PartValues {
                kind: PartKind::Slice,
                values: v,
            }
        };
        let (mut a, mut b) = (Vec::new(), Vec::new());
        cumulative(&end(false), 1.0, &mut a);
        cumulative(&end(true), 1.0, &mut b);
        assert!((parts_distance(&a, &b) - 1.0).abs() < 1e-5);
        assert!(end(true).validate().is_ok());
        let mut short = end(true);
        short.values.pop();
        assert!(short.validate().is_err());
    }
}
