//! The regression corpus of damaged scans (tests/data/bad, written by its
//! make_bad.py): each file gives exactly the message in expected.tsv,
//! strict and lenient. tests/wasm_api runs the same table in wasm32.

include!("../common/bad_corpus.rs");

use placecat::io::{read_scan_named, ReadLimits};

fn read(bytes: &[u8], name: &str, lenient: bool) -> String {
    let limits = ReadLimits {
        lenient,
        ..Default::default()
    };
    bad_outcome(read_scan_named(bytes, name, &limits).map(|c| c.points.len()))
}

#[test]
fn every_damaged_file_gives_its_message() {
    let wrong = bad_mismatches(read);
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_embedded_list_is_the_folder() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/bad");
    let mut on_disk: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".py") && !n.ends_with(".tsv") && !n.ends_with(".md"))
        .collect();
    on_disk.sort();
    let embedded: Vec<&str> = BAD_FILES.iter().map(|(n, _)| *n).collect();
    assert_eq!(
        on_disk, embedded,
        "add new files to tests/common/bad_corpus.rs"
    );
    // The embedded bytes are the files' (not a stale copy).
    for (name, bytes) in BAD_FILES {
        assert_eq!(
            std::fs::read(format!("{dir}/{name}")).unwrap(),
            bytes,
            "{name}"
        );
    }
}

/// Print the table's rows as the readers give them (to write expected.tsv
/// after adding a file; check every message by eye before keeping it):
/// `cargo test --test it bad_files -- --ignored --nocapture`.
#[test]
#[ignore]
fn print_rows() {
    for (name, bytes) in BAD_FILES {
        println!(
            "{name}\t{}\t{}",
            read(bytes, name, false),
            read(bytes, name, true)
        );
    }
}
