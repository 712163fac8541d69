//! How a scan's surfaces stand to each other, after IRON (Schmiedel,
//! Einhorn and Gross, "IRON: A fast interest point descriptor for robust
//! NDT-map matching and its application to robot localization", IROS
//! 2015), the descriptor the paper's future work names. IRON describes a
//! keypoint of an NDT map by a histogram of its neighbouring NDT cells,
//! binned by their distance and by the angle between the cells' normals,
//! and matches keypoints between maps. Here, to make a global descriptor
//! without keypoint detection or training, every planar NDT cell is a
//! keypoint and the histograms are summed over the scan, as 1-D channels.
//!
//! Why for places: how far apart parallel surfaces stand (the aisles
//! between shelving stacks, a bed before a wall, the two walls of a
//! corridor) and at what angles nearby surfaces meet change less from one
//! spot of a room to another than what is seen at each range (issue 18's
//! twelfth round tests that; docs/seeds.md). Every channel is invariant to
//! rotation about z but for the voxel lattice the cells come from (tested
//! in tests/it/parts.rs); a tilt changes which cells lie within 16 m
//! horizontally. The separation is measured along the first cell's normal
//! in voxel order: for normals up to 15 degrees apart the second's would
//! give another value (a symmetric choice would change the part's values,
//! which the round's figures were measured with).
//!
//! The cells: the NDT grid of the points at 0.4 m ([`ndt_grid`]; at least
//! 5 points a cell), classified as the paper does with eigen threshold
//! 0.05 ([`shape`]); the planar ones within 16 m horizontally of the sensor
//! (farther cells are few and their normals noisy) are kept. Each pair of
//! kept cells whose means lie within 4 m of each other counts once.
//!
//! Channels: for parallel pairs (normals within 15 degrees), their
//! separation along the first cell's normal, 0 to 4 m (20 bins: 0 is one
//! plane); the angle between the normals of every pair, 0 to 90 degrees
//! (18 bins); for perpendicular pairs (normals more than 75 degrees
//! apart), the distance between their means, 0 to 4 m (16 bins). A scan
//! with no pair puts each channel's mass in bin 0, as other parts do.

use super::ndt_grid;
use super::parts::{empty_channels, soft_bin, unit_sum};
use super::shape::{self, Shape, ShapedCell};
use rustc_hash::FxHashMap;

/// Bins of each channel: parallel separation, normal angle, perpendicular
/// distance.
pub const CHANNELS: [usize; 3] = [20, 18, 16];

/// NDT cell edge (m), points a cell needs, and the eigen threshold (the
/// paper's indoor values: fixed here, since a part reads only points).
const VOXEL: f64 = 0.4;
const MIN_POINTS: usize = 5;
const EIGEN_THRESHOLD: f64 = 0.05;
/// Cells farther than this horizontally from the sensor are left out (m).
const MAX_RANGE: f64 = 16.0;
/// Pairs farther apart than this are not counted (m); also the top of the
/// separation and distance channels.
const RADIUS: f64 = 4.0;
/// |cos| of the angle between normals at and above which a pair is
/// parallel (15 degrees), and at and below which it is perpendicular (75).
const PARALLEL: f64 = 0.965_925_826_289_068_3;
const PERPENDICULAR: f64 = 0.258_819_045_102_520_8;

/// A planar cell: its mean and unit normal.
struct Plane {
    mean: [f64; 3],
    normal: [f64; 3],
}

/// The three histograms, each of unit sum.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    let grid = ndt_grid::build(points, VOXEL, MIN_POINTS);
    // `planes` checks the range again, for cells handed over whole by
    // `describe_cells`; here it also spares classifying far cells.
    let cells: Vec<ShapedCell> = (grid.cells.iter())
        .filter(|c| within_range(&c.mean))
        .filter_map(|c| shape::classify(c, EIGEN_THRESHOLD))
        .collect();
    describe_cells(&cells)
}

