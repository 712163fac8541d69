//! Adjusted Rand index (Hubert and Arabie, 1985).

use std::collections::HashMap;
use std::hash::Hash;

fn choose2(x: u64) -> f64 {
    (x as f64) * (x as f64 - 1.0) / 2.0
}

/// ARI of two partitions given as label lists of equal length. 1 for
/// identical partitions (up to renaming), ~0 for independent ones. By
/// convention 1 when both partitions are trivial in the same way (the
/// expected and maximum index coincide).
pub fn adjusted_rand_index<A: Eq + Hash + Copy, B: Eq + Hash + Copy>(a: &[A], b: &[B]) -> f64 {
    assert_eq!(a.len(), b.len(), "partitions of different lengths");
    let n = a.len() as u64;
    if n < 2 {
        return 1.0;
    }
    let mut table: HashMap<(A, B), u64> = HashMap::new();
    let mut rows: HashMap<A, u64> = HashMap::new();
    let mut cols: HashMap<B, u64> = HashMap::new();
    for (&x, &y) in a.iter().zip(b) {
        *table.entry((x, y)).or_default() += 1;
        *rows.entry(x).or_default() += 1;
        *cols.entry(y).or_default() += 1;
    }
    let index: f64 = table.values().map(|&v| choose2(v)).sum();
    let sa: f64 = rows.values().map(|&v| choose2(v)).sum();
    let sb: f64 = cols.values().map(|&v| choose2(v)).sum();
    let expected = sa * sb / choose2(n);
    let max = 0.5 * (sa + sb);
    if max == expected {
        return 1.0;
    }
    (index - expected) / (max - expected)
}
