//! The JavaScript boundary: thin `#[wasm_bindgen]` wrappers over the core.
//! Every fallible call returns `Result<_, JsError>`, so errors arrive in JS
//! as `Error` objects with the core's message; large arrays leave as typed
//! arrays; small records as plain objects (serde-wasm-bindgen). Seeds are
//! u32 here (a plain JS number; u64 would demand a BigInt).

use crate::cluster::hkmeans::HkMeansParams;
use crate::cluster::{
    self, Dbscan, DbscanParams, HierarchicalKMeans, KMeans, KMeansParams, KMedoids, Seeding, Space,
};
use crate::descriptor::{Descriptor, DescriptorParams};
use crate::distance::{DistanceMatrix, DistanceOptions};
use crate::io::{self, write, ReadLimits};
use crate::model::LabelledModel;
use crate::sim;
use crate::Error;
use serde::Serialize;
use wasm_bindgen::prelude::*;

type WasmResult<T> = std::result::Result<T, JsError>;

fn js_err(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

/// Plain objects (maps become objects, not `Map`s).
fn to_js<T: Serialize + ?Sized>(v: &T) -> WasmResult<JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("cannot convert to JS: {e}")))
}

fn from_js<T: serde::de::DeserializeOwned>(v: JsValue, what: &str) -> WasmResult<T> {
    serde_wasm_bindgen::from_value(v).map_err(|e| JsError::new(&format!("{what}: {e}")))
}

#[wasm_bindgen(typescript_custom_section)]
const TS_NAMES: &'static str = r#"
/** A parameter preset (paper Tab. II: indoor, outdoor; DESIGN Sec. 2b: indoor_bands; the public C++ code's settings: perception_oru). */
export type Preset = "indoor" | "outdoor" | "indoor_bands" | "perception_oru";
/** k-means seeding: random scans, stride ("deterministic": scan i*n/k), or k-means++. */
export type Seeding = "random" | "stride" | "deterministic" | "plusplus";
/** One simulated scan: its file name, true kind, pose and binary PLY bytes. */
export interface SimulatedScan {
    name: string;
    label: string;
    pose: Pose;
    bytes: Uint8Array;
}
"#;

/// What `kmedoids` returns.
#[derive(Serialize, tsify::Tsify)]
pub struct KMedoidsResult {
    /// Category of each scan.
    labels: Vec<i32>,
    /// The scan at the centre of each category.
    medoids: Vec<usize>,
}

/// A category of a model, without its centre.
#[derive(Serialize, tsify::Tsify)]
pub struct CategorySummary {
    name: String,
    /// The cluster label it came from.
    label: i32,
    /// Scans it was made from.
    members: usize,
    /// Largest Delta from its centre to a member.
    radius: f32,
}

#[wasm_bindgen(start)]
fn start() {
    console_error_panic_hook::set_once();
}

/// The crate version.
#[wasm_bindgen(js_name = version)]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// Descriptor parameters of a preset (`indoor`, `outdoor`, `indoor_bands`,
/// `perception_oru`) as a plain object whose fields can be changed.
#[wasm_bindgen(js_name = presetParams, unchecked_return_type = "Required<DescriptorParams>")]
pub fn preset_params(
    #[wasm_bindgen(unchecked_param_type = "Preset")] name: &str,
) -> WasmResult<JsValue> {
    to_js(&DescriptorParams::preset(name).map_err(js_err)?)
}

/// Parameters from a (possibly partial) object: missing fields take the
/// values of `preset` (default `indoor`). Throws on unknown fields and
/// invalid values; returns the complete, validated parameters.
#[wasm_bindgen(js_name = validateParams, unchecked_return_type = "Required<DescriptorParams>")]
pub fn validate_params(
    #[wasm_bindgen(unchecked_param_type = "Partial<DescriptorParams> | undefined | null")]
    params: JsValue,
    preset: Option<String>,
) -> WasmResult<JsValue> {
    to_js(&params_from_js(params, preset.as_deref())?)
}

