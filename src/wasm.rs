//! The JavaScript boundary: `#[wasm_bindgen]` delegates to the core, each
//! a few lines. Every fallible call returns `Result<_, JsError>` and
//! converts the core's error with `?`, so errors arrive in JS as `Error`
//! objects with the core's message (which already names the file, the
//! parameter or the scan); large arrays leave as typed arrays; small
//! records as plain objects (serde-wasm-bindgen). Seeds are u32 here (a
//! plain JS number; u64 would demand a BigInt). The pipeline itself —
//! parameter merge, matrix policy, names — is [`crate::Collection`].

use crate::cluster::choose_k;
use crate::cluster::hkmeans::HkMeansParams;
use crate::cluster::{self, DbscanParams, KMeansParams, KMedoidsParams, Seeding, SpectralParams};
use crate::collection::{category_names, merge_params, Collection, MATRIX_LIMIT};
use crate::descriptor::{Descriptor, DescriptorParams};
use crate::distance::DistanceMatrix;
use crate::io::{self, write, ReadLimits};
use crate::model::LabelledModel;
use crate::{sim, Error};
use serde::Serialize;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

mod bag;
mod model;
mod scan;
mod set;
mod simulator;
mod source;
mod survey;

pub use bag::{bag_topics, BagClouds};
pub use model::{ClusterTree, Model};
pub use scan::{describe_points, describe_scan, read_scan, DescribedScan, Scan};
pub use set::DescriptorSet;
pub use simulator::Simulator;
pub use survey::E57Scans;

type WasmResult<T> = std::result::Result<T, JsError>;

/// A JS argument that may be left out (then `None`, as `undefined` and
/// `null` are): the .d.ts marks it optional (`params?:`).
type OptionalJs = Option<JsValue>;

/// Plain objects (maps become objects, not `Map`s).
fn to_js<T: Serialize + ?Sized>(v: &T) -> WasmResult<JsValue> {
    Ok(v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())?)
}

/// Parameters as the plain object the .d.ts promises
/// (`Required<DescriptorParams>`): every key, those the core's JSON leaves
/// out at their defaults (`DescriptorParams::fields_left_out_of_json`)
/// included.
/// They are the struct's last fields, so setting them where missing keeps
/// the struct's order (the page shows the object as JSON, `preset` first).
fn params_to_js(params: &DescriptorParams) -> WasmResult<JsValue> {
    let object = to_js(params)?;
    let not_an_object = |_| JsError::new("parameters: not a plain object");
    for (key, value) in params.fields_left_out_of_json() {
        let key = JsValue::from_str(key);
        if !js_sys::Reflect::has(&object, &key).map_err(not_an_object)? {
            js_sys::Reflect::set(&object, &key, &to_js(&value)?).map_err(not_an_object)?;
        }
    }
    Ok(object)
}

/// A JS value as JSON; `undefined` and `null` as `None`.
fn json_of(v: JsValue) -> WasmResult<Option<serde_json::Value>> {
    Ok(serde_wasm_bindgen::from_value(v)?)
}

fn params_from_js(params: JsValue, preset: Option<String>) -> WasmResult<DescriptorParams> {
    Ok(merge_params(preset.as_deref(), json_of(params)?.as_ref())?)
}

fn names_from_js(names: JsValue) -> WasmResult<Vec<(i32, String)>> {
    Ok(category_names(&json_of(names)?.unwrap_or_default())?)
}

/// A file's bytes from JS: a `Uint8Array` (a Node `Buffer` is one) or an
/// `ArrayBuffer` (what `File.arrayBuffer()` and `fetch` give). Anything
/// else is an error naming the file: wasm-bindgen's own `&[u8]` would read
/// an `ArrayBuffer` as empty and say so, which misleads.
fn bytes_from_js(bytes: &JsValue, name: &str) -> WasmResult<Vec<u8>> {
    if let Some(a) = bytes.dyn_ref::<js_sys::Uint8Array>() {
        return Ok(a.to_vec());
    }
    if let Some(b) = bytes.dyn_ref::<js_sys::ArrayBuffer>() {
        return Ok(js_sys::Uint8Array::new(b).to_vec());
    }
    let hint = if bytes.is_instance_of::<js_sys::Float32Array>() {
        " (points already in memory go to describePoints)"
    } else {
        ""
    };
    Err(JsError::new(&format!(
        "{name}: the bytes must be a Uint8Array or an ArrayBuffer, not {}{hint}",
        js_kind(bytes)
    )))
}

/// What a JS value is, for error messages: `undefined`, `null`, `a string`,
/// or an object's constructor name (`Float32Array`, `Object`).
fn js_kind(v: &JsValue) -> String {
    if v.is_undefined() {
        return "undefined".into();
    }
    if v.is_null() {
        return "null".into();
    }
    if !v.is_object() {
        return format!("a {}", v.js_typeof().as_string().unwrap_or_default());
    }
    js_sys::Reflect::get(v, &"constructor".into())
        .and_then(|c| js_sys::Reflect::get(&c, &"name".into()))
        .ok()
        .and_then(|n| n.as_string())
        .unwrap_or_else(|| "an object".into())
}

