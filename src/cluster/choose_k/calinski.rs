//! Calinski-Harabasz (1974) in its distance form: with W_k the squared
//! Delta of every scan to its category's centre and T = W_1,
//! CH(k) = ((T - W_k) / (k - 1)) / (W_k / (n - k)). Larger is better;
//! undefined for k = 1 and for k = n.

/// CH(k) from W_1, W_k, k and n; None where undefined.
pub(crate) fn calinski_harabasz(w1: f64, wk: f64, k: usize, n: usize) -> Option<f64> {
    if k < 2 || k >= n {
        return None;
    }
    if wk <= 0.0 {
        // Every category a point: perfect separation.
        return Some(f64::INFINITY);
    }
    Some(((w1 - wk) / (k - 1) as f64) / (wk / (n - k) as f64))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ch_of_known_sums() {
        // T = 10, W = 2, k = 2, n = 6: (8 / 1) / (2 / 4) = 16.
        assert_eq!(calinski_harabasz(10.0, 2.0, 2, 6), Some(16.0));
        assert_eq!(calinski_harabasz(10.0, 2.0, 1, 6), None);
        assert_eq!(calinski_harabasz(10.0, 2.0, 6, 6), None);
    }
}
