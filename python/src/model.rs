//! The Model class: the core's labelled model, saved and loaded as the
//! same JSON as the CLI's `model` and the page's "Export model".

use crate::convert::{core_err, to_py};
use crate::descriptor::PyDescriptor;
use placecat::model::LabelledModel;
use placecat::Error;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::path::PathBuf;

/// Named categories that classify new scans: `Collection.build_model`,
/// `Model.load` (a file of the CLI's `placecat model` or of the page's
/// "Export model"). Picklable; compare with ==.
#[pyclass(module = "placecat", name = "Model", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyModel {
    pub model: LabelledModel,
}

#[pymethods]
impl PyModel {
    /// Parse and check model JSON.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<PyModel> {
        let model = LabelledModel::from_json(text).map_err(core_err)?;
        Ok(PyModel { model })
    }

    /// Read a model file; errors name it.
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<PyModel> {
        let name = path.display().to_string();
        let model = std::fs::read_to_string(&path)
            .map_err(Error::from)
            .and_then(|text| LabelledModel::from_json(&text))
            .map_err(|e| core_err(e.in_file(name)))?;
        Ok(PyModel { model })
    }

    /// The model as JSON (what the CLI and the page read).
    fn to_json(&self) -> PyResult<String> {
        self.model.to_json().map_err(core_err)
    }

    /// Write the model's JSON to a file.
    fn save(&self, path: PathBuf) -> PyResult<()> {
        let name = path.display().to_string();
        std::fs::write(&path, self.to_json()?).map_err(|e| core_err(Error::from(e).in_file(name)))
    }

    /// The categories without their centres: dicts of name, label,
    /// members, radius.
    #[getter]
    fn categories<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.model.summaries())
    }

    /// The descriptor parameters the model was made with (a dict): new
    /// scans must be described with them (`classify_file` does).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.model.params)
    }

    /// A copy with categories renamed: {label: name} or [(label, name)].
    fn renamed(&self, names: &Bound<'_, PyAny>) -> PyResult<PyModel> {
        let names = placecat::collection::category_names(&crate::collection::names_json(names)?)
            .map_err(core_err)?;
        let mut model = self.model.clone();
        model.rename(&names);
        Ok(PyModel { model })
    }

    /// The nearest category of a descriptor: a dict of name, label,
    /// distance (Delta to its centre) and relative (distance / radius).
    fn classify<'py>(
        &self,
        py: Python<'py>,
        descriptor: PyRef<'py, PyDescriptor>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let answer = self
            .model
            .classify_made_with(&descriptor.descriptor, &descriptor.params)
            .map_err(core_err)?;
        to_py(py, &answer)
    }

    /// Read, describe (with the model's parameters) and classify a scan
    /// file, the GIL released; errors name the file.
    #[pyo3(signature = (path, *, lenient=false))]
    fn classify_file<'py>(
        &self,
        py: Python<'py>,
        path: PathBuf,
        lenient: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let scan = crate::Scan::new(crate::ScanFile::Path(path), lenient, None, None, None);
        let model = &self.model;
        let answer = py
            .detach(|| {
                let cloud = scan.read()?;
                placecat::describe(&cloud.points, &model.params)
                    .and_then(|d| model.classify(&d))
                    .map_err(|e| e.in_file(scan.name()))
            })
            .map_err(core_err)?;
        to_py(py, &answer)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let make = py.get_type::<PyModel>().getattr("from_json")?;
        let text = slf.get().to_json()?;
        PyTuple::new(py, [make, PyTuple::new(py, [text])?.into_any()])
    }

    fn __repr__(&self) -> String {
        let names: Vec<&str> = self
            .model
            .categories
            .iter()
            .map(|c| c.name.as_str())
            .collect();
        format!("Model({names:?})")
    }
}

/// Add the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyModel>()?;
    Ok(())
}
