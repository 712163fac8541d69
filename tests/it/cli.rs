//! The `placecat` command line: the forms other tooling scripts against.

use crate::cli_common::*;
use crate::common;
use common::*;
use placecat::io::write::{self, PlyEncoding};

/// The names of the described scans in a `describe` OUT.json.
fn described_names(v: &serde_json::Value) -> Vec<&str> {
    v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["name"].as_str().unwrap())
        .collect()
}

#[test]
fn info_json_on_the_real_pcd() {
    let out =
        succeeds(placecat().args(["info", &format!("{REAL}/pcl_room/room_scan1.pcd"), "--json"]));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["count"], 112586);
    assert_eq!(v["format"], "pcd_binary_compressed");
    assert_eq!(v["first"].as_array().unwrap().len(), 3);
    assert_eq!(v["last"][2].as_array().unwrap().len(), 3);
    // Recompute the sum from the library's reader.
    let c = placecat::io::read_scan(
        &real("pcl_room/room_scan1.pcd"),
        "x.pcd",
        &Default::default(),
    )
    .unwrap();
    let sx: f64 = c.points.iter().map(|p| p[0] as f64).sum();
    assert!((v["sum"][0].as_f64().unwrap() - sx).abs() < 1e-6);
    assert!((v["first"][0][2].as_f64().unwrap() - 1.6857659816741943).abs() < 1e-7);
}

#[test]
fn describe_skips_bad_files_and_distances_write_csv() {
    let dir = tmp("describe");
    std::fs::write(
        dir.join("a_office.ply"),
        write::ply(&office(1), PlyEncoding::BinaryLittleEndian, false),
    )
    .unwrap();
    std::fs::write(
        dir.join("b_corridor.ply"),
        write::ply(&corridor(2), PlyEncoding::Ascii, false),
    )
    .unwrap();
    std::fs::write(
        dir.join("c_broken.ply"),
        b"ply\nformat ascii 1.0\nelement vertex 5\n",
    )
    .unwrap();
    std::fs::write(dir.join("notes.txt"), b"not a scan").unwrap();
    let out_json = dir.join("d.json");
    let out = succeeds(
        placecat()
            .args(["describe", "--preset", "indoor"])
            .arg(&dir)
            .arg("-o")
            .arg(&out_json),
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("c_broken.ply") && stderr.contains("end_header"),
        "{stderr}"
    );
    let v = read_json(&out_json);
    assert_eq!(described_names(&v), ["a_office.ply", "b_corridor.ply"]);
    assert_eq!(
        v["errors"][0]["file"].as_str().unwrap(),
        dir.join("c_broken.ply").display().to_string()
    );
    assert_eq!(v["params"]["preset"], "indoor");

    let csv_path = dir.join("d.csv");
    succeeds(
        placecat()
            .arg("distances")
            .arg(&out_json)
            .arg("-o")
            .arg(&csv_path),
    );
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "file,a_office.ply,b_corridor.ply");
    let row: Vec<&str> = lines[1].split(',').collect();
    assert_eq!(row[0], "a_office.ply");
    assert_eq!(row[1], "0");
    assert!(row[2].parse::<f32>().unwrap() > 0.0);
    assert_eq!(lines[2].split(',').nth(1), Some(row[2]));

    // A DESCRIPTORS.json edited by hand or cut short is refused on loading,
    // naming the file and the scan, by every command that reads one.
    let good: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out_json).unwrap()).unwrap();
    let edit = |name: &str, change: &dyn Fn(&mut serde_json::Value)| {
        let mut v = good.clone();
        change(&mut v);
        let path = dir.join(name);
        std::fs::write(&path, v.to_string()).unwrap();
        path
    };
    let short = edit("short.json", &|v| {
        v["files"][1]["descriptor"]["matrices"][0]
            .as_array_mut()
            .unwrap()
            .pop();
    });
    let fewer_ranges = edit("ranges.json", &|v| {
        v["params"]["ranges"].as_array_mut().unwrap().pop();
    });
    let negative_voxels = edit("voxels.json", &|v| {
        v["params"]["voxel_size"] = (-1.0).into()
    });
    for (path, want) in [
        (&short, "short.json: b_corridor.ply: mismatch: a matrix does not have rows x cols = 11 x 7 entries"),
        (&fewer_ranges, "ranges.json: a_office.ply: mismatch: the descriptor is 11x7, the set's parameters make 11x6"),
        (&negative_voxels, "voxels.json: invalid parameter: voxel_size must be at least 0.001 m, got -1"),
    ] {
        for args in [
            &["cluster", "--method", "kmeans", "--k", "2", "--seeding", "stride", "--seed", "0"][..],
            &["distances"][..],
        ] {
            let err = fails(placecat().arg(args[0]).arg(path).args(&args[1..]).arg("-o").arg(dir.join("o")));
            assert!(err.contains(want), "{args:?}: {err}");
        }
    }

    // Output piped into a reader that stops early (`placecat ... | head`):
    // the command ends quietly instead of panicking in print!. 300 scans
    // make a matrix of over 64 KiB, more than a pipe holds.
    let mut many = good.clone();
    let first = good["files"][0].clone();
    many["files"] = (0..300)
        .map(|i| {
            let mut f = first.clone();
            f["name"] = format!("scan_{i:03}.ply").into();
            f
        })
        .collect();
    let many_path = dir.join("many.json");
    std::fs::write(&many_path, many.to_string()).unwrap();
    let mut child = placecat()
        .arg("distances")
        .arg(&many_path)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child.stdout = None; // the reader goes away before the first byte
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stderr.is_empty(),
        "{:?}: {stderr}",
        out.status
    );
}

