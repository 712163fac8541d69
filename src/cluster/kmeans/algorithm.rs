use super::hyperparams::KMeansValidParams;
use crate::cluster::lloyd::{
    cheaper, check_iterations, check_k, fit_subset, iterate, Lloyd, Picking, Seeding,
};
use crate::cluster::spectral::{Spectral, SpectralParams, MAX_SCANS};
use crate::cluster::ParamGuard;
use crate::distance::{Centre, DistanceMatrix, Space};
use crate::error::{invalid, Error, Result};
use crate::rng::rng_stream;
use serde::{Deserialize, Serialize};

/// The outcome of k-means.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct KMeansResult {
    /// Category of each scan, 0..k.
    pub labels: Vec<i32>,
    /// Scans the centres started at (empty with spectral seeding, whose
    /// centres start at its groups' means).
    pub seeds: Vec<usize>,
    /// Assign/update rounds run.
    pub iterations: usize,
    /// True if no label changed in the last round (false: stopped at the cap).
    pub converged: bool,
    /// Sum over scans of Delta to their centre: the cost that restarts
    /// compare.
    pub cost: f64,
    /// Of the `restarts` runs, the one kept (the cheapest, the earliest of
    /// equals); 0 for a single run. Results written before restarts
    /// existed read as run 0.
    #[serde(default)]
    pub restart: usize,
}

/// k-means over a [`Space`].
pub struct KMeans;

impl KMeans {
    /// Cluster the space's items; `params` is checked first (a
    /// [`KMeansParams`](super::KMeansParams) or its validated form). With
    /// `restarts` above 1, the run of lowest `cost` of [`KMeans::runs`],
    /// computed one at a time (only the cheapest so far is held).
    pub fn fit(
        space: &Space,
        params: &impl ParamGuard<Checked = KMeansValidParams>,
    ) -> Result<KMeansResult> {
        Self::fit_with_matrix(space, None, params)
    }

    /// [`KMeans::fit`] with the space's Delta matrix when the caller has it
    /// (spectral seeding clusters it; other seedings do not read it), so
    /// that it is not computed again. An error if it is not n x n for the
    /// space's n scans.
    pub fn fit_with_matrix(
        space: &Space,
        matrix: Option<&DistanceMatrix>,
        params: &impl ParamGuard<Checked = KMeansValidParams>,
    ) -> Result<KMeansResult> {
        let mut best: Option<KMeansResult> = None;
        for run in Self::lazy_runs(space, matrix, params)? {
            if best.as_ref().is_none_or(|b| cheaper(run.cost, b.cost)) {
                best = Some(run);
            }
        }
        // check() made restarts at least 1, so there is a run.
        best.ok_or_else(|| crate::Error::InvalidParameter("restarts must be at least 1".into()))
    }

    /// Every one of the `restarts` runs that [`KMeans::fit`] chooses from,
    /// in order (run r depends only on the seed and r, so the first runs of
    /// 10 restarts are those of 3). For callers who want the spread of the
    /// runs (every cost, or the lowest accuracy), not only the kept one.
    pub fn runs(
        space: &Space,
        params: &impl ParamGuard<Checked = KMeansValidParams>,
    ) -> Result<Vec<KMeansResult>> {
        Ok(Self::lazy_runs(space, None, params)?.collect())
    }

