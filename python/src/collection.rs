//! The Collection class (the core's [`Collection`]: descriptors of one
//! parameter set, the prepared space and the Delta matrix kept between
//! calls) and the hierarchical k-means++ Tree. Results are dicts with the
//! keys of the CLI's `cluster` OUT.json, labels as int32 arrays.

use crate::convert::{core_err, to_py};
use crate::descriptor::PyDescriptor;
use crate::model::PyModel;
use crate::PlacecatError;
use numpy::{AllowTypeChange, PyArray1, PyArrayLike1, PyArrayMethods};
use placecat::cluster::choose_k::{ChooseKParams, Clusterer};
use placecat::cluster::hkmeans::{Cut, HkMeansParams};
use placecat::cluster::{
    DbscanParams, KMeansParams, KMedoidsParams, Seeding, SpectralParams, Tree,
};
use placecat::collection::category_names;
use placecat::{Collection, DescriptorParams};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// Labels as an int32 array.
fn labels_array<'py>(py: Python<'py>, labels: Vec<i32>) -> Bound<'py, PyAny> {
    PyArray1::from_vec(py, labels).into_any()
}

/// Labels from any integer array or sequence.
fn labels_vec(labels: PyArrayLike1<'_, i32, AllowTypeChange>) -> Vec<i32> {
    labels.as_array().to_vec()
}

/// A number of categories: an int, or "auto" (chosen from the data).
fn count(k: &Bound<'_, PyAny>) -> PyResult<Option<usize>> {
    if k.is_instance_of::<PyString>() && k.extract::<String>()? == "auto" {
        return Ok(None);
    }
    k.extract::<usize>().map(Some).map_err(|_| {
        PlacecatError::new_err(format!(
            "invalid parameter: expected a whole number of categories or \"auto\", got {k}"
        ))
    })
}

/// Descriptors of one parameter set and the clustering calls on them.
/// `Collection(descriptors, names=None)`: the parameters are the
/// descriptors' (all must have been made with the same ones; `params` for
/// an empty collection); names default to "0", "1", ...
#[pyclass(module = "placecat", name = "Collection")]
pub struct PyCollection {
    inner: Collection,
}

#[pymethods]
impl PyCollection {
    #[new]
    #[pyo3(signature = (descriptors, names=None, params=None))]
    fn new(
        descriptors: Vec<PyRef<'_, PyDescriptor>>,
        names: Option<Vec<String>>,
        params: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyCollection> {
        let params: DescriptorParams = match (descriptors.first(), params) {
            (Some(d), _) => d.params.clone(),
            (None, p) => crate::convert::params_from_py(p)?,
        };
        let names =
            names.unwrap_or_else(|| (0..descriptors.len()).map(|i| i.to_string()).collect());
        if names.len() != descriptors.len() {
            return Err(core_err(placecat::Error::Mismatch(format!(
                "{} names for {} descriptors",
                names.len(),
                descriptors.len()
            ))));
        }
        let mut inner = Collection::new(params).map_err(core_err)?;
        for (name, d) in names.into_iter().zip(&descriptors) {
            add(&mut inner, name, d)?;
        }
        Ok(PyCollection { inner })
    }

    /// Add a descriptor made with the collection's parameters; its index.
    #[pyo3(signature = (descriptor, name=None))]
    fn add(
        &mut self,
        descriptor: PyRef<'_, PyDescriptor>,
        name: Option<String>,
    ) -> PyResult<usize> {
        let name = name.unwrap_or_else(|| self.inner.len().to_string());
        add(&mut self.inner, name, &descriptor)
    }

    fn __len__(&self) -> usize {
        self.inner.len()
    }

    /// The scans' names, in order.
    #[getter]
    fn names(&self) -> Vec<String> {
        self.inner.names().to_vec()
    }

    /// The descriptor parameters (a dict).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, self.inner.params())
    }

    /// The descriptors, in order.
    #[getter]
    fn descriptors(&self) -> Vec<PyDescriptor> {
        let params = self.inner.params();
        self.inner
            .descriptors()
            .iter()
            .map(|d| PyDescriptor {
                params: params.clone(),
                descriptor: d.clone(),
            })
            .collect()
    }

