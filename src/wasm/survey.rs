//! E57 surveys from JS: `E57Scans`, the scans of a survey (one per scanner
//! station) over bytes the caller serves a range at a time, as a bag's
//! (in a worker: `FileReaderSync` over `File.slice`), so that a survey of
//! gigabytes is never held whole; see [`crate::io::e57`].

use super::source::JsSource;
use super::*;
use crate::io::e57::SurveyScans;
use crate::io::source::SourceReader;

/// The scans of an E57 survey, read in file order and described one at a
/// time (`next()`), each with its station's pose (position and heading),
/// so the page draws the survey as a site. A single-scan E57 is a survey
/// of one.
#[wasm_bindgen]
pub struct E57Scans {
    scans: SurveyScans<SourceReader<JsSource>>,
    params: DescriptorParams,
    preview_points: Option<usize>,
}

#[wasm_bindgen]
impl E57Scans {
    /// Open a survey of `size` bytes served by `read(offset, length)` (as
    /// `bagTopics`); `name` names it and prefixes its scans' names
    /// (`survey.e57:office`). `params`, `preset` and `previewPoints` as
    /// `describeScan`. Reads the header and the XML section, no points; a
    /// file that is not E57 throws an Error naming it.
    #[wasm_bindgen(constructor)]
    pub fn new(
        size: f64,
        #[wasm_bindgen(
            unchecked_param_type = "(offset: number, length: number) => Uint8Array | ArrayBuffer"
        )]
        read: js_sys::Function,
        name: &str,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<DescriptorParams> | null")]
        params: OptionalJs,
        #[wasm_bindgen(unchecked_optional_param_type = "string | null")] preset: Option<String>,
        #[wasm_bindgen(js_name = previewPoints, unchecked_optional_param_type = "number | null")]
        preview_points: Option<usize>,
    ) -> WasmResult<E57Scans> {
        let params = params_from_js(params.unwrap_or_default(), preset)?;
        // A failed read is an I/O error inside the E57 reader's own ("E57:
        // Failed to read E57: ... I/O: read(0, 1024) threw: ..."), not a
        // second "E57:".
        let io = |m: String| Error::Io(std::io::Error::other(m));
        let source = SourceReader::new(JsSource::new(size, read, name, io)?);
        Ok(E57Scans {
            scans: SurveyScans::open(source, name, ReadLimits::default())?,
            params,
            preview_points,
        })
    }
    /// Scans in the survey (for progress).
    #[wasm_bindgen(getter)]
    pub fn total(&self) -> f64 {
        self.scans.len() as f64
    }
    /// Scans read so far, failed ones included (for progress).
    #[wasm_bindgen(getter)]
    pub fn met(&self) -> f64 {
        self.scans.met() as f64
    }
    /// The next scan, described (`pose()` its station's pose), or
    /// `undefined` after the last. A scan that cannot be read or described
    /// throws an Error naming the file and the scan: call `next()` again for
    /// the scans after it.
    #[wasm_bindgen(js_name = next)]
    pub fn next_scan(&mut self) -> WasmResult<Option<DescribedScan>> {
        (self.scans.next())
            .map(|scan| DescribedScan::recorded(scan, "e57", &self.params, self.preview_points))
            .transpose()
    }
}
