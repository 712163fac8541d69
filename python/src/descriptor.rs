//! `describe`, `describe_file` and the Descriptor class: the core's
//! descriptor with the parameters it was made with, so a collection or a
//! model knows them without being told again.

use crate::convert::{core_err, json_err, params_from_py, to_py};
use crate::{PlacecatError, Scan, ScanFile};
use numpy::{AllowTypeChange, PyArray1, PyArrayLike2, PyArrayMethods};
use placecat::{Descriptor, DescriptorParams};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// A scan's NDT-histogram descriptor (one count matrix per candidate
/// orientation) and the parameters it was made with. Picklable; compare
/// with ==.
#[pyclass(module = "placecat", name = "Descriptor", frozen, eq)]
#[derive(Clone, PartialEq, Serialize, Deserialize)]
pub struct PyDescriptor {
    pub params: DescriptorParams,
    pub descriptor: Descriptor,
}

impl PyDescriptor {
    fn from_json_text(text: &str) -> PyResult<PyDescriptor> {
        let d: PyDescriptor = serde_json::from_str(text).map_err(json_err)?;
        d.params.validate().map_err(core_err)?;
        d.descriptor.validate_for(&d.params).map_err(core_err)?;
        Ok(d)
    }
}

#[pymethods]
impl PyDescriptor {
    /// Rows of each matrix (shape classes x height bands).
    #[getter]
    fn rows(&self) -> usize {
        self.descriptor.rows
    }

    /// Columns of each matrix (range intervals).
    #[getter]
    fn cols(&self) -> usize {
        self.descriptor.cols
    }

    /// The count matrices as a uint32 array (orientations, rows, cols).
    #[getter]
    fn matrices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let d = &self.descriptor;
        let flat: Vec<u32> = d.matrices.iter().flatten().copied().collect();
        Ok(PyArray1::from_vec(py, flat)
            .reshape([d.matrices.len(), d.rows, d.cols])?
            .into_any())
    }

    /// |F|: the classified voxels in range (of the first orientation).
    #[getter]
    fn total(&self) -> u64 {
        self.descriptor.total()
    }

    /// What describing found: points, dropped, voxels, shape counts,
    /// in_range, alignments, unreliable (a dict).
    #[getter]
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.descriptor.summary)
    }

    /// True when too few classified voxels were in range for the
    /// descriptor to say much (clustering still uses it).
    #[getter]
    fn unreliable(&self) -> bool {
        self.descriptor.summary.unreliable
    }

    /// The descriptor parameters it was made with (a dict).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.params)
    }

    /// JSON of {"params": ..., "descriptor": ...}; `from_json` reads it.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string(self).map_err(json_err)
    }

    /// The core descriptor alone as JSON, in the form of the `descriptor`
    /// field of the CLI's describe output.
    fn descriptor_json(&self) -> PyResult<String> {
        serde_json::to_string(&self.descriptor).map_err(json_err)
    }

    /// Read what `to_json` wrote (checked: shape against parameters).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<PyDescriptor> {
        PyDescriptor::from_json_text(text)
    }

    /// A descriptor from the CLI's describe output: its `params` and one
    /// of its files' `descriptor`, each as JSON text.
    #[staticmethod]
    fn from_parts(params_json: &str, descriptor_json: &str) -> PyResult<PyDescriptor> {
        let params: DescriptorParams = serde_json::from_str(params_json).map_err(json_err)?;
        let descriptor: Descriptor = serde_json::from_str(descriptor_json).map_err(json_err)?;
        params.validate().map_err(core_err)?;
        descriptor.validate_for(&params).map_err(core_err)?;
        Ok(PyDescriptor { params, descriptor })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let make = py.get_type::<PyDescriptor>().getattr("from_json")?;
        let text = slf.get().to_json()?;
        PyTuple::new(py, [make, PyTuple::new(py, [text])?.into_any()])
    }

    fn __repr__(&self) -> String {
        let s = &self.descriptor.summary;
        format!(
            "Descriptor({}x{}, {} orientations, total {}, {} points{})",
            self.descriptor.rows,
            self.descriptor.cols,
            self.descriptor.matrices.len(),
            self.descriptor.total(),
            s.points,
            if s.unreliable { ", unreliable" } else { "" }
        )
    }
}

