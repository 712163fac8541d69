//! A file's bytes served from JS a range at a time (in a worker:
//! `FileReaderSync` over `File.slice`), for the readers that never hold a
//! recording whole: ROS bags ([`crate::io::bag`]) and E57 surveys
//! ([`crate::io::e57::SurveyScans`], through [`crate::io::source::SourceReader`]).

use super::*;
use crate::io::source::ByteSource;

/// A file's bytes served by a JS function `read(offset, length)` that
/// returns exactly those bytes (a Uint8Array or an ArrayBuffer); its
/// failures are errors of the reader's kind (`kind`: `Error::Bag`, ...).
pub(super) struct JsSource {
    size: u64,
    read: js_sys::Function,
    kind: fn(String) -> Error,
}

impl JsSource {
    pub(super) fn new(
        size: f64,
        read: js_sys::Function,
        name: &str,
        kind: fn(String) -> Error,
    ) -> WasmResult<JsSource> {
        if !(size.is_finite() && size >= 0.0 && size.fract() == 0.0) {
            return Err(JsError::new(&format!(
                "{name}: the file's size must be a whole number of bytes, not {size}"
            )));
        }
        Ok(JsSource {
            size: size as u64,
            read,
            kind,
        })
    }
}

impl ByteSource for JsSource {
    fn size(&self) -> u64 {
        self.size
    }
    fn read_at(&mut self, offset: u64, buf: &mut [u8]) -> crate::Result<()> {
        let call = format!("read({offset}, {})", buf.len());
        let got = self
            .read
            .call2(
                &JsValue::NULL,
                &JsValue::from_f64(offset as f64),
                &JsValue::from_f64(buf.len() as f64),
            )
            .map_err(|e| (self.kind)(format!("{call} threw: {}", js_message(&e))))?;
        let bytes = if let Some(a) = got.dyn_ref::<js_sys::Uint8Array>() {
            a.clone()
        } else if let Some(b) = got.dyn_ref::<js_sys::ArrayBuffer>() {
            js_sys::Uint8Array::new(b)
        } else {
            return Err((self.kind)(format!(
                "{call} must return a Uint8Array or an ArrayBuffer, not {}",
                js_kind(&got)
            )));
        };
        if bytes.length() as usize != buf.len() {
            return Err((self.kind)(format!(
                "{call} returned {} bytes",
                bytes.length()
            )));
        }
        bytes.copy_to(buf);
        Ok(())
    }
}

/// The message of a thrown JS value.
fn js_message(e: &JsValue) -> String {
    e.dyn_ref::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .or_else(|| e.as_string())
        .unwrap_or_else(|| js_kind(e))
}
