#![no_main]
//! The JSON a user hands back: a saved model (page "Import model", CLI
//! `classify MODEL.json`) and a descriptor (`DescriptorSet.addJson`,
//! `cluster DESCRIPTORS.json`). Whatever parses must then be safe to use.
use libfuzzer_sys::fuzz_target;
use placecat::cluster::Space;
use placecat::model::LabelledModel;
use placecat::{Descriptor, DistanceOptions};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(model) = LabelledModel::from_json(text) {
        // A scan of the model's own shape: one count in every cell.
        let d = Descriptor {
            rows: model.rows,
            cols: model.cols,
            matrices: vec![vec![1; model.rows * model.cols]],
            summary: Default::default(),
        };
        let _ = model.classify(&d);
    }
    if let Ok(d) = serde_json::from_str::<Descriptor>(text) {
        if let Ok(space) = Space::new(&[d.clone(), d], DistanceOptions::default()) {
            let _ = space.delta(0, 1);
            let _ = space.to_centre(&space.centre_of(0), 1);
        }
    }
});
