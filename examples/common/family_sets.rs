//! What the rounds that add a preset to every family share (round 8,
//! `columns.rs`; round 9, `scaled.rs`): a set's figures for each preset,
//! and the table of their means by family and sensor. Include after
//! `families.rs`, `rounds.rs` and `preset_rounds.rs`.

use crate::families::pct;
use crate::preset_rounds::Figures;
use crate::rounds::{each_row, lowest_over, mean_over, target, Res};
use serde::{Deserialize, Serialize};
use std::fmt::Write;

#[derive(Serialize, Deserialize, Clone)]
pub struct FamilySet {
    pub family: String,
    pub sensor: String,
    pub seed: u64,
    pub scans: usize,
    /// Each preset's clusterings and its room-level 1-NN.
    pub presets: Vec<(String, Figures, f64)>,
}

/// A set's figures for preset `p`.
pub fn entry<'a>(s: &'a FamilySet, p: &str) -> Option<&'a (String, Figures, f64)> {
    s.presets.iter().find(|q| q.0 == p)
}

/// The means over each family and sensor that `sensor_filter` keeps of
/// every preset's figures, one row a preset.
pub fn family_table(
    o: &mut String,
    presets: &[(String, Vec<String>)],
    all: &[FamilySet],
    sensor_filter: impl Fn(&str) -> bool,
) -> Res<()> {
    writeln!(o, "| family | sensor | preset | stride k-means | k-means++ best of 10 | hk-means++, 10 trials | lowest tree | room-level 1-NN | target |\n|---|---|---|---|---|---|---|---|---|")?;
    fn key(s: &FamilySet) -> (&str, &str) {
        (s.family.as_str(), s.sensor.as_str())
    }
    each_row(
        presets,
        all,
        key,
        sensor_filter,
        |family, sensor, sets, i, p| {
            let of = |f: fn(&Figures) -> f64| move |s: &FamilySet| entry(s, p).map(|e| f(&e.1));
            let tag = if i == 0 { " (paper)" } else { "" };
            writeln!(
                o,
                "| {family} | {sensor} | `{p}`{tag} | {} | {} | {} | {} | {} | {} |",
                pct(mean_over(sets, of(|f| f.stride.accuracy))),
                pct(mean_over(sets, of(|f| f.best_of_10.accuracy))),
                pct(mean_over(sets, of(|f| f.hk_trials.accuracy))),
                pct(lowest_over(sets, of(|f| f.hk_trials.lowest))),
                pct(mean_over(sets, |s: &FamilySet| entry(s, p).map(|e| e.2))),
                if i == 0 { "-" } else { target(family) },
            )?;
            Ok(())
        },
    )
}
