//! What k-means, k-medoids and hierarchical k-means++ share: picking seeds
//! and Lloyd's iteration on a subset of the scans. No algorithm reaches
//! into another's module for these.

use crate::distance::{Centre, Space};
use crate::error::{invalid, Error, Result};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// How the k initial centres are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Seeding {
    /// k distinct scans drawn from the seeded RNG.
    Random,
    /// "Deterministic": cluster i starts at scan i * n / k.
    Stride,
    /// k-means++: each next seed drawn with probability proportional to the
    /// squared Delta to the nearest seed so far.
    PlusPlus,
    /// Spectral (k-means only): each centre starts at the mean of one group
    /// of spectral clustering ([`Spectral`](crate::cluster::Spectral) with
    /// its defaults and this seed) of the scans' Delta matrix, then Lloyd's
    /// iterations as for any seeding. It does not start from the scans'
    /// order as stride does; it needs the matrix, so it takes at most
    /// [`spectral::MAX_SCANS`](crate::cluster::spectral::MAX_SCANS) scans.
    /// Added in issue 18's twenty-first round (docs/seeds.md): on room
    /// sets k-means' cheapest runs are not the kinds, and k-means started
    /// from spectral clustering's groups stays near that grouping, which
    /// is nearer the kinds (docs/spectral-seeding-round.md).
    Spectral,
}

impl std::str::FromStr for Seeding {
    type Err = crate::Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "random" => Ok(Seeding::Random),
            "stride" | "deterministic" => Ok(Seeding::Stride),
            "plusplus" | "kmeans++" | "++" => Ok(Seeding::PlusPlus),
            "spectral" => Ok(Seeding::Spectral),
            other => invalid(format!(
                "unknown seeding {other:?} (random, stride, plusplus, spectral)"
            )),
        }
    }
}

/// The seedings that pick k scans as the first centres: every [`Seeding`]
/// but spectral, which starts from its groups' means (k-means computes
/// them before any run). Hierarchical k-means++ and k-medoids pick with
/// k-means++.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Picking {
    Random,
    Stride,
    PlusPlus,
}

impl Seeding {
    /// How this seeding picks scans, if it does (not spectral seeding).
    pub(crate) fn picking(self) -> Option<Picking> {
        match self {
            Seeding::Random => Some(Picking::Random),
            Seeding::Stride => Some(Picking::Stride),
            Seeding::PlusPlus => Some(Picking::PlusPlus),
            Seeding::Spectral => None,
        }
    }
}

/// Reject an iteration cap of 0.
pub(crate) fn check_iterations(max_iterations: usize) -> Result<()> {
    if max_iterations == 0 {
        return invalid("max_iterations must be at least 1");
    }
    Ok(())
}

/// The most runs a `restarts` may ask for (k-means runs, or trial splits
/// per node of hierarchical k-means++): each run is a full k-means, so more
/// would take hours on a large set and, above, would be a slip of the hand
/// (scikit-learn's `n_init` was 10 before 1.4; the page offers 10).
pub const MAX_RESTARTS: usize = 1000;

/// What a `restarts` field left out means: one run, as before restarts.
pub(crate) fn one_run() -> usize {
    1
}

/// Reject 0 runs and more than [`MAX_RESTARTS`]; `what` names the runs in
/// the message ("runs of k-means").
pub(crate) fn check_runs(restarts: usize, what: &str) -> Result<()> {
    if restarts == 0 {
        return invalid(format!(
            "restarts must be at least 1 ({what}; 1: a single run), got 0"
        ));
    }
    if restarts > MAX_RESTARTS {
        return invalid(format!(
            "restarts = {restarts} is more than the limit of {MAX_RESTARTS} {what}"
        ));
    }
    Ok(())
}

/// True if a run of cost `run` should replace the kept run of cost `kept`:
/// strictly cheaper (of equal costs the earliest run stays), and a NaN cost
/// is never kept over a number nor keeps a later number out.
pub(crate) fn cheaper(run: f64, kept: f64) -> bool {
    !run.is_nan() && (kept.is_nan() || run < kept)
}

/// Reject k = 0 (a check of the parameters alone).
pub(crate) fn check_k_positive(k: usize) -> Result<()> {
    if k == 0 {
        return Err(Error::InvalidParameter(
            "k must be at least 1, got 0".into(),
        ));
    }
    Ok(())
}

/// Reject a k that cannot apply to n items.
pub(crate) fn check_k(k: usize, n: usize) -> Result<()> {
    check_k_positive(k)?;
    if k > n {
        return Err(Error::InvalidParameter(format!(
            "k = {k} is more than the {n} scans to cluster"
        )));
    }
    Ok(())
}

