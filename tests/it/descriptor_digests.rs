//! Descriptors unchanged by the speed work of issue 20: every real file,
//! every preset, gives the descriptor (matrices, summary counts, shape
//! classes) that the nalgebra-based code before it gave, bit for bit.
//! tests/fixtures/descriptor_digests.json holds an FNV-1a digest of each,
//! computed from `placecat describe` output of commit 86ed595.

use placecat::io::{read_scan, ReadLimits};
use placecat::{describe, DescriptorParams};

include!("../common/descriptor_digest.rs");

#[test]
fn real_files_give_the_same_descriptors_as_before() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/descriptor_digests.json"
    );
    let want: std::collections::BTreeMap<String, String> =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    assert_eq!(want.len(), 4 * 18);
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real");
    let mut differ = Vec::new();
    for (key, digest_before) in &want {
        let (preset, file) = key.split_once('/').unwrap();
        let params = DescriptorParams::preset(preset).unwrap();
        let bytes = std::fs::read(format!("{root}/{file}")).unwrap();
        let cloud = read_scan(&bytes, file, &ReadLimits::default()).unwrap();
        let got = digest(&describe(&cloud.points, &params).unwrap());
        if &got != digest_before {
            differ.push(key.clone());
        }
    }
    assert!(differ.is_empty(), "descriptors changed: {differ:?}");
}
