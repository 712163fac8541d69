//! `placecat info FILE --json`.

use placecat::io::{e57, read_path_at, ReadLimits};
use placecat::{Error, Format};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

/// Count, finite count and float64 sum of the finite points.
fn tally(pts: &[[f32; 3]]) -> (usize, [f64; 3]) {
    let mut sum = [0f64; 3];
    let mut finite = 0;
    for p in pts.iter().filter(|p| placecat::cloud::is_finite(p)) {
        finite += 1;
        for k in 0..3 {
            sum[k] += f64::from(p[k]);
        }
    }
    (finite, sum)
}

/// The JSON object of `info --json`.
fn summary(
    format: Format,
    count: usize,
    finite: usize,
    sum: [f64; 3],
    first: &[[f32; 3]],
    last: &[[f32; 3]],
) -> serde_json::Value {
    json!({
        "format": format.name(),
        "count": count,
        "first": first,
        "last": last,
        "sum": sum,
        "finite": finite,
    })
}

pub fn run(
    file: &Path,
    as_json: bool,
    lenient: bool,
    origin: Option<[f64; 3]>,
) -> placecat::Result<ExitCode> {
    let limits = ReadLimits {
        lenient,
        ..Default::default()
    };
    if super::describe::is_e57(file) {
        return survey(file, as_json, &limits, origin);
    }
    let cloud = read_path_at(file, &limits, origin)?;
    let pts = &cloud.points;
    let (finite, sum) = tally(pts);
    let first: Vec<[f32; 3]> = pts.iter().take(3).copied().collect();
    let last: Vec<[f32; 3]> = pts[pts.len().saturating_sub(3)..].to_vec();
    if as_json {
        let v = summary(cloud.format, pts.len(), finite, sum, &first, &last);
        super::write_out(None, &format!("{v}\n"))?;
    } else {
        let text = format!(
            "file:   {}\nformat: {}\npoints: {} ({} finite)\nfirst:  {first:?}\nlast:   {last:?}\nsum:    {sum:?}\n",
            file.display(),
            cloud.format.name(),
            pts.len(),
            finite
        );
        super::write_out(None, &text)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// An E57 survey: the totals under the usual keys, and each scan (station)
/// with its name, counts, sum in its own frame, and pose.
fn survey(
    file: &Path,
    as_json: bool,
    limits: &ReadLimits,
    origin: Option<[f64; 3]>,
) -> placecat::Result<ExitCode> {
    let shown = file.display().to_string();
    if origin.is_some() {
        return Err(Error::InvalidParameter(
            "--origin does not apply to E57: each scan is in its scanner's frame, its pose from the file".into(),
        )
        .in_file(shown));
    }
    let (mut count, mut finite, mut sum) = (0, 0, [0f64; 3]);
    let (mut first, mut last) = (Vec::new(), Vec::new());
    let mut scans = Vec::new();
    e57::for_each_scan_path(file, limits, |scan| {
        let (f, s) = tally(&scan.points);
        count += scan.points.len();
        finite += f;
        for k in 0..3 {
            sum[k] += s[k];
        }
        if first.is_empty() {
            first = scan.points.iter().take(3).copied().collect();
        }
        last = scan.points[scan.points.len().saturating_sub(3)..].to_vec();
        let pose = scan
            .pose
            .as_ref()
            .map(|p| json!({"position": p.position, "yaw": p.yaw}));
        scans.push(json!({
            "name": scan.name,
            "count": scan.points.len(),
            "finite": f,
            "sum": s,
            "pose": pose,
        }));
        Ok(())
    })?;
    if as_json {
        let mut v = summary(Format::E57, count, finite, sum, &first, &last);
        v["scans"] = scans.into();
        super::write_out(None, &format!("{v}\n"))?;
    } else {
        let mut text = format!(
            "file:   {shown}\nformat: e57, {} {}\npoints: {count} ({finite} finite)\nsum:    {sum:?}\n",
            scans.len(),
            if scans.len() == 1 { "scan" } else { "scans" }
        );
        for s in &scans {
            text.push_str(&format!(
                "scan:   {} {} points ({} finite), pose {}\n",
                s["name"].as_str().unwrap_or_default(),
                s["count"],
                s["finite"],
                s["pose"]
            ));
        }
        super::write_out(None, &text)?;
    }
    Ok(ExitCode::SUCCESS)
}
