//! What every round's report reads: rows by preset, the rules, the
//! readings, every set, the pooled rows and the common sections.

use super::*;
use std::fmt::Write;

/// The rows of `preset`, in the report's order.
pub fn rows_of<'a>(r: &'a Report, preset: &str) -> Vec<&'a Row> {
    r.rows.iter().filter(|x| x.preset == preset).collect()
}

/// The mean over `rows` of each row's mean of `f`.
pub fn over_rows(rows: &[&Row], f: fn(&Row) -> &Vec<f64>) -> f64 {
    rows.iter().map(|x| mean(f(x))).sum::<f64>() / rows.len() as f64
}

pub fn at_target(x: f64) -> bool {
    100.0 * x >= ROOM_TARGET
}

/// The rule fixed in the plan, computed on the test report.
pub fn rule(o: &mut String, r: &Report, what: &str) -> Res<()> {
    let (ours, paper) = (rows_of(r, RULE_PRESET), rows_of(r, PAPER_PRESET));
    if ours.is_empty() || ours.len() != paper.len() {
        return Err("the report lacks the rule's rows".into());
    }
    let seeded = over_rows(&ours, |x| &x.seeded);
    let best = over_rows(&ours, |x| &x.best_of_10);
    let paper_seeded = over_rows(&paper, |x| &x.seeded);
    let recommendation = if seeded < best {
        "below it, so the README's recommendation of spectral seeding for room sets is withdrawn (it stays an option with its figures)"
    } else {
        "not below it, so the recommendation stands"
    };
    let preset = if seeded < paper_seeded {
        format!("below it, so `{RULE_PRESET}` did not carry over to a family written after it")
    } else {
        format!("not below it, so `{RULE_PRESET}` carried over")
    };
    writeln!(o, "- Over the {} {what} rows, `{RULE_PRESET}` with spectral seeding averages **{} %** against k-means++ best of 10's {} % with `{RULE_PRESET}`: {recommendation}.", ours.len(), pct(seeded), pct(best))?;
    writeln!(
        o,
        "- Against the paper's `{PAPER_PRESET}` with spectral seeding ({} %): {preset}.",
        pct(paper_seeded)
    )?;
    Ok(())
}

/// The readings the plan names, on one report's rows.
pub fn readings(o: &mut String, r: &Report) -> Res<()> {
    let (ours, paper) = (rows_of(r, RULE_PRESET), rows_of(r, PAPER_PRESET));
    if ours.len() != paper.len()
        || ours
            .iter()
            .zip(&paper)
            .any(|(x, p)| (&x.family, &x.sensor) != (&p.family, &p.sensor))
    {
        return Err("the two presets' rows are not the same sensors".into());
    }
    writeln!(o, "Per row, `{RULE_PRESET}`: k-means with spectral seeding against 85 %, against `{PAPER_PRESET}` with spectral seeding and against best of 10 with `{RULE_PRESET}`:\n")?;
    for (x, p) in ours.iter().zip(&paper) {
        let seeded = mean(&x.seeded);
        let verdict = if at_target(seeded) {
            "at least 85 %"
        } else {
            "below 85 %"
        };
        let versus = |other: f64| {
            if seeded >= other {
                "above or level"
            } else {
                "below"
            }
        };
        writeln!(o, "- {}, {}: **{} %** ({verdict}); `{PAPER_PRESET}` {} % ({}); best of 10 {} % ({}); stride k-means {} %.", x.family, x.sensor, pct(seeded), pct(mean(&p.seeded)), versus(mean(&p.seeded)), pct(mean(&x.best_of_10)), versus(mean(&x.best_of_10)), pct(mean(&x.stride)))?;
    }
    writeln!(o)?;
    // The presets in the report's order: the rounds' three, and the
    // twenty-sixth round's candidate where its family ran.
    let mut presets: Vec<&str> = vec![];
    for x in &r.rows {
        if !presets.contains(&x.preset.as_str()) {
            presets.push(&x.preset);
        }
    }
    for preset in presets {
        let rows = rows_of(r, preset);
        let count = |f: fn(&Row) -> bool| rows.iter().filter(|x| f(x)).count();
        let seeded = count(|x| at_target(mean(&x.seeded)));
        let both = count(|x| at_target(mean(&x.stride)) && at_target(mean(&x.best_of_10)));
        let stride = count(|x| at_target(mean(&x.stride)));
        let best = count(|x| at_target(mean(&x.best_of_10)));
        let spectral = count(|x| at_target(mean(&x.spectral)));
        let avg = |f: fn(&Row) -> &Vec<f64>| pct(over_rows(&rows, f));
        let only = if rows.len() < rows_of(r, RULE_PRESET).len() {
            " (only the rows it ran on)"
        } else {
            ""
        };
        writeln!(o, "- `{preset}`, rows of {}{only} at least 85 %: with spectral seeding **{seeded}**; with stride k-means and best of 10 both {both}; stride k-means {stride}; best of 10 {best}; spectral clustering {spectral}. Means over the rows: stride {}, best of 10 {}, spectral seeding {}, hk-means++ {}, spectral {}, room-level 1-NN {} %.", rows.len(), avg(|x| &x.stride), avg(|x| &x.best_of_10), avg(|x| &x.seeded), avg(|x| &x.tree), avg(|x| &x.spectral), avg(|x| &x.nearest))?;
    }
    let s = &r.stride_starts;
    writeln!(
        o,
        "- Stride seeding's first centres were one scan of each kind on {} of the {} room sets.",
        s.one_of_each_kind, s.room_sets
    )?;
    Ok(())
}

