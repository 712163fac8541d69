// The regression corpus of damaged scans (tests/data/bad), shared by
// tests/it/bad_files.rs (native) and tests/wasm_api (wasm32), kept out of
// tests/ itself so cargo does not build it as a test of its own. Included
// with `include!`: the same bytes must give the same message on both
// targets (a header count cast with `as usize` once made them differ).

/// Every file of the corpus, embedded (wasm tests cannot read a folder).
/// tests/it/bad_files.rs checks that this list is the folder's.
pub const BAD_FILES: [(&str, &[u8]); 17] = [
    ("ok_pcd_ascii_crlf.pcd", include_bytes!("../data/bad/ok_pcd_ascii_crlf.pcd")),
    ("ok_pcd_zero_padding.pcd", include_bytes!("../data/bad/ok_pcd_zero_padding.pcd")),
    ("ok_ply_trailing_newline.ply", include_bytes!("../data/bad/ok_ply_trailing_newline.ply")),
    ("pcd_ascii_extra_row.pcd", include_bytes!("../data/bad/pcd_ascii_extra_row.pcd")),
    ("pcd_ascii_row_values.pcd", include_bytes!("../data/bad/pcd_ascii_row_values.pcd")),
    ("pcd_binary_trailing_bytes.pcd", include_bytes!("../data/bad/pcd_binary_trailing_bytes.pcd")),
    ("pcd_size_entries.pcd", include_bytes!("../data/bad/pcd_size_entries.pcd")),
    ("pcd_size_over_32_bits.pcd", include_bytes!("../data/bad/pcd_size_over_32_bits.pcd")),
    ("pcd_type_word.pcd", include_bytes!("../data/bad/pcd_type_word.pcd")),
    ("pcd_width_height_points.pcd", include_bytes!("../data/bad/pcd_width_height_points.pcd")),
    ("ply_ascii_extra_row.ply", include_bytes!("../data/bad/ply_ascii_extra_row.ply")),
    ("ply_ascii_faces_missing.ply", include_bytes!("../data/bad/ply_ascii_faces_missing.ply")),
    ("ply_ascii_row_values.ply", include_bytes!("../data/bad/ply_ascii_row_values.ply")),
    ("ply_face_past_end.ply", include_bytes!("../data/bad/ply_face_past_end.ply")),
    ("ply_list_length_over_32_bits.ply", include_bytes!("../data/bad/ply_list_length_over_32_bits.ply")),
    ("ply_text_round_trip.ply", include_bytes!("../data/bad/ply_text_round_trip.ply")),
    ("ply_trailing_bytes.ply", include_bytes!("../data/bad/ply_trailing_bytes.ply")),
];

/// `file<TAB>strict<TAB>lenient`: what a user gets reading each file, an
/// error's full message or "N points".
pub const BAD_EXPECTED: &str = include_str!("../data/bad/expected.tsv");

/// What reading gives, in the table's words.
pub fn bad_outcome<E: std::fmt::Display>(
    result: Result<usize, E>,
) -> String {
    match result {
        Ok(n) => format!("{n} points"),
        Err(e) => e.to_string(),
    }
}

/// The rows of the table that `read(bytes, name, lenient)` does not
/// reproduce, as "file (strict|lenient): got ..., want ..."; empty when all
/// match. Also fails a row without a file or a file without a row.
pub fn bad_mismatches(read: impl Fn(&[u8], &str, bool) -> String) -> Vec<String> {
    let mut wrong = Vec::new();
    let rows: Vec<Vec<&str>> = BAD_EXPECTED
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| l.split('\t').collect())
        .collect();
    for (name, _) in BAD_FILES {
        if !rows.iter().any(|r| r[0] == name) {
            wrong.push(format!("{name}: no row in expected.tsv"));
        }
    }
    for row in &rows {
        let [name, strict, lenient] = row[..] else {
            wrong.push(format!("not three tab-separated cells: {row:?}"));
            continue;
        };
        let Some((_, bytes)) = BAD_FILES.iter().find(|(n, _)| *n == name) else {
            wrong.push(format!("{name}: in expected.tsv but not in BAD_FILES"));
            continue;
        };
        for (mode, want, lenient) in [("strict", strict, false), ("lenient", lenient, true)] {
            let got = read(bytes, name, lenient);
            if got != want {
                wrong.push(format!("{name} ({mode}):\n  got  {got}\n  want {want}"));
            }
        }
    }
    wrong
}
