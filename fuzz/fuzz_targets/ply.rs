#![no_main]
//! PLY reader on arbitrary bytes: never a panic, hang or huge allocation.
use libfuzzer_sys::fuzz_target;
use placecat::io::{ply, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_points: 1 << 20, max_bytes: 1 << 24, ..ReadLimits::default() };
    let _ = ply::read(data, &limits);
});
