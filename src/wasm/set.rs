//! `DescriptorSet`: the JS face of [`Collection`].

use super::*;

/// Many descriptors made with the same parameters: distances, clustering,
/// evaluation and models.
#[wasm_bindgen]
pub struct DescriptorSet {
    set: Collection,
}

#[wasm_bindgen]
impl DescriptorSet {
    /// An empty set for descriptors made with `params` (partial object ok).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Partial<DescriptorParams> | undefined | null")]
        params: JsValue,
        preset: Option<String>,
    ) -> WasmResult<DescriptorSet> {
        Ok(DescriptorSet {
            set: Collection::new(params_from_js(params, preset)?)?,
        })
    }
    /// Add a descriptor (from `DescribedScan.descriptorJson()`); returns its index.
    #[wasm_bindgen(js_name = addJson)]
    pub fn add_json(&mut self, json: &str) -> WasmResult<usize> {
        let name = format!("scan {}", self.set.len());
        Ok(self.set.push(name, descriptor_from_json(json)?)?)
    }
    /// Add a described scan; returns its index. Refused, naming the scan
    /// and the first parameter that differs, unless it was described with
    /// the set's parameters (the preset's name aside).
    pub fn add(&mut self, scan: &DescribedScan) -> WasmResult<usize> {
        let added =
            self.set
                .push_made_with(scan.name.clone(), scan.descriptor.clone(), &scan.params);
        Ok(added.map_err(|e| e.in_file(&scan.name))?)
    }
    #[wasm_bindgen(getter)]
    /// Number of scans in the set.
    pub fn length(&self) -> usize {
        self.set.len()
    }
    /// The parameters, as a plain object.
    #[wasm_bindgen(unchecked_return_type = "Required<DescriptorParams>")]
    pub fn params(&self) -> WasmResult<JsValue> {
        params_to_js(self.set.params())
    }
    /// Delta between items i and j.
    pub fn delta(&mut self, i: usize, j: usize) -> WasmResult<f32> {
        Ok(self.set.delta(i, j)?)
    }
    /// The full Delta matrix, n x n row-major (computed once, then cached).
    #[wasm_bindgen(js_name = deltaMatrix)]
    pub fn delta_matrix(&mut self) -> WasmResult<js_sys::Float32Array> {
        Ok(js_sys::Float32Array::from(&self.set.matrix()?.data[..]))
    }
    /// Delta from each scan of `rows` to every later one (j > i), row after
    /// row: a share of the matrix for another worker to compute.
    #[wasm_bindgen(js_name = deltaRows)]
    pub fn delta_rows(&mut self, rows: &[u32]) -> WasmResult<js_sys::Float32Array> {
        let rows: Vec<usize> = rows.iter().map(|&i| i as usize).collect();
        Ok(js_sys::Float32Array::from(&self.set.delta_rows(&rows)?[..]))
    }
    /// Use this n x n Delta matrix (row-major, e.g. assembled from
    /// `deltaRows` of an equal set) instead of computing it; refused unless
    /// n x n, zero on the diagonal and symmetric.
    #[wasm_bindgen(js_name = setDeltaMatrix)]
    pub fn set_delta_matrix(&mut self, data: Vec<f32>) -> WasmResult<()> {
        let n = self.set.len();
        Ok(self.set.set_matrix(DistanceMatrix { n, data })?)
    }
    /// k-means: `seeding` is `random`, `stride`, `plusplus` or `spectral`
    /// (each centre starts at the mean of one group of spectral clustering
    /// seeded with `seed`; one run, at most `spectralLimit` scans; for sets
    /// of room scans, not along a route). `restarts`
    /// (optional, default 1: the paper's single run): runs of k-means, the
    /// one of lowest cost kept, the earliest of equals (run r seeded from
    /// stream r of `seed`), a whole number up to 1000; more than 1 needs
    /// `random` or `plusplus`.
    /// Returns `{labels, seeds, iterations, converged, cost, restart}`
    /// (`restart`: the run kept, from 0).
    #[wasm_bindgen(unchecked_return_type = "KMeansResult")]
    pub fn kmeans(
        &mut self,
        k: f64,
        #[wasm_bindgen(unchecked_param_type = "Seeding")] seeding: &str,
        seed: f64,
        restarts: Option<f64>,
    ) -> WasmResult<JsValue> {
        to_js(
            &self
                .set
                .kmeans(&kmeans_params(count("k", k)?, seeding, seed, restarts)?)?,
        )
    }
    /// k-medoids on the Delta matrix. Returns `{labels, medoids}`.
    #[wasm_bindgen(unchecked_return_type = "KMedoidsResult")]
    pub fn kmedoids(&mut self, k: f64, seed: f64) -> WasmResult<JsValue> {
        to_js(
            &self
                .set
                .kmedoids(&KMedoidsParams::new(count("k", k)?).seed(seed_of(seed)?))?,
        )
    }
    /// Spectral clustering on the Delta matrix (Ng, Jordan and Weiss, with
    /// Zelnik-Manor and Perona's local scale): `{labels, eigenvalues, cost,
    /// restart}`. `restarts`: runs of k-means on the embedded scans, the
    /// cheapest kept (10 if left out); `neighbours`: which nearest
    /// neighbour sets a scan's scale (7 if left out). At most 2000 scans.
    #[wasm_bindgen(unchecked_return_type = "SpectralResult")]
    pub fn spectral(
        &mut self,
        k: f64,
        seed: f64,
        restarts: Option<f64>,
        neighbours: Option<f64>,
    ) -> WasmResult<JsValue> {
        let mut params = SpectralParams::new(count("k", k)?).seed(seed_of(seed)?);
        if let Some(r) = restarts {
            params = params.restarts(count("restarts", r)?);
        }
        if let Some(n) = neighbours {
            params = params.neighbours(count("neighbours", n)?);
        }
        to_js(&self.set.spectral(&params)?)
    }
    /// DBSCAN (Delta <= eps are neighbours; minPoints counts the scan itself).
    /// Labels as Int32Array, -1 for noise.
    pub fn dbscan(
        &mut self,
        eps: f32,
        #[wasm_bindgen(js_name = minPoints)] min_points: f64,
    ) -> WasmResult<js_sys::Int32Array> {
        let min_points = count("minPoints", min_points)?;
        let labels = self.set.dbscan(&DbscanParams::new(eps, min_points))?;
        Ok(js_sys::Int32Array::from(&labels[..]))
    }
    /// Epsilons worth sweeping on this set: quantiles 0.5 % to 50 % of the
    /// Delta between two different scans, rounded up to 3 significant
    /// digits, ascending.
    #[wasm_bindgen(js_name = epsilonGrid)]
    pub fn epsilon_grid(&mut self) -> WasmResult<js_sys::Float32Array> {
        Ok(js_sys::Float32Array::from(&self.set.epsilon_grid()?[..]))
    }
    /// DBSCAN at every epsilon x minPoints (paper Fig. 3), epsilon-major:
    /// `[{epsilon, min_points, clusters, inlier_ratio, ari, score}, ...]`.
    /// `truth` (a class name per scan) adds `ari` and `score` (S = ARI x
    /// inliers / all); without it they are `null`.
    #[wasm_bindgen(
        js_name = dbscanSweep,
        unchecked_return_type = "SweepPoint[]"
    )]
    pub fn dbscan_sweep(
        &mut self,
        epsilons: &[f32],
        #[wasm_bindgen(js_name = minPoints)] min_points: &[u32],
        truth: Option<Vec<String>>,
    ) -> WasmResult<JsValue> {
        let cs: Vec<usize> = min_points.iter().map(|&c| c as usize).collect();
        to_js(&self.set.dbscan_sweep(truth.as_deref(), epsilons, &cs)?)
    }
    /// Hierarchical k-means++: the whole tree, to cut at any threshold.
    /// Above `matrixLimit` scans it runs without the n x n matrix (see
    /// `usesMatrix`): heights of nodes over 1500 scans are then an upper
    /// bound of the diameter. `restarts`: 2-means++ trials at every split,
    /// the cheapest kept (default 1, the paper's tree; a whole number up to
    /// 1000).
    pub fn hkmeans(&mut self, seed: f64, restarts: Option<f64>) -> WasmResult<ClusterTree> {
        let params = tree_params(seed, restarts)?;
        Ok(ClusterTree {
            tree: self.set.hkmeans(&params)?,
            params,
        })
    }
    /// How many categories to cut `tree` into, chosen from the data (one
    /// when the scans are all alike): `{k, rule, scores, one_category}`,
    /// `scores` the rule's score for each K tried. See the README.
    #[wasm_bindgen(js_name = chooseCategories, unchecked_return_type = "Choice")]
    pub fn choose_categories(&mut self, tree: &ClusterTree) -> WasmResult<JsValue> {
        let how = choose_k::Clusterer::Tree(&tree.tree, &tree.params);
        to_js(&self.set.choose_categories(how, &Default::default())?)
    }
    /// The gap statistic's reference sets `which` (numbers 0 to
    /// `referenceSets - 1`) of `chooseCategories` for a tree of `seed` (and
    /// `restarts`, as given to `hkmeans`): for
    /// each, log(W*_K / m) at K = 1 to min(10, length), set after set. The
    /// costly part of the choice, and it needs no tree: workers compute it
    /// in shares while the page builds the tree; `chooseCategoriesWith`
    /// takes every set's.
    #[wasm_bindgen(js_name = referenceDispersions)]
    pub fn reference_dispersions(
        &mut self,
        seed: f64,
        which: &[u32],
        restarts: Option<f64>,
    ) -> WasmResult<js_sys::Float64Array> {
        let which: Vec<usize> = which.iter().map(|&b| b as usize).collect();
        let tree = tree_params(seed, restarts)?;
        let how = choose_k::Method::Tree(&tree);
        let sets = self.set.reference_log_w(how, &Default::default(), &which)?;
        Ok(js_sys::Float64Array::from(&sets.concat()[..]))
    }
    /// How many reference sets `chooseCategories` draws (see `referenceDispersions`).
    #[wasm_bindgen(getter, js_name = referenceSets)]
    pub fn reference_sets(&self) -> usize {
        choose_k::ChooseKParams::default().references
    }
    /// `chooseCategories(tree)` with the `referenceDispersions` of every
    /// reference set, in order, one after the other (computed with `seed`
    /// and `restarts`, which must be `tree`'s, by a set of the same
    /// descriptors in the same order, e.g. in workers): the same choice, bit
    /// for bit, without computing them here. Dispersions of another seed or
    /// restarts are an Error: they would give another choice than
    /// `chooseCategories`.
    #[wasm_bindgen(js_name = chooseCategoriesWith, unchecked_return_type = "Choice")]
    pub fn choose_categories_with(
        &mut self,
        tree: &ClusterTree,
        dispersions: &[f64],
        seed: f64,
        restarts: Option<f64>,
    ) -> WasmResult<JsValue> {
        let drawn = tree_params(seed, restarts)?;
        if drawn != tree.params {
            return Err(Error::Mismatch(format!(
                "reference sets drawn for a tree of seed {}, restarts {}; this tree's: \
                 seed {}, restarts {}",
                drawn.seed, drawn.restarts, tree.params.seed, tree.params.restarts
            ))
            .into());
        }
        let params = choose_k::ChooseKParams::default();
        let per_set = params.max_k.min(self.set.len()).max(1);
        let sets: Vec<Vec<f64>> = dispersions.chunks(per_set).map(<[f64]>::to_vec).collect();
        let how = choose_k::Clusterer::Tree(&tree.tree, &tree.params);
        to_js(&self.set.choose_categories_with(how, &params, &sets)?)
    }
    /// How many categories k-means should make of this set (as
    /// `chooseCategories`, for `kmeans(k, seeding, seed, restarts)`: every
    /// K tried is clustered with the same restarts, default 1). Refused
    /// for `"spectral"` seeding, which needs k (docs/spectral-seeding-k-dev.md).
    #[wasm_bindgen(js_name = chooseK, unchecked_return_type = "Choice")]
    pub fn choose_k(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Seeding")] seeding: &str,
        seed: f64,
        restarts: Option<f64>,
    ) -> WasmResult<JsValue> {
        let params = kmeans_params(1, seeding, seed, restarts)?;
        let how = choose_k::Clusterer::KMeans(&params);
        to_js(&self.set.choose_categories(how, &Default::default())?)
    }
    /// True when the set is small enough for the n x n Delta matrix.
    #[wasm_bindgen(getter, js_name = usesMatrix)]
    pub fn uses_matrix(&self) -> bool {
        self.set.uses_matrix()
    }
    /// The largest set for which the Delta matrix is built.
    #[wasm_bindgen(getter, js_name = matrixLimit)]
    pub fn matrix_limit(&self) -> usize {
        MATRIX_LIMIT
    }
    /// The most scans [`spectral`](Self::spectral) takes: its
    /// eigen-decomposition grows with the cube of their number.
    #[wasm_bindgen(getter, js_name = spectralLimit)]
    pub fn spectral_limit(&self) -> usize {
        crate::cluster::spectral::MAX_SCANS
    }
    /// The most central scan of each category: flat pairs
    /// `[label0, index0, label1, index1, ...]` (sampled above 64 members).
    pub fn medoids(&mut self, labels: &[i32]) -> WasmResult<js_sys::Int32Array> {
        let flat: Vec<i32> = (self.set.medoids(labels)?.into_iter())
            .flat_map(|(l, i)| [l, i as i32])
            .collect();
        Ok(js_sys::Int32Array::from(&flat[..]))
    }
    /// Evaluate labels against ground-truth names (array of strings).
    /// Returns `{accuracy, ari, score, inliers, total, confusion}`.
    #[wasm_bindgen(unchecked_return_type = "Evaluation")]
    pub fn evaluate(truth: Vec<String>, labels: &[i32]) -> WasmResult<JsValue> {
        to_js(&crate::eval::evaluate(&truth, labels)?)
    }
    /// A labelled model from cluster labels and names (`{label: name}` object
    /// or `[[label, name], ...]`).
    #[wasm_bindgen(js_name = buildModel)]
    pub fn build_model(
        &self,
        labels: &[i32],
        #[wasm_bindgen(
            unchecked_param_type = "Record<number, string> | [number, string][] | undefined | null"
        )]
        names: JsValue,
    ) -> WasmResult<Model> {
        Ok(Model {
            model: self.set.build_model(labels, &names_from_js(names)?)?,
        })
    }
}

