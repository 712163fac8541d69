//! How far each scan of a route lies from a change of true kind, in metres
//! along the route (for `examples/boundary_errors.rs`; tested in
//! tests/it/boundary.rs on a route of known geometry).

/// Distance driven up to each scan (m): the sum of the horizontal steps
/// between consecutive sensor positions (x, y; the height is left out, as
/// a 20 m range disc is horizontal).
pub fn distance_driven(positions: &[[f64; 3]]) -> Vec<f64> {
    let mut driven = Vec::with_capacity(positions.len());
    let mut total = 0.0;
    for (i, p) in positions.iter().enumerate() {
        if i > 0 {
            let q = positions[i - 1];
            total += (p[0] - q[0]).hypot(p[1] - q[1]);
        }
        driven.push(total);
    }
    driven
}

/// For each scan, the distance along the route (m) to the nearest change
/// of true kind, or None when the route has none. A change between scans
/// c - 1 and c is placed halfway between them: the scans say only that the
/// place changed somewhere in that step (1.8-3.4 m on the outdoor site's
/// seeds 1-10 and 501-505, docs/boundary_errors.json), so a scan next to a change is half a step from it, not 0.
pub fn distance_to_change(truth: &[String], driven: &[f64]) -> Vec<Option<f64>> {
    assert_eq!(truth.len(), driven.len(), "one distance driven a scan");
    let changes: Vec<f64> = (1..truth.len())
        .filter(|&c| truth[c] != truth[c - 1])
        .map(|c| 0.5 * (driven[c - 1] + driven[c]))
        .collect();
    driven
        .iter()
        .map(|&s| {
            changes
                .iter()
                .map(|&c| (s - c).abs())
                .min_by(f64::total_cmp)
        })
        .collect()
}
