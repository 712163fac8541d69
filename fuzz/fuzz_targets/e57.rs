#![no_main]
//! E57 reader (every scan of a survey) on arbitrary bytes.
use libfuzzer_sys::fuzz_target;
use placecat::io::{e57, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_points: 1 << 20, max_bytes: 1 << 24, ..ReadLimits::default() };
    let _ = e57::read_scans(data, "fuzz.e57", &limits);
});