/// Whether an NDT grid of cell edge `voxel`, at least `min_points` a
/// cell, classified with `eigen_threshold`, is the one this part builds:
/// then [`describe_cells`] takes its cells and the grid is built once.
pub(crate) fn shares_grid(voxel: f64, min_points: usize, eigen_threshold: f64) -> bool {
    voxel == VOXEL && min_points == MIN_POINTS && eigen_threshold == EIGEN_THRESHOLD
}

/// [`describe`] from a scan's classified NDT cells in the grid's order,
/// built with this part's settings ([`shares_grid`]): the NDT histogram's
/// own cells when its parameters are the paper's indoor ones. The same
/// values, bit for bit, as from the points (tests/it/parts.rs's digests).
pub(crate) fn describe_cells(cells: &[ShapedCell]) -> Vec<f32> {
    let planes = planes(cells);
    let [sb, ab, db] = CHANNELS;
    let (mut separation, mut angle, mut distance) =
        (vec![0f32; sb], vec![0f32; ab], vec![0f32; db]);
    let mut pairs = 0usize;
    for_each_pair(&planes, |a, b, d| {
        pairs += 1;
        let c = dot(a.normal, b.normal).abs().min(1.0);
        let degrees = c.acos().to_degrees();
        soft_bin(&mut angle, degrees / 90.0 * (ab - 1) as f64, 1.0);
        if c >= PARALLEL {
            let s = dot(d, a.normal).abs();
            soft_bin(&mut separation, s / RADIUS * (sb - 1) as f64, 1.0);
        } else if c <= PERPENDICULAR {
            let r = dot(d, d).sqrt();
            soft_bin(&mut distance, r / RADIUS * (db - 1) as f64, 1.0);
        }
    });
    if pairs == 0 {
        return empty_channels(&CHANNELS);
    }
    for h in [&mut separation, &mut angle, &mut distance] {
        unit_sum(h);
    }
    [separation, angle, distance].concat()
}

/// The planar cells within [`MAX_RANGE`], in the grid's order (sorted by
/// voxel). The grid sums its points in their order, so a shuffle can move
/// the last bits of a mean or a normal: the part is not bit-identical
/// under reordering, as `slice` or `ring` are.
fn planes(cells: &[ShapedCell]) -> Vec<Plane> {
    (cells.iter())
        .filter(|s| s.shape == Shape::Planar && within_range(&s.mean))
        .map(|s| Plane {
            mean: s.mean,
            normal: s.normal,
        })
        .collect()
}

/// A cell mean within [`MAX_RANGE`] of the sensor, horizontally.
fn within_range(mean: &[f64; 3]) -> bool {
    mean[0].hypot(mean[1]) <= MAX_RANGE
}

