//! Dataset trees, pipes and pictures on the command line (issue 16 items 4
//! and 6): a KITTI-style tree whose sequences repeat file names, `-o -`,
//! `cluster --format csv`, and `placecat map`.

use crate::cli_common::*;
use crate::common;
use common::*;
use placecat::io::write;
use std::path::{Path, PathBuf};

const PER_SEQUENCE: usize = 4;

/// `sequences/00/velodyne/00000N.bin` offices and `sequences/01/...`
/// corridors under the same file names, with a labels.csv by relative path.
fn kitti_tree(dir: &Path) -> PathBuf {
    let seq = dir.join("sequences");
    let mut labels = String::from("file,label\n");
    for (s, kind) in [("00", "office"), ("01", "corridor")] {
        let velo = seq.join(s).join("velodyne");
        std::fs::create_dir_all(&velo).unwrap();
        for i in 0..PER_SEQUENCE {
            let seed = 10 * s.parse::<u64>().unwrap() + i as u64;
            let points = if kind == "office" {
                office(seed)
            } else {
                corridor(seed)
            };
            let name = format!("{i:06}.bin");
            std::fs::write(velo.join(&name), write::kitti(&points)).unwrap();
            labels += &format!("{s}/velodyne/{name},{kind}\n");
        }
        // Not scans: skipped by the walk.
        std::fs::write(seq.join(s).join("calib.txt"), "P0: 1 0 0\n").unwrap();
        std::fs::write(velo.join(".000000.bin"), b"junk").unwrap();
    }
    std::fs::write(dir.join("labels.csv"), labels).unwrap();
    seq
}

fn names_of(v: &serde_json::Value, key: &str) -> Vec<String> {
    v[key]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let f = if key == "files" && f.is_object() {
                &f["name"]
            } else {
                f
            };
            f.as_str().unwrap().to_string()
        })
        .collect()
}