#[test]
fn describe_with_params_file_and_all_failing_exits_nonzero() {
    let dir = tmp("params");
    std::fs::write(
        dir.join("p.json"),
        r#"{"voxel_size": 0.5, "height_bands": [0.0]}"#,
    )
    .unwrap();
    std::fs::write(
        dir.join("s.ply"),
        write::ply(&office(3), PlyEncoding::BinaryBigEndian, true),
    )
    .unwrap();
    succeeds(
        placecat()
            .args(["describe", "--params"])
            .arg(dir.join("p.json"))
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("o.json")),
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("o.json")).unwrap()).unwrap();
    assert_eq!(v["params"]["voxel_size"], 0.5);
    assert_eq!(v["files"][0]["descriptor"]["rows"], 22);

    // A limit on points: the scan is refused with a clear error, the run fails.
    let e = fails(
        placecat()
            .args(["describe", "--max-points", "1000"])
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("l.json")),
    );
    assert!(
        e.contains("s.ply") && e.contains("more than the limit of 1000"),
        "{e}"
    );

    std::fs::write(dir.join("bad.bin"), [1u8, 2, 3]).unwrap();
    fails(
        placecat()
            .arg("describe")
            .arg(dir.join("bad.bin"))
            .arg("-o")
            .arg(dir.join("x.json")),
    );
    std::fs::write(dir.join("q.json"), r#"{"voxel_sise": 0.5}"#).unwrap();
    let e = fails(
        placecat()
            .args(["describe", "--params"])
            .arg(dir.join("q.json"))
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("y.json")),
    );
    assert!(e.contains("voxel_sise"), "{e}");

    // A file naming its preset: that preset under the fields it gives,
    // unless --preset says another, which is refused naming the file.
    std::fs::write(
        dir.join("outdoor.json"),
        r#"{"preset": "outdoor", "voxel_size": 0.5}"#,
    )
    .unwrap();
    succeeds(
        placecat()
            .args(["describe", "--params"])
            .arg(dir.join("outdoor.json"))
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("z.json")),
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("z.json")).unwrap()).unwrap();
    let outdoor = placecat::DescriptorParams::outdoor();
    assert_eq!(v["params"]["ranges"], serde_json::json!(outdoor.ranges));
    assert_eq!(v["params"]["voxel_size"], 0.5);
    let e = fails(
        placecat()
            .args(["describe", "--preset", "indoor", "--params"])
            .arg(dir.join("outdoor.json"))
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("w.json")),
    );
    assert!(
        e.contains("outdoor.json")
            && e.contains(r#"name preset "outdoor" but are laid over preset "indoor""#),
        "{e}"
    );
}

/// `--sensor-height` sets the parameters' `sensor_height` (over a
/// `--params` file's) and is checked as they are, naming the field.
#[test]
fn describe_takes_the_sensor_height() {
    let dir = tmp("sensor_height");
    std::fs::write(
        dir.join("s.ply"),
        write::ply(&office(3), PlyEncoding::BinaryBigEndian, true),
    )
    .unwrap();
    std::fs::write(dir.join("p.json"), r#"{"sensor_height": 2.0}"#).unwrap();
    succeeds(
        placecat()
            .args([
                "describe",
                "--preset",
                "indoor_columns",
                "--sensor-height",
                "1.15",
                "--params",
            ])
            .arg(dir.join("p.json"))
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("d.json")),
    );
    let v = read_json(&dir.join("d.json"));
    assert_eq!(v["params"]["sensor_height"], 1.15);
    assert_eq!(v["params"]["preset"], "indoor_columns");
    // A withdrawn preset still describes, and says it is withdrawn; the
    // others say nothing of the kind.
    for (preset, withdrawn) in [("indoor_object_types", true), ("indoor_objects", false)] {
        let out = succeeds(
            placecat()
                .args(["describe", "--preset", preset])
                .arg(dir.join("s.ply"))
                .arg("-o")
                .arg(dir.join("w.json")),
        );
        let said = String::from_utf8_lossy(&out.stderr);
        let note = format!("note: preset {preset} is withdrawn, not on the page's menu");
        assert_eq!(said.contains(&note), withdrawn, "{said}");
        assert_eq!(read_json(&dir.join("w.json"))["params"]["preset"], preset);
    }
    let e = fails(
        placecat()
            .args(["describe", "--sensor-height", "0"])
            .arg(dir.join("s.ply"))
            .arg("-o")
            .arg(dir.join("e.json")),
    );
    assert!(e.contains("sensor_height must be above 0"), "{e}");
}

