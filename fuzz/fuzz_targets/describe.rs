#![no_main]
//! Read any format (sniffed) and describe: the path the page and CLI take.
use libfuzzer_sys::fuzz_target;
use placecat::io::{read_scan, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_points: 1 << 18, max_bytes: 1 << 24, ..ReadLimits::default() };
    // The first byte picks the name, so the .bin path is reached too.
    let name = match data.first().map(|b| b % 3) {
        Some(0) => "scan.bin",
        Some(1) => "scan.ply",
        _ => "scan.pcd",
    };
    if let Ok(cloud) = read_scan(data.get(1..).unwrap_or(&[]), name, &limits) {
        let _ = placecat::describe(&cloud.points, &placecat::DescriptorParams::indoor());
    }
});
