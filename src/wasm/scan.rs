//! `Scan`, `DescribedScan`, `readScan` and `describeScan`.

use super::*;

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
    let c = io::read_scan_named(bytes, name, &ReadLimits::default())?;
    Ok(Scan {
        format: c.format.name(),
        points: c.points.into_iter().flatten().collect(),
    })
}

/// A described scan: its descriptor, a summary, and a decimated preview.
#[wasm_bindgen]
pub struct DescribedScan {
    pub(super) name: String,
    format: &'static str,
    pub(super) descriptor: Descriptor,
    preview: Vec<f32>,
}

#[wasm_bindgen]
impl DescribedScan {
    /// The name the scan was described under (its file name).
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.name.clone()
    }
    /// Format name, e.g. `ply_binary_little_endian`.
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
        Ok(serde_json::to_string(&self.descriptor)?)
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
    let p = params_from_js(params, preset)?;
    let c = io::read_scan_named(bytes, name, &ReadLimits::default())?;
    let descriptor = crate::describe(&c.points, &p).map_err(|e| e.in_file(name))?;
    Ok(DescribedScan {
        name: name.to_string(),
        format: c.format.name(),
        preview: crate::cloud::decimate(&c.points, preview_points.unwrap_or(4000)),
        descriptor,
    })
}