#[test]
fn a_kitti_tree_keeps_scans_with_one_file_name_apart() {
    let dir = tmp("kitti");
    let seq = kitti_tree(&dir);
    let labels = dir.join("labels.csv");
    let d = dir.join("d.json");
    succeeds(placecat().arg("describe").arg(&seq).arg("-o").arg(&d));
    let names = names_of(&read_json(&d), "files");
    let want: Vec<String> = ["00", "01"]
        .iter()
        .flat_map(|s| (0..PER_SEQUENCE).map(move |i| format!("{s}/velodyne/{i:06}.bin")))
        .collect();
    assert_eq!(names, want);

    // Two categories: offices and corridors, found by k-means.
    let c = dir.join("c.json");
    succeeds(
        placecat()
            .arg("cluster")
            .arg(&d)
            .args(["--method", "kmeans", "--k", "2", "--seed", "1", "-o"])
            .arg(&c),
    );
    let clusters = read_json(&c);
    assert_eq!(names_of(&clusters, "files"), want);
    let labels_of: Vec<i64> = clusters["labels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_i64().unwrap())
        .collect();
    let evaluate = |clusters: &Path| -> serde_json::Value {
        let out = succeeds(
            placecat()
                .arg("evaluate")
                .arg(clusters)
                .arg("--truth")
                .arg(&labels),
        );
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let ev = evaluate(&c);
    assert_eq!(ev["accuracy"], 1.0, "{ev}");
    assert_eq!(ev["ari"], 1.0, "{ev}");
    assert_eq!(ev["total"], 2 * PER_SEQUENCE);
    // One category for all: half right, ARI 0 (with base names both
    // sequences took one label and this read 1.0).
    let mut one = clusters.clone();
    one["labels"] = serde_json::json!(vec![0; 2 * PER_SEQUENCE]);
    let one_path = dir.join("one.json");
    std::fs::write(&one_path, one.to_string()).unwrap();
    let ev = evaluate(&one_path);
    assert_eq!(ev["accuracy"], 0.5, "{ev}");
    assert_eq!(ev["ari"], 0.0, "{ev}");

    // A labels.csv of base names is ambiguous here, and says so.
    let bare = dir.join("bare.csv");
    std::fs::write(&bare, "file,label\n000000.bin,office\n000001.bin,office\n").unwrap();
    let err = fails(placecat().arg("evaluate").arg(&c).arg("--truth").arg(&bare));
    assert!(
        err.contains("bare.csv") && err.contains("base name"),
        "{err}"
    );

    // The model has both categories.
    let model = dir.join("model.json");
    succeeds(
        placecat()
            .arg("model")
            .arg(&d)
            .arg("--names")
            .arg(&labels)
            .arg("-o")
            .arg(&model),
    );
    let m = read_json(&model);
    let kinds: Vec<&str> = m["categories"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["office", "corridor"]);

    // The distances CSV: one distinct column per scan.
    let out = succeeds(placecat().arg("distances").arg(&d));
    let csv = String::from_utf8(out.stdout).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(header[0], "file");
    assert_eq!(
        header[1..],
        want.iter().map(String::as_str).collect::<Vec<_>>()[..]
    );

    // classify names the scans as cluster does, each in its kind.
    let out = succeeds(placecat().arg("classify").arg(&model).arg(&seq));
    let rows: Vec<Vec<String>> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let classified: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(
        classified,
        want.iter().map(String::as_str).collect::<Vec<_>>()
    );
    for r in &rows {
        let kind = if r[0].starts_with("00/") {
            "office"
        } else {
            "corridor"
        };
        assert_eq!(r[1], kind, "{r:?}");
    }

    // The same CSV, and the clusters as file,category rows, on stdout.
    let out = succeeds(
        placecat()
            .arg("cluster")
            .arg(&d)
            .args(["--method", "kmeans", "--k", "2", "--seed", "1"])
            .args(["--format", "csv", "-o", "-"]),
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("file,category"));
    let rows: Vec<(String, i64)> = lines
        .map(|l| {
            let (f, c) = l.split_once(',').unwrap();
            (f.to_string(), c.parse().unwrap())
        })
        .collect();
    let from_json: Vec<(String, i64)> = want.iter().cloned().zip(labels_of).collect();
    assert_eq!(rows, from_json);
    // An output named .csv is CSV without --format, and a JSON one with it.
    let c_csv = dir.join("c.csv");
    succeeds(
        placecat()
            .arg("cluster")
            .arg(&d)
            .args(["--method", "kmeans", "--k", "2", "--seed", "1", "-o"])
            .arg(&c_csv),
    );
    assert_eq!(std::fs::read_to_string(&c_csv).unwrap(), text);
    succeeds(
        placecat()
            .arg("cluster")
            .arg(&d)
            .args(["--method", "kmeans", "--k", "2", "--format", "json", "-o"])
            .arg(&c_csv),
    );
    assert!(std::fs::read_to_string(&c_csv).unwrap().starts_with('{'));

    // describe -o - writes the descriptors to stdout, no file named "-".
    let out = succeeds(
        placecat()
            .current_dir(&dir)
            .arg("describe")
            .arg(seq.join("00"))
            .args(["-o", "-"]),
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(names_of(&v, "files")[0], "velodyne/000000.bin");
    assert!(!dir.join("-").exists());
}

#[test]
fn names_are_relative_to_the_common_root_and_never_repeat() {
    let dir = tmp("names");
    let seq = kitti_tree(&dir);
    // Two folders: named from their common parent.
    let d = dir.join("d.json");
    succeeds(
        placecat()
            .arg("describe")
            .arg(seq.join("00/velodyne"))
            .arg(seq.join("01"))
            .arg("-o")
            .arg(&d),
    );
    let names = names_of(&read_json(&d), "files");
    assert_eq!(names[0], "00/velodyne/000000.bin");
    assert_eq!(names[PER_SEQUENCE], "01/velodyne/000000.bin");
    // A scan given twice is an error naming both inputs.
    let err = fails(
        placecat()
            .arg("describe")
            .arg(&seq)
            .arg(seq.join("01/velodyne/000002.bin"))
            .arg("-o")
            .arg(&d),
    );
    assert!(
        err.contains("01/velodyne/000002.bin") && err.contains("both give"),
        "{err}"
    );
    // A folder with no scan in it or below: the message says where it looked.
    let empty = dir.join("empty/deeper");
    std::fs::create_dir_all(&empty).unwrap();
    let err = fails(
        placecat()
            .arg("describe")
            .arg(dir.join("empty"))
            .arg("-o")
            .arg(&d),
    );
    assert!(err.contains("subfolders") && err.contains(".e57"), "{err}");
    // simulate writes a folder: -o - is refused.
    let err = fails(placecat().args(["simulate", "--scene", "indoor", "-o", "-"]));
    assert!(err.contains("folder"), "{err}");
}

#[test]
fn map_draws_the_trajectory_by_category_over_the_points() {
    let dir = tmp("map");
    let sim = dir.join("sim");
    succeeds(
        placecat()
            .args([
                "simulate", "--scene", "indoor", "--seed", "3", "--scans", "2", "-o",
            ])
            .arg(&sim),
    );
    let d = dir.join("d.json");
    let c = dir.join("c.json");
    succeeds(placecat().arg("describe").arg(&sim).arg("-o").arg(&d));
    succeeds(
        placecat()
            .arg("cluster")
            .arg(&d)
            .args(["--method", "kmeans", "--k", "3", "--seed", "2", "-o"])
            .arg(&c),
    );
    let clusters = read_json(&c);
    let labels: Vec<i64> = clusters["labels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_i64().unwrap())
        .collect();
    let poses = sim.join("poses.txt");
    let map = |scans: bool| -> String {
        let mut cmd = placecat();
        cmd.arg("map").arg(&c).arg("--poses").arg(&poses);
        if scans {
            cmd.arg("--scans").arg(&sim);
        }
        let out = succeeds(cmd.args(["-o", "-"]));
        String::from_utf8(out.stdout).unwrap()
    };
    for (svg, with_points) in [(map(true), true), (map(false), false)] {
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(svg.trim_end().ends_with("</svg>"));
        assert_well_formed(&svg);
        // One dot per scan, in its category's colour (the page's palette).
        let dots: Vec<&str> = svg.split("<circle cx=").skip(1).collect();
        let scan_dots: Vec<&&str> = dots.iter().filter(|d| d.contains("<title>")).collect();
        assert_eq!(scan_dots.len(), labels.len());
        let palette = ["#4e79a7", "#f28e2b", "#59a14f"];
        for (dot, &l) in scan_dots.iter().zip(&labels) {
            assert!(
                dot.contains(&format!(
                    "fill=\"{}\" data-category=\"{l}\"",
                    palette[l as usize]
                )),
                "{dot}"
            );
        }
        // A segment into every scan but the first.
        assert_eq!(svg.matches("<line ").count(), labels.len() - 1);
        assert_eq!(svg.contains("<path id=\"points\""), with_points);
        if with_points {
            let cells = svg.matches("h2v2h-2z").count();
            assert!(cells > 500, "{cells} point cells");
        }
        assert!(svg.len() < 400_000, "{} bytes", svg.len());
    }
    // CSV poses match by name (here in reverse order, one scan left out):
    // the path through the named scans, no points (CSV has no heading).
    let kitti = placecat::io::poses::parse(&std::fs::read_to_string(&poses).unwrap()).unwrap();
    let files: Vec<String> = serde_json::from_value(clusters["files"].clone()).unwrap();
    let mut csv = String::from("name,x,y\n");
    for (f, p) in files.iter().zip(&kitti.poses).skip(1).rev() {
        csv += &format!("{f},{},{}\n", p.position[0], p.position[1]);
    }
    let by_name = dir.join("poses.csv");
    std::fs::write(&by_name, csv).unwrap();
    let out = succeeds(
        placecat()
            .arg("map")
            .arg(&c)
            .arg("--poses")
            .arg(&by_name)
            .arg("--scans")
            .arg(&sim)
            .args(["-o", "-"]),
    );
    let svg = String::from_utf8(out.stdout).unwrap();
    assert_well_formed(&svg);
    assert_eq!(svg.matches("<title>").count(), labels.len() - 1);
    assert!(!svg.contains("id=\"points\""));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("1 of") && stderr.contains("heading"),
        "{stderr}"
    );
    // The first dot drawn is the second scan's, in its category colour.
    let first = svg.split("<title>").nth(1).unwrap();
    assert!(first.starts_with(&files[1]), "{first}");

    // Poses that do not fit the scans: an error naming the poses file.
    let short = dir.join("short.txt");
    let text = std::fs::read_to_string(&poses).unwrap();
    std::fs::write(&short, text.lines().next().unwrap()).unwrap();
    let err = fails(
        placecat()
            .arg("map")
            .arg(&c)
            .arg("--poses")
            .arg(&short)
            .args(["-o", "-"]),
    );
    assert!(
        err.contains("short.txt") && err.contains("1 poses for"),
        "{err}"
    );
}

/// A small check of XML well-formedness: every tag closes in order, every
/// attribute value is quoted, no bare `&` or `<` in text.
fn assert_well_formed(xml: &str) {
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = xml.trim();
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        assert!(!text.contains('>'), "stray > in {text:?}");
        for (i, _) in text.match_indices('&') {
            let ent = &text[i..];
            assert!(
                ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"]
                    .iter()
                    .any(|e| ent.starts_with(e)),
                "bare & in {text:?}"
            );
        }
        let close = rest[open..].find('>').expect("an unclosed tag") + open;
        let tag = &rest[open + 1..close];
        assert!(
            tag.matches('"').count() % 2 == 0,
            "unbalanced quotes in <{tag}>"
        );
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name), "</{name}> closes the wrong tag");
        } else if !tag.ends_with('/') {
            stack.push(tag.split_whitespace().next().unwrap());
        }
        rest = &rest[close + 1..];
    }
    assert!(stack.is_empty(), "unclosed: {stack:?}");
    assert!(rest.trim().is_empty());
}

#[test]
fn help_describes_every_command() {
    // Each argument's text is checked in the CLI's own unit test (clap's
    // command tree); here the commands as a user meets them.
    let out = succeeds(placecat().arg("--help"));
    let text = String::from_utf8(out.stdout).unwrap();
    for cmd in [
        "info",
        "describe",
        "topics",
        "cluster",
        "evaluate",
        "sweep",
        "simulate",
        "model",
        "classify",
        "distances",
        "map",
    ] {
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{cmd} ")))
            .unwrap_or_else(|| panic!("{cmd} missing from --help:\n{text}"));
        assert!(line.split_whitespace().count() > 2, "{line:?}");
        succeeds(placecat().args([cmd, "--help"]));
    }
    let out = succeeds(placecat().args(["cluster", "--help"]));
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(
        help.contains("--format") && help.contains("standard output"),
        "{help}"
    );
    let out = succeeds(placecat().args(["describe", "--help"]));
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(
        help.contains("subfolders") && help.contains("relative"),
        "{help}"
    );
}