    /// Delta between scans i and j.
    fn delta(&mut self, py: Python<'_>, i: usize, j: usize) -> PyResult<f32> {
        let inner = &mut self.inner;
        py.detach(|| inner.delta(i, j)).map_err(core_err)
    }

    /// The n x n Delta matrix as float32 (computed once, GIL released);
    /// refused above MATRIX_LIMIT scans.
    fn delta_matrix<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let inner = &mut self.inner;
        let data = py
            .detach(|| inner.matrix().map(|m| m.data.clone()))
            .map_err(core_err)?;
        let n = self.inner.len();
        Ok(PyArray1::from_vec(py, data).reshape([n, n])?.into_any())
    }

    /// k-means: k an int or "auto" (chosen as the CLI chooses it; the
    /// choice is under "choice"). `restarts`: runs of k-means, the one of
    /// lowest cost kept (1: the paper's single run; at most 1000; more
    /// than 1 needs random or plusplus seeding). `seeding`: plusplus,
    /// random, stride or spectral (each centre the mean of one group of
    /// spectral clustering; at most 2000 scans; k must be given). A dict: labels, k, categories, seeding, seed,
    /// iterations, converged, cost, restarts, restart (the run kept).
    #[pyo3(signature = (k=None, seeding="plusplus", seed=0, restarts=1))]
    fn kmeans<'py>(
        &mut self,
        py: Python<'py>,
        k: Option<&Bound<'py, PyAny>>,
        seeding: &str,
        seed: u64,
        restarts: usize,
    ) -> PyResult<Bound<'py, PyDict>> {
        let seeding: Seeding = seeding.parse().map_err(core_err)?;
        let asked = match k {
            Some(k) => count(k)?,
            None => None,
        };
        let params = |k| {
            KMeansParams::new(k)
                .seeding(seeding)
                .seed(seed)
                .restarts(restarts)
        };
        let inner = &mut self.inner;
        let (r, k, choice) = py
            .detach(|| {
                let (k, choice) = match asked {
                    Some(k) => (k, None),
                    None => {
                        let c = inner.choose_categories(
                            Clusterer::KMeans(&params(1)),
                            &ChooseKParams::default(),
                        )?;
                        (c.k, Some(c))
                    }
                };
                Ok::<_, placecat::Error>((inner.kmeans(&params(k))?, k, choice))
            })
            .map_err(core_err)?;
        let out = PyDict::new(py);
        out.set_item("labels", labels_array(py, r.labels))?;
        out.set_item("k", k)?;
        out.set_item("categories", k)?;
        out.set_item("seeding", to_py(py, &seeding)?)?;
        out.set_item("seed", seed)?;
        out.set_item("iterations", r.iterations)?;
        out.set_item("converged", r.converged)?;
        out.set_item("cost", r.cost)?;
        out.set_item("restarts", restarts)?;
        out.set_item("restart", r.restart)?;
        if let Some(c) = choice {
            out.set_item("choice", to_py(py, &c)?)?;
        }
        Ok(out)
    }

    /// k-medoids on the Delta matrix: a dict of labels and medoids (indices).
    #[pyo3(signature = (k, seed=0))]
    fn kmedoids<'py>(
        &mut self,
        py: Python<'py>,
        k: usize,
        seed: u64,
    ) -> PyResult<Bound<'py, PyDict>> {
        let inner = &mut self.inner;
        let r = py
            .detach(|| inner.kmedoids(&KMedoidsParams::new(k).seed(seed)))
            .map_err(core_err)?;
        let out = PyDict::new(py);
        out.set_item("labels", labels_array(py, r.labels))?;
        out.set_item("medoids", r.medoids)?;
        Ok(out)
    }

    /// Spectral clustering on the Delta matrix (Ng, Jordan and Weiss, with
    /// Zelnik-Manor and Perona's local scale; at most 2000 scans): a dict
    /// of labels, eigenvalues (the k leading), cost and restart.
    /// `restarts`: runs of k-means on the embedded scans, the cheapest
    /// kept; `neighbours`: which nearest neighbour sets a scan's scale.
    #[pyo3(signature = (k, seed=0, restarts=10, neighbours=7))]
    fn spectral<'py>(
        &mut self,
        py: Python<'py>,
        k: usize,
        seed: u64,
        restarts: usize,
        neighbours: usize,
    ) -> PyResult<Bound<'py, PyDict>> {
        let inner = &mut self.inner;
        let params = SpectralParams::new(k)
            .seed(seed)
            .restarts(restarts)
            .neighbours(neighbours);
        let r = py.detach(|| inner.spectral(&params)).map_err(core_err)?;
        let out = PyDict::new(py);
        out.set_item("labels", labels_array(py, r.labels))?;
        out.set_item("k", k)?;
        out.set_item("categories", k)?;
        out.set_item("seed", seed)?;
        out.set_item("neighbours", neighbours)?;
        out.set_item("restarts", restarts)?;
        out.set_item("restart", r.restart)?;
        out.set_item("eigenvalues", r.eigenvalues)?;
        out.set_item("cost", r.cost)?;
        Ok(out)
    }

    /// Hierarchical k-means++: the whole tree (built without the n x n
    /// matrix above MATRIX_LIMIT scans), to cut anywhere. `restarts`:
    /// 2-means++ trials at every split, the cheapest kept (1: the paper's
    /// tree; at most 1000).
    #[pyo3(signature = (seed=0, restarts=1))]
    fn hkmeans(&mut self, py: Python<'_>, seed: u64, restarts: usize) -> PyResult<PyTree> {
        let inner = &mut self.inner;
        let params = HkMeansParams::new(seed).restarts(restarts);
        let tree = py.detach(|| inner.hkmeans(&params)).map_err(core_err)?;
        Ok(PyTree { tree, params })
    }

    /// How many categories the scans hold, by the CLI's default rule: for
    /// `tree`'s cuts when given, else for k-means (`seeding`, `seed`;
    /// refused for spectral seeding, which needs k). A dict: k, rule,
    /// scores [(K, score)], one_category.
    #[pyo3(signature = (tree=None, seeding="plusplus", seed=0))]
    fn choose_categories<'py>(
        &mut self,
        py: Python<'py>,
        tree: Option<PyRef<'py, PyTree>>,
        seeding: &str,
        seed: u64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let seeding: Seeding = seeding.parse().map_err(core_err)?;
        let km = KMeansParams::new(1).seeding(seeding).seed(seed);
        let hk = tree
            .as_ref()
            .map_or_else(|| HkMeansParams::new(seed), |t| t.params.clone());
        let tree = tree.as_ref().map(|t| &t.tree);
        let inner = &mut self.inner;
        let choice = py
            .detach(|| {
                let clusterer = match tree {
                    Some(t) => Clusterer::Tree(t, &hk),
                    None => Clusterer::KMeans(&km),
                };
                inner.choose_categories(clusterer, &ChooseKParams::default())
            })
            .map_err(core_err)?;
        to_py(py, &choice)
    }

    /// DBSCAN on the Delta matrix: labels, -1 for noise.
    fn dbscan<'py>(
        &mut self,
        py: Python<'py>,
        eps: f32,
        min_points: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let inner = &mut self.inner;
        let labels = py
            .detach(|| inner.dbscan(&DbscanParams::new(eps, min_points)))
            .map_err(core_err)?;
        Ok(labels_array(py, labels))
    }

    /// The most central scan of each category: a list of (label, index).
    fn medoids(
        &mut self,
        labels: PyArrayLike1<'_, i32, AllowTypeChange>,
    ) -> PyResult<Vec<(i32, usize)>> {
        self.inner.medoids(&labels_vec(labels)).map_err(core_err)
    }

    /// Compare labels with ground truth (see `placecat.evaluate`).
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        truth: Vec<String>,
        labels: PyArrayLike1<'py, i32, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let ev = placecat::eval::evaluate(&truth, &labels_vec(labels)).map_err(core_err)?;
        to_py(py, &ev)
    }

    /// A named model of these scans: one category per label (-1 ignored),
    /// named by `names` ({label: name} or [(label, name)]; unnamed labels
    /// are "category N").
    #[pyo3(signature = (labels, names=None))]
    fn build_model(
        &self,
        labels: PyArrayLike1<'_, i32, AllowTypeChange>,
        names: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyModel> {
        let names = match names {
            Some(n) => category_names(&names_json(n)?).map_err(core_err)?,
            None => Vec::new(),
        };
        let model = self
            .inner
            .build_model(&labels_vec(labels), &names)
            .map_err(core_err)?;
        Ok(PyModel { model })
    }

    fn __repr__(&self) -> String {
        format!("Collection({} scans)", self.inner.len())
    }
}

