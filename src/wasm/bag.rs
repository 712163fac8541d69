//! ROS bags from JS: `bagTopics` and `BagClouds`, over bytes the caller
//! serves a range at a time (in a worker: `FileReaderSync` over
//! `File.slice`), so a bag of gigabytes is never held whole; see
//! [`crate::io::bag`].

use super::source::JsSource;
use super::*;
use crate::io::bag::{self, BagOptions, BagReader};

/// The topics of a bag (ROS 1 `.bag` or rosbag2 `.mcap`) of `size` bytes,
/// sorted by name: `[{name, type, count}]`. `read(offset, length)` returns
/// those bytes (a Uint8Array or an ArrayBuffer); only the bag's index or
/// summary is read when it has one. In a worker, over a `File`:
/// `(o, n) => new FileReaderSync().readAsArrayBuffer(file.slice(o, o + n))`.
#[wasm_bindgen(js_name = bagTopics, unchecked_return_type = "TopicInfo[]")]
pub fn bag_topics(
    size: f64,
    #[wasm_bindgen(
        unchecked_param_type = "(offset: number, length: number) => Uint8Array | ArrayBuffer"
    )]
    read: js_sys::Function,
    name: &str,
) -> WasmResult<JsValue> {
    to_js(&bag::topics(
        JsSource::new(size, read, name, Error::Bag)?,
        name,
    )?)
}

/// The clouds of one `sensor_msgs/PointCloud2` topic of a bag, read in
/// recording order and described one at a time (`next()`), with the pose
/// the bag records for each (odometry or tf) where it has one.
#[wasm_bindgen]
pub struct BagClouds {
    reader: BagReader<JsSource>,
    params: DescriptorParams,
    preview_points: Option<usize>,
}

#[wasm_bindgen]
impl BagClouds {
    /// Open a bag of `size` bytes served by `read` (as `bagTopics`). `topic`
    /// is the cloud topic (by default the only PointCloud2 topic; with
    /// several, an Error lists them); `every` keeps every Nth cloud (1, the
    /// default, keeps all). `params`, `preset` and `previewPoints` as
    /// `describeScan`. `everyMetres` keeps one cloud every so many metres
    /// along the recorded path instead (as the CLI's `--every-metres`; an
    /// Error when the bag has no odometry or tf to give the path).
    #[allow(clippy::too_many_arguments)]
    #[wasm_bindgen(constructor)]
    pub fn new(
        size: f64,
        #[wasm_bindgen(
            unchecked_param_type = "(offset: number, length: number) => Uint8Array | ArrayBuffer"
        )]
        read: js_sys::Function,
        name: &str,
        #[wasm_bindgen(unchecked_optional_param_type = "string | null")] topic: Option<String>,
        #[wasm_bindgen(unchecked_optional_param_type = "number | null")] every: Option<usize>,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<DescriptorParams> | null")]
        params: OptionalJs,
        #[wasm_bindgen(unchecked_optional_param_type = "string | null")] preset: Option<String>,
        #[wasm_bindgen(js_name = previewPoints, unchecked_optional_param_type = "number | null")]
        preview_points: Option<usize>,
        #[wasm_bindgen(js_name = everyMetres, unchecked_optional_param_type = "number | null")]
        every_metres: Option<f64>,
    ) -> WasmResult<BagClouds> {
        let params = params_from_js(params.unwrap_or_default(), preset)?;
        let opts = BagOptions {
            topic,
            every: every.unwrap_or(1),
            every_metres,
            ..Default::default()
        };
        Ok(BagClouds {
            reader: BagReader::open(JsSource::new(size, read, name, Error::Bag)?, name, opts)?,
            params,
            preview_points,
        })
    }
    /// The cloud topic being read.
    #[wasm_bindgen(getter)]
    pub fn topic(&self) -> String {
        self.reader.topic().to_string()
    }
    /// Clouds in the topic, before thinning (for progress).
    #[wasm_bindgen(getter)]
    pub fn total(&self) -> f64 {
        self.reader.topic_len() as f64
    }
    /// Clouds of the topic met so far, kept or not (for progress).
    #[wasm_bindgen(getter)]
    pub fn met(&self) -> f64 {
        self.reader.clouds_met() as f64
    }
    /// The next kept cloud, described (its `name` says bag, topic and
    /// index; `pose()` its pose), or `undefined` after the last. A cloud,
    /// chunk or pose that cannot be read throws an Error naming the bag and
    /// the topic: call `next()` again for the clouds after it.
    #[wasm_bindgen(js_name = next)]
    pub fn next_cloud(&mut self) -> WasmResult<Option<DescribedScan>> {
        (self.reader.next())
            .map(|scan| DescribedScan::recorded(scan, "ros_bag", &self.params, self.preview_points))
            .transpose()
    }
}
