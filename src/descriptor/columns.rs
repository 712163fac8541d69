//! What stands in each direction, from the floor up: for every azimuth
//! sector, the column of the room's contents (issue 18, eighth round).
//!
//! Scan Context (Kim and Kim, "Scan Context: Egocentric spatial descriptor
//! for place recognition within 3D point cloud map", IROS 2018) keeps the
//! highest point of each polar bin; here the bins are the 180 sectors of
//! the free-space [`slice`](mod@super::slice), only what stands inside the
//! room counts (as in the [`clutter`](mod@super::clutter) part: nearer
//! than its sector's wall, above the floor, below the ceiling), heights are
//! measured from the floor, and the sectors are only counted, never ordered,
//! so the part is invariant to rotation about z.
//!
//! Why: the `clutter` part looks at four heights one at a time. Two rooms
//! of the same size can hold the same amount at each of them and still
//! differ in how it stands: a row of stall partitions raised off the floor
//! and reaching 2 m across a whole side, against a desk whose top is at
//! 0.75 m and a bookcase from the floor. Per sector, the part takes the
//! inside points and their heights above the floor in 8 layers of 0.25 m
//! from 0.075 m (to 2.075 m) and counts:
//!
//! - the top: the highest inside point's height (0 to 2.5 m, 26 bins);
//! - the extent: how many of the 8 layers hold a point (1 to 8, 8 bins);
//! - the bottom: the lowest layer that holds one (0 to 7, 8 bins; the
//!   room test drops what lies within 0.1 m of the floor, so layer 0 holds
//!   0.1 to 0.325 m, and a partition raised 0.15 m falls in it as a
//!   bookcase on the floor does: the bottom tells a desk top or a shelf
//!   from what stands on the floor, not a raised partition from it);
//!
//! each a histogram over the sectors that hold any inside point, and the
//! share of sectors that do (0 to 1, 16 bins). A scan with no inside point
//! puts every channel's mass in bin 0, as one with no floor does.

use super::clutter::{room_of, Room};
use super::parts::{empty_channels, scalar_channel, soft_bin, unit_sum};
use super::polar::PolarScan;
use super::slice;
use crate::cloud::is_finite;

/// Layers of a column, 0.25 m each from [`LAYER_BASE`] above the floor.
const LAYERS: usize = 8;
/// Height of a layer (m).
const LAYER: f32 = 0.25;
/// Bottom of the lowest layer above the floor (m).
const LAYER_BASE: f32 = 0.075;
/// Bins of the top channel (0.1 m each, 0 to 2.5 m).
const TOP_BINS: usize = 26;
/// Top of the top channel (m above the floor).
const TOP: f64 = 2.5;
/// Bins of the share channel.
const SHARE_BINS: usize = 16;

/// Bins of each channel: top, extent, bottom, share of sectors.
pub const CHANNELS: [usize; 4] = [TOP_BINS, LAYERS, LAYERS, SHARE_BINS];

/// One sector's column: its highest height, and a bit per layer that
/// holds a point.
#[derive(Clone, Copy, Default)]
struct Column {
    top: f32,
    layers: u16,
}

/// The columns of the sectors that hold anything inside the room. Every
/// point counts, not one a voxel as in `clutter`: a column keeps only
/// extremes and bits, which no point's order or density changes, and a
/// 0.1 m voxel 1.5 m away spans two 2-degree sectors.
fn columns(scan: &PolarScan, room: &Room) -> Vec<Column> {
    let mut cols = vec![None::<Column>; room.walls.len()];
    for (i, p) in scan.points.iter().enumerate() {
        if !is_finite(p) {
            continue;
        }
        let sector = scan.sector(i, slice::SECTORS);
        if !room.holds(scan.range(i), p[2], sector) {
            continue;
        }
        let h = p[2] - room.floor;
        let c = cols[sector].get_or_insert_with(Column::default);
        c.top = c.top.max(h);
        let layer = ((h - LAYER_BASE) / LAYER).floor();
        if (0.0..LAYERS as f32).contains(&layer) {
            c.layers |= 1 << layer as u16;
        }
    }
    cols.into_iter().flatten().collect()
}