/// Names as JSON the core's `category_names` reads: a dict's int keys
/// become the strings JSON needs.
pub(crate) fn names_json(names: &Bound<'_, PyAny>) -> PyResult<serde_json::Value> {
    if let Ok(d) = names.cast::<PyDict>() {
        let mut map = serde_json::Map::new();
        for (k, v) in d.iter() {
            map.insert(
                k.str()?.to_string(),
                serde_json::Value::String(v.extract()?),
            );
        }
        return Ok(serde_json::Value::Object(map));
    }
    crate::convert::from_py(names)
}

fn add(inner: &mut Collection, name: String, d: &PyDescriptor) -> PyResult<usize> {
    let added = inner.push_made_with(name.clone(), d.descriptor.clone(), &d.params);
    added.map_err(|e| core_err(e.in_file(name)))
}

/// The hierarchical k-means++ tree: cut at a height or into k categories
/// without recomputing; `linkage()` for scipy.
#[pyclass(module = "placecat", name = "Tree", frozen)]
pub struct PyTree {
    tree: Tree,
    /// What it was built with: the choice of categories builds its
    /// reference trees alike.
    params: HkMeansParams,
}

fn cut_dict<'py>(py: Python<'py>, cut: Cut) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("categories", cut.nodes.len())?;
    out.set_item("threshold", cut.threshold)?;
    out.set_item("labels", labels_array(py, cut.labels))?;
    out.set_item("nodes", cut.nodes)?;
    Ok(out)
}

