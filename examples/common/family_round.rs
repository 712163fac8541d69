// The modules of a round over every family (rounds 9-16: scaled, floor,
// true_floor, iron, searched, indoor_searched, rooms_searched,
// room_objects). Each of
// those examples `include!`s this file at its root, so the modules name each other
// `crate::families` and so on; the paths are relative to this file.
#[path = "families.rs"]
mod families;
#[path = "real.rs"]
mod real;
#[path = "rounds.rs"]
mod rounds;
// These rounds have no site: the shared site code goes partly unused.
#[allow(dead_code)]
#[path = "site_rounds.rs"]
mod site_rounds;
#[path = "preset_rounds.rs"]
mod preset_rounds;
#[path = "family_sets.rs"]
mod family_sets;
#[path = "seeds.rs"]
mod seeds;
use families::*;
use family_sets::*;
// Only `scaled` reads the preset rounds' tables itself.
#[allow(unused_imports)]
use preset_rounds::*;
use rounds::*;
use site_rounds::*;

/// A round over every family (rounds 10-16): its seeds checked against
/// docs/seeds.md, `added` put after each room family's presets
/// ([`round_presets`]), then [`every_family_round`], which leaves
/// `candidates` (no presets) out of the real scans.
#[allow(dead_code)] // `scaled` makes its presets itself
fn family_round(
    files: &RoundFiles,
    (dev, test): (&[u64], &[u64]),
    added: &[&str],
    candidates: &[&str],
    each: fn(&Family, Sensor, u64, &[String]) -> Res<FamilySet>,
    render: fn(&Report) -> Res<String>,
) -> Res<()> {
    seeds::check_round_seeds(dev, test)?;
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let presets = round_presets(&docs, added)?;
    every_family_round(files, &presets, (dev, test), each, candidates, render)
}
