#![no_main]
//! KITTI .bin reader on arbitrary bytes.
use libfuzzer_sys::fuzz_target;
use placecat::io::{kitti, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let _ = kitti::read(data, &ReadLimits { max_points: 1 << 20, max_bytes: 1 << 24, ..ReadLimits::default() });
});
