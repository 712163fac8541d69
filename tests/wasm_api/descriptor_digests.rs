//! The wasm build describes real files to the same bits as native: the
//! digests of tests/fixtures/descriptor_digests.json (native, every preset)
//! replayed here on a subset of its files small enough to compile in
//! (two sensors' .bin and two .pcd, 4.7 MB). The wasm voxel index
//! (ndt_grid.rs, `voxel_floor_wasm`) is the only path that differs from
//! native's in source, so this checks it end to end.

use placecat::io::{read_scan, ReadLimits};
use placecat::{describe, DescriptorParams};
use wasm_bindgen_test::*;

include!("../common/descriptor_digest.rs");

macro_rules! files {
    ($($name:literal),* $(,)?) => {
        [$(($name, include_bytes!(concat!("../data/real/", $name)) as &[u8])),*]
    };
}

const FILES: [(&str, &[u8]); 13] = files![
    "kitti00/000094.bin",
    "ouster_os0_sequence/scan_000.bin",
    "ouster_os0_sequence/scan_001.bin",
    "ouster_os0_sequence/scan_002.bin",
    "ouster_os0_sequence/scan_003.bin",
    "ouster_os0_sequence/scan_004.bin",
    "ouster_os0_sequence/scan_005.bin",
    "ouster_os0_sequence/scan_006.bin",
    "ouster_os0_sequence/scan_007.bin",
    "ouster_os0_sequence/scan_008.bin",
    "ouster_os0_sequence/scan_009.bin",
    "pcl_room/room_scan1.pcd",
    "velodyne_pair/251370668.pcd",
];

#[wasm_bindgen_test]
fn real_files_give_the_native_descriptor_digests() {
    let want: std::collections::BTreeMap<String, String> =
        serde_json::from_str(include_str!("../fixtures/descriptor_digests.json")).unwrap();
    let mut checked = 0;
    let mut differ = Vec::new();
    for preset in ["indoor", "indoor_bands", "outdoor", "perception_oru"] {
        let params = DescriptorParams::preset(preset).unwrap();
        for (file, bytes) in FILES {
            let key = format!("{preset}/{file}");
            let cloud = read_scan(bytes, file, &ReadLimits::default()).unwrap();
            let got = digest(&describe(&cloud.points, &params).unwrap());
            if Some(&got) != want.get(&key) {
                differ.push(format!("{key}: {got} (native {:?})", want.get(&key)));
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 4 * 13);
    assert!(differ.is_empty(), "wasm descriptors differ: {differ:?}");
}
