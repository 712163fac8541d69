//! Clutter at several heights above the floor: virtual horizontal laser
//! scans, in the manner of Mozos, Stachniss and Burgard, "Supervised
//! learning of places from range data using AdaBoost" (ICRA 2005), whose
//! single-scan features (beam lengths, their relation to each other, the
//! number of gaps between consecutive beams) tell rooms from corridors; and
//! a height distribution after Röhling, Mack and Schulz (IROS 2015), here
//! measured from the floor and of the room's contents only.
//!
//! Mozos et al. had one laser at one height. A 3-D scan holds a laser scan
//! at every height, and the kinds of room that the free-space
//! [`slice`](mod@super::slice) cannot tell apart (a private office and a
//! restroom of the same size; a classroom and a library) differ in what
//! stands inside them, and how high: desks and tables at 0.7 m, benches at
//! 0.45 m, stall partitions, shelving and lockers to 2 m. So:
//!
//! - the floor is the 2nd percentile of height of the points within 8 m
//!   (horizontally), the ceiling the 98th: heights are measured from the
//!   floor, so the sensor's own height moves them little (a box room seen
//!   from 0.3 m and from 1.8 m stays within a small part distance; unit
//!   test). The limit: where the floor is not seen within 8 m (a sensor
//!   high above it, a steep beam pattern, a floor hidden by clutter), the
//!   2nd percentile falls on a wall or on what stands in the room, and
//!   every height is measured from there;
//! - a scan with no finite point within 8 m horizontally (or no return
//!   beyond 0.3 m) has no floor: every channel puts its mass in bin 0, as
//!   for an empty room, without an error;
//! - the *wall* of each of 180 azimuth sectors is its return of farthest
//!   horizontal range (as in the slice); a point is *inside* the room when
//!   it is nearer than 0.9 x its sector's wall - 0.2 m, above the floor
//!   (0.1 m) and below the ceiling (0.2 m);
//! - at each of four levels above the floor (0.3, 0.75, 1.2, 1.7 m; a band
//!   of +-0.08 m) a virtual scan takes each sector's nearest return, as a
//!   share of the sector's wall range (1 where the band has none).
//!
//! Channels: the height above the floor of the inside points thinned to one
//! per 0.1 m voxel (its lowest point, so the part does not depend on the
//! points' order; 0 to 2.5 m, 26 bins); the number of those voxels per
//! m² of the free-space polygon (log10(1 + n / A), 0 to 2.5, 16 bins); then
//! per level the histogram of the 180 shares (16 bins, 0 to 1) and the
//! share of consecutive sectors whose shares differ by more than 0.25
//! (Mozos et al.'s gaps; 0 to 0.5, 16 bins). Every channel is invariant to
//! rotation about z (sectors are only counted, never ordered, but for the
//! gaps, which are counted round the circle).

use super::parts::{empty_channels, scalar_channel, sector_of, soft_bin, unit_sum, voxel_lowest};
use super::polar::PolarScan;
use super::slice;
use crate::cloud::is_finite;

/// Levels of the virtual scans above the floor (m).
const LEVELS: [f32; 4] = [0.3, 0.75, 1.2, 1.7];
/// Half the height of a virtual scan's band (m).
const BAND: f32 = 0.08;
/// Bins of the height profile (0.1 m each, 0 to 2.5 m).
const PROFILE_BINS: usize = 26;
/// Top of the height profile (m above the floor).
const PROFILE_TOP: f64 = 2.5;
/// Bins of the scalar and share channels.
const BINS: usize = 16;
/// Horizontal reach of the floor and ceiling estimate (m).
const NEAR: f32 = 8.0;

/// Bins of each channel: height profile, clutter density, then per level
/// the shares and the gaps.
pub const CHANNELS: [usize; 2 + 2 * LEVELS.len()] = [
    PROFILE_BINS,
    BINS,
    BINS,
    BINS,
    BINS,
    BINS,
    BINS,
    BINS,
    BINS,
    BINS,
];

/// The floor and ceiling heights (relative to the sensor) of a scan: the
/// 2nd and 98th percentiles of the heights of its points within 8 m
/// horizontally; None with no such point. Always the estimate: a given
/// `sensor_height` enters through [`PolarScan::with_sensor_height`].
pub fn floor_and_ceiling(points: &[[f32; 3]]) -> Option<(f32, f32)> {
    PolarScan::new(points).floor_and_ceiling()
}

