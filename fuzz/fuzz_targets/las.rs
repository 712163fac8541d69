#![no_main]
//! LAS / LAZ reader on arbitrary bytes, with and without a sensor position
//! (the laz decoder asserts on some damaged input: the reader must turn
//! that into an error).
use libfuzzer_sys::fuzz_target;
use placecat::io::{las, ReadLimits};

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_points: 1 << 20, max_bytes: 1 << 24, ..ReadLimits::default() };
    let _ = las::read(data, &limits, None);
    let _ = las::read(data, &limits, Some([512345.678, 6123456.789, 98.765]));
});