#[test]
fn simulate_describe_cluster_evaluate_round_trip() {
    let dir = tmp("pipeline");
    let sim = dir.join("sim");
    succeeds(
        placecat()
            .args([
                "simulate", "--scene", "indoor", "--seed", "5", "--scans", "3", "-o",
            ])
            .arg(&sim),
    );
    let labels = std::fs::read_to_string(sim.join("labels.csv")).unwrap();
    assert_eq!(labels.lines().count(), 16);
    assert_eq!(labels.lines().nth(1), Some("scan_00000.ply,office"));
    let kitti =
        placecat::io::poses::parse(&std::fs::read_to_string(sim.join("poses.txt")).unwrap())
            .unwrap();
    let tum =
        placecat::io::poses::parse(&std::fs::read_to_string(sim.join("poses_tum.txt")).unwrap())
            .unwrap();
    assert_eq!((kitti.poses.len(), tum.poses.len()), (15, 15));

    let d = dir.join("d.json");
    succeeds(placecat().arg("describe").arg(&sim).arg("-o").arg(&d));
    let evaluate = |clusters: &std::path::Path| {
        let mut cmd = placecat();
        cmd.arg("evaluate")
            .arg(clusters)
            .arg("--truth")
            .arg(sim.join("labels.csv"));
        cmd
    };
    let run = |args: &[&str], name: &str| -> serde_json::Value {
        let o = dir.join(name);
        succeeds(
            placecat()
                .arg("cluster")
                .arg(&d)
                .args(args)
                .arg("-o")
                .arg(&o),
        );
        let ev = succeeds(&mut evaluate(&o));
        let v: serde_json::Value = serde_json::from_slice(&ev.stdout).unwrap();
        for key in ["accuracy", "ari", "score"] {
            assert!(v[key].as_f64().is_some(), "{key} missing in {v}");
        }
        assert_eq!(v["confusion"]["rows"].as_array().unwrap().len(), 5);
        assert!(v["confusion"]["rates"].is_array());
        let c: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&o).unwrap()).unwrap();
        assert_eq!(c["files"].as_array().unwrap().len(), 15);
        assert_eq!(c["labels"].as_array().unwrap().len(), 15);
        c
    };
    // The descriptors given to evaluate by mistake: say what it wants.
    let err = fails(&mut evaluate(&d));
    assert!(
        err.contains("d.json: mismatch: not the output of placecat cluster"),
        "{err}"
    );
    let km = run(
        &[
            "--method",
            "kmeans",
            "--k",
            "5",
            "--seeding",
            "stride",
            "--seed",
            "1",
        ],
        "km.json",
    );
    assert_eq!(km["k"], 5);
    assert_eq!(km["restarts"], 1, "one run unless asked");
    // The cheapest of 10 k-means++ runs, the same as the library's:
    // measured, seed 1's single run costs 2.5234 and run 5 of 10 costs
    // 2.2227 (so a --restarts that was ignored would fail here).
    let plusplus = |restarts: &str, name: &str| {
        run(
            &[
                "--method",
                "kmeans",
                "--k",
                "5",
                "--seed",
                "1",
                "--restarts",
                restarts,
            ],
            name,
        )
    };
    let (one, ten) = (plusplus("1", "pp1.json"), plusplus("10", "pp10.json"));
    assert_eq!(
        (one["restarts"].as_u64(), ten["restarts"].as_u64()),
        (Some(1), Some(10))
    );
    let cost = |v: &serde_json::Value| v["cost"].as_f64().unwrap();
    assert_eq!(
        (one["restart"].as_u64(), ten["restart"].as_u64()),
        (Some(0), Some(5))
    );
    assert!((cost(&one) - 2.5234).abs() < 1e-4, "{}", cost(&one));
    assert!((cost(&ten) - 2.2227).abs() < 1e-4, "{}", cost(&ten));
    let hk = run(
        &["--method", "hkmeans", "--categories", "5", "--seed", "1"],
        "hk.json",
    );
    assert_eq!(hk["categories"], 5);
    assert_eq!(hk["tree"]["linkage"].as_array().unwrap().len(), 14);
    assert_eq!(hk["restarts"], 1, "one 2-means run per split unless asked");
    // Spectral clustering: its keys, ten k-means runs and the 7th
    // neighbour's scale unless asked, the leading eigenvalue 1.
    let sp = run(
        &["--method", "spectral", "--k", "5", "--seed", "1"],
        "sp.json",
    );
    assert_eq!(
        (&sp["method"], &sp["categories"], &sp["k"], &sp["seed"]),
        (&"spectral".into(), &5.into(), &5.into(), &1.into())
    );
    assert_eq!(
        (&sp["restarts"], &sp["neighbours"]),
        (&10.into(), &7.into())
    );
    let values: Vec<f64> = serde_json::from_value(sp["eigenvalues"].clone()).unwrap();
    assert_eq!(values.len(), 5);
    assert!((values[0] - 1.0).abs() < 1e-9, "{values:?}");
    assert!(values.windows(2).all(|w| w[1] <= w[0]), "{values:?}");
    let labels: Vec<i32> = serde_json::from_value(sp["labels"].clone()).unwrap();
    assert_eq!(labels.len(), 15);
    assert_eq!(labels.iter().max(), Some(&4));
    let one_run = run(
        &[
            "--method",
            "spectral",
            "--k",
            "5",
            "--seed",
            "1",
            "--restarts",
            "1",
            "--neighbours",
            "3",
        ],
        "sp1.json",
    );
    assert_eq!(
        (&one_run["restarts"], &one_run["restart"]),
        (&1.into(), &0.into())
    );
    assert_eq!(one_run["neighbours"], 3);
    // Ten trial splits per node: another tree than seed 1's single runs
    // (measured: its lowest merge joins scans 10 and 11, not 9 and 11).
    let hk10 = run(
        &[
            "--method",
            "hkmeans",
            "--categories",
            "5",
            "--seed",
            "1",
            "--restarts",
            "10",
        ],
        "hk10.json",
    );
    assert_eq!(hk10["restarts"], 10);
    let first_pair = |v: &serde_json::Value| {
        let row = &v["tree"]["linkage"][0];
        (row[0].as_f64().unwrap(), row[1].as_f64().unwrap())
    };
    assert_eq!(
        (first_pair(&hk), first_pair(&hk10)),
        ((9.0, 11.0), (10.0, 11.0))
    );
    let t = hk["threshold"].as_f64().unwrap();
    let hk2 = run(
        &[
            "--method",
            "hkmeans",
            "--threshold",
            &t.to_string(),
            "--seed",
            "1",
        ],
        "hk2.json",
    );
    assert_eq!(hk2["labels"], hk["labels"]);
    let db = run(
        &["--method", "dbscan", "--eps", "0.5", "--min-points", "2"],
        "db.json",
    );
    sweep_agrees_with_dbscan(&d, &sim.join("labels.csv"), &dir, &db);
    for (args, want) in [
        (
            &["--method", "kmeans", "--k", "0"][..],
            "k must be at least 1",
        ),
        (&["--method", "kmeans", "--k", "16"][..], "more than the 15"),
        (
            &["--method", "dbscan", "--eps", "-1", "--min-points", "2"][..],
            "epsilon",
        ),
        (
            &["--method", "hkmeans", "--threshold", "NaN"][..],
            "threshold",
        ),
        // No count is the automatic one (auto_categories_follow_the_data);
        // two are one too many.
        (
            &[
                "--method",
                "hkmeans",
                "--threshold",
                "1",
                "--categories",
                "2",
            ][..],
            "not both",
        ),
        (
            &[
                "--method",
                "kmeans",
                "--k",
                "5",
                "--seeding",
                "stride",
                "--restarts",
                "3",
            ][..],
            "restarts = 3 with stride",
        ),
        (
            &["--method", "kmeans", "--k", "5", "--restarts", "0"][..],
            "restarts must be at least 1",
        ),
        (
            &[
                "--method",
                "kmeans",
                "--k",
                "5",
                "--restarts",
                "18446744073709551615",
            ][..],
            "restarts = 18446744073709551615 is more than the limit of 1000",
        ),
        (
            &[
                "--method",
                "dbscan",
                "--eps",
                "0.5",
                "--min-points",
                "2",
                "--restarts",
                "3",
            ][..],
            "--restarts is for --method kmeans, hkmeans or spectral, not dbscan",
        ),
        (
            &["--method", "hkmeans", "--restarts", "0"][..],
            "2-means runs per split",
        ),
        (
            &["--method", "kmeans", "--k", "2", "--neighbours", "3"][..],
            "--neighbours is for --method spectral, not kmeans",
        ),
        (&["--method", "spectral"][..], "--method spectral needs --k"),
        (
            &["--method", "kmeans", "--seeding", "spectral"][..],
            "--seeding spectral needs a number for --k",
        ),
        (
            &["--method", "kmeans", "--seeding", "spectral", "--k", "auto"][..],
            "--seeding spectral needs a number for --k",
        ),
        (
            &["--method", "spectral", "--k", "auto"][..],
            "auto is for kmeans and hkmeans",
        ),
        (
            &["--method", "spectral", "--k", "2", "--neighbours", "0"][..],
            "neighbours must be at least 1",
        ),
        (
            &["--method", "spectral", "--k", "2", "--restarts", "0"][..],
            "runs of k-means on the embedded scans",
        ),
    ] {
        let e = fails(
            placecat()
                .arg("cluster")
                .arg(&d)
                .args(args)
                .arg("-o")
                .arg(dir.join("bad.json")),
        );
        assert!(e.contains(want), "{args:?}: {e}");
    }
}

