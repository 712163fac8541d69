//! What stands in a room by size and height together (issue 18,
//! twenty-sixth round).
//!
//! The [`objects`](mod@super::objects) part keeps its pieces' footprints and
//! tops in separate histograms, so a room of 2 m² shelving blocks 1.8 m
//! high and one of 2 m² tables 0.75 m high with small racks 1.8 m high give
//! the same channels. A joint histogram keeps which sizes stand at which
//! heights (Pass and Zabih, "Comparing images using joint histograms",
//! ACM Multimedia Systems 1999, on colour histograms); the pieces stand
//! for objects as in object-based place models (Ranganathan and Dellaert,
//! "Semantic modeling of places using objects", RSS 2007), recognised by
//! no detector. Beds, worktops, shelving rows and café tables differ in
//! both at once.
//!
//! The pieces are the `objects` part's, cut with its constants. Channels:
//!
//! - how the pieces share out over three footprint classes: below 0.1 m²,
//!   0.1 to 1 m², 1 m² and more (3 bins, each piece once);
//! - for each class, its pieces' tops above the floor over [0, 2.4] m
//!   (10 bins each; a class with no piece puts its mass in bin 0).
//!
//! So the joint histogram is stored as the classes' shares and each
//! class's tops, channels that compare by the earth mover's distance as
//! every part's. A scan with no floor or no piece puts every channel's
//! mass in bin 0. An empty class's bin 0 lies near real pieces of low tops
//! (a top of 0.1 m is at bin 0.375), so two scans that differ in whether a
//! class holds low pieces differ little in its channel; the shares channel
//! tells them apart. The constants were fixed in the twenty-sixth round's
//! plan (docs/seeds.md) before any run.

use super::objects::{contents_of, of_pieces_or_empty, Contents, Piece};
use super::parts::{soft_bin, unit_sum};
use super::polar::PolarScan;

/// Bins of each channel: the classes' shares, then each class's tops.
pub const CHANNELS: [usize; 4] = [CLASSES, TOP_BINS, TOP_BINS, TOP_BINS];
const CLASSES: usize = 3;
const TOP_BINS: usize = 10;
/// Upper footprints of the first two classes (m²).
const CLASS_LIMITS: [f32; CLASSES - 1] = [0.1, 1.0];
/// Tops are binned over [0, TOP] m.
const TOP: f32 = 2.4;

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

/// A piece's footprint class.
fn class_of(p: &Piece) -> usize {
    CLASS_LIMITS.iter().take_while(|&&l| p.area >= l).count()
}

/// The channels of at least one piece.
fn of_pieces(pieces: &[Piece]) -> Vec<f32> {
    let mut shares = vec![0f32; CLASSES];
    let mut tops = vec![vec![0f32; TOP_BINS]; CLASSES];
    for p in pieces {
        let c = class_of(p);
        shares[c] += 1.0;
        let at = f64::from(p.top / TOP) * (TOP_BINS - 1) as f64;
        soft_bin(&mut tops[c], at, 1.0);
    }
    unit_sum(&mut shares);
    let mut v = shares;
    for mut h in tops {
        if h.iter().sum::<f32>() > 0.0 {
            unit_sum(&mut h);
        } else {
            h[0] = 1.0;
        }
        v.extend(h);
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(area: f32, top: f32) -> Piece {
        Piece {
            area,
            top,
            roundness: 1.0,
            centre: [0.0, 0.0],
            axis: 0.0,
        }
    }

    /// The mean position (in bins) of channel `c`'s mass.
    fn mean_bin(v: &[f32], c: usize) -> f32 {
        let at: usize = CHANNELS[..c].iter().sum();
        (v[at..at + CHANNELS[c]].iter().enumerate())
            .map(|(i, m)| i as f32 * m)
            .sum()
    }

    /// A large low piece and a small tall one: the classes' shares and
    /// each class's top say which is which; the marginals of the `objects`
    /// part would be the same for a large tall and a small low one.
    #[test]
    fn sizes_and_heights_are_kept_together() {
        let a = of_pieces(&[piece(2.0, 0.75), piece(0.05, 1.8)]);
        let b = of_pieces(&[piece(2.0, 1.8), piece(0.05, 0.75)]);
        assert_eq!(&a[..3], &[0.5, 0.0, 0.5]);
        assert_eq!(&a[..3], &b[..3]);
        let bins = (TOP_BINS - 1) as f32;
        let (low, tall) = (0.75 / TOP * bins, 1.8 / TOP * bins);
        assert!((mean_bin(&a, 1) - tall).abs() < 1e-4);
        assert!((mean_bin(&a, 3) - low).abs() < 1e-4);
        assert!((mean_bin(&b, 1) - low).abs() < 1e-4);
        assert!((mean_bin(&b, 3) - tall).abs() < 1e-4);
        // The empty middle class: its mass in bin 0.
        assert_eq!(mean_bin(&a, 2), 0.0);
        assert_eq!(a.len(), CHANNELS.iter().sum::<usize>());
    }

    #[test]
    fn the_classes_part_at_0_1_and_1_square_metres() {
        let classes: Vec<usize> = [0.03, 0.0999, 0.1, 0.99, 1.0, 7.0]
            .iter()
            .map(|&a| class_of(&piece(a, 1.0)))
            .collect();
        assert_eq!(classes, [0, 0, 1, 1, 2, 2]);
    }
}
