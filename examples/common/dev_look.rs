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

/// The development seeds of every issue 18 round (docs/seeds.md); `main`
/// refuses them if the table ever lists one as a test seed.
const DEV_SEEDS: &[u64] = &[1, 2, 3, 4, 5, 6];