/// `placecat sweep` on the same descriptors: its row at (0.5, 2) is what
/// `cluster --method dbscan` and `evaluate` said; the default grid.
fn sweep_agrees_with_dbscan(
    d: &std::path::Path,
    truth: &std::path::Path,
    dir: &std::path::Path,
    db: &serde_json::Value,
) {
    let rows = |out: &std::process::Output| -> Vec<Vec<String>> {
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .map(|l| l.split(',').map(String::from).collect())
            .collect()
    };
    let out = succeeds(
        placecat()
            .arg("sweep")
            .arg(d)
            .arg("--truth")
            .arg(truth)
            .args(["--eps", "0.25,0.5", "--min-points", "2,3"]),
    );
    let table = rows(&out);
    assert_eq!(
        table[0].join(","),
        "epsilon,min_points,clusters,inlier_ratio,ari,score"
    );
    assert_eq!(table.len(), 5, "{table:?}");
    let at = table.iter().find(|r| r[0] == "0.5" && r[1] == "2").unwrap();
    let labels: Vec<i64> = db["labels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_i64().unwrap())
        .collect();
    let clusters = labels.iter().max().unwrap() + 1;
    let inliers = labels.iter().filter(|&&l| l >= 0).count() as f64 / labels.len() as f64;
    assert_eq!(at[2], clusters.to_string());
    assert_eq!(at[3], format!("{inliers:.4}"));
    let ev = succeeds(
        placecat()
            .arg("evaluate")
            .arg(dir.join("db.json"))
            .arg("--truth")
            .arg(truth),
    );
    let ev: serde_json::Value = serde_json::from_slice(&ev.stdout).unwrap();
    assert_eq!(at[4], format!("{:.4}", ev["ari"].as_f64().unwrap()));
    assert_eq!(at[5], format!("{:.4}", ev["score"].as_f64().unwrap()));
    let best = String::from_utf8_lossy(&out.stderr);
    assert!(best.starts_with("best S "), "{best}");

    // The default grid, without truth, to a file: ascending epsilons, each
    // with the five default min points, and no AR.
    let csv = dir.join("sweep.csv");
    let out = succeeds(placecat().arg("sweep").arg(d).arg("-o").arg(&csv));
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    let text = std::fs::read_to_string(&csv).unwrap();
    let table: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(table.len() % 5, 0);
    assert!((2..=12 * 5).contains(&table.len()), "{} rows", table.len());
    let eps: Vec<f32> = table.iter().map(|r| r[0].parse().unwrap()).collect();
    assert!(eps.windows(2).all(|w| w[0] <= w[1]), "{eps:?}");
    let cs: Vec<&str> = table[..5].iter().map(|r| r[1]).collect();
    assert_eq!(cs, ["2", "3", "5", "8", "12"]);
    assert!(table.iter().all(|r| r[4].is_empty() && r[5].is_empty()));

    for (args, want) in [
        (&["--eps", "-1"][..], "epsilon"),
        (&["--min-points", "0"][..], "min_points"),
        (
            &["--truth", "/nonexistent/labels.csv"][..],
            "/nonexistent/labels.csv",
        ),
    ] {
        let e = fails(placecat().arg("sweep").arg(d).args(args));
        assert!(e.contains(want), "{args:?}: {e}");
    }
}

#[test]
fn simulate_rooms_from_one_or_many_buildings() {
    let dir = tmp("buildings");
    let first_scan = |buildings: &str| {
        let sim = dir.join(buildings);
        succeeds(
            placecat()
                .args([
                    "simulate", "--scene", "indoor", "--seed", "2", "--scans", "1",
                ])
                .args(["--buildings", buildings, "-o"])
                .arg(&sim),
        );
        std::fs::read(sim.join("scan_00000.ply")).unwrap()
    };
    // Same seed, rooms drawn differently: a different first scan (of the
    // same length: in a closed room only dropouts lose rays).
    assert_ne!(first_scan("one"), first_scan("many"));
    let err = fails(
        placecat()
            .args(["simulate", "--scene", "indoor", "--buildings", "few", "-o"])
            .arg(dir.join("few")),
    );
    assert!(
        err.contains("\"few\"") && err.contains("one, many"),
        "{err}"
    );
}

/// The batch path to a named model: describe, name the files (as the
/// page's "Export CSV" writes them), build the model; it then puts each
/// real scan in its place. A broken file is reported by name and skipped;
/// files that are not a model or name no scan are clear errors.
#[test]
fn model_from_named_scans_classifies_new_scans() {
    let dir = tmp("classify");
    let descriptors = dir.join("described.json");
    succeeds(placecat().args([
        "describe",
        &format!("{REAL}/pcl_room"),
        &format!("{REAL}/velodyne_pair"),
        "-o",
        descriptors.to_str().unwrap(),
    ]));
    let names = dir.join("names.csv");
    std::fs::write(
        &names,
        "file,category\nroom_scan1.pcd,room\nroom_scan2.pcd,room\n251370668.pcd,street\n251371071.pcd,street\nunknown.pcd,street\n",
    )
    .unwrap();
    let model_path = dir.join("model.json");
    let build_model = || {
        let mut cmd = placecat();
        cmd.arg("model")
            .arg(&descriptors)
            .arg("--names")
            .arg(&names);
        cmd.arg("-o").arg(&model_path);
        cmd
    };
    let out = succeeds(&mut build_model());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("2 categories from 4 scans (0 not named)"),
        "{stderr}"
    );
    let model: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&model_path).unwrap()).unwrap();
    let categories = model["categories"].as_array().unwrap();
    assert_eq!(categories.len(), 2);
    assert_eq!(categories[0]["name"], "room");
    assert_eq!(categories[0]["members"], 2);
    assert_eq!(categories[1]["name"], "street");
    assert_eq!(categories[1]["members"], 2);
    let broken = dir.join("broken.ply");
    std::fs::write(&broken, b"ply\nformat ascii 1.0\nelement vertex 5\n").unwrap();

    let csv_path = dir.join("named.csv");
    let out = succeeds(placecat().args([
        "classify",
        model_path.to_str().unwrap(),
        &format!("{REAL}/pcl_room"),
        &format!("{REAL}/velodyne_pair"),
        broken.to_str().unwrap(),
        "-o",
        csv_path.to_str().unwrap(),
    ]));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("broken.ply"), "{stderr}");
    assert!(stderr.contains("classified 4 of 5 files"), "{stderr}");
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows[0], ["file", "category", "distance", "relative"]);
    assert_eq!(rows.len(), 5);
    for row in &rows[1..] {
        let want = if row[0].contains("pcl_room") {
            "room"
        } else {
            "street"
        };
        assert_eq!(row[1], want, "{row:?}");
        // Scans the model was made from lie within their category's reach.
        let (distance, relative): (f32, f32) = (row[2].parse().unwrap(), row[3].parse().unwrap());
        assert!(
            distance >= 0.0 && (0.0..=1.0 + 1e-4).contains(&relative),
            "{row:?}"
        );
    }

    // To stdout; and a model file that is not one.
    let out = succeeds(placecat().args([
        "classify",
        model_path.to_str().unwrap(),
        &format!("{REAL}/pcl_room/room_scan2.pcd"),
    ]));
    assert!(String::from_utf8_lossy(&out.stdout).contains("room_scan2.pcd,room,"));
    let err = fails(placecat().args([
        "classify",
        csv_path.to_str().unwrap(),
        &format!("{REAL}/pcl_room/room_scan2.pcd"),
    ]));
    assert!(err.contains("named.csv"), "{err}");
    // Names as the page's export quotes them; an unclosed quote is an error.
    std::fs::write(
        &names,
        "file,category\nroom_scan1.pcd,\"room, \"\"B\"\" wing\"\n\"251370668.pcd\",street\n",
    )
    .unwrap();
    succeeds(&mut build_model());
    let model: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&model_path).unwrap()).unwrap();
    assert_eq!(model["categories"][0]["name"], "room, \"B\" wing");
    assert_eq!(model["categories"][1]["name"], "street");
    // As a spreadsheet saves it: a byte order mark, CRLF, a line break
    // inside a quoted name.
    std::fs::write(
        &names,
        "\u{feff}file,category\r\nroom_scan1.pcd,\"room\r\nB\"\r\n251370668.pcd,street\r\n",
    )
    .unwrap();
    succeeds(&mut build_model());
    let model: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&model_path).unwrap()).unwrap();
    assert_eq!(model["categories"][0]["name"], "room\r\nB");
    std::fs::write(&names, "file,category\nroom_scan1.pcd,\"room\n").unwrap();
    let err = fails(&mut build_model());
    assert!(
        err.contains("names.csv: CSV: line 2: a quote opened here is not closed"),
        "{err}"
    );
    std::fs::write(&names, "file,category\nelsewhere.pcd,room\n").unwrap();
    let err = fails(&mut build_model());
    assert!(
        err.contains("names.csv") && err.contains("names none of the 4 scans"),
        "{err}"
    );
}