#[pymethods]
impl PyTree {
    /// Number of scans.
    #[getter]
    fn n(&self) -> usize {
        self.tree.n
    }

    /// The nodes (root first): dicts of members, height, children, parent.
    #[getter]
    fn nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.tree.nodes)
    }

    /// Categories at height `threshold`: a dict of labels, threshold,
    /// categories, nodes.
    fn cut<'py>(&self, py: Python<'py>, threshold: f32) -> PyResult<Bound<'py, PyDict>> {
        cut_dict(py, self.tree.cut(threshold).map_err(core_err)?)
    }

    /// The cut that gives k categories (the k - 1 highest splits).
    fn cut_k<'py>(&self, py: Python<'py>, k: usize) -> PyResult<Bound<'py, PyDict>> {
        cut_dict(py, self.tree.cut_k(k).map_err(core_err)?)
    }

    /// Number of categories a cut at `threshold` makes.
    fn count_at(&self, threshold: f32) -> PyResult<usize> {
        self.tree.count_at(threshold).map_err(core_err)
    }

    /// The scipy.cluster.hierarchy linkage matrix: (n - 1, 4) float64 rows
    /// [a, b, height, count], for `dendrogram`, `fcluster` and friends.
    fn linkage<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let rows = self.tree.linkage();
        let n = rows.len();
        let flat: Vec<f64> = rows.into_iter().flatten().collect();
        Ok(PyArray1::from_vec(py, flat).reshape([n, 4])?.into_any())
    }

    fn __repr__(&self) -> String {
        format!(
            "Tree({} scans, {} nodes)",
            self.tree.n,
            self.tree.nodes.len()
        )
    }
}

/// Add the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyCollection>()?;
    m.add_class::<PyTree>()?;
    Ok(())
}
