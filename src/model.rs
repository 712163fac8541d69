//! A labelled model: the user's names for categories and what is needed to
//! classify a new scan (each category's centre in descriptor space), with
//! the descriptor parameters it was made with. Saved and loaded as JSON.

use crate::descriptor::parts::{cumulative_len, MAX_PARTS};
use crate::descriptor::{Descriptor, DescriptorParams, Scale};
use crate::distance::{
    check_shape, matrix_distance, pad, size_factor, unpad, DistanceOptions, Prepared, Space,
};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Format tag written into every model file.
pub const MODEL_FORMAT: &str = "placecat-model/1";

/// One named category.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Category {
    /// The name the user gave it.
    pub name: String,
    /// Cluster label this category came from.
    pub label: i32,
    /// Scans it was made from.
    pub members: usize,
    /// Normalised centre matrix, column-major (cols blocks of rows values).
    pub centre: Vec<f32>,
    /// Members' mean |F|.
    pub total: f32,
    /// Largest Delta from the centre to a member: beyond ~this, a new scan
    /// is unlike anything the category saw.
    pub radius: f32,
    /// Members' mean extra parts, weighted as the model's parameters say
    /// (the form of `Prepared::parts`); absent without parts.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub parts: Vec<f32>,
}

/// Categories with names, ready to classify new scans. Deserialisation
/// goes through the checks of [`LabelledModel::from_json`], so a model read
/// by serde is never malformed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "ModelData")]
pub struct LabelledModel {
    /// [`MODEL_FORMAT`].
    pub format: String,
    /// The descriptor parameters the model was made with.
    pub params: DescriptorParams,
    /// Rows of every centre matrix.
    pub rows: usize,
    /// Columns of every centre matrix.
    pub cols: usize,
    /// The named categories (at least one).
    pub categories: Vec<Category>,
    /// With [`Scale::Median`] parameters, the weights the scans it was
    /// built from gave (`distance::scale`): new scans are compared with
    /// these, not with medians of their own. Absent otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scaled_weights: Option<ScaledWeights>,
}

/// The weights of a median-scaled distance, as a space resolved them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ScaledWeights {
    /// Delta's weight over its median.
    pub ndt_weight: f32,
    /// Each part kind's weight over its median, indexed by
    /// [`PartKind::index`](crate::descriptor::PartKind::index).
    #[serde(deserialize_with = "part_weights_of_any_version")]
    pub part_weights: [f32; MAX_PARTS],
}

/// Part weights as a model file holds them: one per part kind of the
/// version that wrote it. A model written before `iron` was added lists
/// seven (the only count written before; the median scale came after
/// `columns`), one written before `objects` eight, one written before
/// `object_types` and `object_layout` (added together) nine; the kinds
/// added since weigh 0 in it. Any other count is an error.
fn part_weights_of_any_version<'de, D: serde::Deserializer<'de>>(
    d: D,
) -> std::result::Result<[f32; MAX_PARTS], D::Error> {
    /// The part kinds of the versions that wrote models: before `iron`
    /// (when the median scale came), before `objects`, before
    /// `object_types` and `object_layout`.
    const EARLIER: [usize; 3] = [7, 8, 9];
    let given = Vec::<f32>::deserialize(d)?;
    if given.len() != MAX_PARTS && !EARLIER.contains(&given.len()) {
        return Err(serde::de::Error::custom(format!(
            "{} part weights, but this version knows {MAX_PARTS} part kinds (or 7, 8 or 9 from earlier versions)",
            given.len()
        )));
    }
    let mut weights = [0.0; MAX_PARTS];
    weights[..given.len()].copy_from_slice(&given);
    Ok(weights)
}

/// A model as read, before its checks.
#[derive(Deserialize)]
struct ModelData {
    format: String,
    params: DescriptorParams,
    rows: usize,
    cols: usize,
    categories: Vec<Category>,
    #[serde(default)]
    scaled_weights: Option<ScaledWeights>,
}