fn params_from_js(params: JsValue, preset: Option<&str>) -> WasmResult<DescriptorParams> {
    let base = DescriptorParams::preset(preset.unwrap_or("indoor")).map_err(js_err)?;
    if params.is_undefined() || params.is_null() {
        return Ok(base);
    }
    let over: serde_json::Value = from_js(params, "parameters")?;
    let mut merged = serde_json::to_value(&base).map_err(|e| js_err(e.into()))?;
    let Some(obj) = over.as_object() else {
        return Err(JsError::new(
            "invalid parameter: parameters must be an object",
        ));
    };
    for (k, v) in obj {
        merged[k] = v.clone();
    }
    let p: DescriptorParams = serde_json::from_value(merged)
        .map_err(|e| JsError::new(&format!("invalid parameter: {e}")))?;
    p.validate().map_err(js_err)?;
    Ok(p)
}

/// A scan's points as read from a file.
#[wasm_bindgen]
pub struct Scan {
    format: &'static str,
    points: Vec<f32>,
}

#[wasm_bindgen]
impl Scan {
    /// Format name, e.g. `ply_binary_little_endian`.
    #[wasm_bindgen(getter)]
    pub fn format(&self) -> String {
        self.format.to_string()
    }
    /// Number of points (non-finite included).
    #[wasm_bindgen(getter)]
    pub fn count(&self) -> usize {
        self.points.len() / 3
    }
    /// Interleaved x, y, z (a copy).
    #[wasm_bindgen(js_name = positions)]
    pub fn positions(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.points[..])
    }
}

/// Read a scan's bytes (PLY, PCD sniffed from the bytes; `.bin` from the
/// name). Throws an Error naming the file when the bytes are bad.
#[wasm_bindgen(js_name = readScan)]
pub fn read_scan(bytes: &[u8], name: &str) -> WasmResult<Scan> {
    let c = io::read_scan_named(bytes, name, &ReadLimits::default()).map_err(js_err)?;
    Ok(Scan {
        format: c.format.name(),
        points: c.points.into_iter().flatten().collect(),
    })
}

/// A described scan: its descriptor, a summary, and a decimated preview.
#[wasm_bindgen]
pub struct DescribedScan {
    name: String,
    format: &'static str,
    descriptor: Descriptor,
    preview: Vec<f32>,
}

#[wasm_bindgen]
impl DescribedScan {
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.name.clone()
    }
    #[wasm_bindgen(getter)]
    pub fn format(&self) -> String {
        self.format.to_string()
    }
    /// `{points, dropped, voxels, sparse_voxels, spherical, planar, linear, in_range, alignments, unreliable}`.
    #[wasm_bindgen(unchecked_return_type = "Summary")]
    pub fn summary(&self) -> WasmResult<JsValue> {
        to_js(&self.descriptor.summary)
    }
    /// Decimated finite points, interleaved x, y, z (sensor frame).
    pub fn preview(&self) -> js_sys::Float32Array {
        js_sys::Float32Array::from(&self.preview[..])
    }
    /// The descriptor as JSON text (to pass between workers or store).
    #[wasm_bindgen(js_name = descriptorJson)]
    pub fn descriptor_json(&self) -> WasmResult<String> {
        serde_json::to_string(&self.descriptor).map_err(|e| js_err(e.into()))
    }
}

/// Read and describe a scan in one call. `params` is a (partial) parameter
/// object or undefined; `previewPoints` caps the preview (e.g. 4000).
#[wasm_bindgen(js_name = describeScan)]
pub fn describe_scan(
    bytes: &[u8],
    name: &str,
    #[wasm_bindgen(unchecked_param_type = "Partial<DescriptorParams> | undefined | null")]
    params: JsValue,
    preset: Option<String>,
    #[wasm_bindgen(js_name = previewPoints)] preview_points: Option<usize>,
) -> WasmResult<DescribedScan> {
    let p = params_from_js(params, preset.as_deref())?;
    let c = io::read_scan_named(bytes, name, &ReadLimits::default()).map_err(js_err)?;
    let descriptor = crate::describe(&c.points, &p).map_err(|e| js_err(e.in_file(name)))?;
    Ok(DescribedScan {
        name: name.to_string(),
        format: c.format.name(),
        preview: crate::cloud::decimate(&c.points, preview_points.unwrap_or(4000)),
        descriptor,
    })
}

/// Many descriptors made with the same parameters: distances, clustering,
/// evaluation and models.
#[wasm_bindgen]
pub struct DescriptorSet {
    params: DescriptorParams,
    descriptors: Vec<Descriptor>,
    /// Prepared once per content (each add clears it), with its matrix:
    /// the page re-cuts and re-computes medoids on every threshold drag.
    space: Option<Space>,
    matrix: Option<DistanceMatrix>,
}

