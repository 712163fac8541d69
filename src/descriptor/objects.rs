//! What stands in a room, object by object (issue 18, sixteenth round).
//!
//! Object-based place models describe a place by the objects in it
//! (Vasudevan, Gächter, Nguyen and Siegwart, "Cognitive maps for mobile
//! robots: an object based approach", Robotics and Autonomous Systems
//! 2007; Ranganathan and Dellaert, "Semantic modeling of places using
//! objects", RSS 2007). They recognise the objects with trained detectors;
//! this part, training-free, only cuts the room's contents into connected
//! pieces and describes the pieces by their size and shape.
//!
//! Why: the [`clutter`](mod@super::clutter) and
//! [`columns`](mod@super::columns) parts count what stands in the room
//! direction by direction, so one bed seen from near the door and from the
//! window fills different sectors at different shares. Counted as objects,
//! it is one footprint of about 2 m², one top at 0.6 m and one elongated
//! shape from anywhere it is seen whole. The kinds the other parts confuse
//! differ in their furniture (a ward's bed against an examination couch; a
//! library's shelving stacks against a staff room's sofa and tables).
//!
//! The contents are the points within [`NEAR`] m horizontally, from 0.1 m
//! above the floor to 0.3 m below the ceiling (the floor and ceiling of
//! `clutter`, or the floor `sensor_height` below the sensor where given),
//! and nearer than 0.9 of the farthest return in their azimuth sector (of
//! 180) in that height band: what stands on the walls is the wall. They
//! are gridded in 0.1 m cells on the floor plane; 8-connected groups of at
//! least 3 cells are the objects. Channels, 10 bins each:
//!
//! - the objects' footprints: log10 of the area of their cells (m²), over
//!   [-2, 1];
//! - their tops: the highest point's height above the floor, over [0, 2.4]
//!   m;
//! - their roundness: the square root of the ratio of the smaller to the
//!   larger second moment of their cells (1 round or square, towards 0 a
//!   line), over [0, 1];
//! - how many there are per m² of the cells the scan saw (any return
//!   within `NEAR`), over [0, 0.5].
//!
//! The first three are histograms over the objects (unit sum), the last a
//! scalar. A scan with no floor or no object puts every channel's mass in
//! bin 0. The constants are those of the development probe
//! (docs/objects-dev.md) that the sixteenth round's plan fixed
//! (docs/seeds.md). The part is invariant to rotation about z up to the
//! grid's cells.

use super::parts::{empty_channels, scalar_channel, soft_bin, unit_sum};
use super::polar::PolarScan;
use crate::cloud::is_finite;
use rustc_hash::{FxHashMap, FxHashSet};

/// Bins of each channel: footprint, top, roundness, density.
pub const CHANNELS: [usize; 4] = [BINS; 4];
const BINS: usize = 10;
/// Contents lie within this horizontal range (m).
pub const NEAR: f32 = 8.0;
/// Contents lie this far above the floor and below the ceiling (m).
const ABOVE_FLOOR: f32 = 0.1;
const BELOW_CEILING: f32 = 0.3;
/// Contents lie nearer than this share of their sector's wall.
const WALL_SHARE: f32 = 0.9;
const SECTORS: usize = 180;
/// The floor grid's cell (m).
const CELL: f32 = 0.1;
/// An object has at least this many cells.
const MIN_CELLS: usize = 3;
/// Ranges of the channels: log10 footprint (m²), top (m), density (per m²).
const LOG_AREA: (f32, f32) = (-2.0, 1.0);
const TOP: f32 = 2.4;
const DENSITY: f64 = 0.5;

type Cell = (i32, i32);

/// The part of a scan's points.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// The part of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    of_contents(contents_of(scan).as_ref())
}