/// Every set's figure of `preset`: spectral seeding, best of 10 and
/// stride k-means, seed by seed.
pub fn per_set(o: &mut String, r: &Report, preset: &str) -> Res<()> {
    let seeds: Vec<String> = r.seeds.iter().map(|s| s.to_string()).collect();
    writeln!(o, "| family | sensor | {} |", seeds.join(" | "))?;
    writeln!(o, "|---|---|{}", "---|".repeat(seeds.len()))?;
    for x in rows_of(r, preset) {
        let cells: Vec<String> = (0..seeds.len())
            .map(|i| {
                format!(
                    "{} / {} / {}",
                    pct(x.seeded[i]),
                    pct(x.best_of_10[i]),
                    pct(x.stride[i])
                )
            })
            .collect();
        writeln!(o, "| {} | {} | {} |", x.family, x.sensor, cells.join(" | "))?;
    }
    Ok(())
}

/// Test seeds `s` as a span, "541-545".
pub fn span(s: &[u64]) -> String {
    format!("{}-{}", s[0], s[s.len() - 1])
}

/// The rounds run before the one of `flag`, in [`ROUNDS`]' order.
fn rounds_before(flag: &str) -> Res<&'static [Round]> {
    let at = (ROUNDS.iter().position(|r| r.flag == flag)).ok_or(format!("no round {flag}"))?;
    Ok(&ROUNDS[..at])
}

/// The test seeds of the rounds before the one of `flag`, as spans.
pub fn earlier_seeds(flag: &str) -> Res<Vec<String>> {
    Ok(rounds_before(flag)?
        .iter()
        .map(|r| span(r.test_seeds))
        .collect())
}

/// [`pooled`] over the reports of the rounds before the one of `flag`.
pub fn pooled_before(flag: &str, last: &Report) -> Res<Report> {
    let stems: Vec<&str> = rounds_before(flag)?.iter().map(|r| r.stem).collect();
    pooled(&stems, last)
}

