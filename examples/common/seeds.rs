//! The simulator test seeds of docs/seeds.md, which the development
//! examples refuse to run.

/// Every simulator test seed of docs/seeds.md: the numbers of the table's
/// test-seed column ("301, 302", "11 to 20"), but for the clustering
/// seeds' row (those seed k-means, not scenes).
pub fn test_seeds() -> Result<Vec<u64>, Box<dyn std::error::Error>> {
    let mut seeds = table_seeds(|_| true)?;
    if seeds.is_empty() {
        return Err("docs/seeds.md: no test seed found".into());
    }
    // Those known when this was written, in case the file read is an older
    // one (401-405: issue 14's third round, on another branch then).
    for range in [
        101..=105,
        201..=205,
        301..=305,
        311..=315,
        321..=325,
        401..=405,
        501..=505,
    ] {
        seeds.extend(range);
    }
    Ok(seeds)
}

/// The test seeds of the rows of docs/seeds.md whose test-seed cell
/// `keep` accepts (every number in the cell, ranges "11 to 20" expanded).
fn table_seeds(keep: impl Fn(&str) -> bool) -> Result<Vec<u64>, Box<dyn std::error::Error>> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/seeds.md");
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut seeds = Vec::new();
    for line in text.lines().filter(|l| l.starts_with('|')) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        if cells.len() < 4 || cells[1].starts_with("clustering") || cells[1] == "work" {
            continue;
        }
        if !keep(cells[3]) {
            continue;
        }
        // Dates ("Run once on 2026-12-01"), times ("at 01:02") and file
        // names ("docs/descriptors-2.md") are not seeds.
        let cell = strip_times(&strip_dates(&strip_paths(cells[3])));
        let words: Vec<&str> = cell
            .split(|c: char| !c.is_ascii_alphanumeric())
            .filter(|w| !w.is_empty())
            .collect();
        for (i, w) in words.iter().enumerate() {
            let Ok(n) = w.parse::<u64>() else { continue };
            seeds.push(n);
            let upto = words.get(i + 2).and_then(|w| w.parse::<u64>().ok());
            if let (Some(&"to"), Some(m)) = (words.get(i + 1), upto) {
                seeds.extend(n + 1..m);
            }
        }
    }
    Ok(seeds)
}

/// Refuse a round whose development seeds include a test seed of
/// docs/seeds.md, or whose test seeds are not written there (a round's
/// seeds are written down before its first run).
#[allow(dead_code)] // unused by the seeds guard test, which includes this file alone
pub fn check_round_seeds(dev: &[u64], test: &[u64]) -> Result<(), Box<dyn std::error::Error>> {
    let blocked = test_seeds()?;
    if let Some(s) = dev.iter().find(|s| blocked.contains(s)) {
        return Err(format!("seed {s} is a test seed (docs/seeds.md)").into());
    }
    if let Some(s) = test.iter().find(|s| !blocked.contains(s)) {
        return Err(format!("seed {s} is not a test seed of docs/seeds.md").into());
    }
    Ok(())
}

/// Refuse seen seeds that a round uses for development unless each was
/// run as a test seed already (listed in a row of docs/seeds.md that says
/// "now seen", so it no longer judges anything) and none is among the
/// round's own test seeds.
#[allow(dead_code)] // the fifteenth round (rooms_search.rs)
pub fn check_seen(seen: &[u64], test: &[u64]) -> Result<(), Box<dyn std::error::Error>> {
    let run = table_seeds(|cell| cell.contains("now seen"))?;
    if let Some(s) = seen.iter().find(|s| test.contains(s)) {
        return Err(format!("seed {s} is one of this round's own test seeds").into());
    }
    if let Some(s) = seen.iter().find(|s| !run.contains(s)) {
        return Err(format!("seed {s} is no test seed that docs/seeds.md says was run").into());
    }
    Ok(())
}

/// `text` without the words that begin with `docs/`.
fn strip_paths(text: &str) -> String {
    text.split(' ')
        .map(|w| {
            let w = w.trim_start_matches('(');
            if w.starts_with("docs/") {
                ""
            } else {
                w
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// `text` with every YYYY-MM-DD date blanked out.
fn strip_dates(text: &str) -> String {
    let mut out: Vec<char> = text.chars().collect();
    let digit = |c: Option<&char>| c.is_some_and(|c| c.is_ascii_digit());
    for i in 0..out.len() {
        let at = |k: usize| out.get(i + k);
        let shape = (0..10).all(|k| {
            if k == 4 || k == 7 {
                at(k) == Some(&'-')
            } else {
                digit(at(k))
            }
        });
        if shape {
            out[i..i + 10].iter_mut().for_each(|c| *c = ' ');
        }
    }
    out.into_iter().collect()
}

/// `text` with every clock time (HH:MM, HH:MM:SS) blanked out: a digit pair
/// joined to another by a colon is a time, never a seed, which the table
/// writes as "301, 302".
fn strip_times(text: &str) -> String {
    let mut out: Vec<char> = text.chars().collect();
    let n = out.len();
    let digit = |v: &Vec<char>, i: usize| v.get(i).is_some_and(char::is_ascii_digit);
    let mut blank = vec![false; n];
    for i in 0..n {
        if out[i] != ':' || i == 0 || !digit(&out, i - 1) || !digit(&out, i + 1) {
            continue;
        }
        let mut a = i;
        while a > 0 && digit(&out, a - 1) {
            a -= 1;
        }
        let mut b = i + 1;
        while digit(&out, b) {
            b += 1;
        }
        blank[a..b].iter_mut().for_each(|x| *x = true);
    }
    for (c, &x) in out.iter_mut().zip(&blank) {
        if x {
            *c = ' ';
        }
    }
    out.into_iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_and_dates_are_not_seeds() {
        let cell = strip_times(&strip_dates("381, 382 (run at 01:02:33 on 2026-12-02)"));
        let numbers: Vec<&str> = cell
            .split(|c: char| !c.is_ascii_digit())
            .filter(|w| !w.is_empty())
            .collect();
        assert_eq!(numbers, ["381", "382"]);
    }

    #[test]
    fn every_test_seed_of_the_table_and_no_development_seed() {
        let seeds = test_seeds().unwrap();
        for s in [11, 20, 101, 305, 381, 385, 391, 395, 445, 451, 455, 805] {
            assert!(seeds.contains(&s), "{s}");
        }
        for s in 0..=10 {
            assert!(!seeds.contains(&s), "{s} is a development seed");
        }
    }

    #[test]
    fn seen_seeds_are_test_seeds_already_run() {
        check_seen(&[421, 441, 445], &[451]).unwrap();
        // The round's own test seed, a development seed, a seed never written.
        assert!(check_seen(&[451], &[451]).is_err());
        assert!(check_seen(&[7], &[451]).is_err());
        assert!(check_seen(&[999], &[451]).is_err());
    }
}