/// Above this many scans the n x n Delta matrix is not built (it would take
/// n^2 * 4 bytes): hierarchical k-means++ and k-means take their
/// centre-based paths, DBSCAN and k-medoids are refused.
pub const MATRIX_LIMIT: usize = 5000;

impl DescriptorSet {
    fn opts(&self) -> DistanceOptions {
        DistanceOptions::from(&self.params)
    }
    /// The prepared space, and the Delta matrix when `with_matrix`, each
    /// computed once and kept until the set changes.
    fn prepared(&mut self, with_matrix: bool) -> WasmResult<(&Space, Option<&DistanceMatrix>)> {
        if with_matrix && self.descriptors.len() > MATRIX_LIMIT {
            return Err(JsError::new(&format!(
                "invalid parameter: this needs the n x n Delta matrix, and {} scans are more than the {MATRIX_LIMIT} it is built for; use k-means or hierarchical k-means++",
                self.descriptors.len()
            )));
        }
        if self.space.is_none() {
            self.space = Some(Space::new(&self.descriptors, self.opts()).map_err(js_err)?);
        }
        let space = self.space.as_ref().expect("just prepared");
        if with_matrix && self.matrix.is_none() {
            self.matrix = Some(space.matrix());
        }
        Ok((
            space,
            if with_matrix {
                self.matrix.as_ref()
            } else {
                None
            },
        ))
    }
    fn space(&mut self) -> WasmResult<&Space> {
        Ok(self.prepared(false)?.0)
    }
    fn matrix(&mut self) -> WasmResult<&DistanceMatrix> {
        Ok(self.prepared(true)?.1.expect("asked for the matrix"))
    }
    /// Add a descriptor after checking it fits the set's parameters.
    fn push(&mut self, d: Descriptor) -> WasmResult<usize> {
        d.validate_for(&self.params).map_err(js_err)?;
        self.descriptors.push(d);
        self.space = None;
        self.matrix = None;
        Ok(self.descriptors.len() - 1)
    }
    fn check_nonempty(&self) -> WasmResult<()> {
        if self.descriptors.is_empty() {
            return Err(JsError::new(
                "invalid parameter: the set has no descriptors",
            ));
        }
        Ok(())
    }
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
            params: params_from_js(params, preset.as_deref())?,
            descriptors: Vec::new(),
            space: None,
            matrix: None,
        })
    }
    /// Add a descriptor (from `DescribedScan.descriptorJson()`); returns its index.
    #[wasm_bindgen(js_name = addJson)]
    pub fn add_json(&mut self, json: &str) -> WasmResult<usize> {
        let d: Descriptor = serde_json::from_str(json)
            .map_err(|e| JsError::new(&format!("descriptor JSON: {e}")))?;
        self.push(d)
    }
    /// Add a described scan; returns its index.
    pub fn add(&mut self, scan: &DescribedScan) -> WasmResult<usize> {
        self.push(scan.descriptor.clone())
    }
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.descriptors.len()
    }
    /// The parameters, as a plain object.
    #[wasm_bindgen(unchecked_return_type = "Required<DescriptorParams>")]
    pub fn params(&self) -> WasmResult<JsValue> {
        to_js(&self.params)
    }
    /// Delta between items i and j.
    pub fn delta(&mut self, i: usize, j: usize) -> WasmResult<f32> {
        let n = self.descriptors.len();
        if i >= n || j >= n {
            return Err(JsError::new(&format!(
                "invalid parameter: index out of range (set has {n})"
            )));
        }
        Ok(self.space()?.delta(i, j))
    }
    /// The full Delta matrix, n x n row-major (computed once, then cached).
    #[wasm_bindgen(js_name = deltaMatrix)]
    pub fn delta_matrix(&mut self) -> WasmResult<js_sys::Float32Array> {
        Ok(js_sys::Float32Array::from(&self.matrix()?.data[..]))
    }
    /// k-means: `seeding` is `random`, `stride` or `plusplus`. Returns
    /// `{labels, seeds, iterations, converged, cost}`.
    #[wasm_bindgen(unchecked_return_type = "KMeansResult")]
    pub fn kmeans(
        &mut self,
        k: usize,
        #[wasm_bindgen(unchecked_param_type = "Seeding")] seeding: &str,
        seed: u32,
    ) -> WasmResult<JsValue> {
        self.check_nonempty()?;
        let s: Seeding = seeding.parse().map_err(js_err)?;
        let r = KMeans::fit(
            self.space()?,
            &KMeansParams::new(k).seeding(s).seed(seed.into()),
        )
        .map_err(js_err)?;
        to_js(&r)
    }
    /// k-medoids on the Delta matrix. Returns `{labels, medoids}`.
    #[wasm_bindgen(unchecked_return_type = "KMedoidsResult")]
    pub fn kmedoids(&mut self, k: usize, seed: u32) -> WasmResult<JsValue> {
        self.check_nonempty()?;
        let (space, m) = self.prepared(true)?;
        let m = m.expect("asked for the matrix");
        let (labels, medoids) = KMedoids::fit(space, m, k, seed.into(), 100).map_err(js_err)?;
        to_js(&KMedoidsResult { labels, medoids })
    }
    /// DBSCAN (Delta <= eps are neighbours; minPoints counts the scan itself).
    /// Labels as Int32Array, -1 for noise.
    pub fn dbscan(
        &mut self,
        eps: f32,
        #[wasm_bindgen(js_name = minPoints)] min_points: usize,
    ) -> WasmResult<js_sys::Int32Array> {
        let m = self.matrix()?;
        let labels = Dbscan::fit(m, &DbscanParams::new(eps, min_points)).map_err(js_err)?;
        Ok(js_sys::Int32Array::from(&labels[..]))
    }
    /// Epsilons worth sweeping on this set: quantiles 0.5 % to 50 % of the
    /// Delta between two different scans, rounded up to 3 significant
    /// digits, ascending.
    #[wasm_bindgen(js_name = epsilonGrid)]
    pub fn epsilon_grid(&mut self) -> WasmResult<js_sys::Float32Array> {
        let grid = crate::eval::epsilon_grid(self.matrix()?);
        Ok(js_sys::Float32Array::from(&grid[..]))
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
        let m = self.matrix()?;
        let sweep =
            crate::eval::dbscan_sweep(m, truth.as_deref(), epsilons, &cs).map_err(js_err)?;
        to_js(&sweep)
    }
    /// Hierarchical k-means++: the whole tree, to cut at any threshold.
    /// Above `matrixLimit` scans it runs without the n x n matrix (see
    /// `usesMatrix`): heights of nodes over 1500 scans are then an upper
    /// bound of the diameter.
    pub fn hkmeans(&mut self, seed: u32) -> WasmResult<ClusterTree> {
        self.check_nonempty()?;
        let params = HkMeansParams::new(seed.into());
        let with_matrix = self.uses_matrix();
        let tree = match self.prepared(with_matrix)? {
            (space, Some(m)) => HierarchicalKMeans::fit(space, m, &params),
            (space, None) => HierarchicalKMeans::fit_without_matrix(space, &params),
        };
        Ok(ClusterTree {
            tree: tree.map_err(js_err)?,
        })
    }
    /// True when the set is small enough for the n x n Delta matrix.
    #[wasm_bindgen(getter, js_name = usesMatrix)]
    pub fn uses_matrix(&self) -> bool {
        self.descriptors.len() <= MATRIX_LIMIT
    }
    /// The largest set for which the Delta matrix is built.
    #[wasm_bindgen(getter, js_name = matrixLimit)]
    pub fn matrix_limit(&self) -> usize {
        MATRIX_LIMIT
    }
    /// The most central scan of each category: flat pairs
    /// `[label0, index0, label1, index1, ...]` (sampled above 64 members).
    pub fn medoids(&mut self, labels: &[i32]) -> WasmResult<js_sys::Int32Array> {
        if labels.len() != self.descriptors.len() {
            return Err(JsError::new(&format!(
                "mismatch: {} labels for {} scans",
                labels.len(),
                self.descriptors.len()
            )));
        }
        let flat: Vec<i32> = cluster::medoids(self.space()?, labels, 64, 0)
            .into_iter()
            .flat_map(|(l, i)| [l, i as i32])
            .collect();
        Ok(js_sys::Int32Array::from(&flat[..]))
    }
    /// Evaluate labels against ground-truth names (array of strings).
    /// Returns `{accuracy, ari, score, inliers, total, confusion}`.
    #[wasm_bindgen(unchecked_return_type = "Evaluation")]
    pub fn evaluate(truth: Vec<String>, labels: &[i32]) -> WasmResult<JsValue> {
        to_js(&crate::eval::evaluate(&truth, labels).map_err(js_err)?)
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
        let names = names_from_js(names)?;
        Ok(Model {
            model: LabelledModel::build(&self.params, &self.descriptors, labels, &names)
                .map_err(js_err)?,
        })
    }
}

