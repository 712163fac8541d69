//! `placecat info FILE --json`.

use placecat::io::{read_path, ReadLimits};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

pub fn run(file: &Path, as_json: bool, lenient: bool) -> placecat::Result<ExitCode> {
    let limits = ReadLimits {
        lenient,
        ..Default::default()
    };
    let cloud = read_path(file, &limits)?;
    let pts = &cloud.points;
    let mut sum = [0f64; 3];
    for p in pts {
        for k in 0..3 {
            if p[k].is_finite() {
                sum[k] += p[k] as f64;
            }
        }
    }
    let first: Vec<[f32; 3]> = pts.iter().take(3).copied().collect();
    let last: Vec<[f32; 3]> = pts[pts.len().saturating_sub(3)..].to_vec();
    if as_json {
        let v = json!({
            "format": cloud.format.name(),
            "count": pts.len(),
            "first": first,
            "last": last,
            "sum": sum,
            "finite": cloud.finite_count(),
        });
        super::write_out(None, &format!("{v}\n"))?;
    } else {
        let text = format!(
            "file:   {}\nformat: {}\npoints: {} ({} finite)\nfirst:  {first:?}\nlast:   {last:?}\nsum:    {sum:?}\n",
            file.display(),
            cloud.format.name(),
            pts.len(),
            cloud.finite_count()
        );
        super::write_out(None, &text)?;
    }
    Ok(ExitCode::SUCCESS)
}