/// The channels (see the module doc).
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// [`describe`] of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    let Some(room) = room_of(scan) else {
        return empty_channels(&CHANNELS);
    };
    let sectors = room.walls.len();
    let cols = columns(scan, &room);
    if cols.is_empty() {
        return empty_channels(&CHANNELS);
    }
    let mut top = vec![0f32; TOP_BINS];
    let mut extent = vec![0f32; LAYERS];
    let mut bottom = vec![0f32; LAYERS];
    for c in &cols {
        soft_bin(&mut top, c.top as f64 / TOP * (TOP_BINS - 1) as f64, 1.0);
        // A column whose points all lie above the top layer (a shelf above
        // 2.075 m) counts as one layer at the top.
        let n = c.layers.count_ones().max(1) as usize;
        extent[n - 1] += 1.0;
        let lowest = if c.layers == 0 {
            LAYERS - 1
        } else {
            c.layers.trailing_zeros() as usize
        };
        bottom[lowest] += 1.0;
    }
    for h in [&mut top, &mut extent, &mut bottom] {
        unit_sum(h);
    }
    let mut v = top;
    v.extend(extent);
    v.extend(bottom);
    v.extend(scalar_channel(
        SHARE_BINS,
        cols.len() as f64 / sectors as f64,
        0.0,
        1.0,
    ));
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on the walls, floor and ceiling of a 6 x 4 x 3 m box round
    /// the origin (floor at -1.2), every 5 cm, and `inside` (solid boxes
    /// given as x, y and z ranges above the floor) sampled on their faces.
    fn room(inside: &[[[f32; 2]; 3]]) -> Vec<[f32; 3]> {
        let (w, d, z0, step) = (6.0f32, 4.0f32, -1.2f32, 0.05f32);
        let mut p = Vec::new();
        let grid = |a: f32, b: f32| {
            let n = ((b - a) / step).round() as usize;
            (0..=n).map(move |i| a + i as f32 * step)
        };
        for x in grid(-w / 2.0, w / 2.0) {
            for y in grid(-d / 2.0, d / 2.0) {
                p.push([x, y, z0]);
                p.push([x, y, z0 + 3.0]);
            }
            for z in grid(z0, z0 + 3.0) {
                p.push([x, -d / 2.0, z]);
                p.push([x, d / 2.0, z]);
            }
        }
        for y in grid(-d / 2.0, d / 2.0) {
            for z in grid(z0, z0 + 3.0) {
                p.push([-w / 2.0, y, z]);
                p.push([w / 2.0, y, z]);
            }
        }
        for [[x0, x1], [y0, y1], [h0, h1]] in inside {
            // The face towards the sensor (x = x0) and the top.
            for y in grid(*y0, *y1) {
                for z in grid(z0 + h0, z0 + h1) {
                    p.push([*x0, y, z]);
                }
                for x in grid(*x0, *x1) {
                    p.push([x, y, z0 + h1]);
                }
            }
        }
        p
    }

    fn channel(v: &[f32], c: usize) -> &[f32] {
        let at: usize = CHANNELS[..c].iter().sum();
        &v[at..at + CHANNELS[c]]
    }

    fn peak(h: &[f32]) -> usize {
        (0..h.len()).max_by(|&a, &b| h[a].total_cmp(&h[b])).unwrap()
    }

    #[test]
    fn an_empty_room_has_no_columns() {
        let v = describe(&room(&[]));
        assert_eq!(v.len(), CHANNELS.iter().sum::<usize>());
        for c in 0..CHANNELS.len() {
            assert_eq!(channel(&v, c)[0], 1.0, "channel {c}");
        }
    }

    /// A table top at 0.75 m (a slab 0.05 m thick, no legs) against a
    /// partition raised 0.15 m off the floor to 2 m: the tops, the extents
    /// and the bottoms are where they are built.
    #[test]
    fn a_table_and_a_partition_stand_as_built() {
        let table = describe(&room(&[[[1.0, 2.0], [-0.5, 0.5], [0.7, 0.75]]]));
        let partition = describe(&room(&[[[1.5, 1.55], [-1.0, 1.0], [0.15, 2.0]]]));
        // Tops: 0.75 m is bin 7.5 of 0.1 m; 2.0 m bin 20.
        assert!((7..=8).contains(&peak(channel(&table, 0))), "{table:?}");
        assert!((19..=20).contains(&peak(channel(&partition, 0))));
        // Extent: the slab lies in one layer (0.575-0.825 m); the
        // partition in every one from 0.075 m up to 2.075 m.
        assert_eq!(peak(channel(&table, 1)), 0);
        assert_eq!(peak(channel(&partition, 1)), LAYERS - 1);
        // Bottom: layer 2 for the slab, layer 0 for the partition.
        assert_eq!(peak(channel(&table, 2)), 2);
        assert_eq!(peak(channel(&partition, 2)), 0);
        // Share of sectors: the partition spans atan(1 / 1.5) either side
        // of +x, about 67 of 360 degrees, 0.19 of the sectors.
        let share = channel(&partition, 3);
        let at =
            (0..SHARE_BINS).map(|b| share[b] * b as f32).sum::<f32>() / (SHARE_BINS - 1) as f32;
        assert!((0.15..0.23).contains(&at), "share {at}");
    }

    /// Turning the room about z leaves the part as it was, but for the
    /// sectors' edges.
    #[test]
    fn the_part_does_not_depend_on_the_heading() {
        let pts = room(&[
            [[1.0, 2.0], [-0.5, 0.5], [0.7, 0.75]],
            [[-2.5, -2.2], [-1.0, 1.0], [0.0, 1.9]],
        ]);
        let (s, c) = (0.7f32.sin(), 0.7f32.cos());
        let turned: Vec<[f32; 3]> = pts
            .iter()
            .map(|p| [c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]])
            .collect();
        let part = |pts: &[[f32; 3]]| {
            let mut out = Vec::new();
            super::super::parts::cumulative(
                &super::super::parts::PartValues {
                    kind: super::super::parts::PartKind::Columns,
                    values: describe(pts),
                },
                1.0,
                &mut out,
            );
            out
        };
        let dist = super::super::parts::parts_distance;
        let (a, b, empty) = (part(&pts), part(&turned), part(&room(&[])));
        assert!(
            dist(&a, &b) < 0.1 * dist(&a, &empty),
            "{} vs {}",
            dist(&a, &b),
            dist(&a, &empty)
        );
    }
}
