#![no_main]
//! The JSON a user hands back: a saved model (page "Import model", CLI
//! `classify MODEL.json`) and a descriptor (`DescriptorSet.addJson`,
//! `cluster DESCRIPTORS.json`).
use libfuzzer_sys::fuzz_target;

include!("../common/use_json.rs");

fuzz_target!(|data: &[u8]| use_json(data));
