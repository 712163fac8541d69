//! `placecat`: the command-line tool (native only).
//!
//! Forms (other tooling scripts against these; add, never rename):
//! - `placecat info FILE --json`
//! - `placecat describe [--preset P] [--params FILE.json] INPUT... -o OUT.json`
//! - `placecat distances DESCRIPTORS.json [-o OUT.csv]`

#[cfg(not(target_arch = "wasm32"))]
mod cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

// wasm-pack builds every target of the crate for wasm32; the CLI has no
// meaning there.
#[cfg(target_arch = "wasm32")]
fn main() {}