/// The rows of the earlier rounds' reports `earlier` (docs/`stem`.json)
/// and of `last` as one report (the rules from the twenty-fourth round
/// on read them pooled).
pub fn pooled(earlier: &[&str], last: &Report) -> Res<Report> {
    let mut all = Report {
        seeds: last.seeds.clone(),
        seconds: 0.0,
        rows: vec![],
        stride_starts: StrideStarts {
            room_sets: 0,
            one_of_each_kind: 0,
        },
    };
    let reports: Vec<Report> = (earlier.iter())
        .map(|stem| read_json(&docs().join(format!("{stem}.json"))))
        .collect::<Res<_>>()?;
    for r in reports.iter().chain([last]) {
        all.seconds += r.seconds;
        all.rows.extend(r.rows.iter().cloned());
        all.stride_starts.room_sets += r.stride_starts.room_sets;
        all.stride_starts.one_of_each_kind += r.stride_starts.one_of_each_kind;
    }
    Ok(all)
}

/// A round's report after its notes: the test table, every test set of
/// [`RULE_PRESET`], and the development run with its check (`check_tail`
/// ends the check's sentence).
pub fn sections(
    o: &mut String,
    dev: &Report,
    test: &Report,
    test_seeds: &str,
    check_tail: &str,
) -> Res<()> {
    writeln!(o, "## 1. Test seeds {test_seeds}\n")?;
    seeding_table(o, test)?;
    writeln!(o, "\n## 2. Every test set, `{RULE_PRESET}` (spectral seeding / best of 10 / stride k-means, %)\n")?;
    per_set(o, test, RULE_PRESET)?;
    writeln!(o, "\n## 3. Development seeds 1-6, the hospital's rows (run first, to check the harness; they decide nothing)\n")?;
    let compared = same_as_again_dev(dev)?;
    writeln!(o, "**Check.** Every figure equals the twenty-second round's development run on the same rows (docs/{EARLIER_DEV}; {compared} figures, checked each time this file is rendered){check_tail}.\n")?;
    seeding_table(o, dev)
}

/// The candidate against [`RULE_PRESET`] over `what`'s rows with
/// spectral seeding, and the verdict of `judge`.
pub fn candidate_rule(o: &mut String, r: &Report, what: &str, judge: Judge) -> Res<()> {
    let (cand, ours) = (rows_of(r, CANDIDATE), rows_of(r, RULE_PRESET));
    if cand.is_empty() || cand.len() != ours.len() {
        return Err("the report lacks the candidate's rows".into());
    }
    let (c, b) = (
        over_rows(&cand, |x| &x.seeded),
        over_rows(&ours, |x| &x.seeded),
    );
    let verdict = match judge {
        Judge::Reading => String::new(),
        _ if c <= b => ": not above it, so the preset is withdrawn".to_string(),
        Judge::RecommendBy(points) if 100.0 * (c - b) >= points => format!(
            ": above it by {} points (at least {points}), so the README's recommendation for sets of room scans names `{CANDIDATE}` with spectral seeding in place of `{RULE_PRESET}`",
            gap(c, b)
        ),
        Judge::RecommendBy(points) => format!(
            ": above it by {} points (less than {points}), so the preset stays, an option no default uses",
            gap(c, b)
        ),
        Judge::WithdrawUnlessAbove => ": above it, so the preset stays, an option no default uses".to_string(),
    };
    writeln!(o, "- Over the {} {what} rows, `{CANDIDATE}` with spectral seeding averages **{} %** against `{RULE_PRESET}`'s {} %{verdict}.", cand.len(), pct(c), pct(b))?;
    let higher = (cand.iter().zip(&ours))
        .filter(|(x, y)| mean(&x.seeded) > mean(&y.seeded))
        .count();
    writeln!(
        o,
        "- Row by row it is above `{RULE_PRESET}` in {higher} of the {} rows.",
        cand.len()
    )?;
    Ok(())
}

/// What [`candidate_rule`] decides.
pub enum Judge {
    /// The twenty-sixth round's rule: withdrawn unless above.
    WithdrawUnlessAbove,
    /// The twenty-seventh round's: withdrawn unless above, recommended in
    /// place of [`RULE_PRESET`] where above by at least these points.
    RecommendBy(f64),
    /// No rule: the means only.
    Reading,
}

/// The difference of two shares in points, from the unrounded means.
fn gap(a: f64, b: f64) -> String {
    format!("{:.1}", 100.0 * (a - b))
}
