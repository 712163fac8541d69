//! `placecat`: the command-line tool (native only).
//!
//! Forms (other tooling scripts against these; add, never rename). Folders
//! are walked recursively; scans are named by their path relative to the
//! inputs' common folder; `-o -` writes to standard output.
//! - `placecat info FILE --json`
//! - `placecat describe [--preset P] [--params FILE.json] INPUT... -o OUT.json`
//! - `placecat describe BAG... [--topic T] [--every N | --every-metres D] [--pose-topic T | --tf-frame F | --no-poses] [--poses-out POSES.csv] -o OUT.json`
//! - `placecat topics BAG [--json]`
//! - `placecat distances DESCRIPTORS.json [-o OUT.csv]`
//! - `placecat cluster DESCRIPTORS.json --method kmeans --k K --seeding random|stride|plusplus|spectral --seed S [--restarts N] -o OUT.json`
//! - `placecat cluster DESCRIPTORS.json --method hkmeans [--threshold T | --categories K|auto] --seed S [--restarts N] -o OUT.json`
//! - `placecat cluster DESCRIPTORS.json --method spectral --k K [--seed S] [--restarts N] [--neighbours M] -o OUT.json` (at most 2000 scans)
//! - `placecat cluster DESCRIPTORS.json --method dbscan --eps E --min-points C -o OUT.json`
//! - `placecat cluster ... --format csv -o OUT.csv` (`file,category` rows; also for any `*.csv` output)
//! - `placecat evaluate OUT.json --truth labels.csv`
//! - `placecat sweep DESCRIPTORS.json [--truth labels.csv] [--eps E,...] [--min-points C,...] [-o OUT.csv]`
//! - `placecat model DESCRIPTORS.json --names NAMES.csv -o MODEL.json`
//! - `placecat classify MODEL.json INPUT... [-o OUT.csv]`
//! - `placecat map OUT.json --poses POSES [--scans ROOT] -o map.svg`
//! - `placecat simulate --scene indoor|warehouse|outdoor --seed S [--scans N] [--buildings one|many] -o DIR`

#[cfg(not(target_arch = "wasm32"))]
mod cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    keep_freed_memory();
    cli::main()
}

/// glibc returns freed blocks of a few MB to the kernel (mmap'd blocks, and
/// the heap's top once 2x the mmap threshold is free), so every scan of a
/// folder faulted its buffers in again: 28,500 page faults and a quarter
/// of the CPU time of `describe` on 40 scans of 100k points (issue 20).
/// Keeping freed memory for reuse costs nothing the process does not
/// already hold at its peak.
#[cfg(not(target_arch = "wasm32"))]
fn keep_freed_memory() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets allocator parameters; called before any
    // thread starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 1 << 30);
        libc::mallopt(libc::M_TRIM_THRESHOLD, 1 << 30);
    }
}

// wasm-pack builds every target of the crate for wasm32; the CLI has no
// meaning there.
#[cfg(target_arch = "wasm32")]
fn main() {}
