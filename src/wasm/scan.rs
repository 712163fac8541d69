//! `Scan`, `DescribedScan`, `readScan`, `describeScan` and `describePoints`.

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
/// name), given as a `Uint8Array` (or Node `Buffer`) or an `ArrayBuffer`.
/// Throws an Error naming the file when the bytes are bad.
#[wasm_bindgen(js_name = readScan)]
pub fn read_scan(
    #[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue,
    name: &str,
) -> WasmResult<Scan> {
    let bytes = bytes_from_js(&bytes, name)?;
    let c = io::read_scan_named(&bytes, name, &ReadLimits::default())?;
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
    /// The parameters it was described with: a set or a model of other
    /// parameters refuses it (same shape is not same meaning).
    pub(super) params: DescriptorParams,
    preview: Vec<f32>,
    /// Where the recording put the sensor (bag clouds, E57 stations); None for files.
    pose: Option<io::poses::Pose>,
}

impl DescribedScan {
    /// Describe points already read (the one path of `describeScan`,
    /// `describePoints` and the bags' clouds): errors name `name`.
    pub(super) fn new(
        name: &str,
        format: &'static str,
        points: &[[f32; 3]],
        params: &DescriptorParams,
        preview_points: Option<usize>,
    ) -> WasmResult<DescribedScan> {
        let descriptor = crate::describe(points, params).map_err(|e| e.in_file(name))?;
        let finite = descriptor.summary.points;
        Ok(DescribedScan {
            name: name.to_string(),
            format,
            preview: crate::cloud::decimate_counted(points, finite, preview_points.unwrap_or(4000)),
            descriptor,
            params: params.clone(),
            pose: None,
        })
    }

    /// A scan taken out of a recording (a bag's cloud, a survey's station),
    /// described, with the pose the recording gives it.
    pub(super) fn recorded(
        scan: crate::Result<crate::io::recording::RecordedScan>,
        format: &'static str,
        params: &DescriptorParams,
        preview_points: Option<usize>,
    ) -> WasmResult<DescribedScan> {
        let scan = scan?;
        let mut d = DescribedScan::new(&scan.name, format, &scan.points, params, preview_points)?;
        d.pose = scan.pose;
        Ok(d)
    }
}

#[wasm_bindgen]
impl DescribedScan {
    /// The name it was described under (a file name, or the name given to
    /// `describePoints`).
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.name.clone()
    }
    /// Format of the bytes read (as `Scan.format`); `points` for
    /// `describePoints`.
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
    /// The sensor's pose where the recording holds one (a bag cloud with
    /// odometry or tf: `{name, time, position, yaw}`), else `null`.
    #[wasm_bindgen(unchecked_return_type = "Pose | null")]
    pub fn pose(&self) -> WasmResult<JsValue> {
        to_js(&self.pose)
    }
    /// The descriptor as JSON text (to pass between workers or store).
    #[wasm_bindgen(js_name = descriptorJson)]
    pub fn descriptor_json(&self) -> WasmResult<String> {
        Ok(serde_json::to_string(&self.descriptor)?)
    }
}

/// Read and describe a scan in one call. `bytes` is a `Uint8Array` (or
/// Node `Buffer`) or an `ArrayBuffer`; `params` is a (partial) parameter
/// object or undefined; `previewPoints` caps the preview (default 4000).
#[wasm_bindgen(js_name = describeScan)]
pub fn describe_scan(
    #[wasm_bindgen(unchecked_param_type = "Uint8Array | ArrayBuffer")] bytes: JsValue,
    name: &str,
    #[wasm_bindgen(unchecked_optional_param_type = "Partial<DescriptorParams> | null")]
    params: OptionalJs,
    #[wasm_bindgen(unchecked_optional_param_type = "string | null")] preset: Option<String>,
    #[wasm_bindgen(js_name = previewPoints, unchecked_optional_param_type = "number | null")]
    preview_points: Option<usize>,
) -> WasmResult<DescribedScan> {
    let p = params_from_js(params.unwrap_or_default(), preset)?;
    let bytes = bytes_from_js(&bytes, name)?;
    let c = io::read_scan_named(&bytes, name, &ReadLimits::default())?;
    DescribedScan::new(name, c.format.name(), &c.points, &p, preview_points)
}

/// Describe points already in memory: `xyz` holds x, y, z of each point in
/// turn (sensor frame, metres), e.g. a `Float32Array` of 3 n numbers.
/// `name` names the scan in the set and in errors (a length that is not a
/// multiple of 3 throws an Error naming it). Non-finite points are dropped,
/// as from files. `params`, `preset` and `previewPoints` as `describeScan`.
#[wasm_bindgen(js_name = describePoints)]
pub fn describe_points(
    xyz: &[f32],
    name: &str,
    #[wasm_bindgen(unchecked_optional_param_type = "Partial<DescriptorParams> | null")]
    params: OptionalJs,
    #[wasm_bindgen(unchecked_optional_param_type = "string | null")] preset: Option<String>,
    #[wasm_bindgen(js_name = previewPoints, unchecked_optional_param_type = "number | null")]
    preview_points: Option<usize>,
) -> WasmResult<DescribedScan> {
    let p = params_from_js(params.unwrap_or_default(), preset)?;
    let points = points_of(xyz).map_err(|e| e.in_file(name))?;
    DescribedScan::new(name, "points", &points, &p, preview_points)
}

/// Flat x, y, z as points; a length that is not a multiple of 3 is an error.
fn points_of(xyz: &[f32]) -> crate::Result<Vec<[f32; 3]>> {
    if xyz.len() % 3 != 0 {
        return Err(Error::InvalidParameter(format!(
            "the points must be flat x, y, z triples, but {} numbers is not a multiple of 3",
            xyz.len()
        )));
    }
    Ok(xyz.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}
