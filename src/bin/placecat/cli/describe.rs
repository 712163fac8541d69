//! `placecat describe` and `placecat distances`.

use super::bag::BagArgs;
use super::names::{expand, Input, EXTENSIONS};
use super::progress;
use placecat::collection::merge_params;
use placecat::descriptor::DescriptorParams;
use placecat::io::csv::quote;
use placecat::io::poses::Pose;
use placecat::io::{csv, e57, read_path_at, ReadLimits};
use placecat::{Collection, Descriptor, Error, Result};
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
    /// Where the recording puts the scan (an E57 station's pose, a bag
    /// cloud's from odometry or tf); absent for loose files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pose: Option<ScanPose>,
}

/// A scan's pose in OUT.json: the sensor's position (m) and heading (yaw
/// about z, radians) in the recording's frame, and the stamp (s) of a bag
/// cloud.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct ScanPose {
    pub position: [f64; 3],
    pub yaw: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time: Option<f64>,
}

impl From<&Pose> for ScanPose {
    fn from(p: &Pose) -> Self {
        ScanPose {
            position: p.position,
            yaw: p.yaw,
            time: p.time,
        }
    }
}

/// How scan files are read: the library's limits, and the sensor position
/// (`--origin`) for files whose points are not centred on it.
#[derive(Clone, Copy)]
pub struct ReadOptions {
    pub limits: ReadLimits,
    pub origin: Option<[f64; 3]>,
}

/// A file that failed, with its error.
#[derive(Serialize, Deserialize)]
pub struct FileError {
    pub file: String,
    pub error: String,
}

/// The whole OUT.json of `describe`: the file form of a
/// [`Collection`].
#[derive(Serialize, Deserialize)]
pub struct DescriptorsFile {
    pub params: DescriptorParams,
    pub files: Vec<DescribedFile>,
    #[serde(default)]
    pub errors: Vec<FileError>,
}

impl DescriptorsFile {
    /// Read a described set as a collection, checking its parameters and
    /// every descriptor against them, so a hand-edited or truncated file is
    /// refused here, naming it and the scan, not later in a model that
    /// cannot be loaded.
    pub fn load(path: &Path) -> Result<Collection> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&name))?;
        let file: DescriptorsFile =
            serde_json::from_str(&text).map_err(|e| Error::from(e).in_file(&name))?;
        let named = file.files.into_iter().map(|f| (f.name, f.descriptor));
        Collection::from_parts(file.params, named).map_err(|e| e.in_file(&name))
    }
}

/// The preset's parameters with the fields of the `--params` file over them
/// (no `--preset`: the one the file names, else indoor; see `merge_params`).
fn load_params(preset: Option<&str>, params: Option<&Path>) -> Result<DescriptorParams> {
    let Some(path) = params else {
        return merge_params(preset, None);
    };
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&name))?;
    let over: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| Error::from(e).in_file(&name))?;
    merge_params(preset, Some(&over)).map_err(|e| e.in_file(&name))
}