impl TryFrom<ModelData> for LabelledModel {
    type Error = Error;
    fn try_from(m: ModelData) -> Result<LabelledModel> {
        if m.format != MODEL_FORMAT {
            return Err(Error::Mismatch(format!(
                "not a placecat model (format {:?}, expected {MODEL_FORMAT:?})",
                m.format
            )));
        }
        m.params.validate()?;
        if m.rows != m.params.rows() || m.cols != m.params.cols() {
            return Err(Error::Mismatch(
                "the model's matrix shape does not match its parameters".into(),
            ));
        }
        if m.categories.is_empty() {
            return Err(Error::Mismatch("the model has no categories".into()));
        }
        match (m.params.scale, &m.scaled_weights) {
            (Scale::Fixed, None) => {}
            (Scale::Median, Some(w)) => {
                let mut all = std::iter::once(w.ndt_weight).chain(w.part_weights);
                if !all.all(|v| v.is_finite() && v >= 0.0) {
                    return Err(Error::Mismatch(
                        "the model's scaled weights must be finite and not negative".into(),
                    ));
                }
            }
            (Scale::Median, None) => {
                return Err(Error::Mismatch(
                    "the model's parameters scale by medians but it holds no scaled weights".into(),
                ))
            }
            (Scale::Fixed, Some(_)) => {
                return Err(Error::Mismatch(
                    "the model holds scaled weights but its parameters do not scale".into(),
                ))
            }
        }
        let parts_len: usize = m.params.parts.iter().map(|p| cumulative_len(p.kind)).sum();
        for c in &m.categories {
            if c.parts.len() != parts_len || !c.parts.iter().all(|v| v.is_finite()) {
                return Err(Error::Mismatch(format!(
                    "category {:?} has {} part values, its parameters make {parts_len}",
                    c.name,
                    c.parts.len()
                )));
            }
            if c.centre.len() != m.rows * m.cols
                || !c.centre.iter().all(|v| v.is_finite())
                || c.total.is_nan()
                || c.total <= 0.0
            {
                return Err(Error::Mismatch(format!(
                    "category {:?} has a malformed centre",
                    c.name
                )));
            }
        }
        Ok(LabelledModel {
            format: m.format,
            params: m.params,
            rows: m.rows,
            cols: m.cols,
            categories: m.categories,
            scaled_weights: m.scaled_weights,
        })
    }
}

/// A category without its centre: what a user sees of a model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct CategorySummary {
    /// The category's name.
    pub name: String,
    /// The cluster label it came from.
    pub label: i32,
    /// Scans it was made from.
    pub members: usize,
    /// Largest Delta from its centre to a member.
    pub radius: f32,
}

/// The answer for one scan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(target_arch = "wasm32", derive(tsify::Tsify))]
pub struct Classification {
    /// The category's name.
    pub name: String,
    /// The cluster label of the category.
    pub label: i32,
    /// Delta from the scan to the category's centre.
    pub distance: f32,
    /// distance / the category's radius (> 1: farther than any member was).
    /// A category made from one scan has radius 0: a scan at distance 0 (the
    /// same scan again) is 0, any other is infinite.
    pub relative: f32,
}

/// `distance / radius`, where a zero radius (a one-scan category) gives 0
/// for a zero distance instead of NaN: "as near as any member was".
fn relative_distance(distance: f32, radius: f32) -> f32 {
    if radius > 0.0 {
        distance / radius
    } else if distance == 0.0 {
        0.0
    } else {
        f32::INFINITY
    }
}