/// The part of a scan's [`contents_of`] (cut once for the three parts
/// that read them).
pub(crate) fn of_contents(contents: Option<&Contents>) -> Vec<f32> {
    let Some(Contents { pieces, seen }) = contents else {
        return empty_channels(&CHANNELS);
    };
    // Every piece's cells were seen, so `seen` > 0 past this.
    if pieces.is_empty() {
        return empty_channels(&CHANNELS);
    }
    let mut area = vec![0f32; BINS];
    let mut top = vec![0f32; BINS];
    let mut roundness = vec![0f32; BINS];
    // A value's position on [0, 1] of its range, in bins.
    let at = |x: f32| f64::from(x) * (BINS - 1) as f64;
    for piece in pieces {
        let a = piece.area.log10();
        soft_bin(
            &mut area,
            at((a - LOG_AREA.0) / (LOG_AREA.1 - LOG_AREA.0)),
            1.0,
        );
        soft_bin(&mut top, at(piece.top / TOP), 1.0);
        soft_bin(&mut roundness, at(piece.roundness), 1.0);
    }
    let density = pieces.len() as f64 / (*seen as f64 * f64::from(CELL * CELL));
    let mut v = Vec::with_capacity(CHANNELS.iter().sum());
    for mut h in [area, top, roundness] {
        unit_sum(&mut h);
        v.extend(h);
    }
    v.extend(scalar_channel(BINS, density, 0.0, DENSITY));
    v
}

/// One connected piece of what stands in the room.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    /// The area of its cells (m²).
    pub area: f32,
    /// Its highest point above the floor (m).
    pub top: f32,
    /// See [`moments_of`]: 1 round or square, towards 0 a line.
    pub roundness: f32,
    /// The mean of its cells' centres (m, sensor frame).
    pub centre: [f32; 2],
    /// The direction of its longer second moment (radians, in (-pi/2, pi/2]).
    pub axis: f32,
}

/// A scan's pieces and how many cells it saw within [`NEAR`].
pub(crate) struct Contents {
    /// The pieces, in the order of their least cell.
    pub pieces: Vec<Piece>,
    /// Cells with any return within [`NEAR`].
    pub seen: usize,
}

/// `of_pieces` of a scan's pieces where it has any; else every channel's
/// mass in bin 0 (the parts that describe the pieces otherwise).
pub(crate) fn of_pieces_or_empty(
    contents: Option<&Contents>,
    channels: &[usize],
    of_pieces: fn(&[Piece]) -> Vec<f32>,
) -> Vec<f32> {
    match contents {
        Some(c) if !c.pieces.is_empty() => of_pieces(&c.pieces),
        _ => empty_channels(channels),
    }
}

/// The pieces of what stands in the room, as this part cuts them (the
/// `object_types` and `object_layout` parts describe the same pieces
/// otherwise); `None` when the scan shows no floor.
pub(crate) fn contents_of(scan: &PolarScan) -> Option<Contents> {
    let (floor, ceiling) = scan.floor_and_ceiling()?;
    let (tops, seen) = contents(scan, floor, ceiling);
    let pieces = objects(&tops)
        .iter()
        .map(|cells| {
            let (roundness, centre, axis) = moments_of(cells);
            Piece {
                area: cells.len() as f32 * CELL * CELL,
                top: cells.iter().map(|c| tops[c]).fold(f32::MIN, f32::max),
                roundness,
                centre,
                axis,
            }
        })
        .collect();
    Some(Contents { pieces, seen })
}

/// The cells holding contents, each with its highest point above the
/// floor, and how many cells the scan saw within [`NEAR`].
fn contents(scan: &PolarScan, floor: f32, ceiling: f32) -> (FxHashMap<Cell, f32>, usize) {
    let points = scan.points;
    let in_band = |p: &[f32; 3]| p[2] > floor + ABOVE_FLOOR && p[2] < ceiling - BELOW_CEILING;
    let mut wall = [0f32; SECTORS];
    for (i, p) in points.iter().enumerate() {
        if is_finite(p) && in_band(p) {
            let s = scan.sector(i, SECTORS);
            wall[s] = wall[s].max(scan.range(i));
        }
    }
    let cell = |p: &[f32; 3]| ((p[0] / CELL).floor() as i32, (p[1] / CELL).floor() as i32);
    let mut seen: FxHashSet<Cell> = FxHashSet::default();
    let mut tops: FxHashMap<Cell, f32> = FxHashMap::default();
    for (i, p) in points.iter().enumerate() {
        // A non-finite point's range is NaN: never near.
        if !(is_finite(p) && scan.range(i) < NEAR) {
            continue;
        }
        let c = cell(p);
        seen.insert(c);
        if in_band(p) && scan.range(i) < WALL_SHARE * wall[scan.sector(i, SECTORS)] {
            let top = tops.entry(c).or_insert(f32::MIN);
            *top = top.max(p[2] - floor);
        }
    }
    (tops, seen.len())
}