#[test]
fn lenient_reads_a_damaged_file_that_strict_refuses() {
    let bad = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/bad/ply_trailing_bytes.ply"
    );
    let e = fails(placecat().args(["info", bad, "--json"]));
    assert!(
        e.contains("ply_trailing_bytes.ply: PLY: the body does not match the header: 24 bytes follow the 3216 bytes it declares"),
        "{e}"
    );
    let out = succeeds(placecat().args(["info", bad, "--json", "--lenient"]));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["count"], 86);
    // describe takes the flag too: strict skips the file for its header.
    let dir = tmp("lenient");
    let out = dir.join("d.json");
    let strict = placecat()
        .args(["describe", bad, "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&strict.stderr).contains("does not match the header"));
    let lenient = placecat()
        .args(["describe", "--lenient", bad, "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&lenient.stderr).contains("does not match the header"));
}

/// `--categories auto` and `--k auto` (and hkmeans/kmeans given no count):
/// the number of categories chosen from the data, written as `categories`
/// with the rule's scores under `choice`. Ten scans of one enclosed place
/// (Ouster) are one category; the four KITTI scans of two places are two.
#[test]
fn auto_categories_follow_the_data() {
    let dir = tmp("auto");
    let one_place = dir.join("ouster.json");
    let two_places = dir.join("kitti.json");
    for (input, preset, out) in [
        ("ouster_os0_sequence", "indoor", &one_place),
        ("kitti00", "outdoor", &two_places),
    ] {
        let input = format!("{REAL}/{input}");
        succeeds(
            placecat()
                .args(["describe", "--preset", preset, &input, "-o"])
                .arg(out),
        );
    }
    let cluster = |d: &std::path::Path, args: &[&str]| -> serde_json::Value {
        let out = dir.join("out.json");
        succeeds(
            placecat()
                .arg("cluster")
                .arg(d)
                .args(args)
                .arg("-o")
                .arg(&out),
        );
        serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap()
    };
    for args in [
        &["--method", "hkmeans", "--categories", "auto", "--seed", "0"][..],
        &["--method", "hkmeans", "--seed", "3"],
        &["--method", "kmeans", "--k", "auto", "--seeding", "stride"],
        &["--method", "kmeans"],
        // Every K the rule tries is clustered with the restarts too.
        &["--method", "kmeans", "--k", "auto", "--restarts", "10"],
        // The rule's reference trees are built with the trial splits too.
        &["--method", "hkmeans", "--restarts", "10"],
    ] {
        let v = cluster(&one_place, args);
        assert_eq!(v["categories"], 1, "{args:?}: {v}");
        assert!(v["labels"].as_array().unwrap().iter().all(|l| l == 0));
        assert_eq!(v["choice"]["rule"], "silhouette_gap");
        assert!(v["choice"]["one_category"].as_f64().unwrap() < 0.5, "{v}");
        let v = cluster(&two_places, args);
        assert_eq!(v["categories"], 2, "{args:?}: {v}");
        // 000094/000095 are one place, 000198/000199 the other.
        let l = v["labels"].as_array().unwrap();
        assert!(l[0] == l[1] && l[2] == l[3] && l[0] != l[2], "{v}");
        assert!(!v["choice"]["scores"].as_array().unwrap().is_empty());
    }
    // The restarts reach the K tried and the clustering kept; measured:
    // the one-place set keeps run 2 of 10 (cost 1.1077 against the single
    // run's 1.1089), and the KITTI score of K = 2 falls from 1.4325 to
    // 1.3424 (the rule's reference sets are clustered with restarts too).
    let auto = |d: &std::path::Path, restarts: &str| {
        cluster(
            d,
            &["--method", "kmeans", "--k", "auto", "--restarts", restarts],
        )
    };
    let (one, ten) = (auto(&one_place, "1"), auto(&one_place, "10"));
    assert_eq!(
        (one["restart"].as_u64(), ten["restart"].as_u64()),
        (Some(0), Some(2))
    );
    let near = |v: &serde_json::Value, want: f64| (v.as_f64().unwrap() - want).abs() < 1e-4;
    assert!(
        near(&one["cost"], 1.1089) && near(&ten["cost"], 1.1077),
        "{one} {ten}"
    );
    let score_of_2 = |v: &serde_json::Value| v["choice"]["scores"][1].clone();
    let (one, ten) = (auto(&two_places, "1"), auto(&two_places, "10"));
    assert_eq!(score_of_2(&one)[0], 2);
    assert!(near(&score_of_2(&one)[1], 1.4325), "{one}");
    assert!(near(&score_of_2(&ten)[1], 1.3424), "{ten}");
    // An explicit count is kept as given, with no choice.
    let v = cluster(&two_places, &["--method", "hkmeans", "--categories", "3"]);
    assert_eq!(v["categories"], 3);
    assert!(v.get("choice").is_none());
    let e = fails(placecat().arg("cluster").arg(&two_places).args([
        "--method",
        "kmedoids",
        "--k",
        "auto",
        "-o",
        "/dev/null",
    ]));
    assert!(e.contains("auto is for kmeans and hkmeans"), "{e}");
    let e = fails(placecat().arg("cluster").arg(&two_places).args([
        "--method",
        "hkmeans",
        "--categories",
        "many",
        "-o",
        "/dev/null",
    ]));
    assert!(e.contains("expected a whole number or auto"), "{e}");
}

/// LAS/LAZ and E57 (tests/data/survey, written by laspy and pye57): `info`
/// of a survey lists its stations with their poses, `--origin` centres a
/// georeferenced LAS on its sensor, and `describe` gives one described scan
/// per station.
#[test]
fn surveys_and_georeferenced_las_on_the_command_line() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/survey");
    let expected: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(format!("{data}/expected.json")).unwrap())
            .unwrap();
    let survey = format!("{data}/survey.e57");
    let out = succeeds(placecat().args(["info", &survey, "--json"]));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["format"], "e57");
    assert_eq!(v["count"], 2500);
    assert_eq!(v["finite"], 2490);
    let scans = v["scans"].as_array().unwrap();
    assert_eq!(scans.len(), 4);
    assert_eq!(scans[2]["name"], format!("{survey}:hall (scan 2)"));
    assert_eq!(
        scans[1]["pose"]["position"],
        serde_json::json!([10.0, 2.0, 0.5])
    );
    assert_eq!(scans[1]["finite"], 690);

    let geo = format!("{data}/geo14_fmt6.las");
    let err = fails(placecat().args(["info", &geo]));
    assert!(
        err.contains("geo14_fmt6.las") && err.contains("--origin"),
        "{err}"
    );
    let out = succeeds(placecat().args([
        "info",
        &geo,
        "--json",
        "--origin",
        "512345.678,6123456.789,98.765",
    ]));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["format"], "las");
    let want = &expected["geo14_fmt6.las"]["centred"]["sum"];
    for a in 0..3 {
        let (got, want) = (v["sum"][a].as_f64().unwrap(), want[a].as_f64().unwrap());
        assert!((got - want).abs() < 1e-3, "axis {a}: {got} vs {want}");
    }
    let err = fails(placecat().args(["info", &geo, "--origin", "1,2"]));
    assert!(err.contains("three numbers"), "{err}");
    let err = fails(placecat().args(["info", &survey, "--origin", "1,2,3"]));
    assert!(err.contains("does not apply to E57"), "{err}");

    let dir = tmp("survey");
    let out_json = dir.join("d.json");
    let out = succeeds(placecat().args([
        "describe",
        &survey,
        &format!("{data}/laz14_fmt6.laz"),
        &geo,
        "-o",
        out_json.to_str().unwrap(),
    ]));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("described 5 of 6 scans from 3 files"),
        "{stderr}"
    );
    let d = read_json(&out_json);
    assert_eq!(
        described_names(&d),
        [
            "survey.e57:hall",
            "survey.e57:office",
            "survey.e57:hall (scan 2)",
            "survey.e57:store",
            "laz14_fmt6.laz"
        ]
    );
    assert!(d["errors"][0]["error"]
        .as_str()
        .unwrap()
        .contains("no sensor position"));
    std::fs::remove_dir_all(&dir).ok();
}
