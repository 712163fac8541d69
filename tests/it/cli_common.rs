//! Helpers of the command-line tests: run the built `placecat`, require
//! success or failure, read its JSON, make a scratch folder.

use std::process::{Command, Output};

/// The `placecat` binary built for these tests.
pub fn placecat() -> Command {
    Command::new(env!("CARGO_BIN_EXE_placecat"))
}

/// Run `cmd` and require success; a failure shows the command and stderr.
pub fn succeeds(cmd: &mut Command) -> Output {
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{cmd:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Run `cmd` and require failure; its stderr.
pub fn fails(cmd: &mut Command) -> String {
    let out = cmd.output().unwrap();
    assert!(!out.status.success(), "{cmd:?} succeeded");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A JSON file's value.
pub fn read_json(path: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// An empty scratch folder of this test process.
pub fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("placecat-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}
