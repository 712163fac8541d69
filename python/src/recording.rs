//! Recordings from Python: `scans(path)` iterates the scans of a ROS bag (a
//! PointCloud2 topic, ROS 1 `.bag` or rosbag2 `.mcap`) or of an E57 survey
//! (one scan a station), one at a time, read from disk a chunk or a page at
//! a time as the CLI's describe reads them, each with the pose the
//! recording gives it. A scan that cannot be read is reported (a Python
//! warning, and `errors`) and skipped; a file that cannot be opened raises.

use crate::convert::core_err;
use numpy::{PyArray1, PyArrayMethods};
use placecat::io::bag::BagOptions;
use placecat::io::recording::{RecordedScan, Recording};
use placecat::io::ReadLimits;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// The scans of a recording, one at a time (a for loop, `next()`): each a
/// dict `{"name", "points", "pose", "stamp"}`, `name` the file's base name
/// and the topic and index or the station (`run.bag:/points:000042`,
/// `site.e57:hall`), `points` an (N, 3) float32
/// array in the sensor's frame, `pose` `{"position": [x, y, z], "yaw",
/// "time", "name"}` or None. Scans that cannot be read are skipped, each
/// with a warning; `errors` lists them. `total` and `met` count the
/// recording's scans (a bag: its topic's clouds, before thinning) and those
/// read so far. Not shared between threads; the GIL is held while reading.
#[pyclass(module = "placecat._placecat", name = "Scans", unsendable)]
pub struct PyScans {
    source: Recording,
    errors: Vec<String>,
}

#[pymethods]
impl PyScans {
    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__<'py>(&mut self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        loop {
            match self.source.next() {
                None => return Ok(None),
                Some(Ok(scan)) => return scan_dict(py, scan).map(Some),
                Some(Err(e)) => {
                    // Listed first: a warning turned into an error (-W error) raises here.
                    let message = e.to_string();
                    // A damaged bag's names can hold NUL, which a C string cannot.
                    let text =
                        std::ffi::CString::new(message.replace('\0', "\\0")).expect("no NUL left");
                    self.errors.push(message);
                    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
                    PyErr::warn(py, category.as_any(), &text, 1)?;
                }
            }
        }
    }

    /// Scans in the recording (a bag: its topic's clouds, before thinning).
    #[getter]
    fn total(&self) -> u64 {
        self.source.total()
    }

    /// Scans met so far, kept or not, read or not.
    #[getter]
    fn met(&self) -> u64 {
        self.source.met()
    }

    /// The cloud topic read (a bag), or None (a survey).
    #[getter]
    fn topic(&self) -> Option<String> {
        self.source.topic().map(str::to_string)
    }

    /// The messages of the scans skipped so far, each naming the file and the scan.
    #[getter]
    fn errors(&self) -> Vec<String> {
        self.errors.clone()
    }
}

/// A read scan as a dict of plain Python values and a numpy array.
fn scan_dict(py: Python<'_>, scan: RecordedScan) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    let n = scan.points.len();
    let flat: Vec<f32> = scan.points.into_iter().flatten().collect();
    d.set_item("name", scan.name)?;
    d.set_item("points", PyArray1::from_vec(py, flat).reshape([n, 3])?)?;
    d.set_item("stamp", scan.stamp)?;
    let pose = match scan.pose {
        None => None,
        Some(p) => {
            let q = PyDict::new(py);
            q.set_item("position", p.position.to_vec())?;
            q.set_item("yaw", p.yaw)?;
            q.set_item("time", p.time)?;
            q.set_item("name", p.name)?;
            Some(q)
        }
    };
    d.set_item("pose", pose)?;
    Ok(d)
}

/// The scans of a recording, one at a time (see `Scans`): a ROS bag (ROS 1
/// `.bag`, rosbag2 `.mcap`; `topic` the PointCloud2 topic, by default the
/// only one; `every` keeps every Nth cloud, `every_metres` one cloud so
/// many metres along the recorded path, as the CLI's `--topic`, `--every`
/// and `--every-metres`) or an E57 survey (every station; the bag keywords
/// do not apply). `max_points` caps each scan. `name` replaces the file's
/// base name at the start of the scans' names, their poses' and the
/// skipped scans' (e.g. the recording's path under a fleet's folder, as the
/// CLI's describe names a bag's clouds), so that recordings of one name in
/// different folders keep apart. Raises
/// PlacecatError naming the file when it cannot be opened.
#[pyfunction]
#[pyo3(signature = (path, *, topic=None, every=1, every_metres=None, max_points=None, name=None))]
pub fn scans(
    path: PathBuf,
    topic: Option<String>,
    every: usize,
    every_metres: Option<f64>,
    max_points: Option<usize>,
    name: Option<String>,
) -> PyResult<PyScans> {
    let mut limits = ReadLimits::default();
    if let Some(m) = max_points {
        limits.max_points = m;
    }
    let opts = BagOptions {
        topic,
        every,
        every_metres,
        limits,
        ..Default::default()
    };
    let source = Recording::open_path_as(&path, name.as_deref(), opts).map_err(core_err)?;
    Ok(PyScans {
        source,
        errors: Vec::new(),
    })
}

/// Add `scans` and `Scans` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyScans>()?;
    m.add_function(wrap_pyfunction!(scans, m)?)?;
    Ok(())
}
