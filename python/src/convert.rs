//! Crossing the boundary: core errors to PlacecatError, serde structs to
//! plain Python objects and back (through JSON text, the format every
//! other front end of the core already speaks), parameters from a preset
//! name or a dict.

use crate::PlacecatError;
use placecat::collection::merge_params;
use placecat::DescriptorParams;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use serde::Serialize;
use serde_json::Value;

/// A core error as a PlacecatError with the core's message.
pub fn core_err(e: placecat::Error) -> PyErr {
    PlacecatError::new_err(e.to_string())
}

/// A JSON error of this layer, as the core words them.
pub fn json_err(e: serde_json::Error) -> PyErr {
    core_err(placecat::Error::from(e))
}

/// A serde value as plain Python objects (dicts, lists, numbers).
pub fn to_py<'py>(py: Python<'py>, value: &impl Serialize) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value).map_err(json_err)?;
    py.import("json")?.call_method1("loads", (text,))
}

/// Plain Python objects as a JSON value.
pub fn from_py(obj: &Bound<'_, PyAny>) -> PyResult<Value> {
    let text: String = obj
        .py()
        .import("json")?
        .call_method1("dumps", (obj,))?
        .extract()?;
    serde_json::from_str(&text).map_err(json_err)
}

/// Descriptor parameters from None (indoor), a preset name, or a dict of
/// overrides over indoor or over the preset its "preset" key names: the
/// core's merge, as the CLI's `--preset` + `--params` and the page's form.
pub fn params_from_py(params: Option<&Bound<'_, PyAny>>) -> PyResult<DescriptorParams> {
    let Some(p) = params.filter(|p| !p.is_none()) else {
        return merge_params(None, None).map_err(core_err);
    };
    if p.is_instance_of::<PyString>() {
        return merge_params(Some(&p.extract::<String>()?), None).map_err(core_err);
    }
    let Ok(dict) = p.cast::<PyDict>() else {
        return Err(PlacecatError::new_err(
            "invalid parameter: params must be a preset name or a dict of overrides",
        ));
    };
    let mut over = from_py(dict.as_any())?;
    let preset = match over.as_object_mut().and_then(|o| o.remove("preset")) {
        None => None,
        Some(Value::String(s)) => Some(s),
        Some(other) => {
            return Err(PlacecatError::new_err(format!(
                "invalid parameter: preset must be a name, got {other}"
            )))
        }
    };
    merge_params(preset.as_deref(), Some(&over)).map_err(core_err)
}