/// [`floor_and_ceiling`] of a scan whose ranges are known (cached by
/// [`PolarScan::floor_and_ceiling`], which the parts call).
pub(super) fn floor_and_ceiling_of(scan: &PolarScan) -> Option<(f32, f32)> {
    let mut z: Vec<f32> = scan
        .points
        .iter()
        .enumerate()
        .filter(|(i, p)| is_finite(p) && scan.range(*i) < NEAR)
        .map(|(_, p)| p[2])
        .collect();
    if z.is_empty() {
        return None;
    }
    let mut at = |q: f64| {
        let k = ((z.len() - 1) as f64 * q).round() as usize;
        *z.select_nth_unstable_by(k, f32::total_cmp).1
    };
    let ceiling = at(0.98);
    Some((scan.known_floor().unwrap_or_else(|| at(0.02)), ceiling))
}

/// Each sector's nearest return in the band at `level` above the floor,
/// as a share of its wall range (1 where the band has none or the wall is
/// unknown); one share per wall, so none for no walls.
pub fn level_shares(points: &[[f32; 3]], walls: &[f32], floor: f32, level: f32) -> Vec<f32> {
    level_shares_of(&PolarScan::new(points), walls, floor, level)
}

fn level_shares_of(scan: &PolarScan, walls: &[f32], floor: f32, level: f32) -> Vec<f32> {
    let [shares] = levels_shares_of(scan, walls, floor, [level]);
    shares
}

/// [`level_shares`] at each of `levels`, in one pass over the points.
fn levels_shares_of<const L: usize>(
    scan: &PolarScan,
    walls: &[f32],
    floor: f32,
    levels: [f32; L],
) -> [Vec<f32>; L] {
    let sectors = walls.len();
    if sectors == 0 {
        return std::array::from_fn(|_| Vec::new());
    }
    let mut near = [(); L].map(|_| vec![f32::INFINITY; sectors]);
    for (i, p) in scan.points.iter().enumerate() {
        if !is_finite(p) || scan.range(i) < 0.3 {
            continue;
        }
        let bands: [bool; L] = levels.map(|level| (p[2] - floor - level).abs() <= BAND);
        if !bands.contains(&true) {
            continue;
        }
        let (r, s) = (scan.range(i), scan.sector(i, sectors));
        for (near, _) in near.iter_mut().zip(bands).filter(|(_, b)| *b) {
            near[s] = near[s].min(r);
        }
    }
    near.map(|near| {
        near.iter()
            .zip(walls)
            .map(|(&n, &w)| if w > 0.0 { (n / w).min(1.0) } else { 1.0 })
            .collect()
    })
}

/// The channels (see the module doc); a scan with no return beyond 0.3 m,
/// or no finite point within 8 m horizontally (no floor), puts every
/// channel's mass in bin 0.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// The room round a scan: the walls of the free-space polygon's sectors,
/// its floor and ceiling, and the polygon's area. Shared with the
/// [`columns`](super::columns) part, which reads what stands inside it by
/// direction.
pub(super) struct Room {
    /// Horizontal range of each sector's wall ([`slice::SECTORS`] of them).
    pub walls: Vec<f32>,
    /// Floor height relative to the sensor (m).
    pub floor: f32,
    /// Ceiling height relative to the sensor (m).
    pub ceiling: f32,
    /// Area of the free-space polygon (m², at least 1).
    pub area: f64,
}

impl Room {
    /// Whether a point at horizontal range `r` in sector `sector`, `z`
    /// relative to the sensor, stands inside the room (see the module
    /// doc).
    pub fn holds(&self, r: f32, z: f32, sector: usize) -> bool {
        // Written positively, so that a NaN is never inside (the same
        // answer as the old negated test for every finite point).
        let wall = self.walls[sector];
        r >= 0.3 && r <= 0.9 * wall - 0.2 && z - self.floor >= 0.1 && z <= self.ceiling - 0.2
    }
}

/// The [`Room`] of a scan; None with no return beyond 0.3 m or no finite
/// point within 8 m horizontally.
pub(super) fn room_of(scan: &PolarScan) -> Option<Room> {
    let (pts, (floor, ceiling)) = (scan.polygon()?, scan.floor_and_ceiling()?);
    Some(Room {
        walls: pts.iter().map(|p| p[0].hypot(p[1]) as f32).collect(),
        floor,
        ceiling,
        area: slice::features(pts).area.max(1.0),
    })
}

