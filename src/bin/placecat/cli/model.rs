//! Named models: `placecat model` builds one from described scans and
//! their names, `placecat classify` puts new scans into its categories
//! (also for models exported from the page).

use super::bag::BagArgs;
use super::cluster::read_labels;
use super::describe::{describe_inputs, DescriptorsFile, ReadOptions};
use placecat::io::csv::quote;

use placecat::model::LabelledModel;
use placecat::{Error, Result};
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// One category per distinct name in `names` (`file,name` rows: the page's
/// "Export CSV", or a labels.csv, matched as `evaluate` matches them: on
/// the relative path, or on a base name only one scan has); scans it does
/// not name are left out.
pub fn build(descriptors: &Path, names: &Path, output: &Path) -> Result<ExitCode> {
    let set = DescriptorsFile::load(descriptors)?;
    let files = set.names();
    let table = read_labels(names)?;
    let mut kinds: Vec<String> = Vec::new();
    let labels: Vec<i32> = table
        .for_names(files)
        .into_iter()
        .map(|name| match name {
            Some(name) => match kinds.iter().position(|k| k == name) {
                Some(i) => i as i32,
                None => {
                    kinds.push(name.to_string());
                    kinds.len() as i32 - 1
                }
            },
            None => -1,
        })
        .collect();
    if kinds.is_empty() {
        return Err(Error::Mismatch(format!(
            "names none of the {} scans of {}",
            files.len(),
            descriptors.display()
        ))
        .in_file(names.display().to_string()));
    }
    let named: Vec<(i32, String)> = (0..).zip(kinds.iter().cloned()).collect();
    let model = set.build_model(&labels, &named)?;
    super::write_out(Some(output), &model.to_json()?)?;
    let unnamed = labels.iter().filter(|&&l| l < 0).count();
    eprintln!(
        "model of {} categories from {} scans ({unnamed} not named) -> {}",
        kinds.len(),
        labels.len() - unnamed,
        super::shown(output)
    );
    Ok(ExitCode::SUCCESS)
}

/// CSV `file,category,distance,relative` to `output` (stdout if none):
/// each scan's nearest category; relative > 1 means farther from it than
/// any scan the category was made from. Scans are named as `describe`
/// names them (relative to the inputs' common root), so the rows agree
/// with `cluster`'s; a bag's clouds are read as `describe BAG` reads them
/// by default. Bad files are reported and skipped.
pub fn classify(
    model: &Path,
    inputs: &[PathBuf],
    output: Option<&Path>,
    limits: &ReadOptions,
) -> Result<ExitCode> {
    let shown = model.display().to_string();
    let text = std::fs::read_to_string(model).map_err(|e| Error::from(e).in_file(&shown))?;
    let model = LabelledModel::from_json(&text).map_err(|e| e.in_file(&shown))?;
    // The scans are described with the model's own parameters; a bag's
    // clouds as `describe BAG` reads them by default.
    let bag_args = BagArgs {
        every: 1,
        ..BagArgs::default()
    };
    let (set, of) = describe_inputs(
        inputs,
        model.params.clone(),
        limits,
        &bag_args,
        "classifying",
    )?;
    let mut out = String::from("file,category,distance,relative\n");
    let mut classified = 0;
    for described in set.files {
        // Described with the model's parameters, a scan matches its shape;
        // should it not, that one file is reported, never the batch ended.
        let c = match model.classify(&described.descriptor) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("skipped {}: {e}", described.path);
                continue;
            }
        };
        classified += 1;
        writeln!(
            out,
            "{},{},{},{}",
            quote(&described.name),
            quote(&c.name),
            c.distance,
            c.relative
        )
        .expect("writing to a String");
    }
    super::write_out(output, &out)?;
    eprintln!("classified {classified} of {of}");
    Ok(if classified == 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}
