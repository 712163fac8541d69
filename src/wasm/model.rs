//! `ClusterTree` (a hierarchical k-means++ tree) and `Model`.

use super::*;

/// The hierarchical k-means++ tree.
#[wasm_bindgen]
pub struct ClusterTree {
    pub(super) tree: cluster::Tree,
    /// What built it: the choice of K builds trees on reference sets alike.
    pub(super) params: HkMeansParams,
}

#[wasm_bindgen]
impl ClusterTree {
    /// Categories at threshold t: `{threshold, labels, nodes}`.
    #[wasm_bindgen(unchecked_return_type = "Cut")]
    pub fn cut(&self, threshold: f32) -> WasmResult<JsValue> {
        to_js(&self.tree.cut(threshold)?)
    }
    /// The cut giving k categories: the tree's k - 1 highest splits (of two
    /// splits at one height, the parent's first, which no threshold can
    /// separate). Fewer only when the tree has fewer than k leaves.
    #[wasm_bindgen(js_name = cutK, unchecked_return_type = "Cut")]
    pub fn cut_k(&self, k: f64) -> WasmResult<JsValue> {
        to_js(&self.tree.cut_k(set::count("k", k)?)?)
    }
    /// Number of categories at threshold t; throws for a threshold that
    /// is not a finite number >= 0, as `cut` does.
    #[wasm_bindgen(js_name = countAt)]
    pub fn count_at(&self, threshold: f32) -> WasmResult<usize> {
        Ok(self.tree.count_at(threshold)?)
    }
    /// scipy-style linkage, (n-1) x 4 row-major: a, b, height, count.
    pub fn linkage(&self) -> js_sys::Float64Array {
        let flat: Vec<f64> = self.tree.linkage().into_iter().flatten().collect();
        js_sys::Float64Array::from(&flat[..])
    }
    /// Nodes: `[{members, height, children, parent}]`, node 0 the root.
    #[wasm_bindgen(unchecked_return_type = "TreeNode[]")]
    pub fn nodes(&self) -> WasmResult<JsValue> {
        to_js(&self.tree.nodes)
    }
    /// Height of the root (the largest Delta in the set).
    #[wasm_bindgen(js_name = rootHeight)]
    pub fn root_height(&self) -> f32 {
        self.tree.nodes[0].height
    }
}

/// A labelled model: names for categories, and centres to classify new scans.
#[wasm_bindgen]
pub struct Model {
    pub(super) model: LabelledModel,
}

#[wasm_bindgen]
impl Model {
    /// Load a model saved by `toJson()`; throws on malformed input.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> WasmResult<Model> {
        Ok(Model {
            model: LabelledModel::from_json(text).map_err(|e| e.in_file("model"))?,
        })
    }
    #[wasm_bindgen(js_name = toJson)]
    /// The model as JSON (`placecat-model/1`), as the CLI's `model` writes it.
    pub fn to_json(&self) -> WasmResult<String> {
        Ok(self.model.to_json()?)
    }
    /// `[{name, label, members, radius}]`.
    #[wasm_bindgen(unchecked_return_type = "CategorySummary[]")]
    pub fn categories(&self) -> WasmResult<JsValue> {
        to_js(&self.model.summaries())
    }
    /// Rename: `{label: name}` or `[[label, name], ...]`.
    pub fn rename(
        &mut self,
        #[wasm_bindgen(
            unchecked_param_type = "Record<number, string> | [number, string][] | undefined | null"
        )]
        names: JsValue,
    ) -> WasmResult<()> {
        self.model.rename(&names_from_js(names)?);
        Ok(())
    }
    /// The model's descriptor parameters (describe new scans with these).
    #[wasm_bindgen(unchecked_return_type = "Required<DescriptorParams>")]
    pub fn params(&self) -> WasmResult<JsValue> {
        params_to_js(&self.model.params)
    }
    /// Classify a described scan: `{name, label, distance, relative}`
    /// (`relative` = distance / the category's radius; > 1: farther than
    /// any scan it was made from; `Infinity` for a one-scan category and
    /// any other scan). Refused, naming the scan and the first parameter
    /// that differs, unless the scan was described with the model's
    /// parameters (the preset's name aside).
    #[wasm_bindgen(unchecked_return_type = "Classification")]
    pub fn classify(&self, scan: &DescribedScan) -> WasmResult<JsValue> {
        let c = self
            .model
            .classify_made_with(&scan.descriptor, &scan.params);
        to_js(&c.map_err(|e| e.in_file(&scan.name))?)
    }
    /// Classify a descriptor given as JSON text. The bare JSON carries no
    /// parameters, so only its shape is checked: check the parameters it
    /// was described with once with `checkMadeWith`.
    #[wasm_bindgen(js_name = classifyJson, unchecked_return_type = "Classification")]
    pub fn classify_json(&self, json: &str) -> WasmResult<JsValue> {
        to_js(&self.model.classify(&descriptor_from_json(json)?)?)
    }
    /// Throw unless scans described with `params` (a plain object, as the
    /// set's constructor takes it) can be classified here: the model's
    /// parameters, the preset's name aside. The message names the first
    /// field that differs.
    #[wasm_bindgen(js_name = checkMadeWith)]
    pub fn check_made_with(
        &self,
        #[wasm_bindgen(unchecked_param_type = "DescriptorParams")] params: JsValue,
    ) -> WasmResult<()> {
        let made_with = params_from_js(params, None)?;
        Ok(self.model.params.check_made_with(&made_with, "model")?)
    }
}