/// [`describe`] of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    let Some(room) = room_of(scan) else {
        return empty_channels(&CHANNELS);
    };
    let (walls, floor, area) = (&room.walls, room.floor, room.area);
    let mut heights: Vec<f32> = voxel_lowest(scan.points, 0.1)
        .into_iter()
        .filter_map(|p| {
            let r = p[0].hypot(p[1]);
            room.holds(r, p[2], sector_of(&p, slice::SECTORS))
                .then_some(p[2] - floor)
        })
        .collect();
    // Summed in sorted order: the same bits whatever the points' order.
    heights.sort_unstable_by(f32::total_cmp);
    let inside = heights.len();
    let mut profile = vec![0f32; PROFILE_BINS];
    for h in heights {
        soft_bin(
            &mut profile,
            h as f64 / PROFILE_TOP * (PROFILE_BINS - 1) as f64,
            1.0,
        );
    }
    unit_sum(&mut profile);
    let mut v = profile;
    v.extend(scalar_channel(
        BINS,
        (1.0 + inside as f64 / area).log10(),
        0.0,
        2.5,
    ));
    for shares in levels_shares_of(scan, walls, floor, LEVELS) {
        let mut h = vec![0f32; BINS];
        for &s in &shares {
            soft_bin(&mut h, s as f64 * (BINS - 1) as f64, 1.0);
        }
        unit_sum(&mut h);
        v.extend(h);
        let n = shares.len();
        let gaps = (0..n)
            .filter(|&i| (shares[i] - shares[(i + 1) % n]).abs() > 0.25)
            .count();
        v.extend(scalar_channel(BINS, gaps as f64 / n as f64, 0.0, 0.5));
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::descriptor::parts::{describe_parts, describe_parts_with, parts_distance, PartKind};

    /// Points on the walls, floor and ceiling of a w x d x 3 m box round
    /// the origin (floor at -1.2), every 5 cm, and a table top (0.75 m
    /// above the floor) of 1 x 1 m at x in [1, 2].
    fn box_room(w: f32, d: f32, table: bool) -> Vec<[f32; 3]> {
        let mut p = Vec::new();
        let step = 0.05;
        let n = |len: f32| (len / step) as usize;
        let (x0, y0, z0) = (-w / 2.0, -d / 2.0, -1.2f32);
        for i in 0..=n(w) {
            for j in 0..=n(d) {
                let (x, y) = (x0 + i as f32 * step, y0 + j as f32 * step);
                p.push([x, y, z0]);
                p.push([x, y, z0 + 3.0]);
            }
        }
        for k in 0..=n(3.0) {
            let z = z0 + k as f32 * step;
            for i in 0..=n(w) {
                let x = x0 + i as f32 * step;
                p.push([x, y0, z]);
                p.push([x, -y0, z]);
            }
            for j in 0..=n(d) {
                let y = y0 + j as f32 * step;
                p.push([x0, y, z]);
                p.push([-x0, y, z]);
            }
        }
        if table {
            for i in 0..=n(1.0) {
                for j in 0..=n(1.0) {
                    p.push([1.0 + i as f32 * step, -0.5 + j as f32 * step, z0 + 0.75]);
                }
            }
        }
        p
    }

    /// The bin of the inside-height profile that holds the most mass.
    fn profile_peak(v: &[f32]) -> usize {
        (0..PROFILE_BINS)
            .max_by(|&a, &b| v[a].total_cmp(&v[b]))
            .unwrap()
    }

    /// As a sparse sensor sees a small room: no floor, and the walls only
    /// from 0.6 m above it. The estimated floor lands on the walls' lowest
    /// points, so the table top reads 0.15 m above it; given the sensor's
    /// height (1.2 m), the floor is where it is and the table at 0.75 m.
    #[test]
    fn a_given_sensor_height_places_the_floor_the_scan_cannot_see() {
        let floor = -1.2f32;
        let pts: Vec<[f32; 3]> = box_room(6.0, 4.0, true)
            .into_iter()
            .filter(|p| p[2] > floor + 0.55)
            .collect();
        let estimated = PolarScan::new(&pts).floor_and_ceiling().unwrap().0;
        assert!(
            (estimated - (floor + 0.6)).abs() < 0.06,
            "estimate {estimated}"
        );
        let given = PolarScan::with_sensor_height(&pts, Some(1.2));
        assert_eq!(given.floor_and_ceiling().unwrap().0, floor);
        let kinds = [PartKind::Clutter];
        let [v] = &describe_parts(&pts, &kinds)[..] else {
            panic!()
        };
        let [w] = &describe_parts_with(&pts, &kinds, Some(1.2))[..] else {
            panic!()
        };
        assert!(
            profile_peak(v) <= 2,
            "estimate: peak at bin {}",
            profile_peak(v)
        );
        assert!(
            (7..=8).contains(&profile_peak(w)),
            "given: peak at bin {}",
            profile_peak(w)
        );
        // Where the floor is seen, the given height changes little.
        let seen = box_room(6.0, 4.0, true);
        let [a] = &describe_parts(&seen, &kinds)[..] else {
            panic!()
        };
        let [b] = &describe_parts_with(&seen, &kinds, Some(1.2))[..] else {
            panic!()
        };
        assert!(parts_distance(a, b) < 0.05, "{}", parts_distance(a, b));
    }

    #[test]
    fn floor_and_ceiling_of_a_box_are_its_floor_and_ceiling() {
        let (f, c) = floor_and_ceiling(&box_room(6.0, 4.0, false)).unwrap();
        assert!((f + 1.2).abs() < 0.06, "floor {f}");
        assert!((c - 1.8).abs() < 0.06, "ceiling {c}");
    }

    /// An empty room has nothing inside: every virtual scan reaches its
    /// walls (shares 1, no gaps) and the density is 0; a table top at
    /// 0.75 m puts the inside mass at 0.75 m and shortens the beams of the
    /// sectors it spans at that level only.
    #[test]
    fn a_table_shows_at_its_height_and_nowhere_else() {
        let empty = describe(&box_room(6.0, 4.0, false));
        let density = &empty[PROFILE_BINS..PROFILE_BINS + BINS];
        assert!(density[0] > 0.99, "{density:?}");
        let pts = box_room(6.0, 4.0, true);
        let (floor, _) = floor_and_ceiling(&pts).unwrap();
        let walls: Vec<f32> = slice::sector_points(&pts)
            .unwrap()
            .iter()
            .map(|p| p[0].hypot(p[1]) as f32)
            .collect();
        // The table spans atan(0.5 / 1) either side of +x: about 53 degrees,
        // 26 of 180 sectors, at a share of 1 / 3 to 1 / 2.2 of the wall.
        let at_table = level_shares(&pts, &walls, floor, 0.75);
        let short = at_table.iter().filter(|&&s| s < 0.5).count();
        assert!((24..=29).contains(&short), "{short} short sectors");
        let low = level_shares(&pts, &walls, floor, 0.3);
        assert!(low.iter().all(|&s| s > 0.95), "{low:?}");
        let v = describe(&pts);
        let profile = &v[..PROFILE_BINS];
        let peak = profile_peak(profile);
        assert!((7..=8).contains(&peak), "peak at bin {peak}: {profile:?}");
        assert!(v[PROFILE_BINS] < 0.9, "density still 0");
    }

    /// No walls, no shares (it used to underflow `sectors - 1`).
    #[test]
    fn no_walls_give_no_shares() {
        assert!(level_shares(&box_room(4.0, 3.0, false), &[], -1.2, 0.3).is_empty());
    }

    /// The same room seen from 0.3 m and from 1.8 m above its floor (the
    /// points moved down by 1.5 m): floor and ceiling move with them, so
    /// the part changes little against another room's.
    #[test]
    fn the_sensor_height_moves_the_part_little() {
        let part = |pts: &[[f32; 3]]| {
            let values = describe(pts);
            let mut out = Vec::new();
            super::super::parts::cumulative(
                &super::super::parts::PartValues {
                    kind: super::super::parts::PartKind::Clutter,
                    values,
                },
                1.0,
                &mut out,
            );
            out
        };
        let dist = super::super::parts::parts_distance;
        let shift = |pts: &[[f32; 3]], dz: f32| -> Vec<[f32; 3]> {
            pts.iter().map(|p| [p[0], p[1], p[2] + dz]).collect()
        };
        // box_room's floor is 1.2 m below the sensor.
        let room = box_room(6.0, 4.0, true);
        let (low, high) = (part(&shift(&room, 0.9)), part(&shift(&room, -0.6)));
        let other = part(&shift(&box_room(6.0, 4.0, false), 0.9));
        let (same, diff) = (dist(&low, &high), dist(&low, &other));
        assert!(same < 0.02, "{same}");
        assert!(same < 0.25 * diff, "{same} vs another room {diff}");
    }

    #[test]
    fn no_points_put_the_mass_in_bin_zero() {
        let v = describe(&[[0.0, 0.0, 0.0]]);
        assert_eq!(v.len(), CHANNELS.iter().sum::<usize>());
        assert_eq!(v[0], 1.0);
    }
}
