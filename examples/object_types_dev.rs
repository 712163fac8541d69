//! Issue 18, twenty-sixth round, the development probe its plan fixed
//! (docs/seeds.md, "issue 18, twenty-sixth round"): objects described
//! jointly by size and height (`object_types`), and with their layout
//! (`object_layout`), added to `indoor_objects`' distance.
//!
//!     cargo run --release --example object_types_dev   # -> docs/object-types-dev.{md,json}
//!     cargo run --release --example object_types_dev -- --seen   # -> docs/object-types-seen.{md,json}
//!
//! `--seen`, a reading after the round's test run that its plan did not
//! name and that decides nothing: the same eight on the hotel's, mall's and
//! home's test seeds (541-545, 551-555, 561-565; seen, their rounds' figures
//! reported, but never used to choose between the eight), each set listed
//! as its round listed it; `indoor_objects`' spectral seeding and 1-NN
//! must equal those rounds' JSON set by set.
//! Development seeds 1-6 only. Variant A adds `object_types` at weight w;
//! variant B is the plan's one part of six channels at w, which is
//! `object_types` at 4w/6 and `object_layout` at 2w/6 (a part's distance is
//! the mean over its channels). w in 2, 5, 10, 20. Each set is described
//! once with `indoor_objects` and both new parts (a part's values do not
//! depend on the others), listed in its row's own random order as the
//! twenty-fifth round listed its sets, and clustered by k-means with
//! spectral seeding (clustering seeds 0-9, mean; each run checked against
//! k-means from spectral clustering's groups). Room-level 1-NN beside it.
//! The rule, fixed in the plan: among the eight, the highest mean over the
//! eighteen hotel, mall and home rows (the smaller weight, then A, on a
//! tie) is the candidate if it is at least 2 points above
//! `indoor_objects`' there and the fourteen earlier room rows' mean is
//! less than 1 point below `indoor_objects`'.

use placecat::descriptor::{DescriptorParams, Part, PartKind};
use placecat::distance::{DistanceOptions, Space};
use rayon::prelude::*;
use serde::Serialize;
use std::fmt::Write;

#[path = "common/families.rs"]
mod families;
#[allow(dead_code)]
#[path = "common/listed_rounds.rs"]
mod listed_rounds;
#[allow(dead_code)]
#[path = "common/preset_rounds.rs"]
mod preset_rounds;
#[allow(dead_code)]
#[path = "common/rounds.rs"]
mod rounds;
#[allow(dead_code)]
#[path = "common/site_rounds.rs"]
mod site_rounds;
use families::*;
use listed_rounds::{relisted, spectral_seeding};
use rounds::*;

/// Fixed in the plan before any run.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];
const WEIGHTS: [f32; 4] = [2.0, 5.0, 10.0, 20.0];
const BASE: &str = "indoor_objects";
/// The rule's margins (points).
const LIFT: f64 = 2.0;
const GIVE: f64 = 1.0;

/// One way to weigh the new parts: (name, object_types, object_layout).
fn configs() -> Vec<(String, f32, f32)> {
    let mut c = vec![(BASE.to_string(), 0.0, 0.0)];
    for w in WEIGHTS {
        c.push((format!("A, w = {w}"), w, 0.0));
    }
    for w in WEIGHTS {
        c.push((format!("B, w = {w}"), 4.0 * w / 6.0, 2.0 * w / 6.0));
    }
    c
}

#[derive(Serialize)]
struct SetFigures {
    family: String,
    sensor: String,
    seed: u64,
    /// Per config: k-means with spectral seeding, room-level 1-NN (%).
    seeded: Vec<f64>,
    nearest: Vec<f64>,
}

fn probe_params() -> placecat::Result<DescriptorParams> {
    let mut p = DescriptorParams::preset(BASE)?;
    p.preset = "object_types_probe".into();
    for kind in [PartKind::ObjectTypes, PartKind::ObjectLayout] {
        p.parts.push(Part { kind, weight: 0.0 });
    }
    Ok(p)
}

