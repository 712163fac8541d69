//! How the pieces of what stands in a room are laid out (issue 18,
//! twenty-sixth round): rows of shelving or racks stand parallel at
//! regular spacing, café tables and a living room's furniture stand
//! scattered. The spacing and relative orientation of objects is what
//! object-based place models add to the objects themselves (Ranganathan
//! and Dellaert, "Semantic modeling of places using objects", RSS 2007,
//! model where objects stand in a place); here, without recognising any,
//! two histograms over the [`objects`](mod@super::objects) part's pieces,
//! cut with its constants:
//!
//! - each piece's horizontal distance to the nearest other piece's centre
//!   over [0, 4] m (10 bins; a lone piece counts as beyond 4 m);
//! - the angle between the long axes of every pair of elongated pieces
//!   (roundness below 0.5), folded to [0, 90] degrees (10 bins; bin 0
//!   when there are fewer than two): parallel rows put it near 0.
//!
//! The spacings are invariant to rotation about z up to the grid's cells;
//! the angles are not where a piece's roundness lies near 0.5: the grid
//! turned under it can carry it across the threshold, and a pair appears
//! or goes (a three-piece office turned by 1.1 rad moves the part by 0.33,
//! tests/it/parts.rs). A scan with no floor or no piece puts every
//! channel's mass in bin 0, which in the spacing channel reads as pieces
//! packed close and in the angle channel as parallel axes, as do fewer
//! than two elongated pieces: these limits are the plan's or were fixed
//! before any run (a lone piece's spacing counts as beyond 4 m, the top
//! bin). The constants were fixed in the twenty-sixth round's plan
//! (docs/seeds.md) before any run.

use super::objects::{contents_of, of_pieces_or_empty, Contents, Piece};
use super::parts::{soft_bin, unit_sum};
use super::polar::PolarScan;
use std::f32::consts::{FRAC_PI_2, PI};

/// Bins of each channel: nearest spacing, angles between long axes.
pub const CHANNELS: [usize; 2] = [BINS, BINS];
const BINS: usize = 10;
/// Spacings are binned over [0, SPACING] m.
const SPACING: f32 = 4.0;
/// A piece is elongated below this roundness.
const ELONGATED: f32 = 0.5;

/// The part of a scan's points.
pub fn describe(points: &[[f32; 3]]) -> Vec<f32> {
    describe_scan(&PolarScan::new(points))
}

/// The part of a scan whose ranges and azimuths are known.
pub fn describe_scan(scan: &PolarScan) -> Vec<f32> {
    of_contents(contents_of(scan).as_ref())
}

/// The part of a scan's pieces (cut once for the parts that read them).
pub(crate) fn of_contents(contents: Option<&Contents>) -> Vec<f32> {
    of_pieces_or_empty(contents, &CHANNELS, of_pieces)
}

/// The channels of at least one piece.
fn of_pieces(pieces: &[Piece]) -> Vec<f32> {
    let top = (BINS - 1) as f64;
    let mut spacing = vec![0f32; BINS];
    for (i, p) in pieces.iter().enumerate() {
        let nearest = (pieces.iter().enumerate())
            .filter(|&(j, _)| j != i)
            .map(|(_, q)| (p.centre[0] - q.centre[0]).hypot(p.centre[1] - q.centre[1]))
            .fold(f32::INFINITY, f32::min);
        // A lone piece's INFINITY lands in the top bin (soft_bin clamps).
        soft_bin(&mut spacing, f64::from(nearest / SPACING) * top, 1.0);
    }
    unit_sum(&mut spacing);
    let axes: Vec<f32> = (pieces.iter())
        .filter(|p| p.roundness < ELONGATED)
        .map(|p| p.axis)
        .collect();
    let mut angles = vec![0f32; BINS];
    for (i, a) in axes.iter().enumerate() {
        for b in &axes[i + 1..] {
            // Axes are lines: the angle between them is at most pi / 2.
            let d = (a - b).abs() % PI;
            let d = d.min(PI - d);
            soft_bin(&mut angles, f64::from(d / FRAC_PI_2) * top, 1.0);
        }
    }
    if axes.len() < 2 {
        angles[0] = 1.0;
    } else {
        unit_sum(&mut angles);
    }
    spacing.extend(angles);
    spacing
}

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(x: f32, y: f32, roundness: f32, axis: f32) -> Piece {
        Piece {
            area: 1.0,
            top: 1.0,
            roundness,
            centre: [x, y],
            axis,
        }
    }

    fn mean_bin(h: &[f32]) -> f32 {
        h.iter().enumerate().map(|(i, m)| i as f32 * m).sum()
    }

    /// Three parallel rows 2 m apart: every nearest spacing 2 m, every
    /// angle 0. Turned by 1 rad, the same channels.
    #[test]
    fn parallel_rows_at_even_spacing() {
        let rows = |turn: f32| {
            let (s, c) = turn.sin_cos();
            (0..3)
                .map(|i| {
                    let y = 2.0 * i as f32;
                    piece(-y * s, y * c, 0.1, 0.3 + turn)
                })
                .collect::<Vec<_>>()
        };
        let v = of_pieces(&rows(0.0));
        let bins = (BINS - 1) as f32;
        assert!((mean_bin(&v[..BINS]) - 2.0 / SPACING * bins).abs() < 1e-4);
        assert!(mean_bin(&v[BINS..]).abs() < 1e-4, "{v:?}");
        let turned = of_pieces(&rows(1.0));
        for (a, b) in v.iter().zip(&turned) {
            assert!((a - b).abs() < 1e-4, "{v:?} {turned:?}");
        }
    }

    /// Axes near +90 and -90 degrees are nearly the same line: 1.5 and
    /// -1.5 rad lie pi - 3 = 0.14 rad apart, not 3 rad.
    #[test]
    fn axes_on_either_side_of_the_vertical_are_near() {
        let v = of_pieces(&[piece(0.0, 0.0, 0.2, 1.5), piece(2.0, 0.0, 0.2, -1.5)]);
        let want = (PI - 3.0) / FRAC_PI_2 * (BINS - 1) as f32;
        assert!((mean_bin(&v[BINS..]) - want).abs() < 1e-4, "{v:?}");
    }

    /// Axes across each other meet at 90 degrees whichever way each
    /// points; round pieces have no axis; a lone piece is far from any.
    #[test]
    fn crossed_axes_round_pieces_and_a_lone_piece() {
        let v = of_pieces(&[
            piece(0.0, 0.0, 0.2, 0.1),
            piece(1.0, 0.0, 0.2, 0.1 - FRAC_PI_2),
            piece(5.0, 0.0, 0.9, 1.0),
        ]);
        assert!(
            (mean_bin(&v[BINS..]) - (BINS - 1) as f32).abs() < 1e-3,
            "{v:?}"
        );
        let lone = of_pieces(&[piece(0.0, 0.0, 0.2, 0.0)]);
        assert_eq!(lone[BINS - 1], 1.0);
        assert_eq!(lone[BINS], 1.0);
    }
}