fn names_from_js(names: JsValue) -> WasmResult<Vec<(i32, String)>> {
    if names.is_undefined() || names.is_null() {
        return Ok(Vec::new());
    }
    let v: serde_json::Value = from_js(names, "names")?;
    let mut out = Vec::new();
    match v {
        serde_json::Value::Object(map) => {
            for (k, n) in map {
                let l: i32 = k
                    .parse()
                    .map_err(|_| JsError::new(&format!("names: {k:?} is not a label number")))?;
                out.push((l, n.as_str().unwrap_or_default().to_string()));
            }
        }
        serde_json::Value::Array(rows) => {
            for r in rows {
                let (Some(l), Some(n)) = (
                    r.get(0).and_then(|v| v.as_i64()),
                    r.get(1).and_then(|v| v.as_str()),
                ) else {
                    return Err(JsError::new("names: expected [[label, name], ...]"));
                };
                out.push((l as i32, n.to_string()));
            }
        }
        _ => {
            return Err(JsError::new(
                "names: expected an object {label: name} or [[label, name], ...]",
            ))
        }
    }
    Ok(out)
}

/// The hierarchical k-means++ tree.
#[wasm_bindgen]
pub struct ClusterTree {
    tree: cluster::Tree,
}

#[wasm_bindgen]
impl ClusterTree {
    /// Categories at threshold t: `{threshold, labels, nodes}`.
    #[wasm_bindgen(unchecked_return_type = "Cut")]
    pub fn cut(&self, threshold: f32) -> WasmResult<JsValue> {
        to_js(&self.tree.cut(threshold).map_err(js_err)?)
    }
    /// The cut giving k categories: the tree's k - 1 highest splits (of two
    /// splits at one height, the parent's first, which no threshold can
    /// separate). Fewer only when the tree has fewer than k leaves.
    #[wasm_bindgen(js_name = cutK, unchecked_return_type = "Cut")]
    pub fn cut_k(&self, k: usize) -> WasmResult<JsValue> {
        to_js(&self.tree.cut_k(k).map_err(js_err)?)
    }
    /// Number of categories at threshold t; throws for a threshold that
    /// is not a finite number >= 0, as `cut` does.
    #[wasm_bindgen(js_name = countAt)]
    pub fn count_at(&self, threshold: f32) -> WasmResult<usize> {
        self.tree.count_at(threshold).map_err(js_err)
    }
    /// scipy-style linkage, (n-1) x 4 row-major: a, b, height, count.
    pub fn linkage(&self) -> js_sys::Float64Array {
        let flat: Vec<f64> = self.tree.linkage().into_iter().flatten().collect();
        js_sys::Float64Array::from(&flat[..])
    }
    /// Nodes: `[{members, height, children, parent}]`, node 0 the root.
    #[wasm_bindgen(unchecked_return_type = "TreeNode[]")]
    pub fn nodes(&self) -> WasmResult<JsValue> {
        to_js(&self.tree.nodes)
    }
    /// Height of the root (the largest Delta in the set).
    #[wasm_bindgen(js_name = rootHeight)]
    pub fn root_height(&self) -> f32 {
        self.tree.nodes[0].height
    }
}

