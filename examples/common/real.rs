//! The real scans in tests/data/real with the place each was recorded at
//! (groups.csv), for the examples that report on them.

use placecat::cluster::Space;
use placecat::{describe, io, DescriptorParams, DistanceOptions};
use rayon::prelude::*;

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

/// Same-place retrieval: the files of `scans` whose nearest other scan
/// under `params`' Delta was recorded at another place, or (the inner
/// error) why a scan could not be described.
#[allow(dead_code)] // choose_k.rs and experiments.rs only read the scans
pub fn wrong_places(
    scans: &[(String, String, Vec<[f32; 3]>)],
    params: &DescriptorParams,
) -> placecat::Result<Result<Vec<String>, placecat::Error>> {
    let ds = match scans
        .par_iter()
        .map(|s| describe(&s.2, params))
        .collect::<placecat::Result<Vec<_>>>()
    {
        Ok(ds) => ds,
        Err(e) => return Ok(Err(e)),
    };
    let m = Space::new(&ds, DistanceOptions::from(params))?.matrix();
    Ok(Ok((0..m.n)
        .filter(|&i| m.nearest_other(i).is_none_or(|j| scans[j].1 != scans[i].1))
        .map(|i| scans[i].0.clone())
        .collect()))
}