/// The hierarchical k-means++ parameters of a tree of `seed` and
/// `restarts` (1 unless given): the same for the page's tree (`hkmeans`)
/// and for the reference sets of its choice (`referenceDispersions`), which
/// must be built alike. The count's range is checked where the tree is built.
fn tree_params(seed: f64, restarts: Option<f64>) -> crate::Result<HkMeansParams> {
    Ok(HkMeansParams::new(seed_of(seed)?).restarts(runs(restarts)?))
}

/// A count of runs from JS: 1 unless given; a whole number, or an Error
/// (as a `u32` parameter, 2.5 would be taken as 2 and -1 as 4294967295
/// without a word). Its range (1 to 1000) is the core's check.
fn runs(restarts: Option<f64>) -> crate::Result<usize> {
    match restarts.map(whole) {
        None => Ok(1),
        Some(Ok(r)) => Ok(r),
        // {r:?}: 1e300 and NaN print as such, not as 300 digits.
        Some(Err(NotWhole::Fraction(r))) => Err(Error::InvalidParameter(format!(
            "restarts must be a whole number of runs from 1, got {r:?}"
        ))),
        Some(Err(NotWhole::TooLarge(r))) => Err(Error::InvalidParameter(format!(
            "restarts = {r:?} is more than the limit of {} runs",
            crate::cluster::MAX_RESTARTS
        ))),
    }
}

