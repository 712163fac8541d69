//! placecat for Python: the extension module `placecat._placecat`, a thin
//! layer over the core's public API (io, describe, Collection, model). No
//! algorithm is written here: each function converts its arguments, calls
//! the core with the GIL released where the work is heavy, and converts
//! the answer (numpy arrays for numbers, plain dicts for the core's serde
//! structs). Core errors become `placecat.PlacecatError` with the core's
//! message, which names the file.

mod collection;
mod convert;
mod descriptor;
mod model;
mod recording;

use convert::{core_err, params_from_py, to_py};
use numpy::{PyArray1, PyArrayMethods};
use placecat::io::ReadLimits;
use placecat::PointCloud;
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::path::PathBuf;

create_exception!(
    placecat,
    PlacecatError,
    PyValueError,
    "An error of placecat's core: a file that cannot be read (the message names it), \
     an invalid parameter, descriptors that do not fit together. A ValueError."
);

/// Where a scan's bytes come from, with the CLI's read options: a path
/// read by the core, or bytes already read (through fsspec, say) with the
/// file's name. Reading names the file in errors either way.
pub(crate) struct Scan<'a> {
    pub file: ScanFile<'a>,
    pub limits: ReadLimits,
    pub origin: Option<[f64; 3]>,
}

/// A path, or bytes and the name they came from.
pub(crate) enum ScanFile<'a> {
    Path(PathBuf),
    Bytes(&'a [u8], &'a str),
}

impl Scan<'_> {
    /// The limits of the CLI's flags, defaults where not given.
    pub fn new(
        file: ScanFile<'_>,
        lenient: bool,
        max_points: Option<usize>,
        max_bytes: Option<usize>,
        origin: Option<[f64; 3]>,
    ) -> Scan<'_> {
        let d = ReadLimits::default();
        let limits = ReadLimits {
            max_points: max_points.unwrap_or(d.max_points),
            max_bytes: max_bytes.unwrap_or(d.max_bytes),
            lenient,
        };
        Scan {
            file,
            limits,
            origin,
        }
    }

    /// The file's name as errors show it.
    pub fn name(&self) -> String {
        match &self.file {
            ScanFile::Path(p) => p.display().to_string(),
            ScanFile::Bytes(_, name) => name.to_string(),
        }
    }

    /// Read the points (call with the GIL released).
    pub fn read(&self) -> placecat::Result<PointCloud> {
        match &self.file {
            ScanFile::Path(p) => placecat::io::read_path_at(p, &self.limits, self.origin),
            ScanFile::Bytes(data, name) => {
                placecat::io::read_scan_at(data, name, &self.limits, self.origin)
                    .map_err(|e| e.in_file(*name))
            }
        }
    }
}

/// Read a scan with the GIL released, as an (N, 3) float32 array.
fn read_points<'py>(py: Python<'py>, scan: Scan<'_>) -> PyResult<Bound<'py, PyAny>> {
    let cloud = py.detach(|| scan.read()).map_err(core_err)?;
    let n = cloud.points.len();
    let flat: Vec<f32> = cloud.points.into_iter().flatten().collect();
    Ok(PyArray1::from_vec(py, flat).reshape([n, 3])?.into_any())
}

/// Read a scan file (PLY, PCD, KITTI .bin, LAS/LAZ, single-scan E57) as an
/// (N, 3) float32 array of x, y, z in the sensor frame.
///
/// `lenient`, `max_points`, `max_bytes` and `origin` (the sensor position,
/// subtracted from every point) are the CLI's `--lenient`, `--max-points`,
/// `--max-bytes` and `--origin`. Raises PlacecatError naming the file.
#[pyfunction]
#[pyo3(signature = (path, *, lenient=false, max_points=None, max_bytes=None, origin=None))]
fn read<'py>(
    py: Python<'py>,
    path: PathBuf,
    lenient: bool,
    max_points: Option<usize>,
    max_bytes: Option<usize>,
    origin: Option<[f64; 3]>,
) -> PyResult<Bound<'py, PyAny>> {
    let scan = Scan::new(ScanFile::Path(path), lenient, max_points, max_bytes, origin);
    read_points(py, scan)
}

/// [`read`] from the bytes of a scan file; `name` tells KITTI .bin files
/// and names the scan in errors.
#[pyfunction]
#[pyo3(signature = (data, name, *, lenient=false, max_points=None, max_bytes=None, origin=None))]
fn read_bytes<'py>(
    py: Python<'py>,
    data: &[u8],
    name: &str,
    lenient: bool,
    max_points: Option<usize>,
    max_bytes: Option<usize>,
    origin: Option<[f64; 3]>,
) -> PyResult<Bound<'py, PyAny>> {
    let scan = Scan::new(
        ScanFile::Bytes(data, name),
        lenient,
        max_points,
        max_bytes,
        origin,
    );
    read_points(py, scan)
}

/// The names of the descriptor parameter presets (`indoor`, `outdoor`, ...).
#[pyfunction]
fn presets() -> Vec<&'static str> {
    placecat::descriptor::preset_names()
}

/// Every preset with its one-line explanation and whether a later round
/// withdrew it (kept so that earlier reports re-run): dicts with `name`,
/// `note` and `withdrawn`, in the order of `presets()`.
#[pyfunction]
fn preset_notes<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
    let notes: Vec<serde_json::Value> = (placecat::descriptor::PRESET_NOTES.iter())
        .map(|(name, note)| {
            let withdrawn = placecat::descriptor::WITHDRAWN_PRESETS.contains(name);
            serde_json::json!({ "name": name, "note": note, "withdrawn": withdrawn })
        })
        .collect();
    to_py(py, &notes)
}

/// Descriptor parameters as a dict: a preset's (`params("outdoor")`), or a
/// dict of overrides put over `indoor` (or over the preset named by its
/// "preset" key), checked as the CLI's `--params` file is.
#[pyfunction]
#[pyo3(signature = (params=None))]
fn params<'py>(py: Python<'py>, params: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyAny>> {
    to_py(py, &params_from_py(params)?)
}

/// Compare labels with ground truth: accuracy, ARI, score, inliers, total
/// and the confusion matrix, as the CLI's `evaluate` (a dict).
#[pyfunction]
fn evaluate<'py>(
    py: Python<'py>,
    truth: Vec<String>,
    labels: Vec<i32>,
) -> PyResult<Bound<'py, PyAny>> {
    let ev = placecat::eval::evaluate(&truth, &labels).map_err(core_err)?;
    to_py(py, &ev)
}

/// The extension module.
#[pymodule]
fn _placecat(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("PlacecatError", m.py().get_type::<PlacecatError>())?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(read_bytes, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(preset_notes, m)?)?;
    m.add_function(wrap_pyfunction!(params, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    descriptor::register(m)?;
    collection::register(m)?;
    model::register(m)?;
    recording::register(m)?;
    m.add("MATRIX_LIMIT", placecat::collection::MATRIX_LIMIT)?;
    m.add("MAX_RESTARTS", placecat::cluster::MAX_RESTARTS)?;
    Ok(())
}