fn descriptor_from_json(json: &str) -> crate::Result<Descriptor> {
    Ok(serde_json::from_str(json)?)
}

#[wasm_bindgen(typescript_custom_section)]
const TS_NAMES: &'static str = r#"
/** A parameter preset (paper Tab. II: indoor, outdoor; docs/design.md#variants: indoor_bands; the public C++ code's settings: perception_oru; with the extra parts of docs/parts.md: indoor_plus, warehouse, outdoor_plus, free_space, indoor_clutter; the Hellinger distance of docs/hellinger.md: outdoor_hellinger; with ranges from 2 m, docs/near-ranges.md: outdoor_near; with the columns part, docs/columns.md: indoor_columns; weighted by a search, docs/indoor-searched.md: indoor_searched; with the objects part, docs/room-objects.md: indoor_objects; with the objects by size and height and their layout, docs/object-types-dev.md: indoor_object_types, withdrawn by docs/fresh-family-5.md). `presetNotes()` gives each one's one-line explanation. */
export type Preset = "indoor" | "outdoor" | "indoor_bands" | "perception_oru" | "indoor_plus" | "warehouse" | "outdoor_plus" | "free_space" | "indoor_clutter" | "outdoor_hellinger" | "outdoor_near" | "indoor_columns" | "indoor_searched" | "indoor_objects" | "indoor_object_types";
/** A preset's name, its one-line explanation, and whether a later round withdrew it (kept so that earlier reports re-run; the page does not offer it). */
export interface PresetNote {
    name: Preset;
    note: string;
    withdrawn: boolean;
}
/** k-means seeding: random scans, stride ("deterministic": scan i*n/k), k-means++, or spectral (the means of spectral clustering's groups). */
export type Seeding = "random" | "stride" | "deterministic" | "plusplus" | "spectral";
/** One simulated scan: its file name, true kind, pose and binary PLY bytes. */
export interface SimulatedScan {
    name: string;
    label: string;
    pose: Pose;
    bytes: Uint8Array;
}
"#;

#[wasm_bindgen(start)]
fn start() {
    console_error_panic_hook::set_once();
}

/// The crate version.
#[wasm_bindgen(js_name = version)]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// Descriptor parameters of a preset (`indoor`, `outdoor`, `indoor_bands`,
/// `perception_oru`, `indoor_plus`, `warehouse`, `outdoor_plus`,
/// `free_space`, `indoor_clutter`, `outdoor_hellinger`, `outdoor_near`,
/// `indoor_columns`, `indoor_searched`, `indoor_objects`,
/// `indoor_object_types`) as a plain object
/// whose fields can be changed.
#[wasm_bindgen(js_name = presetParams, unchecked_return_type = "Required<DescriptorParams>")]
pub fn preset_params(
    #[wasm_bindgen(unchecked_param_type = "Preset")] name: &str,
) -> WasmResult<JsValue> {
    params_to_js(&DescriptorParams::preset(name)?)
}

/// Every preset with its one-line explanation and whether it was
/// withdrawn, in the order of the menu.
#[wasm_bindgen(js_name = presetNotes, unchecked_return_type = "PresetNote[]")]
pub fn preset_notes() -> WasmResult<JsValue> {
    let notes: Vec<serde_json::Value> = crate::descriptor::PRESET_NOTES
        .iter()
        .map(|(name, note)| {
            let withdrawn = crate::descriptor::WITHDRAWN_PRESETS.contains(name);
            serde_json::json!({ "name": name, "note": note, "withdrawn": withdrawn })
        })
        .collect();
    to_js(&notes)
}

/// Parameters from a (possibly partial) object: missing fields take the
/// values of `preset` (default `indoor`). Throws on unknown fields and
/// invalid values; returns the complete, validated parameters.
#[wasm_bindgen(js_name = validateParams, unchecked_return_type = "Required<DescriptorParams>")]
pub fn validate_params(
    #[wasm_bindgen(unchecked_param_type = "Partial<DescriptorParams> | undefined | null")]
    params: JsValue,
    preset: Option<String>,
) -> WasmResult<JsValue> {
    params_to_js(&params_from_js(params, preset)?)
}

/// Parse a poses file (KITTI, TUM or CSV): `{format, poses: [{name, time, position, yaw}]}`.
#[wasm_bindgen(js_name = parsePoses, unchecked_return_type = "Poses")]
pub fn parse_poses(
    text: &str,
    #[wasm_bindgen(js_name = fileName)] file_name: Option<String>,
) -> WasmResult<JsValue> {
    let p = io::poses::parse(text)
        .map_err(|e| e.in_file(file_name.unwrap_or_else(|| "poses".into())))?;
    to_js(&p)
}
