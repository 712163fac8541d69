//! The real scans in tests/data/real with the place each was recorded at
//! (groups.csv), for the examples that report on them.

use placecat::io;

/// (file, place, points) for each row of groups.csv; empty (with a note on
/// stderr) when the folder is missing.
pub fn real_scans() -> Vec<(String, String, Vec<[f32; 3]>)> {
    let real = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real");
    let Ok(groups) = std::fs::read_to_string(format!("{real}/groups.csv")) else {
        eprintln!("no {real}/groups.csv: real files left out");
        return vec![];
    };
    groups
        .lines()
        .skip(1)
        .filter_map(|l| l.split_once(','))
        .map(|(f, p)| {
            let path = format!("{real}/{f}");
            let c = io::read_path(std::path::Path::new(&path), &Default::default())
                .unwrap_or_else(|e| panic!("{e}"));
            (f.to_string(), p.to_string(), c.points)
        })
        .collect()
}
