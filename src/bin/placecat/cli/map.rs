//! `placecat map`: the trajectory coloured by category, top-down, as SVG,
//! drawn as the page's map draws it (www/map.js, colours from
//! www/colours.js): the scans' points faint grey underneath (each scan's
//! subsample turned by its heading and moved to its position), the path
//! segment into each scan and a dot on it in the scan's category colour.
//!
//! The SVG is written by hand: a few element kinds, no dependency. The
//! point layer is one path of the occupied 2-pixel cells, so its size is
//! bounded by the picture, not by the number of scans or points.

use super::cluster::read_clusters;
use super::names::Labels;
use placecat::io::poses::{self, PoseFormat};
use placecat::io::{read_path, ReadLimits};
use placecat::{Error, Result};
use rayon::prelude::*;
use std::collections::BTreeSet;
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Options of `placecat map`.
#[derive(clap::Args)]
pub struct MapArgs {
    /// The OUT.json of `placecat cluster` (files and their labels).
    clusters: PathBuf,
    /// Poses of the scans: KITTI or TUM rows (one per scan, in the order of
    /// OUT.json's files) or name,x,y[,z] CSV (matched to the scans by name,
    /// as labels are).
    #[arg(long)]
    poses: PathBuf,
    /// The folder the scans' names are relative to (the folder given to
    /// `describe`): each scan is read from ROOT/NAME and a subsample of its
    /// points drawn under the path. Without it the path alone is drawn.
    /// Needs poses with headings (KITTI, TUM); bag clouds and E57 stations
    /// are not drawn.
    #[arg(long, value_name = "ROOT")]
    scans: Option<PathBuf>,
    /// Points drawn of each scan (an even subsample).
    #[arg(long, default_value_t = 400)]
    points: usize,
    /// Width of the picture in pixels (the height follows the trajectory).
    #[arg(long, default_value_t = 800)]
    width: u32,
    /// The SVG file to write; `-` for standard output.
    #[arg(short, long)]
    output: PathBuf,
}

/// The page's category palette (www/colours.js), then evenly spaced hues.
const PALETTE: [&str; 12] = [
    "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#b07aa1", "#76b7b2", "#edc948", "#9c755f",
    "#ff9da7", "#2f4b7c", "#a05195", "#665191",
];

/// The colour of a category on the map (www/map.js: noise is red there).
pub fn colour(label: i32) -> String {
    match usize::try_from(label) {
        Err(_) => "#c0392b".into(),
        Ok(k) if k < PALETTE.len() => PALETTE[k].into(),
        Ok(k) => format!("hsl({} 60% 45%)", (k as f64 * 137.5) % 360.0),
    }
}

/// A scan placed on the map.
struct Placed {
    name: String,
    label: i32,
    position: [f64; 2],
    yaw: f64,
}

/// Each scan's pose: by order for KITTI/TUM (as many rows as scans), by
/// name for CSV (scans without a row are left off the map).
fn place(files: &[String], labels: &[i32], path: &Path) -> Result<(Vec<Placed>, bool)> {
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::from(e).in_file(&shown))?;
    let parsed = poses::parse(&text).map_err(|e| e.in_file(&shown))?;
    let headings = parsed.format != PoseFormat::Csv;
    let index: Vec<Option<usize>> = if headings {
        if parsed.poses.len() != files.len() {
            return Err(Error::Mismatch(format!(
                "{} poses for {} scans ({:?} poses are matched by order)",
                parsed.poses.len(),
                files.len(),
                parsed.format
            ))
            .in_file(&shown));
        }
        (0..files.len()).map(Some).collect()
    } else {
        let rows = parsed
            .poses
            .iter()
            .enumerate()
            .map(|(i, p)| (p.name.clone().unwrap_or_default(), i.to_string()));
        let table = Labels::new(rows.collect(), path)?;
        table
            .for_names(files)
            .into_iter()
            .map(|i| i.and_then(|i| i.parse().ok()))
            .collect()
    };
    let placed: Vec<Placed> = files
        .iter()
        .zip(labels)
        .zip(index)
        .filter_map(|((name, &label), i)| {
            let p = &parsed.poses[i?];
            Some(Placed {
                name: name.clone(),
                label,
                position: [p.position[0], p.position[1]],
                yaw: p.yaw,
            })
        })
        .collect();
    if placed.is_empty() {
        return Err(Error::Mismatch(format!(
            "no pose row names any of the {} scans",
            files.len()
        ))
        .in_file(&shown));
    }
    if placed.len() < files.len() {
        eprintln!(
            "{} of {} scans have no pose in {shown} and are left off the map",
            files.len() - placed.len(),
            files.len()
        );
    }
    Ok((placed, headings))
}

/// An even subsample of a scan's finite points, in world x, y.
fn world_points(scan: &Placed, root: &Path, n: usize) -> Result<Vec<[f64; 2]>> {
    let cloud = read_path(&root.join(&scan.name), &ReadLimits::default())?;
    let finite: Vec<&[f32; 3]> = cloud
        .points
        .iter()
        .filter(|p| p.iter().all(|v| v.is_finite()))
        .collect();
    let step = finite.len().div_ceil(n.max(1)).max(1);
    let (s, c) = scan.yaw.sin_cos();
    let [px, py] = scan.position;
    Ok(finite
        .iter()
        .step_by(step)
        .map(|p| {
            let (x, y) = (f64::from(p[0]), f64::from(p[1]));
            [px + c * x - s * y, py + s * x + c * y]
        })
        .collect())
}

/// XML text with its five special characters escaped.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&apos;")
}