/// Call `f` once for each pair of planes whose means lie within
/// [`RADIUS`], with the second's mean less the first's: planes are
/// bucketed by RADIUS-sized blocks, and each looks at the 27 blocks around
/// its own, at planes after it in order.
fn for_each_pair(planes: &[Plane], mut f: impl FnMut(&Plane, &Plane, [f64; 3])) {
    let block = |m: &[f64; 3]| m.map(|v| (v / RADIUS).floor() as i64);
    let mut blocks: FxHashMap<[i64; 3], Vec<usize>> = FxHashMap::default();
    for (i, p) in planes.iter().enumerate() {
        blocks.entry(block(&p.mean)).or_default().push(i);
    }
    let r2 = RADIUS * RADIUS;
    for (i, a) in planes.iter().enumerate() {
        let [x, y, z] = block(&a.mean);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    // Saturating: a wild but finite coordinate saturates
                    // its block index, and one more must not overflow.
                    let near = [
                        x.saturating_add(dx),
                        y.saturating_add(dy),
                        z.saturating_add(dz),
                    ];
                    let Some(members) = blocks.get(&near) else {
                        continue;
                    };
                    for &j in members.iter().filter(|&&j| j > i) {
                        let b = &planes[j];
                        let d = sub(b.mean, a.mean);
                        if dot(d, d) <= r2 {
                            f(a, b, d);
                        }
                    }
                }
            }
        }
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on a wall: x = `x0`, y in [-4, 4], z in [-1, 2], 0.05 m apart.
    fn wall(x0: f32) -> Vec<[f32; 3]> {
        let mut v = Vec::new();
        for i in 0..160 {
            for k in 0..60 {
                v.push([x0, -4.0 + 0.05 * i as f32, -1.0 + 0.05 * k as f32]);
            }
        }
        v
    }

    /// The grid is shared with the paper's settings alone: any other cell
    /// edge, point count or eigen threshold builds the part's own.
    #[test]
    fn the_grid_is_shared_only_with_the_parts_own_settings() {
        assert!(shares_grid(0.4, 5, 0.05));
        assert!(!shares_grid(0.5, 5, 0.05));
        assert!(!shares_grid(0.4, 3, 0.05));
        assert!(!shares_grid(0.4, 5, 0.1));
        assert!(!shares_grid(0.4, 3, 0.02), "perception_oru's settings");
    }

    /// Two parallel walls 1.5 m apart: the separation channel holds the
    /// pairs of one wall (0 m) and of the two walls (1.5 m), every angle is
    /// 0, and no pair is perpendicular.
    #[test]
    fn two_parallel_walls_give_their_separation() {
        let pts = [wall(1.2), wall(2.7)].concat();
        let v = describe(&pts);
        let [sb, ab, _] = CHANNELS;
        let (sep, angle, dist) = (&v[..sb], &v[sb..sb + ab], &v[sb + ab..]);
        assert!(angle[0] > 0.99, "{angle:?}");
        assert!(dist[0] == 1.0, "no perpendicular pair: {dist:?}");
        // The separation's mass lies at 0 (bin 0) and at 1.5 m (between
        // bins 7 and 8): the pairs of one wall and those of the two.
        let (at_zero, at_gap) = (sep[0], sep[7] + sep[8]);
        assert!(at_zero > 0.3 && at_gap > 0.15, "{sep:?}");
        assert!(at_zero + at_gap > 0.98, "{sep:?}");
        // One wall alone: all of it at 0.
        let one = describe(&wall(1.2));
        assert!(one[0] > 0.99, "{:?}", &one[..sb]);
    }

    /// A wall and the floor meet at right angles: the perpendicular
    /// channel holds pairs from where they meet on; a floor 1.5 m below
    /// the wall's foot has none nearer than 1.5 m.
    #[test]
    fn a_wall_and_a_floor_are_perpendicular_pairs() {
        let floor = |z: f32| -> Vec<[f32; 3]> {
            let mut v = Vec::new();
            for i in 0..60 {
                for j in 0..160 {
                    v.push([1.3 + 0.05 * i as f32, -4.0 + 0.05 * j as f32, z]);
                }
            }
            v
        };
        let [sb, ab, _] = CHANNELS;
        let perpendicular = |z: f32| describe(&[wall(1.2), floor(z)].concat())[sb + ab..].to_vec();
        let angle = describe(&[wall(1.2), floor(-1.0)].concat())[sb..sb + ab].to_vec();
        assert!(angle[ab - 1] > 0.2, "right angles: {angle:?}");
        // Bins of 4 / 15 m: bins 0-4 hold distances below 1.33 m (soft
        // binning shares a value with the next bin up). Most pairs lie
        // farther (their number grows with the distance), so the near
        // share is small where the two meet (1.9 % measured), and none
        // where they do not.
        let (meet, apart) = (perpendicular(-1.0), perpendicular(-2.5));
        assert!(meet[..5].iter().sum::<f32>() > 0.015, "{meet:?}");
        assert_eq!(apart[..5].iter().sum::<f32>(), 0.0, "{apart:?}");
    }

    /// No points, or points without a planar cell: every channel's mass in
    /// bin 0.
    #[test]
    fn no_pair_is_the_empty_part() {
        assert_eq!(describe(&[]), empty_channels(&CHANNELS));
        let line: Vec<[f32; 3]> = (0..500)
            .map(|i| [1.0 + 0.01 * i as f32, 0.0, 0.0])
            .collect();
        assert_eq!(describe(&line), empty_channels(&CHANNELS));
    }
}