/// A labelled model: names for categories, and centres to classify new scans.
#[wasm_bindgen]
pub struct Model {
    model: LabelledModel,
}

#[wasm_bindgen]
impl Model {
    /// Load a model saved by `toJson()`; throws on malformed input.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> WasmResult<Model> {
        Ok(Model {
            model: LabelledModel::from_json(text)
                .map_err(|e| JsError::new(&format!("model: {e}")))?,
        })
    }
    #[wasm_bindgen(js_name = toJson)]
    pub fn to_json(&self) -> WasmResult<String> {
        self.model.to_json().map_err(js_err)
    }
    /// `[{name, label, members, radius}]`.
    #[wasm_bindgen(unchecked_return_type = "CategorySummary[]")]
    pub fn categories(&self) -> WasmResult<JsValue> {
        let c: Vec<CategorySummary> = self
            .model
            .categories
            .iter()
            .map(|c| CategorySummary {
                name: c.name.clone(),
                label: c.label,
                members: c.members,
                radius: c.radius,
            })
            .collect();
        to_js(&c)
    }
    /// Rename: `{label: name}` or `[[label, name], ...]`.
    pub fn rename(
        &mut self,
        #[wasm_bindgen(
            unchecked_param_type = "Record<number, string> | [number, string][] | undefined | null"
        )]
        names: JsValue,
    ) -> WasmResult<()> {
        self.model.rename(&names_from_js(names)?);
        Ok(())
    }
    /// The model's descriptor parameters (describe new scans with these).
    #[wasm_bindgen(unchecked_return_type = "Required<DescriptorParams>")]
    pub fn params(&self) -> WasmResult<JsValue> {
        to_js(&self.model.params)
    }
    /// Classify a described scan: `{name, label, distance, relative}`
    /// (`relative` = distance / the category's radius; > 1: farther than
    /// any scan it was made from; `Infinity` for a one-scan category and
    /// any other scan).
    #[wasm_bindgen(unchecked_return_type = "Classification")]
    pub fn classify(&self, scan: &DescribedScan) -> WasmResult<JsValue> {
        to_js(&self.model.classify(&scan.descriptor).map_err(js_err)?)
    }
    /// Classify a descriptor given as JSON text.
    #[wasm_bindgen(js_name = classifyJson, unchecked_return_type = "Classification")]
    pub fn classify_json(&self, json: &str) -> WasmResult<JsValue> {
        let d: Descriptor = serde_json::from_str(json)
            .map_err(|e| JsError::new(&format!("descriptor JSON: {e}")))?;
        to_js(&self.model.classify(&d).map_err(js_err)?)
    }
}