fn one_set(f: &Family, sensor: Sensor, seed: u64) -> Res<SetFigures> {
    let probe = probe_params()?;
    let set = describe_set_with(f, sensor, seed, &[BASE.to_string()], |_| {
        Ok(vec![("probe".into(), probe.clone())])
    })?;
    let set = relisted(set, f.name, &sensor.name(), seed)?;
    let k = set.kinds;
    let find = |name: &str| set.presets.iter().find(|p| p.0 == name);
    let (Some(base), Some(with)) = (find(BASE), find("probe")) else {
        return Err(format!("{} {} seed {seed}: not described", f.name, sensor.name()).into());
    };
    // The harness check: the preset's own descriptors and the probe's with
    // the new parts at 0 must give the same figure.
    let base_space = Space::new(&base.2, DistanceOptions::from(&base.1))?;
    let own = spectral_seeding(&base_space, &base_space.matrix(), &set.truth, k)?;
    let out: Vec<(f64, f64)> = configs()
        .par_iter()
        .map(|(_, types, layout)| -> Result<(f64, f64), String> {
            let mut opts = DistanceOptions::from(&with.1);
            opts.part_weights[PartKind::ObjectTypes.index()] = *types;
            opts.part_weights[PartKind::ObjectLayout.index()] = *layout;
            let go = || -> Res<(f64, f64)> {
                let space = Space::new(&with.2, opts)?;
                let m = space.matrix();
                Ok((
                    100.0 * spectral_seeding(&space, &m, &set.truth, k)?,
                    100.0 * room_level_nn(&m, &set.truth, &set.apart),
                ))
            };
            go().map_err(|e| e.to_string())
        })
        .collect::<Result<_, String>>()?;
    if (out[0].0 - 100.0 * own).abs() > 1e-9 {
        return Err(format!(
            "{} {} seed {seed}: {BASE} {} against {} with the new parts at 0",
            f.name,
            sensor.name(),
            100.0 * own,
            out[0].0
        )
        .into());
    }
    Ok(SetFigures {
        family: f.name.into(),
        sensor: sensor.name(),
        seed,
        seeded: out.iter().map(|o| o.0).collect(),
        nearest: out.iter().map(|o| o.1).collect(),
    })
}

fn run(rows: &[(Family, Sensor)], t0: std::time::Instant) -> Res<Vec<SetFigures>> {
    run_on(rows, |_| DEV_SEEDS, t0)
}

fn run_on(
    rows: &[(Family, Sensor)],
    seeds_of: impl Fn(&Family) -> &'static [u64],
    t0: std::time::Instant,
) -> Res<Vec<SetFigures>> {
    let mut sets = vec![];
    for (f, sensor) in rows {
        let f = Family {
            shuffle: true,
            ..f.clone()
        };
        for &seed in seeds_of(&f) {
            sets.push(one_set(&f, *sensor, seed)?);
        }
        eprintln!(
            "{} {} ({:.0} s)",
            f.name,
            sensor.name(),
            t0.elapsed().as_secs_f64()
        );
    }
    Ok(sets)
}

/// Per config, the mean over the rows of each row's mean over its seeds
/// (every row has the same seeds, so the mean over the sets).
fn means<'a>(
    sets: impl IntoIterator<Item = &'a SetFigures>,
    figure: impl Fn(&SetFigures) -> &Vec<f64>,
) -> Vec<f64> {
    let mut sum = vec![0.0; configs().len()];
    let mut n = 0;
    for s in sets {
        for (t, v) in sum.iter_mut().zip(figure(s)) {
            *t += v;
        }
        n += 1;
    }
    sum.iter().map(|t| t / n as f64).collect()
}

