//! The real scans in tests/data/real with the place each was recorded at
//! (groups.csv), for the examples that report on them.

use placecat::cluster::Space;
use placecat::{describe, io, DescriptorParams, DistanceOptions};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

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

/// Same-place retrieval on the real scans (tests/data/real/groups.csv).
#[allow(dead_code)] // the rounds that compare presets (near_ranges.rs, columns.rs)
#[derive(Serialize, Deserialize, Clone)]
pub struct RealRow {
    pub preset: String,
    pub scans: usize,
    pub same_place: usize,
    /// Scans whose nearest other scan is of another place (or the reason
    /// none could be described).
    pub wrong: Vec<String>,
}

/// Real-scan retrieval for every preset of the round.
#[allow(dead_code)]
pub fn real_rows(
    presets: &[(String, Vec<String>)],
) -> Result<Vec<RealRow>, Box<dyn std::error::Error>> {
    let scans = real_scans();
    if scans.is_empty() {
        return Err(
            "no real scans (tests/data/real/groups.csv): retrieval cannot be reported".into(),
        );
    }
    let mut names: Vec<&String> = presets.iter().flat_map(|p| &p.1).collect();
    names.sort();
    names.dedup();
    let mut rows = vec![];
    for name in names {
        let p = DescriptorParams::preset(name)?;
        let (same_place, wrong) = match wrong_places(&scans, &p)? {
            Ok(wrong) => (scans.len() - wrong.len(), wrong),
            Err(e) => (0, vec![format!("cannot describe every scan: {e}")]),
        };
        rows.push(RealRow {
            preset: name.clone(),
            scans: scans.len(),
            same_place,
            wrong,
        });
    }
    Ok(rows)
}

/// [`real_rows`] as a markdown table.
#[allow(dead_code)]
pub fn real_table(o: &mut String, rows: &[RealRow]) -> Result<(), Box<dyn std::error::Error>> {
    use std::fmt::Write;
    writeln!(o, "| preset | same place | wrong |\n|---|---|---|")?;
    for r in rows {
        let wrong = if r.wrong.is_empty() {
            "-".into()
        } else {
            r.wrong.join(", ")
        };
        writeln!(
            o,
            "| `{}` | {} of {} | {wrong} |",
            r.preset, r.same_place, r.scans
        )?;
    }
    Ok(())
}
