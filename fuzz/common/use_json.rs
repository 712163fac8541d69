// What the `json` fuzz target does with its input, shared with
// tests/fuzz_regressions.rs (both `include!` this file): a saved model and
// a descriptor, as a user hands them back; whatever parses must be safe to
// use.
fn use_json(bytes: &[u8]) {
    use placecat::cluster::Space;
    use placecat::model::LabelledModel;
    use placecat::{Descriptor, DistanceOptions};

    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    if let Ok(model) = LabelledModel::from_json(text) {
        // A scan of the model's own shape: one count in every cell, and
        // each of its parts' channels uniform.
        let parts = model
            .params
            .parts
            .iter()
            .map(|p| placecat::descriptor::PartValues {
                kind: p.kind,
                values: p
                    .kind
                    .channels()
                    .iter()
                    .flat_map(|&b| vec![1.0 / b as f32; b])
                    .collect(),
            })
            .collect();
        let d = Descriptor {
            rows: model.rows,
            cols: model.cols,
            matrices: vec![vec![1; model.rows * model.cols]],
            summary: Default::default(),
            parts,
        };
        let _ = model.classify(&d);
    }
    if let Ok(d) = serde_json::from_str::<Descriptor>(text) {
        if let Ok(space) = Space::new(&[d.clone(), d], DistanceOptions::default()) {
            let _ = space.delta(0, 1);
            let _ = space.to_centre(&space.centre_of(0), 1);
        }
    }
}
