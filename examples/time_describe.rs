//! Times read + describe (outdoor preset) of each file natively, one core,
//! median and fastest of RUNS runs (default 5) after a warm-up; prints JSON. Used by bench/run.mjs to
//! compare with the wasm build on the same files. bench/run.mjs runs it with
//! glibc told to keep freed memory (`GLIBC_TUNABLES`), as wasm's allocator
//! does: otherwise this loop pays the kernel for the points' buffer on
//! every run, which no other user of the library does.
use placecat::io::{read_scan, ReadLimits};
use placecat::{describe, DescriptorParams};
use std::time::Instant;

fn main() {
    let p = DescriptorParams::outdoor();
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(5);
    let mut out = serde_json::Map::new();
    for path in std::env::args().skip(1) {
        let bytes = std::fs::read(&path).unwrap();
        let mut times = Vec::new();
        let mut points = 0;
        for r in 0..=runs {
            let t = Instant::now();
            let c = read_scan(&bytes, &path, &ReadLimits::default()).unwrap();
            let d = describe(&c.points, &p).unwrap();
            let dt = t.elapsed().as_secs_f64();
            points = c.points.len();
            std::hint::black_box(d);
            if r > 0 {
                times.push(dt);
            }
        }
        times.sort_by(f64::total_cmp);
        out.insert(
            path,
            serde_json::json!({"points": points, "seconds": times[times.len() / 2], "fastest": times[0]}),
        );
    }
    println!("{}", serde_json::Value::Object(out));
}
