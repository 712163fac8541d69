//! Mean silhouette on Delta (Rousseeuw 1987): for scan i in category A,
//! a(i) = mean Delta to the other members of A, b(i) = the smallest mean
//! Delta to the members of another category, s(i) = (b - a) / max(a, b);
//! s(i) = 0 for a scan alone in its category (Rousseeuw's convention).
//! Undefined for one category.

/// Mean silhouette of `labels` (0..k) under `dist`, over the scans
/// `0..labels.len()`. None when there are fewer than two categories.
pub fn mean_silhouette(labels: &[i32], dist: impl Fn(usize, usize) -> f32) -> Option<f64> {
    let k = labels.iter().copied().max().map_or(0, |m| m as usize + 1);
    if k < 2 {
        return None;
    }
    let mut size = vec![0usize; k];
    for &l in labels {
        size[l as usize] += 1;
    }
    let mut sum = 0.0;
    let mut sums = vec![0f64; k];
    for (i, &li) in labels.iter().enumerate() {
        let li = li as usize;
        if size[li] < 2 {
            continue; // s(i) = 0
        }
        sums.iter_mut().for_each(|s| *s = 0.0);
        for (j, &lj) in labels.iter().enumerate() {
            if j != i {
                sums[lj as usize] += dist(i, j) as f64;
            }
        }
        let a = sums[li] / (size[li] - 1) as f64;
        let b = (0..k)
            .filter(|&c| c != li && size[c] > 0)
            .map(|c| sums[c] / size[c] as f64)
            .fold(f64::INFINITY, f64::min);
        let m = a.max(b);
        if m > 0.0 && b.is_finite() {
            sum += (b - a) / m;
        }
    }
    Some(sum / labels.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_tight_far_pairs_score_near_one_and_a_wrong_split_negative() {
        // Points on a line: 0, 1, 100, 101.
        let x = [0.0f32, 1.0, 100.0, 101.0];
        let d = |i: usize, j: usize| (x[i] - x[j]).abs();
        let good = mean_silhouette(&[0, 0, 1, 1], d).unwrap();
        // a = 1, b = 100 (or 99.5 ...): s = 1 - a/b per scan.
        let want = [
            1.0 - 1.0 / 100.5,
            1.0 - 1.0 / 99.5,
            1.0 - 1.0 / 99.5,
            1.0 - 1.0 / 100.5,
        ];
        assert!((good - want.iter().sum::<f64>() / 4.0).abs() < 1e-9);
        assert!(mean_silhouette(&[0, 1, 0, 1], d).unwrap() < 0.0);
        assert_eq!(mean_silhouette(&[0, 0, 0, 0], d), None);
    }
}
