#![no_main]
//! Poses parser (KITTI, TUM, CSV) on arbitrary text.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = placecat::io::poses::parse(text);
    }
});