/// Parse a poses file (KITTI, TUM or CSV): `{format, poses: [{name, time, position, yaw}]}`.
#[wasm_bindgen(js_name = parsePoses, unchecked_return_type = "Poses")]
pub fn parse_poses(
    text: &str,
    #[wasm_bindgen(js_name = fileName)] file_name: Option<String>,
) -> WasmResult<JsValue> {
    let p = io::poses::parse(text)
        .map_err(|e| js_err(e.in_file(file_name.unwrap_or_else(|| "poses".into()))))?;
    to_js(&p)
}

/// A simulated data set; scans are made one at a time.
#[wasm_bindgen]
pub struct Simulator {
    sim: sim::Simulation,
}

#[wasm_bindgen]
impl Simulator {
    /// `scene`: `indoor`, `warehouse` or `outdoor`; `scans`: per kind for
    /// indoor, along the path otherwise; `buildings` (indoor): `one` (the
    /// default: rooms of a kind share a plan) or `many`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "\"indoor\" | \"warehouse\" | \"outdoor\"")]
        scene: &str,
        seed: u32,
        scans: Option<usize>,
        buildings: Option<String>,
    ) -> WasmResult<Simulator> {
        let kind: sim::SceneKind = scene.parse().map_err(js_err)?;
        let mut p = sim::SimParams::new(kind, seed.into());
        if let Some(n) = scans {
            p.scans = n;
        }
        if let Some(b) = buildings {
            p.buildings = b.parse().map_err(js_err)?;
        }
        Ok(Simulator {
            sim: sim::Simulation::new(&p).map_err(js_err)?,
        })
    }
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.sim.len()
    }
    /// Scan i as binary PLY bytes plus `{name, label, pose}`:
    /// returns `{name, label, pose, bytes}`.
    #[wasm_bindgen(unchecked_return_type = "SimulatedScan")]
    pub fn scan(&self, i: usize) -> WasmResult<JsValue> {
        if i >= self.sim.len() {
            return Err(JsError::new(&format!(
                "invalid parameter: scan {i} of {}",
                self.sim.len()
            )));
        }
        let s = self.sim.scan(i);
        let obj = js_sys::Object::new();
        let set = |k: &str, v: JsValue| {
            js_sys::Reflect::set(&obj, &k.into(), &v)
                .map(|_| ())
                .map_err(|_| JsError::new("cannot build object"))
        };
        set("name", s.name.clone().into())?;
        set("label", s.label.clone().into())?;
        set("pose", to_js(&s.pose)?)?;
        let bytes = write::ply(&s.points, write::PlyEncoding::BinaryLittleEndian, false);
        set("bytes", js_sys::Uint8Array::from(&bytes[..]).into())?;
        Ok(obj.into())
    }
}
