//! Reads every cloud of a ROS bag and reports throughput, to show that the
//! bag streams (run under `/usr/bin/time -v` for the peak memory):
//! `cargo run --release --example bag_throughput -- BAG`
//!
//! Measured (2 cores shared with other builds, load average 10-15), on bags
//! from `tests/data/bags/make_big_bag.py` (ROS 1, lz4 chunks of one 100k-point
//! cloud each, with odometry, poses on): 308 MB (200 clouds) in 2.8-3.1 s wall,
//! 0.54 s CPU, peak RSS 8.0 MB; 1018 MB (660 clouds) in 5.4 s wall (190 MB/s),
//! 1.76 s CPU (580 MB/s), peak RSS 8.2 MB: memory follows the chunk, not the file.
//! rosbag2 MCAP with zstd chunks (`make_big_bag.py OUT.mcap`), 251 MB (200
//! clouds): 3.6-4.6 s wall, 2.2 s CPU (ruzstd, pure Rust: ~115 MB/s of
//! compressed input), peak RSS 11 MB.
use placecat::io::bag::{BagOptions, BagReader};
use std::time::Instant;

fn main() -> placecat::Result<()> {
    let path = std::env::args().nth(1).expect("usage: bag_throughput BAG");
    let path = std::path::Path::new(&path);
    let bytes = std::fs::metadata(path)?.len() as f64;
    let start = Instant::now();
    let (mut clouds, mut points, mut errors, mut posed) = (0usize, 0usize, 0usize, 0usize);
    for item in BagReader::open_path(path, BagOptions::default())? {
        match item {
            Ok(c) => {
                clouds += 1;
                points += c.points.len();
                posed += c.pose.is_some() as usize;
            }
            Err(e) => {
                errors += 1;
                eprintln!("{e}");
            }
        }
    }
    let s = start.elapsed().as_secs_f64();
    println!(
        "{clouds} clouds ({posed} with a pose), {points} points, {errors} errors, {:.0} MB in {s:.2} s: {:.0} MB/s",
        bytes / 1e6,
        bytes / 1e6 / s
    );
    Ok(())
}