/// Pick the seeds among `members` (positions into `members`).
pub(crate) fn seeds(
    space: &Space,
    members: &[usize],
    k: usize,
    picking: Picking,
    r: &mut ChaCha8Rng,
) -> Vec<usize> {
    let n = members.len();
    match picking {
        Picking::Stride => (0..k).map(|i| i * n / k).collect(),
        Picking::Random => rand::seq::index::sample(r, n, k).into_vec(),
        Picking::PlusPlus => {
            let mut chosen = vec![r.random_range(0..n)];
            let mut nearest: Vec<f64> = (0..n)
                .map(|i| space.delta(members[i], members[chosen[0]]) as f64)
                .collect();
            while chosen.len() < k {
                let weights: f64 = nearest.iter().map(|d| d * d).sum();
                let next = if weights > 0.0 {
                    let mut x = r.random::<f64>() * weights;
                    let mut pick = n - 1;
                    for (i, d) in nearest.iter().enumerate() {
                        x -= d * d;
                        if x < 0.0 && d * d > 0.0 {
                            pick = i;
                            break;
                        }
                    }
                    pick
                } else {
                    // All remaining scans coincide with a seed: take the
                    // first one not chosen yet.
                    (0..n).find(|i| !chosen.contains(i)).unwrap_or(0)
                };
                chosen.push(next);
                for i in 0..n {
                    nearest[i] = nearest[i].min(space.delta(members[i], members[next]) as f64);
                }
            }
            chosen
        }
    }
}

/// Where Lloyd's iterations ended: labels per position in `members`, the
/// rounds run, whether the last changed no label, and the cost (the sum of
/// Delta from each member to its centre in the last assignment).
pub(crate) struct Lloyd {
    pub labels: Vec<usize>,
    pub iterations: usize,
    pub converged: bool,
    pub cost: f64,
}

/// k-means on a subset: the seeds `picking` picks, then [`iterate`]. The
/// seeds are positions in `members`.
pub(crate) fn fit_subset(
    space: &Space,
    members: &[usize],
    k: usize,
    picking: Picking,
    max_iterations: usize,
    r: &mut ChaCha8Rng,
) -> (Lloyd, Vec<usize>) {
    let seed_pos = seeds(space, members, k, picking, r);
    let centres: Vec<Centre> = seed_pos
        .iter()
        .map(|&s| space.centre_of(members[s]))
        .collect();
    (iterate(space, members, centres, max_iterations), seed_pos)
}

/// Lloyd's iterations over `members` from the given centres (at least
/// one): assign each member to its nearest centre (the first of equals),
/// move each centre to its members' mean, until no label changes or
/// `max_iterations` rounds have run.
pub(crate) fn iterate(
    space: &Space,
    members: &[usize],
    mut centres: Vec<Centre>,
    max_iterations: usize,
) -> Lloyd {
    let mut labels = vec![usize::MAX; members.len()];
    let mut converged = false;
    let mut iterations = 0;
    let mut cost = 0.0;
    while iterations < max_iterations {
        iterations += 1;
        let mut changed = false;
        cost = 0.0;
        let mut dist = vec![0f32; members.len()];
        for (p, &i) in members.iter().enumerate() {
            let (best, d) = centres
                .iter()
                .enumerate()
                .map(|(c, centre)| (c, space.to_centre(centre, i).0))
                .fold((0, f32::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
            dist[p] = d;
            cost += d as f64;
            if labels[p] != best {
                labels[p] = best;
                changed = true;
            }
        }
        if !changed {
            converged = true;
            break;
        }
        for (c, centre) in centres.iter_mut().enumerate() {
            let in_c: Vec<usize> = (0..members.len())
                .filter(|&p| labels[p] == c)
                .map(|p| members[p])
                .collect();
            match space.mean(&in_c, centre) {
                Some(m) => *centre = m,
                None => {
                    // An empty cluster restarts at the scan farthest from its
                    // centre, so k clusters stay k.
                    let far = (0..members.len())
                        .max_by(|&a, &b| dist[a].total_cmp(&dist[b]))
                        .unwrap_or(0);
                    dist[far] = 0.0;
                    *centre = space.centre_of(members[far]);
                }
            }
        }
    }
    Lloyd {
        labels,
        iterations,
        converged,
        cost,
    }
}

#[cfg(test)]
mod tests {
    use super::cheaper;

    #[test]
    fn a_nan_cost_neither_wins_nor_blocks() {
        assert!(cheaper(1.0, 2.0));
        assert!(!cheaper(2.0, 2.0), "the earliest of equals stays");
        assert!(!cheaper(f64::NAN, 2.0));
        assert!(cheaper(2.0, f64::NAN), "a later number replaces a NaN run");
        assert!(cheaper(2.0, -f64::NAN));
        assert!(!cheaper(-f64::NAN, 2.0));
    }
}
