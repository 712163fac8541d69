//! A scan's points with their horizontal range and azimuth, computed once
//! for every part that needs them ([`slice`](mod@super::slice),
//! [`ring`](super::ring), [`clutter`]): each used to take
//! its own `hypot` and `atan2` of every point, and the slice's polygon was
//! made twice when the clutter part came with it. The values are the very
//! ones each part computed, so descriptors stay bit for bit the same
//! (tests/it/parts.rs checks it).

use super::{clutter, slice};
use std::cell::OnceCell;

/// Points, their ranges and azimuths, and the free-space polygon made on
/// first use.
pub struct PolarScan<'a> {
    /// The points (sensor frame, z up).
    pub points: &'a [[f32; 3]],
    /// Horizontal range of each point (NaN for a non-finite one).
    range: Vec<f32>,
    /// atan2(y, x) + pi of each point, in [0, 2 pi].
    angle: Vec<f32>,
    /// [`slice::sector_points_of`], made once.
    polygon: OnceCell<Option<Vec<[f64; 2]>>>,
    /// The floor and ceiling heights, found once for the parts that
    /// measure from them (`clutter`, `columns` and `objects`).
    floor_and_ceiling: OnceCell<Option<(f32, f32)>>,
    /// The floor's height relative to the sensor when it is known
    /// (`-sensor_height`), in place of the estimate.
    known_floor: Option<f32>,
}

impl<'a> PolarScan<'a> {
    /// Ranges and azimuths of every point.
    pub fn new(points: &'a [[f32; 3]]) -> Self {
        #[cfg(test)]
        BUILT.with(|b| b.set(b.get() + 1));
        PolarScan {
            points,
            range: points.iter().map(|p| p[0].hypot(p[1])).collect(),
            angle: points
                .iter()
                .map(|p| p[1].atan2(p[0]) + std::f32::consts::PI)
                .collect(),
            polygon: OnceCell::new(),
            floor_and_ceiling: OnceCell::new(),
            known_floor: None,
        }
    }

    /// [`new`](Self::new), with the floor `sensor_height` below the sensor
    /// where it is given.
    pub fn with_sensor_height(points: &'a [[f32; 3]], sensor_height: Option<f32>) -> Self {
        PolarScan {
            known_floor: sensor_height.map(|h| -h),
            ..Self::new(points)
        }
    }

    /// The floor's height relative to the sensor, when it is given.
    pub fn known_floor(&self) -> Option<f32> {
        self.known_floor
    }

    /// Horizontal range of point `i`.
    #[inline]
    pub fn range(&self, i: usize) -> f32 {
        self.range[i]
    }

    /// The azimuth sector (of `sectors` equal ones, counted from -pi) of
    /// point `i`: [`sector_of`](super::parts::sector_of) of the point.
    #[inline]
    pub fn sector(&self, i: usize, sectors: usize) -> usize {
        debug_assert!(sectors > 0, "no sectors");
        ((self.angle[i] / std::f32::consts::TAU * sectors as f32) as usize).min(sectors - 1)
    }

    /// The free-space polygon's vertices ([`slice::sector_points_of`]).
    pub fn polygon(&self) -> Option<&[[f64; 2]]> {
        self.polygon
            .get_or_init(|| slice::sector_points_of(self))
            .as_deref()
    }

    /// The floor and ceiling heights relative to the sensor
    /// ([`clutter::floor_and_ceiling`]), found on first use.
    pub fn floor_and_ceiling(&self) -> Option<(f32, f32)> {
        *self
            .floor_and_ceiling
            .get_or_init(|| clutter::floor_and_ceiling_of(self))
    }
}

#[cfg(test)]
thread_local! {
    /// How many [`PolarScan`]s this thread built (tests check that parts
    /// which do not read them do not pay for one).
    static BUILT: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// [`PolarScan`]s built so far by this thread.
#[cfg(test)]
pub(crate) fn built() -> usize {
    BUILT.with(|b| b.get())
}
