//! `placecat describe` and `placecat distances`.

use super::progress;
use placecat::descriptor::DescriptorParams;
use placecat::io::csv::quote;
use placecat::io::{is_scan_name, read_path, ReadLimits};
use placecat::{Descriptor, Error, Result};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// One described scan in OUT.json.
#[derive(Serialize, Deserialize)]
pub struct DescribedFile {
    pub name: String,
    pub path: String,
    pub descriptor: Descriptor,
}

/// A file that failed, with its error.
#[derive(Serialize, Deserialize)]
pub struct FileError {
    pub file: String,
    pub error: String,
}

/// The whole OUT.json of `describe`.
#[derive(Serialize, Deserialize)]
pub struct DescriptorSet {
    pub params: DescriptorParams,
    pub files: Vec<DescribedFile>,
    #[serde(default)]
    pub errors: Vec<FileError>,
}

impl DescriptorSet {
    /// Read and check a set: its parameters, and every descriptor against
    /// them, so a hand-edited or truncated file is refused here, naming it
    /// and the scan, not later in a model that cannot be loaded.
    pub fn load(path: &Path) -> Result<DescriptorSet> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&name))?;
        let set: DescriptorSet =
            serde_json::from_str(&text).map_err(|e| Error::from(e).in_file(&name))?;
        set.check().map_err(|e| e.in_file(&name))?;
        Ok(set)
    }

    fn check(&self) -> Result<()> {
        self.params.validate()?;
        for f in &self.files {
            f.descriptor
                .validate_for(&self.params)
                .map_err(|e| e.in_file(&f.name))?;
        }
        Ok(())
    }

    /// The parameters, file names and descriptors, moved out (a large set's
    /// descriptors are not copied to be clustered).
    pub fn into_parts(self) -> (DescriptorParams, Vec<String>, Vec<Descriptor>) {
        let (names, descriptors) = self
            .files
            .into_iter()
            .map(|f| (f.name, f.descriptor))
            .unzip();
        (self.params, names, descriptors)
    }
}

/// Expand folders into the scans inside them, sorted by name.
pub fn expand(inputs: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let mut inside: Vec<PathBuf> = std::fs::read_dir(input)
                .map_err(|e| Error::from(e).in_file(input.display().to_string()))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.is_file() && is_scan_name(&p.to_string_lossy()))
                .collect();
            inside.sort();
            files.extend(inside);
        } else {
            files.push(input.clone());
        }
    }
    Ok(files)
}

fn load_params(preset: &str, params: Option<&Path>) -> Result<DescriptorParams> {
    let base = DescriptorParams::preset(preset)?;
    let Some(path) = params else {
        return Ok(base);
    };
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&name))?;
    // Fields the file gives override the preset's.
    let mut merged = serde_json::to_value(&base)?;
    let over: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| Error::from(e).in_file(&name))?;
    let Some(obj) = over.as_object() else {
        return Err(
            Error::InvalidParameter("the params file must hold a JSON object".into())
                .in_file(&name),
        );
    };
    for (k, v) in obj {
        merged[k] = v.clone();
    }
    let p: DescriptorParams =
        serde_json::from_value(merged).map_err(|e| Error::from(e).in_file(&name))?;
    p.validate().map_err(|e| e.in_file(&name))?;
    Ok(p)
}

pub fn run(
    preset: &str,
    params: Option<&Path>,
    inputs: &[PathBuf],
    output: &Path,
    limits: &ReadLimits,
) -> Result<ExitCode> {
    let params = load_params(preset, params)?;
    params.validate()?;
    let files = expand(inputs)?;
    let mut set = DescriptorSet {
        files: Vec::new(),
        errors: Vec::new(),
        params,
    };
    for r in describe_files(&files, &set.params, limits, "describing")? {
        match r {
            Ok(f) => set.files.push(f),
            Err(e) => set.errors.push(e),
        }
    }
    let text = serde_json::to_string(&set)?;
    super::write_out(Some(output), &text)?;
    eprintln!(
        "described {} of {} files -> {}",
        set.files.len(),
        files.len(),
        output.display()
    );
    Ok(if set.files.is_empty() {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

/// Read and describe files in parallel (each worker holds one file's
/// points at a time), with a progress bar; a file that fails is reported
/// on stderr and comes back as its error, in input order.
pub fn describe_files(
    files: &[PathBuf],
    params: &DescriptorParams,
    limits: &ReadLimits,
    what: &'static str,
) -> Result<Vec<std::result::Result<DescribedFile, FileError>>> {
    if files.is_empty() {
        return Err(Error::InvalidParameter(
            "no scan files in the inputs".into(),
        ));
    }
    let bar = progress::bar(files.len() as u64, what);
    let results: Vec<std::result::Result<DescribedFile, FileError>> = files
        .par_iter()
        .map(|path| {
            let shown = path.display().to_string();
            let out = read_path(path, limits)
                .and_then(|cloud| {
                    placecat::describe(&cloud.points, params).map_err(|e| e.in_file(&shown))
                })
                .map(|descriptor| DescribedFile {
                    name: path
                        .file_name()
                        .map(|n| n.to_string_lossy().into_owned())
                        .unwrap_or_default(),
                    path: shown.clone(),
                    descriptor,
                })
                .map_err(|e| FileError {
                    file: shown,
                    error: e.to_string(),
                });
            bar.inc(1);
            out
        })
        .collect();
    bar.finish_and_clear();
    for e in results.iter().filter_map(|r| r.as_ref().err()) {
        eprintln!("skipped {}", e.error);
    }
    Ok(results)
}

pub fn distances(descriptors: &Path, output: Option<&Path>) -> Result<ExitCode> {
    let (params, names, ds) = DescriptorSet::load(descriptors)?.into_parts();
    let m = placecat::delta_matrix(&ds, (&params).into())?;
    let names: Vec<String> = names.iter().map(|n| quote(n).into_owned()).collect();
    let mut out = String::from("file");
    for n in &names {
        out.push(',');
        out.push_str(n);
    }
    out.push('\n');
    for (i, n) in names.iter().enumerate() {
        out.push_str(n);
        for j in 0..m.n {
            out.push_str(&format!(",{}", m.get(i, j)));
        }
        out.push('\n');
    }
    super::write_out(output, &out)?;
    Ok(ExitCode::SUCCESS)
}