fn table(o: &mut String, sets: &[SetFigures]) {
    let names: Vec<String> = configs().into_iter().map(|c| c.0).collect();
    o.push_str("| row |");
    for n in &names {
        let _ = write!(o, " {n} |");
    }
    o.push_str("\n|---|");
    o.push_str(&"---|".repeat(names.len()));
    o.push('\n');
    let mut rows: Vec<(String, String)> = vec![];
    for s in sets {
        let key = (s.family.clone(), s.sensor.clone());
        if !rows.contains(&key) {
            rows.push(key);
        }
    }
    for (family, sensor) in &rows {
        let of_row: Vec<&SetFigures> = (sets.iter())
            .filter(|s| &s.family == family && &s.sensor == sensor)
            .collect();
        let (seeded, nearest) = (
            means(of_row.iter().copied(), |s| &s.seeded),
            means(of_row.iter().copied(), |s| &s.nearest),
        );
        let _ = write!(o, "| {family}, {sensor} |");
        for (a, b) in seeded.iter().zip(&nearest) {
            let _ = write!(o, " {a:.1} / {b:.1} |");
        }
        o.push('\n');
    }
    let (seeded, nearest) = (means(sets, |s| &s.seeded), means(sets, |s| &s.nearest));
    let _ = write!(o, "| **mean over the {} rows** |", rows.len());
    for (a, b) in seeded.iter().zip(&nearest) {
        let _ = write!(o, " **{a:.1} / {b:.1}** |");
    }
    o.push_str("\n\n");
}

/// The rounds that ran the hotel, mall and home test seeds.
const SEEN: [(&str, &[u64], &str); 3] = [
    (
        "hotel (fresh)",
        &[541, 542, 543, 544, 545],
        "fresh-family.json",
    ),
    (
        "mall (fresh)",
        &[551, 552, 553, 554, 555],
        "fresh-family-2.json",
    ),
    (
        "home (fresh)",
        &[561, 562, 563, 564, 565],
        "fresh-family-3.json",
    ),
];

fn seen(t0: std::time::Instant) -> Res<()> {
    let rows: Vec<(Family, Sensor)> = [hotel_family(), mall_family(), home_family()]
        .into_iter()
        .flat_map(sensor_rows)
        .collect();
    let seeds_of = |f: &Family| SEEN.iter().find(|s| s.0 == f.name).map_or(&[][..], |s| s.1);
    let sets = run_on(&rows, seeds_of, t0)?;
    // indoor_objects' figures must be the rounds' own, set by set.
    let mut compared = 0;
    for (family, seeds, json) in SEEN {
        let r: listed_rounds::Report = read_json(&docs().join(json))?;
        for row in r.rows.iter().filter(|x| x.preset == BASE) {
            for (i, &seed) in seeds.iter().enumerate() {
                let s = (sets.iter())
                    .find(|s| s.family == family && s.sensor == row.sensor && s.seed == seed)
                    .ok_or("a set of the round not run here")?;
                let (a, b) = (
                    (s.seeded[0], s.nearest[0]),
                    (100.0 * row.seeded[i], 100.0 * row.nearest[i]),
                );
                if (a.0 - b.0).abs() > 1e-9 || (a.1 - b.1).abs() > 1e-9 {
                    return Err(format!(
                        "{family} {} seed {seed}: {a:?} here, {b:?} in docs/{json}",
                        row.sensor
                    )
                    .into());
                }
                compared += 2;
            }
        }
    }
    let f = means(&sets, |s| &s.seeded);
    let mut o = String::new();
    o.push_str("# Objects by size and height together, and their layout, on the hotel's, mall's and home's test seeds (issue 18, after the twenty-sixth round)\n\n");
    let _ = writeln!(
        o,
        "A reading after the twenty-sixth round's test run, which its plan did not name and which decides nothing. Regenerate with `cargo run --release --example object_types_dev -- --seen` ({:.0} s). The eight probe variants and `indoor_objects` of docs/object-types-dev.md, on the test seeds of the hotel (541-545), mall (551-555) and home (561-565) floors. These seeds were seen (their rounds reported `indoor_objects` on them) but were never used to choose among the eight, which the development seeds 1-6 of the same families did; so they are held out for that choice, not for the families (the choice looked at other seeds of them). Each set is listed as its round listed it. **Check:** `indoor_objects`' k-means with spectral seeding and room-level 1-NN equal the rounds' JSON on every set ({compared} figures). Each cell: k-means with spectral seeding (clustering seeds 0-9, mean) / room-level 1-NN, %.\n",
        t0.elapsed().as_secs_f64()
    );
    let names: Vec<String> = configs().into_iter().map(|c| c.0).collect();
    let cand = names
        .iter()
        .position(|n| n == "B, w = 10")
        .ok_or("no candidate")?;
    let _ = writeln!(
        o,
        "The candidate (B, w = 10, the preset `indoor_object_types`): **{:.1} %** against `{BASE}`'s {:.1} % over the 18 rows ({:+.1} points; on the development seeds +2.9).\n",
        f[cand],
        f[0],
        f[cand] - f[0]
    );
    table(&mut o, &sets);
    let json = serde_json::json!({ "configs": names, "sets": sets });
    write(
        "object-types-seen.json",
        &serde_json::to_string_pretty(&json)?,
    )?;
    write("object-types-seen.md", &o)
}