/// World to picture: the trajectory's box padded by 15 m (as the page
/// fits it), y up.
struct View {
    s: f64,
    ox: f64,
    oy: f64,
    w: f64,
    h: f64,
}

impl View {
    fn fit(placed: &[Placed], width: u32) -> View {
        let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for p in placed {
            x0 = x0.min(p.position[0] - 15.0);
            x1 = x1.max(p.position[0] + 15.0);
            y0 = y0.min(p.position[1] - 15.0);
            y1 = y1.max(p.position[1] + 15.0);
        }
        let w = f64::from(width.max(100));
        let s = (w - 40.0) / (x1 - x0).max(1e-6);
        let h = ((y1 - y0) * s + 40.0).clamp(100.0, 4.0 * w);
        let s = s.min((h - 40.0) / (y1 - y0).max(1e-6));
        View {
            s,
            ox: w / 2.0 - (x0 + x1) / 2.0 * s,
            oy: h / 2.0 + (y0 + y1) / 2.0 * s,
            w,
            h,
        }
    }

    fn screen(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        [self.ox + x * self.s, self.oy - y * self.s]
    }
}

/// The SVG text: points (if any), path segments, scan dots, legend.
fn svg(placed: &[Placed], points: &[Vec<[f64; 2]>], view: &View) -> String {
    let mut out = String::new();
    let (w, h) = (view.w, view.h);
    let _ = write!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" font-family="sans-serif" font-size="11"><rect width="100%" height="100%" fill="#ffffff"/>"##
    );
    if !points.is_empty() {
        // One 2-pixel cell per occupied place: the layer's size is bounded
        // by the picture.
        let cells: BTreeSet<(i32, i32)> = points
            .iter()
            .flatten()
            .map(|&p| view.screen(p))
            .filter(|[x, y]| (0.0..w).contains(x) && (0.0..h).contains(y))
            .map(|[x, y]| ((x / 2.0) as i32, (y / 2.0) as i32))
            .collect();
        out += r#"<path id="points" fill="rgb(70,78,92)" fill-opacity="0.22" d=""#;
        for (cx, cy) in &cells {
            let _ = write!(out, "M{} {}h2v2h-2z", cx * 2, cy * 2);
        }
        out += r#""/>"#;
    }
    out += r#"<g id="path" stroke-width="3" stroke-linecap="round">"#;
    for pair in placed.windows(2) {
        let [ax, ay] = view.screen(pair[0].position);
        let [bx, by] = view.screen(pair[1].position);
        let _ = write!(
            out,
            r#"<line x1="{ax:.1}" y1="{ay:.1}" x2="{bx:.1}" y2="{by:.1}" stroke="{}"/>"#,
            colour(pair[1].label)
        );
    }
    out += r#"</g><g id="scans">"#;
    for p in placed {
        let [x, y] = view.screen(p.position);
        let _ = write!(
            out,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="3.5" fill="{}" data-category="{}"><title>{}: category {}</title></circle>"#,
            colour(p.label),
            p.label,
            escape(&p.name),
            p.label
        );
    }
    out += r#"</g><g id="legend">"#;
    let mut kinds: Vec<i32> = placed.iter().map(|p| p.label).collect();
    kinds.sort_unstable();
    kinds.dedup();
    for (row, k) in kinds.iter().enumerate() {
        let y = 16.0 + 16.0 * row as f64;
        let n = placed.iter().filter(|p| p.label == *k).count();
        let what = if *k < 0 {
            "noise".to_string()
        } else {
            format!("category {k}")
        };
        let _ = write!(
            out,
            r#"<circle cx="14" cy="{:.0}" r="5" fill="{}"/><text x="24" y="{y:.0}">{what} ({n} scans)</text>"#,
            y - 4.0,
            colour(*k)
        );
    }
    out += "</g></svg>\n";
    out
}

/// `placecat map`.
pub fn run(a: &MapArgs) -> Result<ExitCode> {
    let (files, labels) = read_clusters(&a.clusters)?;
    let (placed, headings) = place(&files, &labels, &a.poses)?;
    let view = View::fit(&placed, a.width);
    let points: Vec<Vec<[f64; 2]>> = match &a.scans {
        Some(_) if !headings => {
            eprintln!(
                "CSV poses carry no heading: the scans' points are not drawn (as on the page)"
            );
            Vec::new()
        }
        Some(root) => {
            // A bag cloud or survey station (`FILE:...`) is not a file.
            let (files, recorded): (Vec<&Placed>, Vec<&Placed>) = placed
                .iter()
                .partition(|p| !super::names::base_name(&p.name).contains(':'));
            if !recorded.is_empty() {
                eprintln!(
                    "{} bag clouds or survey stations: their points are not drawn",
                    recorded.len()
                );
            }
            let read: Vec<Result<Vec<[f64; 2]>>> = files
                .par_iter()
                .map(|p| world_points(p, root, a.points))
                .collect();
            let mut kept = Vec::new();
            for r in read {
                match r {
                    Ok(p) => kept.push(p),
                    Err(e) => eprintln!("not drawn: {e}"),
                }
            }
            if kept.is_empty() {
                return Err(Error::InvalidParameter(format!(
                    "no scan of {} could be read under {} (--scans is the folder the names are relative to)",
                    a.clusters.display(),
                    root.display()
                )));
            }
            kept
        }
        None => Vec::new(),
    };
    let text = svg(&placed, &points, &view);
    super::write_out(Some(&a.output), &text)?;
    eprintln!(
        "map of {} scans{} ({} kB) -> {}",
        placed.len(),
        if points.is_empty() {
            ""
        } else {
            " over their points"
        },
        text.len().div_ceil(1000),
        super::shown(&a.output)
    );
    Ok(ExitCode::SUCCESS)
}
