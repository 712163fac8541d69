//! Inputs and their names: folders walked recursively (the `walkdir`
//! crate), every scan named by its path relative to the common root of the
//! inputs, and names matched against a `file,label` CSV.
//!
//! A dataset tree such as KITTI's `sequences/NN/velodyne/000000.bin` repeats
//! file names in every sequence; base names would merge those scans (one
//! label, one row, one column). Relative paths keep them apart and stay
//! short: `describe sequences` names `00/velodyne/000000.bin`, and loose
//! files of one folder keep their base names as before.

use super::bag::is_bag;
use placecat::io::is_scan_name;
use placecat::{Error, Result};
use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};

/// The extensions a folder walk takes, for messages and help.
pub const EXTENSIONS: &str = ".ply .pcd .bin .las .laz .e57, and bags .bag .mcap";

/// One scan file (or bag) to read, with its name.
#[derive(Debug, Clone)]
pub struct Input {
    /// Where the file is, as the user gave it (or found under a folder).
    pub path: PathBuf,
    /// Its path relative to the common root of the inputs, with `/`
    /// between components on every platform.
    pub name: String,
}

impl Input {
    /// True for a ROS bag (read cloud by cloud).
    pub fn is_bag(&self) -> bool {
        is_bag(&self.path)
    }
}

/// True for a file name a folder walk takes.
fn readable(path: &Path) -> bool {
    is_scan_name(&path.to_string_lossy()) || is_bag(path)
}

/// Expand the inputs: a file is taken as given, a folder is walked
/// recursively (symbolic links followed, hidden entries skipped, each
/// folder's entries sorted by name) for every file whose name ends in one
/// of [`EXTENSIONS`]. Every file is named by its path relative to the
/// common root of the inputs (a folder's root is itself, a file's its
/// folder). Two inputs that give one name (the same file given twice) are
/// an error naming both.
pub fn expand(inputs: &[PathBuf]) -> Result<Vec<Input>> {
    let mut found: Vec<(PathBuf, &Path)> = Vec::new();
    for input in inputs {
        if !input.is_dir() {
            found.push((input.clone(), input));
            continue;
        }
        let walk = walkdir::WalkDir::new(input)
            .follow_links(true)
            .sort_by_file_name()
            .into_iter()
            // The root itself may be `.`; hidden entries below it are
            // editor and OS leftovers (macOS `._000000.bin`), not scans.
            .filter_entry(|e| e.depth() == 0 || !e.file_name().to_string_lossy().starts_with('.'));
        for entry in walk {
            let entry = entry.map_err(|e| {
                let at = e.path().unwrap_or(input).display().to_string();
                Error::from(std::io::Error::other(e.to_string())).in_file(at)
            })?;
            if entry.file_type().is_file() && readable(entry.path()) {
                found.push((entry.into_path(), input));
            }
        }
    }
    let roots: Vec<PathBuf> = inputs
        .iter()
        .map(|p| {
            let p = normal(p);
            if p.is_dir() {
                p
            } else {
                p.parent().map(Path::to_path_buf).unwrap_or_default()
            }
        })
        .collect();
    let root = common_root(&roots);
    let mut seen: HashMap<String, &Path> = HashMap::new();
    let mut out = Vec::with_capacity(found.len());
    for (path, input) in found {
        let name = relative(&normal(&path), &root);
        if let Some(first) = seen.insert(name.clone(), input) {
            return Err(Error::InvalidParameter(format!(
                "the inputs {} and {} both give the scan {name}: give each scan once",
                first.display(),
                input.display()
            )));
        }
        out.push(Input { path, name });
    }
    Ok(out)
}

