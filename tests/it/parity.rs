//! Native side of the native/wasm parity check: the labels computed here
//! must equal tests/fixtures/parity.json, which the wasm tests check too.
//! Regenerate the fixture with PLACECAT_WRITE_FIXTURES=1 cargo test --test it parity.

include!("../common/parity_case.rs");

#[test]
fn native_labels_match_the_shared_fixture() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/parity.json");
    let got = parity_case();
    if std::env::var_os("PLACECAT_WRITE_FIXTURES").is_some() {
        std::fs::write(path, serde_json::to_string_pretty(&got).unwrap() + "\n").unwrap();
    }
    let want: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    assert_eq!(got, want);
}