/// The 8-connected groups of at least [`MIN_CELLS`] cells, in the order of
/// their least cell (the hash map's order would make the histograms'
/// float sums depend on it).
fn objects(tops: &FxHashMap<Cell, f32>) -> Vec<Vec<Cell>> {
    let mut starts: Vec<Cell> = tops.keys().copied().collect();
    starts.sort_unstable();
    let mut grouped: FxHashSet<Cell> = FxHashSet::default();
    let mut found = vec![];
    for start in starts {
        if !grouped.insert(start) {
            continue;
        }
        let (mut cells, mut stack) = (vec![], vec![start]);
        while let Some(c) = stack.pop() {
            cells.push(c);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    let n = (c.0 + dx, c.1 + dy);
                    if tops.contains_key(&n) && grouped.insert(n) {
                        stack.push(n);
                    }
                }
            }
        }
        if cells.len() >= MIN_CELLS {
            found.push(cells);
        }
    }
    found
}

/// The square root of the ratio of the smaller to the larger second
/// moment (eigenvalue of the covariance) of the cells' centres (1 for a
/// disc or a square, towards 0 for a line); the centres' mean (m); and the
/// direction of the larger moment (radians).
fn moments_of(cells: &[Cell]) -> (f32, [f32; 2], f32) {
    let n = cells.len() as f32;
    let mx = cells.iter().map(|c| c.0 as f32).sum::<f32>() / n;
    let my = cells.iter().map(|c| c.1 as f32).sum::<f32>() / n;
    let (mut sxx, mut syy, mut sxy) = (0f32, 0f32, 0f32);
    for c in cells {
        let (x, y) = (c.0 as f32 - mx, c.1 as f32 - my);
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
    }
    let trace = sxx + syy;
    let d = ((sxx - syy).powi(2) + 4.0 * sxy * sxy).sqrt();
    let (large, small) = ((trace + d) / 2.0, ((trace - d) / 2.0).max(0.0));
    let roundness = if large > 0.0 {
        (small / large).sqrt()
    } else {
        1.0
    };
    let centre = [(mx + 0.5) * CELL, (my + 0.5) * CELL];
    (roundness, centre, 0.5 * (2.0 * sxy).atan2(sxx - syy))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points every 5 cm on the floor, walls and ceiling of a 6 x 4 x 3 m
    /// box round the origin (floor at -1.2), and flat tops: (x0, y0, size
    /// x, size y, height above the floor).
    fn room(tops: &[(f32, f32, f32, f32, f32)]) -> Vec<[f32; 3]> {
        let (w, d, h, step) = (6.0f32, 4.0f32, 3.0f32, 0.05f32);
        let n = |len: f32| (len / step).round() as usize;
        let (x0, y0, z0) = (-w / 2.0, -d / 2.0, -1.2f32);
        let mut p = Vec::new();
        for i in 0..=n(w) {
            for j in 0..=n(d) {
                let (x, y) = (x0 + i as f32 * step, y0 + j as f32 * step);
                p.extend([[x, y, z0], [x, y, z0 + h]]);
            }
        }
        for k in 0..=n(h) {
            let z = z0 + k as f32 * step;
            for i in 0..=n(w) {
                let x = x0 + i as f32 * step;
                p.extend([[x, y0, z], [x, -y0, z]]);
            }
            for j in 0..=n(d) {
                let y = y0 + j as f32 * step;
                p.extend([[x0, y, z], [-x0, y, z]]);
            }
        }
        // Tops sampled at cell centres (0.025 and 0.075 m into each 0.1 m
        // cell), so that a top covers a known number of cells.
        for &(tx, ty, sx, sy, top) in tops {
            for i in 0..(sx / step).round() as usize {
                for j in 0..(sy / step).round() as usize {
                    let x = tx + 0.025 + i as f32 * step;
                    let y = ty + 0.025 + j as f32 * step;
                    p.push([x, y, z0 + top]);
                }
            }
        }
        p
    }

    /// The mean position (in bins) of a channel's mass.
    fn mean_bin(v: &[f32], channel: usize) -> f32 {
        let h = &v[channel * BINS..(channel + 1) * BINS];
        h.iter().enumerate().map(|(i, m)| i as f32 * m).sum()
    }

    #[test]
    fn an_empty_room_has_no_objects() {
        let v = describe(&room(&[]));
        assert_eq!(v, empty_channels(&CHANNELS));
    }

    /// A 1 x 0.5 m top 0.75 m above the floor is one object of 10 x 5
    /// cells: footprint 0.5 m², top 0.75 m, roundness 0.5 (second moments
    /// (10² - 1) / 12 and (5² - 1) / 12).
    #[test]
    fn a_table_is_one_object_of_its_size_height_and_shape() {
        let v = describe(&room(&[(1.0, -0.5, 1.0, 0.5, 0.75)]));
        let bins = (BINS - 1) as f32;
        let area = (0.5f32.log10() + 2.0) / 3.0 * bins;
        assert!((mean_bin(&v, 0) - area).abs() < 1e-3, "{v:?}");
        assert!((mean_bin(&v, 1) - 0.75 / 2.4 * bins).abs() < 1e-3, "{v:?}");
        let round = (24.0f32 / 99.0).sqrt() * bins;
        assert!((mean_bin(&v, 2) - round).abs() < 1e-3, "{v:?}");
        // One object in the room's 61 x 41 cells (the box's walls at
        // multiples of 0.1 m put its edges in cells of their own).
        let density = mean_bin(&v, 3) / bins * DENSITY as f32;
        assert!((density * 2501.0 * 0.01 - 1.0).abs() < 0.05, "{density}");
    }

    /// Two tables apart: the same histograms, twice the density. Cells
    /// that touch (diagonally too) are one object; fewer than three cells
    /// are none.
    #[test]
    fn objects_are_counted_by_connected_cells() {
        let one = describe(&room(&[(1.0, -0.5, 1.0, 0.5, 0.75)]));
        let two = describe(&room(&[
            (1.0, -0.5, 1.0, 0.5, 0.75),
            (-2.0, 0.5, 1.0, 0.5, 0.75),
        ]));
        assert_eq!(one[..3 * BINS], two[..3 * BINS]);
        let ratio = mean_bin(&two, 3) / mean_bin(&one, 3);
        assert!((ratio - 2.0).abs() < 1e-3, "{ratio}");
        // A second top touching the first corner to corner makes one
        // larger object (0.5 + 0.04 m²); a 0.1 x 0.2 m post is no object.
        let joined = describe(&room(&[
            (1.0, -0.5, 1.0, 0.5, 0.75),
            (2.0, 0.0, 0.2, 0.2, 0.75),
            (-2.0, 1.0, 0.1, 0.2, 1.0),
        ]));
        let area = (0.54f32.log10() + 2.0) / 3.0 * (BINS - 1) as f32;
        assert!((mean_bin(&joined, 0) - area).abs() < 1e-3, "{joined:?}");
        assert_eq!(mean_bin(&joined, 3), mean_bin(&one, 3));
    }

    /// A line of cells along x, along y and along the diagonal: roundness
    /// 0, the long axis 0, pi/2 and pi/4, and the centre its middle.
    #[test]
    fn a_line_of_cells_has_its_direction_and_middle() {
        let along = |dx: i32, dy: i32| (0..5).map(|i| (i * dx, i * dy)).collect::<Vec<Cell>>();
        for ((dx, dy), axis) in [
            ((1, 0), 0.0),
            ((0, 1), std::f32::consts::FRAC_PI_2),
            ((1, 1), std::f32::consts::FRAC_PI_4),
        ] {
            let (roundness, centre, a) = moments_of(&along(dx, dy));
            assert!(roundness < 1e-3, "{dx},{dy}: {roundness}");
            assert!((a - axis).abs() < 1e-5, "{dx},{dy}: {a}");
            let want = [(2 * dx) as f32 + 0.5, (2 * dy) as f32 + 0.5].map(|c| c * CELL);
            assert!((centre[0] - want[0]).abs() < 1e-5 && (centre[1] - want[1]).abs() < 1e-5);
        }
    }

    /// What stands against a wall belongs to the wall: a top within the
    /// last tenth of its sectors' range is no object.
    #[test]
    fn what_stands_on_the_walls_is_no_object() {
        let v = describe(&room(&[(2.8, -0.5, 0.1, 1.0, 1.5)]));
        assert_eq!(v, empty_channels(&CHANNELS));
    }
}