/// Describe a scan: `points` an (N, 3) array (any float dtype; sensor at
/// the origin), `params` a preset name or a dict of overrides (see
/// `placecat.params`). The GIL is released while describing.
#[pyfunction]
#[pyo3(signature = (points, params=None))]
fn describe(
    py: Python<'_>,
    points: PyArrayLike2<'_, f32, AllowTypeChange>,
    params: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyDescriptor> {
    let params = params_from_py(params)?;
    let view = points.as_array();
    if view.ncols() != 3 {
        return Err(PlacecatError::new_err(format!(
            "invalid parameter: points must be an (N, 3) array, got shape {:?}",
            view.shape()
        )));
    }
    let pts: Vec<[f32; 3]> = view
        .rows()
        .into_iter()
        .map(|r| [r[0], r[1], r[2]])
        .collect();
    let descriptor = py
        .detach(|| placecat::describe(&pts, &params))
        .map_err(core_err)?;
    Ok(PyDescriptor { params, descriptor })
}

/// Read and describe a scan file in one call, the GIL released throughout
/// (what a Dask task runs); errors name the file, as the CLI's describe.
/// The keywords are `read`'s.
#[pyfunction]
#[pyo3(signature = (path, params=None, *, lenient=false, max_points=None, max_bytes=None, origin=None))]
fn describe_file(
    py: Python<'_>,
    path: PathBuf,
    params: Option<&Bound<'_, PyAny>>,
    lenient: bool,
    max_points: Option<usize>,
    max_bytes: Option<usize>,
    origin: Option<[f64; 3]>,
) -> PyResult<PyDescriptor> {
    let scan = Scan::new(ScanFile::Path(path), lenient, max_points, max_bytes, origin);
    describe_scan(py, scan, params)
}

/// Describe a scan from the bytes of its file (e.g. read through fsspec);
/// `name` is used to tell KITTI .bin files and to name the scan in errors.
/// The keywords are `read`'s; the GIL is released.
#[pyfunction]
#[pyo3(signature = (data, name, params=None, *, lenient=false, max_points=None, max_bytes=None, origin=None))]
#[allow(clippy::too_many_arguments)] // the keywords of read(), one by one
fn describe_bytes(
    py: Python<'_>,
    data: &[u8],
    name: &str,
    params: Option<&Bound<'_, PyAny>>,
    lenient: bool,
    max_points: Option<usize>,
    max_bytes: Option<usize>,
    origin: Option<[f64; 3]>,
) -> PyResult<PyDescriptor> {
    let scan = Scan::new(
        ScanFile::Bytes(data, name),
        lenient,
        max_points,
        max_bytes,
        origin,
    );
    describe_scan(py, scan, params)
}

/// Read and describe with the GIL released; errors name the file.
fn describe_scan(
    py: Python<'_>,
    scan: Scan<'_>,
    params: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyDescriptor> {
    let params = params_from_py(params)?;
    let descriptor = py
        .detach(|| {
            let cloud = scan.read()?;
            placecat::describe(&cloud.points, &params).map_err(|e| e.in_file(scan.name()))
        })
        .map_err(core_err)?;
    Ok(PyDescriptor { params, descriptor })
}

/// Add the functions and the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyDescriptor>()?;
    m.add_function(wrap_pyfunction!(describe, m)?)?;
    m.add_function(wrap_pyfunction!(describe_file, m)?)?;
    m.add_function(wrap_pyfunction!(describe_bytes, m)?)?;
    Ok(())
}