pub fn run(
    preset: Option<&str>,
    params: Option<&Path>,
    sensor_height: Option<f64>,
    inputs: &[PathBuf],
    output: &Path,
    limits: &ReadOptions,
    bag_args: &BagArgs,
) -> Result<ExitCode> {
    let mut params = load_params(preset, params)?;
    if placecat::descriptor::WITHDRAWN_PRESETS.contains(&params.preset.as_str()) {
        // Kept so that earlier reports re-run; said, so that nobody picks
        // it up as a recommendation.
        let note = placecat::descriptor::preset_note(&params.preset).unwrap_or_default();
        eprintln!("note: preset {} is {note}", params.preset);
    }
    if sensor_height.is_some() {
        params.sensor_height = sensor_height;
        params.validate()?;
    }
    let (set, of) = describe_inputs(inputs, params, limits, bag_args, "describing")?;
    let text = serde_json::to_string(&set)?;
    super::write_out(Some(output), &text)?;
    let shown = super::shown(output);
    eprintln!("described {} of {of} -> {shown}", set.files.len());
    Ok(if set.files.is_empty() {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

/// Describe every scan of the inputs (files, folders walked recursively,
/// bags) with `params`, each named by its path relative to the inputs'
/// common root; also "N files" or "M scans from N files" for messages.
pub fn describe_inputs(
    inputs: &[PathBuf],
    params: DescriptorParams,
    limits: &ReadOptions,
    bag_args: &BagArgs,
    what: &'static str,
) -> Result<(DescriptorsFile, String)> {
    let (bags, files): (Vec<Input>, Vec<Input>) =
        expand(inputs)?.into_iter().partition(Input::is_bag);
    let mut set = DescriptorsFile {
        files: Vec::new(),
        errors: Vec::new(),
        params,
    };
    // Bags alone are fine; only files-and-folders inputs need a scan inside.
    if !files.is_empty() || bags.is_empty() {
        for r in describe_files(&files, &set.params, limits, what)? {
            match r {
                Ok(f) => set.files.push(f),
                Err(e) => set.errors.push(e),
            }
        }
    }
    super::bag::describe(&bags, bag_args, &limits.limits, &mut set)?;
    if let Some(out) = &bag_args.poses_out {
        let n = set.files.iter().filter(|f| f.pose.is_some()).count();
        super::write_out(Some(out), &poses_csv(&set.files))?;
        eprintln!("{n} poses -> {}", super::shown(out));
    }
    let scans = set.files.len() + set.errors.len();
    let inputs = files.len() + bags.len();
    let of = if scans == inputs {
        format!("{inputs} files")
    } else {
        // E57 surveys give a scan per station, bags a scan per cloud.
        format!("{scans} scans from {inputs} files")
    };
    Ok((set, of))
}

/// The described scans' poses (bag clouds, E57 stations) as name,x,y,z
/// rows with a header: the CSV form of `io::poses`, which the map reads.
fn poses_csv(files: &[DescribedFile]) -> String {
    let mut s = String::from("name,x,y,z\n");
    for f in files {
        if let Some(p) = &f.pose {
            let [x, y, z] = p.position.map(|v| v.to_string());
            s += &csv::record([f.name.as_str(), &x, &y, &z]);
            s.push('\n');
        }
    }
    s
}

/// Read and describe files in parallel (each worker holds one file's
/// points at a time; an E57 survey gives one scan after another), with a
/// progress bar; a file or scan that fails is reported on stderr and comes
/// back as its error, in input order.
fn describe_files(
    files: &[Input],
    params: &DescriptorParams,
    opts: &ReadOptions,
    what: &'static str,
) -> Result<Vec<std::result::Result<DescribedFile, FileError>>> {
    if files.is_empty() {
        return Err(Error::InvalidParameter(format!(
            "no scan files in the inputs (folders are searched with their subfolders for {EXTENSIONS})"
        )));
    }
    let bar = progress::bar(files.len() as u64, what);
    let results: Vec<std::result::Result<DescribedFile, FileError>> = files
        .par_iter()
        .flat_map_iter(|input| {
            let out = describe_path(input, params, opts);
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

/// True when the file starts with the E57 signature.
pub fn is_e57(path: &Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 8];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut head))
        .is_ok()
        && e57::looks_like_e57(&head)
}

/// The described scans of one file, named by its relative path: one, or
/// one per station of an E57 survey, named `FILE:STATION` (a station that
/// cannot be described is reported alone; a survey that cannot be read
/// stops there).
fn describe_path(
    input: &Input,
    params: &DescriptorParams,
    opts: &ReadOptions,
) -> Vec<std::result::Result<DescribedFile, FileError>> {
    let path = input.path.as_path();
    let shown = path.display().to_string();
    let base = input.name.clone();
    let failed = |file: &str, e: Error| FileError {
        file: file.to_string(),
        error: e.to_string(),
    };
    if !is_e57(path) {
        let out = read_path_at(path, &opts.limits, opts.origin)
            .and_then(|cloud| {
                placecat::describe(&cloud.points, params).map_err(|e| e.in_file(&shown))
            })
            .map(|descriptor| DescribedFile {
                name: base,
                path: shown.clone(),
                descriptor,
                pose: None,
            })
            .map_err(|e| failed(&shown, e));
        return vec![out];
    }
    if opts.origin.is_some() {
        let e = Error::InvalidParameter(
            "--origin does not apply to E57: each scan is in its scanner's frame, its pose from the file".into(),
        );
        return vec![Err(failed(&shown, e.in_file(&shown)))];
    }
    let mut out = Vec::new();
    let read = e57::for_each_scan_path(path, &opts.limits, |scan| {
        // The scan's name is `PATH:STATION`; the short name is `NAME:STATION`.
        let station = scan.name.strip_prefix(shown.as_str()).unwrap_or(&scan.name);
        out.push(
            placecat::describe(&scan.points, params)
                .map(|descriptor| DescribedFile {
                    name: format!("{base}{station}"),
                    path: scan.name.clone(),
                    descriptor,
                    pose: scan.pose.as_ref().map(ScanPose::from),
                })
                .map_err(|e| failed(&scan.name, e.in_file(&scan.name))),
        );
        Ok(())
    });
    if let Err(e) = read {
        out.push(Err(failed(&shown, e)));
    }
    out
}

pub fn distances(descriptors: &Path, output: Option<&Path>) -> Result<ExitCode> {
    // The matrix is the output here, so it is built at any size.
    let set = DescriptorsFile::load(descriptors)?;
    let m = placecat::delta_matrix(set.descriptors(), set.params().into())?;
    let names: Vec<String> = set.names().iter().map(|n| quote(n).into_owned()).collect();
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
