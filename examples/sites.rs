//! The sequence sites' seed table alone (a part of docs/experiments.md,
//! section 4, without the rest of the report): for the development and
//! test seeds fixed in docs/seeds.md (outdoor: 1-10 and 501-505, issue
//! 14's fourth round's; warehouse: 1-3 and 101-105),
//! `placecat simulate --scene outdoor|warehouse --seed S`, described with
//! the `outdoor` / `indoor` preset, clustered into 3 by deterministic
//! k-means and by hierarchical k-means++ (clustering seeds 0-9). Also the
//! time to simulate, and the site maps and label strips
//! (docs/outdoor_map.svg, docs/outdoor_strip.svg and the warehouse's, from
//! seed 1).
//!
//!     cargo run --release --example sites -- [outdoor|warehouse|both] [dev]
//!
//! `dev`: the development seeds only (the test seeds are run once, at the
//! end).

#[path = "common/sites.rs"]
mod sites;

use placecat::sim::sites::{OUTDOOR_KINDS, WAREHOUSE_KINDS};
use placecat::sim::SceneKind;

fn main() {
    let only = std::env::args().nth(1).filter(|o| o != "both");
    let test = std::env::args().nth(2).as_deref() != Some("dev");
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    for (scene, kinds, name) in [
        (SceneKind::Outdoor, OUTDOOR_KINDS, "outdoor"),
        (SceneKind::Warehouse, WAREHOUSE_KINDS, "warehouse"),
    ] {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        let (plan, per_scan, n) = sites::timing(scene, 1, 30);
        println!(
            "{name}: {n} scans; CPU time (release, one core): plan {:.0} ms, {:.1} ms a scan, {:.1} s for all {n}",
            1e3 * plan,
            1e3 * per_scan,
            plan + per_scan * n as f64
        );
        let t = std::time::Instant::now();
        let (table, runs) = sites::seed_table(scene, &kinds, test);
        println!(
            "\n### {name} (preset `{}`)\n\n{table}",
            sites::preset(scene).preset
        );
        let run = &runs.iter().find(|(s, _)| *s == 1).unwrap().1;
        std::fs::write(
            docs.join(format!("{name}_map.svg")),
            sites::map_svg(run, &kinds),
        )
        .unwrap();
        std::fs::write(
            docs.join(format!("{name}_strip.svg")),
            sites::strip_svg(&run.truth, &run.stride, &run.stride_labels),
        )
        .unwrap();
        println!("({:.0} s)", t.elapsed().as_secs_f64());
    }
}
