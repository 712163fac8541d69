//! The report's section on choosing the number of categories, built from the
//! tables the `choose_k` example wrote (docs/choose_k_dev.md and
//! docs/choose_k_test.md): that evaluation takes long and its test seeds are
//! run once, so the report embeds its output instead of running it again.

use std::fmt::Write;
use std::path::Path;

/// Marks the section in docs/experiments.md, so that
/// `experiments -- --choose-k-only` can replace it alone.
pub const BEGIN: &str = "<!-- choose_k: from docs/choose_k_dev.md and docs/choose_k_test.md -->";
pub const END: &str = "<!-- /choose_k -->";

/// The default rule, and the rows it is compared with.
const RULE: &str = "silhouette_gap";
const ORACLE: &str = "oracle (true K)";

/// One row of the choose_k example's table.
struct Row {
    data: String,
    scans: String,
    levels: String,
    clusterer: String,
    rule: String,
    found: String,
    chosen: String,
    accuracy: String,
    ari: String,
}

fn rows(text: &str) -> Vec<Row> {
    text.lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| data "))
        .filter_map(|l| {
            let c: Vec<&str> = l.trim_matches('|').split(" | ").map(str::trim).collect();
            (c.len() == 9).then(|| Row {
                data: c[0].into(),
                scans: c[1].into(),
                levels: c[2].into(),
                clusterer: c[3].into(),
                rule: c[4].into(),
                found: c[5].into(),
                chosen: c[6].into(),
                accuracy: c[7].into(),
                ari: c[8].into(),
            })
        })
        .collect()
}

/// The default rule's rows beside the oracle's, for the data sets `keep`
/// selects.
fn table(out: &mut String, rows: &[Row], keep: impl Fn(&str) -> bool) {
    writeln!(out, "| data | scans | true K (levels) | clusterer | found | K chosen | accuracy % | ARI | oracle accuracy % | oracle ARI |\n|---|---|---|---|---|---|---|---|---|---|").unwrap();
    for r in rows.iter().filter(|r| r.rule == RULE && keep(&r.data)) {
        let oracle = rows
            .iter()
            .find(|o| o.rule == ORACLE && o.data == r.data && o.clusterer == r.clusterer);
        let (oa, oari) = oracle.map_or(("-", "-"), |o| (o.accuracy.as_str(), o.ari.as_str()));
        writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {oa} | {oari} |",
            r.data, r.scans, r.levels, r.clusterer, r.found, r.chosen, r.accuracy, r.ari
        )
        .unwrap();
    }
}

/// The section, or a line saying which file is missing.
pub fn section(docs: &Path) -> String {
    let mut out =
        format!("{BEGIN}\n## 6. Choosing the number of categories (issue 14, item 3)\n\n");
    let read = |f: &str| std::fs::read_to_string(docs.join(f)).map(|t| rows(&t));
    let (Ok(dev), Ok(test)) = (read("choose_k_dev.md"), read("choose_k_test.md")) else {
        writeln!(out, "docs/choose_k_dev.md or docs/choose_k_test.md is missing: run `cargo run --release --example choose_k -- --seeds dev docs/choose_k_dev.md` and `-- --seeds test docs/choose_k_test.md`.\n{END}").unwrap();
        return out;
    };
    writeln!(out, "The default rule, `{RULE}` (docs/choose_k.md: one category unless the best mean silhouette on Delta over K = 2..10 reaches 0.5, else the gap statistic's 1-SE rule), chosen on the development seeds before the test seeds were run; against the oracle (the true number of kinds). Tree: hierarchical k-means++ cut with `cut_k`; k-means: plusplus seeding; clustering seeds 0-9 in each data set. \"found\": the K chosen is the true number of kinds or a coarser level of the true hierarchy (outdoor: plain vs forest, 2; warehouse: halls vs airlock, 2; real files: KITTI's two places as one). \"found\" counts the number only: a K = 2 counts for the warehouse whether or not its two categories are halls and airlock. Accuracy and ARI at the K chosen; at K = 1 the accuracy is the share of the largest kind (the warehouse's large hall, about 74 %) and the ARI is 0, so read the ARI. Where the rule works and where it fails: docs/choose_k.md. Every rule tried, with every figure: docs/choose_k_dev.md and docs/choose_k_test.md, written by\n\n    cargo run --release --example choose_k -- --seeds dev docs/choose_k_dev.md\n    cargo run --release --example choose_k -- --seeds test docs/choose_k_test.md\n\nIndoor: 10 scans per kind; warehouse and outdoor: the sites of section 4 (300 scans).\n").unwrap();
    let simulated = |d: &str| !d.starts_with("real: ");
    writeln!(out, "### Development seeds (simulator seeds 1, 2, 3)\n").unwrap();
    table(&mut out, &dev, simulated);
    writeln!(
        out,
        "\n### Test seeds (simulator seeds 101-105, indoor one building also 11-20; run once)\n"
    )
    .unwrap();
    table(&mut out, &test, simulated);
    writeln!(
        out,
        "\n### Real files (`tests/data/real`; deterministic, the same on both runs)\n"
    )
    .unwrap();
    table(&mut out, &test, |d| d.starts_with("real: "));
    if let Ok(round2) = read("choose_k_round2.md") {
        writeln!(out, "\n### The outdoor site of the second round (section 4), one row per seed\n\nThe outdoor rows above are of the first round's site. The site was changed after them (a forest that is not see-through at the sensor's height; labels from the place the vehicle stands in; section 4), so it has its own rows, from `cargo run --release --example choose_k -- --seeds round2 docs/choose_k_round2.md`: development seeds 1-3 and the second round's test seeds 201-205 (run once). The rule is unchanged.\n").unwrap();
        table(&mut out, &round2, |_| true);
    }
    if let Ok(round3) = read("choose_k_round3.md") {
        writeln!(out, "\n### The outdoor site of the third round and the warehouse under its own preset (section 4), one row per seed\n\nThe second round's rows above are of its site. The third round kept branches out of the vehicle's corridor (section 4), so the site has its own rows, from `cargo run --release --example choose_k -- --seeds round3 docs/choose_k_round3.md`: development seeds 1-10 and the third round's test seeds 401-405 (run once). The warehouse site is unchanged; its rows here are under the `warehouse` preset (issue 18), as the page's warehouse demo would describe it (section 4: the demo stays on `indoor`). The rule is unchanged.\n").unwrap();
        table(&mut out, &round3, |_| true);
    }
    if let Ok(round4) = read("choose_k_round4.md") {
        writeln!(out, "\n### The outdoor site of the fourth round (section 4), one row per seed\n\nThe third round's outdoor rows above are of its site. The fourth round kept the vehicle's corridor clear of trunks, boulders, bushes, machines and low crowns (section 4), so the site has its own rows, from `cargo run --release --example choose_k -- --seeds round4 docs/choose_k_round4.md`: development seeds 1-10 and the fourth round's test seeds 501-505 (run once). The rule is unchanged.\n").unwrap();
        table(&mut out, &round4, |_| true);
    }
    writeln!(out, "{END}").unwrap();
    out
}
