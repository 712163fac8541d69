//! Inputs the fuzzers (fuzz/) found to crash, hang or over-allocate, kept so
//! the normal suite checks them: each must give a result (usually an error)
//! quickly. The file's extension picks the reader, as in the CLI; `.json`
//! takes the path of the `json` fuzz target (model, then descriptor).

use placecat::io::{read_scan, ReadLimits};
use std::time::{Duration, Instant};

include!("../fuzz/common/use_json.rs");

#[test]
fn every_kept_fuzz_finding_reads_or_fails_fast() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fuzz_regressions");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        let t = Instant::now();
        // On a thread, so a hang fails the test instead of stalling it.
        let (tx, rx) = std::sync::mpsc::channel();
        let shown = name.clone();
        std::thread::spawn(move || {
            if shown.ends_with(".json") {
                use_json(&bytes);
            } else if let Ok(c) = read_scan(&bytes, &shown, &ReadLimits::default()) {
                let _ = placecat::describe(&c.points, &placecat::DescriptorParams::indoor());
            }
            let _ = tx.send(());
        });
        // Generous for a slow CI machine; the bugs these catch took minutes or forever.
        assert!(
            rx.recv_timeout(Duration::from_secs(5)).is_ok(),
            "{name} did not finish in {:?}",
            t.elapsed()
        );
        n += 1;
    }
    assert!(n >= 1);
}
