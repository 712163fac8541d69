#![no_main]
//! PCD reader (ascii, binary, LZF) on arbitrary bytes.
use libfuzzer_sys::fuzz_target;
use placecat::io::{pcd, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_points: 1 << 20, max_bytes: 1 << 24, ..ReadLimits::default() };
    let _ = pcd::read(data, &limits);
});
