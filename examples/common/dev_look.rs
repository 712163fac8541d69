// The modules and seeds of a development look (profiles_dev,
// hospital_sensors_dev, objects_dev): examples that measure on
// development seeds only, change no preset and judge nothing. Each
// `include!`s this file at its root; the paths are relative to this file.
#[path = "families.rs"]
mod families;
// The rounds' tables go unused here.
#[allow(dead_code)]
#[path = "rounds.rs"]
mod rounds;
#[path = "seeds.rs"]
mod seeds;
use families::*;
use rounds::*;

/// Development seeds 1-6 (docs/seeds.md); [`check_dev`] refuses them if
/// the table ever lists one as a test seed.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];

/// What every development look's report says of itself first (but
/// spectral_routes_dev's, which runs seeds 7-10 too and says so).
#[allow(dead_code)]
const DEV_NOTE: &str =
    "Development seeds 1-6 only; it changes no preset, parameter or file but this one and tunes nothing.";

/// Refuse to run if a development seed is a test seed of docs/seeds.md.
fn check_dev() -> Res<()> {
    seeds::check_round_seeds(DEV_SEEDS, &[])
}

/// Write a development look's report to docs/`name`.
fn write_doc(name: &str, text: &str) -> Res<()> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs").join(name);
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    eprintln!("wrote docs/{name}");
    Ok(())
}

/// Stride k-means' accuracy, and k-means++ best of 10's as the mean over
/// clustering seeds 0-9 (as the rounds' harness), on `space` at `k`.
#[allow(dead_code)] // profiles_dev and hospital_sensors_dev
fn kmeans_figures(space: &placecat::distance::Space, truth: &[String], k: usize) -> Res<(f64, f64)> {
    use placecat::cluster::{KMeans, KMeansParams, Seeding};
    let stride = KMeans::fit(space, &KMeansParams::new(k).seeding(Seeding::Stride))?;
    let best = best_of_10(space, truth, k)?;
    Ok((once(truth, &stride.labels)?.accuracy, best.accuracy))
}

/// A report's table row: the family and sensor, then `cells`.
#[allow(dead_code)] // objects_dev, and finish_row
fn table_row(table: &mut String, f: &Family, sensor: Sensor, cells: &[String]) -> std::fmt::Result {
    use std::fmt::Write as _;
    writeln!(table, "| {}, {} | {} |", f.name, sensor.name(), cells.join(" | "))
}

/// A finished row: its cells on stderr with the seconds since `t0`, and in
/// the report's table.
#[allow(dead_code)] // spectral_k_dev and spectral_seeding_k_dev
fn finish_row(
    table: &mut String,
    f: &Family,
    sensor: Sensor,
    cells: &[String],
    t0: std::time::Instant,
) -> std::fmt::Result {
    let seconds = t0.elapsed().as_secs_f64();
    eprintln!("{} {}: {} ({seconds:.0} s)", f.name, sensor.name(), cells.join(" / "));
    table_row(table, f, sensor, cells)
}