impl LabelledModel {
    /// Build from described scans, their cluster labels (-1 ignored) and a
    /// name per label (labels without a name are called "category N").
    pub fn build(
        params: &DescriptorParams,
        descriptors: &[Descriptor],
        labels: &[i32],
        names: &[(i32, String)],
    ) -> Result<LabelledModel> {
        if descriptors.len() != labels.len() {
            return Err(Error::Mismatch(format!(
                "{} labels for {} descriptors",
                labels.len(),
                descriptors.len()
            )));
        }
        // A model must load again: its descriptors' shape and parts must be
        // those its parameters make (from_json checks the same).
        for d in descriptors {
            d.validate_for(params)?;
        }
        let space = Space::new(descriptors, DistanceOptions::from(params))?;
        let mut ids: Vec<i32> = labels.iter().copied().filter(|&l| l >= 0).collect();
        ids.sort_unstable();
        ids.dedup();
        if ids.is_empty() {
            return Err(Error::InvalidParameter(
                "no labelled scans to build a model from".into(),
            ));
        }
        let first = &space.items[0];
        let mut categories = Vec::new();
        for id in ids {
            let members: Vec<usize> = (0..labels.len()).filter(|&i| labels[i] == id).collect();
            // Start at the first member, then refine twice so each member
            // contributes its candidate nearest to the mean.
            let mut centre = space.centre_of(members[0]);
            for _ in 0..3 {
                centre = space.mean(&members, &centre).unwrap_or(centre);
            }
            let radius = members
                .iter()
                .map(|&i| space.to_centre(&centre, i).0)
                .fold(0f32, f32::max);
            let name = names
                .iter()
                .find(|(l, _)| *l == id)
                .map(|(_, n)| n.clone())
                .unwrap_or_else(|| format!("category {id}"));
            categories.push(Category {
                name,
                label: id,
                members: members.len(),
                centre: unpad(&centre.matrix, first.rows, first.stride),
                total: centre.total,
                radius,
                parts: centre.parts,
            });
        }
        let scaled_weights = (!params.scale.is_fixed()).then_some(ScaledWeights {
            ndt_weight: space.options.ndt_weight,
            part_weights: space.options.part_weights,
        });
        Ok(LabelledModel {
            format: MODEL_FORMAT.into(),
            params: params.clone(),
            rows: first.rows,
            cols: first.cols,
            categories,
            scaled_weights,
        })
    }

    /// Parse and check a model file (the checks' own message, not wrapped
    /// in serde's).
    pub fn from_json(text: &str) -> Result<LabelledModel> {
        LabelledModel::try_from(serde_json::from_str::<ModelData>(text)?)
    }

    /// The model as JSON text (what [`LabelledModel::from_json`] reads).
    pub fn to_json(&self) -> Result<String> {
        Ok(serde_json::to_string(self)?)
    }

    /// Every category without its centre.
    pub fn summaries(&self) -> Vec<CategorySummary> {
        self.categories
            .iter()
            .map(|c| CategorySummary {
                name: c.name.clone(),
                label: c.label,
                members: c.members,
                radius: c.radius,
            })
            .collect()
    }

    /// Rename categories: (label, new name) pairs.
    pub fn rename(&mut self, names: &[(i32, String)]) {
        for c in &mut self.categories {
            if let Some((_, n)) = names.iter().find(|(l, _)| *l == c.label) {
                c.name = n.clone();
            }
        }
    }

    /// How new scans are compared with the centres: the parameters'
    /// distance, with the scaled weights when the model has them.
    fn distance_options(&self) -> DistanceOptions {
        let opts = DistanceOptions::from(&self.params);
        match self.scaled_weights {
            Some(w) => DistanceOptions {
                ndt_weight: w.ndt_weight,
                part_weights: w.part_weights,
                scale: Scale::Fixed,
                ..opts
            },
            None => opts,
        }
    }

    /// The nearest category of a scan described with `made_with`, refused
    /// unless those are the model's parameters but for the preset's name
    /// (a scan of another `sensor_height` or voxel size has the same shape
    /// and would be classified by a distance that means nothing).
    pub fn classify_made_with(
        &self,
        d: &Descriptor,
        made_with: &DescriptorParams,
    ) -> Result<Classification> {
        self.params.check_made_with(made_with, "model")?;
        self.classify(d)
    }

    /// The nearest category of a described scan.
    pub fn classify(&self, d: &Descriptor) -> Result<Classification> {
        check_shape((d.rows, d.cols), (self.rows, self.cols))?;
        d.validate_for(&self.params)?;
        let p = Prepared::new(d, self.distance_options())?;
        let mut best: Option<Classification> = None;
        for c in &self.categories {
            let centre = pad(&c.centre, self.rows, p.stride);
            let ndt = || {
                p.candidates()
                    .map(|m| matrix_distance(&centre, m, p.stride, self.cols, self.params.metric))
                    .fold(f32::INFINITY, f32::min)
                    * size_factor(c.total, p.total)
            };
            let dist = p.combined(ndt, &c.parts);
            if best.as_ref().is_none_or(|b| dist < b.distance) {
                best = Some(Classification {
                    name: c.name.clone(),
                    label: c.label,
                    distance: dist,
                    relative: relative_distance(dist, c.radius),
                });
            }
        }
        best.ok_or_else(|| Error::Mismatch("the model has no categories".into()))
    }
}
