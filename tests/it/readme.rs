//! The README's Rust example is the crate's doc example (which `cargo test`
//! compiles and runs), so the README cannot drift from code that works.

/// The first ```rust block of `text`, with `strip` taken off each line.
fn rust_block(text: &str, strip: &str) -> String {
    let lines: Vec<&str> = text
        .lines()
        // "//! code", and "//!" alone for an empty line.
        .map(|l| {
            l.strip_prefix(strip)
                .or_else(|| l.strip_prefix(strip.trim_end()))
                .unwrap_or(l)
        })
        .collect();
    let start = lines
        .iter()
        .position(|l| *l == "```rust")
        .expect("a ```rust block")
        + 1;
    let len = lines[start..]
        .iter()
        .position(|l| *l == "```")
        .expect("its end");
    lines[start..start + len].join("\n")
}

#[test]
fn readme_rust_example_is_the_crate_doc_example() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/README.md")).unwrap();
    let lib = std::fs::read_to_string(format!("{root}/src/lib.rs")).unwrap();
    let doc: String = lib
        .lines()
        .take_while(|l| l.starts_with("//!"))
        .collect::<Vec<_>>()
        .join("\n");
    let from_readme = rust_block(&readme, "");
    assert!(
        from_readme.contains("LabelledModel::build"),
        "{from_readme}"
    );
    assert_eq!(from_readme, rust_block(&doc, "//! "));
}
