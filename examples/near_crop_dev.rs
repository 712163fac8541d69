//! Issue 18, after the twenty-fourth round, a development look: do the
//! mall's kinds group better when each scan keeps only its returns within
//! R m horizontally? Its shopfronts are open to the lidar, so a shop's
//! scan also holds the concourse and the shops opposite
//! (docs/mall-kinds.md); the hotel's lobby opens onto its corridor too.
//!
//!     cargo run --release --example near_crop_dev   # -> docs/near-crop-dev.md
//!
//! Development seeds 1-3 only (the hotel's and the mall's were first
//! described in docs/part-weights-dev.md; the earlier room rows' in every
//! round). `indoor_objects` on each scan cropped to R = 4, 6 and 8 m and
//! not cropped; k-means with spectral seeding (clustering seeds 0-2, mean)
//! and room-level 1-NN. It changes no preset and judges nothing.

use placecat::cluster::{KMeans, KMeansParams, Seeding};
use placecat::descriptor::DescriptorParams;
use placecat::distance::{DistanceOptions, Space};
use placecat::sim::Simulation;
use placecat::{describe, Descriptor};
use rayon::prelude::*;
use std::fmt::Write;

#[allow(dead_code)]
#[path = "common/families.rs"]
mod families;
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
use families::*;
use rounds::*;

const SEEDS: [u64; 3] = [1, 2, 3];
/// Horizontal ranges kept (m); infinity: the whole scan.
const CROPS: [f32; 4] = [4.0, 6.0, 8.0, f32::INFINITY];

fn crop_name(r: f32) -> String {
    if r.is_finite() {
        format!("within {r} m")
    } else {
        "whole scan".into()
    }
}

/// Per crop: spectral seeding and room-level 1-NN (%).
fn one_set(f: &Family, sensor: Sensor, seed: u64) -> Result<Vec<[f64; 2]>, String> {
    let go = || -> Res<Vec<[f64; 2]>> {
        let sim = Simulation::new(&sim_params(f, sensor, seed)?)?;
        let p = DescriptorParams::preset("indoor_objects")?;
        let truth: Vec<String> = (0..sim.len()).map(|i| sim.label(i).to_string()).collect();
        let mut kinds = truth.clone();
        kinds.sort();
        kinds.dedup();
        let apart = Apart::Rooms((0..sim.len()).map(|i| sim.room(i)).collect());
        let scans: Vec<Vec<[f32; 3]>> = (0..sim.len()).map(|i| sim.scan(i).points).collect();
        let mut out = vec![];
        for r in CROPS {
            let ds: Vec<Descriptor> = scans
                .iter()
                .map(|pts| {
                    // The points are in the sensor's frame, so the
                    // horizontal range is the hypotenuse of x and y.
                    let kept: Vec<[f32; 3]> = (pts.iter())
                        .filter(|q| q[0].hypot(q[1]) <= r)
                        .copied()
                        .collect();
                    describe(&kept, &p)
                })
                .collect::<placecat::Result<_>>()?;
            let sp = Space::new(&ds, DistanceOptions::from(&p))?;
            let m = sp.matrix();
            let mut spec = 0.0;
            for s in 0..3 {
                let params = KMeansParams::new(kinds.len())
                    .seeding(Seeding::Spectral)
                    .seed(s);
                let fit = KMeans::fit_with_matrix(&sp, Some(&m), &params)?;
                spec += placecat::eval::evaluate(&truth, &fit.labels)?.accuracy / 3.0;
            }
            out.push([100.0 * spec, 100.0 * room_level_nn(&m, &truth, &apart)]);
        }
        Ok(out)
    };
    go().map_err(|e| format!("{} {} seed {seed}: {e}", f.name, sensor.name()))
}

fn main() -> Res<()> {
    let t0 = std::time::Instant::now();
    // The rows and the group each is summed in: the two families written
    // after the presets, each on its own, then the earlier room rows.
    let fresh = [hotel_family(), mall_family()].into_iter().flat_map(|f| {
        let group = f.name;
        sensor_rows(f).into_iter().map(move |row| (row, group))
    });
    let earlier = (room_rows().into_iter()).map(|row| (row, "the fourteen earlier room rows"));
    let (rows, group_of): (Vec<(Family, Sensor)>, Vec<&str>) = fresh.chain(earlier).unzip();
    let jobs: Vec<(usize, u64)> = (0..rows.len())
        .flat_map(|r| SEEDS.iter().map(move |&s| (r, s)))
        .collect();
    let got: Vec<(usize, Vec<[f64; 2]>)> = jobs
        .par_iter()
        .map(|&(r, seed)| {
            let v = one_set(&rows[r].0, rows[r].1, seed)?;
            eprintln!(
                "{} {} seed {seed} ({:.0} s)",
                rows[r].0.name,
                rows[r].1.name(),
                t0.elapsed().as_secs_f64()
            );
            Ok((r, v))
        })
        .collect::<Result<_, String>>()?;

    let mut o = String::new();
    o.push_str(include_str!("near_crop_dev_intro.md"));
    let _ = write!(o, "\nEach cell: k-means with spectral seeding (clustering seeds 0-2, mean) / room-level 1-NN, %, the mean over development seeds {SEEDS:?}, `indoor_objects`. Run time {:.0} s.\n\n| row |", t0.elapsed().as_secs_f64());
    for r in CROPS {
        let _ = write!(o, " {} |", crop_name(r));
    }
    o.push_str("\n|---|");
    o.push_str(&"---|".repeat(CROPS.len()));
    o.push('\n');
    let mut groups: Vec<(&str, Vec<Vec<f64>>)> = vec![];
    for (r, (f, s)) in rows.iter().enumerate() {
        let sets: Vec<&Vec<[f64; 2]>> = got.iter().filter(|g| g.0 == r).map(|g| &g.1).collect();
        let mean: Vec<f64> = (0..CROPS.len() * 2)
            .map(|x| sets.iter().map(|v| v[x / 2][x % 2]).sum::<f64>() / sets.len() as f64)
            .collect();
        let _ = write!(o, "| {}, {} |", f.name, s.name());
        for c in 0..CROPS.len() {
            let _ = write!(o, " {:.1} / {:.1} |", mean[2 * c], mean[2 * c + 1]);
        }
        o.push('\n');
        let group = group_of[r];
        match groups.iter_mut().find(|g| g.0 == group) {
            Some(g) => g.1.push(mean),
            None => groups.push((group, vec![mean])),
        }
    }
    for (g, means) in &groups {
        let _ = write!(o, "| **{g}, mean of {} rows** |", means.len());
        for c in 0..CROPS.len() {
            let m = |x: usize| means.iter().map(|v| v[x]).sum::<f64>() / means.len() as f64;
            let _ = write!(o, " **{:.1} / {:.1}** |", m(2 * c), m(2 * c + 1));
        }
        o.push('\n');
    }
    eprintln!("{:.0} s", t0.elapsed().as_secs_f64());
    write("near-crop-dev.md", &o)
}