/// Why a JS number is not a count.
enum NotWhole {
    /// A fraction, negative or NaN.
    Fraction(f64),
    /// Above any count the core takes (and above usize on wasm32).
    TooLarge(f64),
}

/// A JS number as a count: a whole number from 0 to u32::MAX.
fn whole(v: f64) -> Result<usize, NotWhole> {
    if v.fract() != 0.0 || v.is_nan() || v < 0.0 {
        Err(NotWhole::Fraction(v))
    } else if v > u32::MAX as f64 {
        Err(NotWhole::TooLarge(v))
    } else {
        Ok(v as usize)
    }
}

/// A count from JS (`k`, `minPoints`): a whole number, or an Error naming
/// it (as a `usize` parameter, 2.5 would be taken as 2 and -1 as
/// 4294967295 without a word). Its range is the core's check.
pub(super) fn count(name: &str, v: f64) -> crate::Result<usize> {
    whole(v).map_err(|e| {
        Error::InvalidParameter(match e {
            NotWhole::Fraction(v) => format!("{name} must be a whole number, got {v:?}"),
            NotWhole::TooLarge(v) => format!("{name} = {v:?} is more than any set holds"),
        })
    })
}

/// The largest whole number a JS number holds exactly (2^53 - 1,
/// `Number.MAX_SAFE_INTEGER`).
const MAX_SAFE_INTEGER: f64 = 9_007_199_254_740_991.0;

/// A seed from JS: a whole number from 0 to `Number.MAX_SAFE_INTEGER`, the
/// CLI's `--seed` for the same number, or an Error (as a `u32` parameter,
/// 2.5 would be taken as 2, -1 as 4294967295 and 2^32 as 0 without a word).
pub(super) fn seed_of(v: f64) -> crate::Result<u64> {
    if v.fract() == 0.0 && (0.0..=MAX_SAFE_INTEGER).contains(&v) {
        Ok(v as u64)
    } else {
        Err(Error::InvalidParameter(format!(
            "seed must be a whole number from 0 to 2^53 - 1, got {v:?}"
        )))
    }
}

/// The k-means parameters of `kmeans` and `chooseK` (restarts: 1 unless given).
fn kmeans_params(
    k: usize,
    seeding: &str,
    seed: f64,
    restarts: Option<f64>,
) -> crate::Result<KMeansParams> {
    Ok(KMeansParams::new(k)
        .seeding(seeding.parse::<Seeding>()?)
        .seed(seed_of(seed)?)
        .restarts(runs(restarts)?))
}