/// The absolute form of a path with `.` and `name/..` removed (lexically:
/// the file need not exist, and a missing file is reported when read).
fn normal(p: &Path) -> PathBuf {
    let abs = std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    let mut out = PathBuf::new();
    for c in abs.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(out.components().next_back(), Some(Component::Normal(_))) =>
            {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

/// The longest leading path the folders share.
fn common_root(dirs: &[PathBuf]) -> PathBuf {
    let Some((first, rest)) = dirs.split_first() else {
        return PathBuf::new();
    };
    let mut root: Vec<Component> = first.components().collect();
    for d in rest {
        let same = root
            .iter()
            .zip(d.components())
            .take_while(|(a, b)| *a == b)
            .count();
        root.truncate(same);
    }
    root.iter().collect()
}

/// `path` below `root`, components joined by `/`.
fn relative(path: &Path, root: &Path) -> String {
    let rel = path.strip_prefix(root).unwrap_or(path);
    rel.components()
        .filter_map(|c| match c {
            Component::Normal(s) => Some(s.to_string_lossy().into_owned()),
            _ => None,
        })
        .collect::<Vec<_>>()
        .join("/")
}

/// The file part of a scan name without its folders: `a/b/run.bag:/points:000042`
/// gives `run.bag:/points:000042` (a bag's or survey's `:` suffix keeps its
/// `/`s), `C:\data\x.ply` gives `x.ply`.
pub fn base_name(name: &str) -> &str {
    // A drive letter's colon is not a suffix.
    let skip = if name.as_bytes().get(1) == Some(&b':') {
        2
    } else {
        0
    };
    let file_end = name[skip..].find(':').map_or(name.len(), |i| i + skip);
    let start = name[..file_end].rfind(['/', '\\']).map_or(0, |i| i + 1);
    &name[start..]
}

/// A `file,label` table, matched against scan names: a row whose file is
/// the scan's name (its relative path) first, else the row whose base name
/// is the scan's base name, when no other scan and no other row has that
/// base name (labels.csv of a flat folder, or rows written with longer
/// paths). Matching on base names alone would give the scans of a tree
/// that share a file name one label.
pub struct Labels {
    exact: HashMap<String, String>,
    /// Base name -> the labels of the rows with that base name.
    by_base: HashMap<String, Vec<String>>,
}

/// A row's file in the form of a scan name: `/` between folders, no `./`.
fn row_name(file: &str) -> String {
    let s = file.trim().replace('\\', "/");
    s.strip_prefix("./").unwrap_or(&s).to_string()
}

impl Labels {
    /// From `(file, label)` rows; a file given two different labels is an
    /// error naming it and `source`.
    pub fn new(rows: Vec<(String, String)>, source: &Path) -> Result<Self> {
        let mut exact: HashMap<String, String> = HashMap::new();
        let mut by_base: HashMap<String, Vec<String>> = HashMap::new();
        for (file, label) in rows {
            let file = row_name(&file);
            match exact.get(&file) {
                Some(l) if *l != label => {
                    return Err(Error::Mismatch(format!(
                        "{file} is labelled both {l:?} and {label:?}"
                    ))
                    .in_file(source.display().to_string()))
                }
                Some(_) => continue,
                None => {}
            }
            by_base
                .entry(base_name(&file).to_string())
                .or_default()
                .push(label.clone());
            exact.insert(file, label);
        }
        Ok(Labels { exact, by_base })
    }

    /// The label of each name (None where no row matches it).
    pub fn for_names<'a>(&'a self, names: &[impl AsRef<str>]) -> Vec<Option<&'a str>> {
        let mut base_count: HashMap<&str, usize> = HashMap::new();
        for n in names {
            *base_count.entry(base_name(n.as_ref())).or_default() += 1;
        }
        names
            .iter()
            .map(|n| {
                let n = n.as_ref();
                if let Some(l) = self.exact.get(&row_name(n)) {
                    return Some(l.as_str());
                }
                let base = base_name(n);
                match self.by_base.get(base).map(Vec::as_slice) {
                    Some([l]) if base_count[base] == 1 => Some(l.as_str()),
                    _ => None,
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base_names_keep_a_bag_or_survey_suffix() {
        assert_eq!(base_name("00/velodyne/000000.bin"), "000000.bin");
        assert_eq!(
            base_name("x/run.bag:/points:000042"),
            "run.bag:/points:000042"
        );
        assert_eq!(base_name("a/survey.e57:scan 3"), "survey.e57:scan 3");
        assert_eq!(base_name(r"C:\data\x.ply"), "x.ply");
        assert_eq!(base_name("a.ply"), "a.ply");
    }

    #[test]
    fn labels_match_paths_then_unique_base_names() {
        let rows = vec![
            ("00/velodyne/000000.bin".to_string(), "road".to_string()),
            ("01/velodyne/000000.bin".to_string(), "forest".to_string()),
            ("/elsewhere/office_1.ply".to_string(), "office".to_string()),
            ("000001.bin".to_string(), "field".to_string()),
        ];
        let t = Labels::new(rows, Path::new("labels.csv")).unwrap();
        let names = [
            "00/velodyne/000000.bin",
            "01/velodyne/000000.bin",
            "office_1.ply",
            "00/velodyne/000001.bin",
            "01/velodyne/000001.bin",
        ];
        assert_eq!(
            t.for_names(&names),
            // 000001.bin is in both sequences: its base-name row is ambiguous.
            [Some("road"), Some("forest"), Some("office"), None, None]
        );
        let clash = vec![
            ("a.ply".to_string(), "x".to_string()),
            ("./a.ply".to_string(), "y".to_string()),
        ];
        let e = Labels::new(clash, Path::new("labels.csv")).err().unwrap();
        assert!(e.to_string().contains("labels.csv"), "{e}");
    }

    #[test]
    fn the_common_root_is_the_folders_shared_prefix() {
        let r = common_root(&[
            PathBuf::from("/d/seq/00"),
            PathBuf::from("/d/seq/01/velodyne"),
        ]);
        assert_eq!(r, PathBuf::from("/d/seq"));
        assert_eq!(
            relative(Path::new("/d/seq/01/velodyne/a.bin"), &r),
            "01/velodyne/a.bin"
        );
        assert_eq!(normal(Path::new("/d/./x/../y")), PathBuf::from("/d/y"));
    }
}
