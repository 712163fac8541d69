//! `placecat classify`: new scans into the named categories of a model
//! (exported from the page, or built with `placecat::model`).

use super::describe::{csv_cell, describe_files, expand};
use placecat::io::ReadLimits;
use placecat::model::LabelledModel;
use placecat::{Error, Result};
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// CSV `file,category,distance,relative` to `output` (stdout if none):
/// each scan's nearest category; relative > 1 means farther from it than
/// any scan the category was made from. Bad files are reported and skipped.
pub fn run(
    model: &Path,
    inputs: &[PathBuf],
    output: Option<&Path>,
    limits: &ReadLimits,
) -> Result<ExitCode> {
    let shown = model.display().to_string();
    let text = std::fs::read_to_string(model).map_err(|e| Error::from(e).in_file(&shown))?;
    let model = LabelledModel::from_json(&text).map_err(|e| e.in_file(&shown))?;
    let files = expand(inputs)?;
    let mut out = String::from("file,category,distance,relative\n");
    let mut classified = 0;
    // The scans are described with the model's own parameters.
    for described in describe_files(&files, &model.params, limits, "classifying")?
        .into_iter()
        .flatten()
    {
        let c = model.classify(&described.descriptor)?;
        classified += 1;
        writeln!(
            out,
            "{},{},{},{}",
            csv_cell(&described.path),
            csv_cell(&c.name),
            c.distance,
            c.relative
        )
        .expect("writing to a String");
    }
    super::write_out(output, &out)?;
    eprintln!("classified {classified} of {} files", files.len());
    Ok(if classified == 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}