    /// The runs of [`KMeans::runs`], each computed when asked for.
    fn lazy_runs<'a>(
        space: &'a Space,
        matrix: Option<&DistanceMatrix>,
        params: &impl ParamGuard<Checked = KMeansValidParams>,
    ) -> Result<impl Iterator<Item = KMeansResult> + 'a> {
        let params = params.check()?;
        let all: Vec<usize> = (0..space.len()).collect();
        check_k(params.k, all.len())?;
        // A seeding picks scans in each run; spectral seeding's centres
        // are known before its (single) run.
        let start = match params.seeding.picking() {
            Some(picking) => Start::Picking(picking),
            None => Start::Centres(spectral_start(space, matrix, &params)?),
        };
        Ok((0..params.restarts).map(move |restart| match &start {
            Start::Centres(centres) => {
                let run = iterate(space, &all, centres.clone(), params.max_iterations);
                KMeansResult::of(run, Vec::new(), restart)
            }
            Start::Picking(picking) => Self::run(space, &all, &params, *picking, restart),
        }))
    }

    /// Run `restart` of k-means: seeding and Lloyd's iterations with RNG
    /// stream `restart` of the user's seed (stream 0: the single run).
    fn run(
        space: &Space,
        all: &[usize],
        params: &KMeansValidParams,
        picking: Picking,
        restart: usize,
    ) -> KMeansResult {
        let mut r = rng_stream(params.seed, restart as u64);
        let (run, seeds) = fit_subset(space, all, params.k, picking, params.max_iterations, &mut r);
        KMeansResult::of(run, seeds.iter().map(|&s| all[s]).collect(), restart)
    }

    /// Lloyd's iterations from the given centres instead of a seeding: one
    /// cluster a centre, at most `max_iterations` rounds. For centres known
    /// beforehand (a named model's, or each true category's mean to see
    /// where k-means walks from the truth). The result's `seeds` is empty.
    /// An empty cluster restarts at the scan farthest from its centre, as
    /// in [`KMeans::fit`].
    pub fn fit_from_centres(
        space: &Space,
        centres: Vec<Centre>,
        max_iterations: usize,
    ) -> Result<KMeansResult> {
        check_iterations(max_iterations)?;
        check_k(centres.len(), space.len())?;
        for (which, c) in centres.iter().enumerate() {
            space.check_centre(c, which)?;
        }
        let all: Vec<usize> = (0..space.len()).collect();
        let run = iterate(space, &all, centres, max_iterations);
        Ok(KMeansResult::of(run, Vec::new(), 0))
    }

    /// [`KMeans::fit_from_centres`] from the means of given groups:
    /// `groups[i]` is scan i's group, 0..k, each of at least one scan (as
    /// spectral clustering's labels, which spectral seeding starts from,
    /// or the true kinds, to see where k-means walks from the truth).
    pub fn fit_from_groups(
        space: &Space,
        groups: &[i32],
        k: usize,
        max_iterations: usize,
    ) -> Result<KMeansResult> {
        Self::fit_from_centres(space, group_means(space, groups, k)?, max_iterations)
    }
}

/// The mean of each of the `k` groups of `groups` (scan i in group
/// `groups[i]`), the group's first scan orienting it as Lloyd's update
/// does. An error for a group with no scan, a label outside 0..k or a
/// label count that is not the space's.
fn group_means(space: &Space, groups: &[i32], k: usize) -> Result<Vec<Centre>> {
    if groups.len() != space.len() {
        return Err(Error::Mismatch(format!(
            "{} group labels for {} scans",
            groups.len(),
            space.len()
        )));
    }
    if let Some(bad) = groups.iter().find(|&&g| g < 0 || g as usize >= k) {
        return invalid(format!("group label {bad} is not in 0..{k}"));
    }
    let mut members = vec![Vec::new(); k];
    for (i, &g) in groups.iter().enumerate() {
        members[g as usize].push(i);
    }
    (members.iter().enumerate())
        .map(|(g, m)| {
            m.first()
                .and_then(|&first| space.mean(m, &space.centre_of(first)))
                .ok_or_else(|| Error::InvalidParameter(format!("group {g} of {k} has no scan")))
        })
        .collect()
}

/// Where a k-means run starts: scans its seeding picks, or centres known
/// beforehand (spectral seeding's groups' means).
enum Start {
    Picking(Picking),
    Centres(Vec<Centre>),
}

/// Refuse spectral seeding of more than spectral clustering's
/// [`MAX_SCANS`] scans (callers check first, before building a matrix or
/// clustering reference sets).
pub(crate) fn check_seeding_size(seeding: Seeding, n: usize) -> Result<()> {
    if seeding == Seeding::Spectral && n > MAX_SCANS {
        return invalid(format!(
            "spectral seeding takes at most {MAX_SCANS} scans (it clusters their Delta matrix \
             spectrally first), got {n}; use plusplus seeding"
        ));
    }
    Ok(())
}

/// Spectral seeding's centres: the means of the groups of spectral
/// clustering of the space's Delta matrix (`matrix`, else computed here;
/// spectral clustering's defaults, `params.seed`).
fn spectral_start(
    space: &Space,
    matrix: Option<&DistanceMatrix>,
    params: &KMeansValidParams,
) -> Result<Vec<Centre>> {
    check_seeding_size(Seeding::Spectral, space.len())?;
    let own;
    let matrix = match matrix {
        Some(m) if m.n != space.len() => {
            return Err(Error::Mismatch(format!(
                "a Delta matrix of {} scans for {} scans",
                m.n,
                space.len()
            )))
        }
        Some(m) => m,
        None => {
            own = space.matrix();
            &own
        }
    };
    // Spectral clustering returns k groups of at least one scan.
    let groups = Spectral::fit(matrix, &SpectralParams::new(params.k).seed(params.seed))?;
    group_means(space, &groups.labels, params.k)
}

impl KMeansResult {
    fn of(run: Lloyd, seeds: Vec<usize>, restart: usize) -> Self {
        KMeansResult {
            labels: run.labels.into_iter().map(|l| l as i32).collect(),
            seeds,
            iterations: run.iterations,
            converged: run.converged,
            cost: run.cost,
            restart,
        }
    }
}
