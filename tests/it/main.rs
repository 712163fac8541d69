//! The Rust integration tests, in one binary: one module a subject, so the
//! crate is linked once rather than once per file (`cargo test --test it`;
//! `cargo test --test it cli::` runs one module).
//!
//! Kept apart: `tests/fuzz_regressions.rs` (also run in a debug build by
//! scripts/test.sh, where a hang cannot be optimised away) and
//! `tests/web.rs` / `tests/node.rs` (the wasm API tests, `tests/wasm_api/`,
//! that `wasm-pack test` runs in Chromium and in Node). Helpers shared with
//! them are in `tests/common/`.

#[path = "../common/mod.rs"]
mod common;

mod bad_files;
mod bags;
mod boundary;
mod choose_k;
mod cli;
mod cli_bags;
mod cli_common;
mod cli_trees;
mod clustering;
mod descriptor_digests;
mod descriptor_geometry;
mod parity;
mod parts;
mod properties;
mod readers;
mod readme;
mod real_data;
mod restarts;
mod scaled;
mod scene_families;
mod simulator;
mod survey;
mod untrusted_json;
mod wild_points;