fn main() -> Res<()> {
    let t0 = std::time::Instant::now();
    if std::env::args().any(|a| a == "--seen") {
        return seen(t0);
    }
    let fresh_rows: Vec<(Family, Sensor)> = [hotel_family(), mall_family(), home_family()]
        .into_iter()
        .flat_map(sensor_rows)
        .collect();
    let fresh = run(&fresh_rows, t0)?;
    let earlier = run(&families::room_rows(), t0)?;
    let (f, e) = (means(&fresh, |s| &s.seeded), means(&earlier, |s| &s.seeded));
    let names: Vec<String> = configs().into_iter().map(|c| c.0).collect();
    // The highest fresh mean; on a tie the smaller weight, then A.
    let tie_order = |c: usize| (WEIGHTS[(c - 1) % WEIGHTS.len()], (c - 1) / WEIGHTS.len());
    let best = (1..names.len()).fold(1, |b, c| {
        let better = f[c] > f[b] || (f[c] == f[b] && tie_order(c) < tie_order(b));
        if better {
            c
        } else {
            b
        }
    });
    let candidate = f[best] >= f[0] + LIFT && e[best] > e[0] - GIVE;

    let mut o = String::new();
    o.push_str(include_str!("object_types_dev_intro.md"));
    let _ = writeln!(
        o,
        "\nRun time {:.0} s. Each cell: k-means with spectral seeding (clustering seeds 0-9, mean) / room-level 1-NN, %, the mean over development seeds {DEV_SEEDS:?}.\n",
        t0.elapsed().as_secs_f64()
    );
    let _ = writeln!(
        o,
        "## The rule\n\nHighest mean over the eighteen hotel, mall and home rows: **{}**, {:.1} % against `{BASE}`'s {:.1} % ({:+.1} points; the rule asks at least +{LIFT}); on the fourteen earlier room rows {:.1} % against {:.1} % ({:+.1}; the rule asks more than -{GIVE}). **{}**\n",
        names[best],
        f[best],
        f[0],
        f[best] - f[0],
        e[best],
        e[0],
        e[best] - e[0],
        if candidate {
            "A candidate: it becomes the preset `indoor_object_types` and the round's test run judges it."
        } else {
            "No candidate: the round runs without one."
        }
    );
    o.push_str("## The hotel, mall and home rows\n\n");
    table(&mut o, &fresh);
    o.push_str("## The fourteen earlier room rows\n\n");
    table(&mut o, &earlier);
    let json = serde_json::json!({
        "seeds": DEV_SEEDS,
        "configs": names,
        "fresh": fresh,
        "earlier": earlier,
        "best": names[best],
        "candidate": candidate,
    });
    write(
        "object-types-dev.json",
        &serde_json::to_string_pretty(&json)?,
    )?;
    write("object-types-dev.md", &o)
}
