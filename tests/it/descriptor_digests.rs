//! Descriptors unchanged by the speed work of issue 20: every real file,
//! every preset, gives the descriptor (matrices, summary counts, shape
//! classes) that the nalgebra-based code before it gave, bit for bit.
//! tests/fixtures/descriptor_digests.json holds an FNV-1a digest of each,
//! computed from `placecat describe` output of commit 86ed595.

use placecat::io::{read_scan, ReadLimits};
use placecat::{describe, Descriptor, DescriptorParams};

fn fnv(words: impl IntoIterator<Item = u32>) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    for w in words {
        for b in w.to_le_bytes() {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

fn digest(d: &Descriptor) -> String {
    let s = &d.summary;
    let head = [d.rows, d.cols, d.matrices.len()].map(|v| v as u32);
    let tail = [
        s.points,
        s.dropped,
        s.voxels,
        s.sparse_voxels,
        s.spherical,
        s.planar,
        s.linear,
        s.in_range,
        s.alignments,
    ]
    .map(|v| v as u32);
    let body = d.matrices.iter().flatten().copied();
    format!("{:016x}", fnv(head.into_iter().chain(body).chain(tail)))
}

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
