//! `placecat topics BAG` and `placecat describe BAG ...` on the bags of
//! tests/data/bags (written by rosbags and mcap-ros2-support).
#![cfg(not(target_arch = "wasm32"))]

use crate::cli_common::placecat;
use std::path::PathBuf;
use std::process::Command;

fn bag(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/bags")
        .join(name)
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("placecat-bags-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The scan names and the error messages of a describe output.
fn described(path: &std::path::Path) -> (Vec<String>, Vec<String>) {
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let texts = |key: &str, field: &str| -> Vec<String> {
        let list = v[key].as_array().unwrap().iter();
        list.map(|f| f[field].as_str().unwrap().to_string())
            .collect()
    };
    (texts("files", "name"), texts("errors", "error"))
}

/// (success, stdout, stderr)
fn run(cmd: &mut Command) -> (bool, String, String) {
    let out = cmd.output().unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.success(), text(&out.stdout), text(&out.stderr))
}

#[test]
fn topics_lists_name_type_and_count() {
    let (ok, out, err) = run(placecat().arg("topics").arg(bag("ros2_mcap_lz4.mcap")));
    assert!(ok, "{err}");
    let lines: Vec<Vec<&str>> = out
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(lines[0], ["topic", "type", "count"]);
    assert!(
        lines.contains(&vec!["/points", "sensor_msgs/msg/PointCloud2", "5"]),
        "{out}"
    );
    assert!(
        lines.contains(&vec!["/odom", "nav_msgs/msg/Odometry", "41"]),
        "{out}"
    );

    let (ok, out, _) = run(placecat()
        .args(["topics", "--json"])
        .arg(bag("ros1_plain.bag")));
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let points = v
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "/points")
        .unwrap();
    assert_eq!(points["type"], "sensor_msgs/PointCloud2");
    assert_eq!(points["count"], 5);

    let (ok, _, err) = run(placecat().arg("topics").arg(bag("make_bags.py")));
    assert!(
        !ok && err.contains("make_bags.py") && err.contains("not a ROS bag"),
        "{err}"
    );
}

#[test]
fn describe_a_bag_names_each_cloud_and_writes_its_poses() {
    let dir = tmp("describe");
    let (d, poses) = (dir.join("d.json"), dir.join("poses.csv"));
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(bag("ros1_corridor.bag"))
        .args(["--topic", "/points", "--pose-topic", "/odom", "-o"])
        .arg(&d)
        .arg("--poses-out")
        .arg(&poses));
    assert!(ok, "{err}");
    let (names, errors) = described(&d);
    assert_eq!(
        names,
        [
            "ros1_corridor.bag:/points:000000",
            "ros1_corridor.bag:/points:000001"
        ]
    );
    assert!(errors.is_empty());
    // The robot drives x = t - 100, y = (t - 100) / 2: clouds at t = 100, 100.5.
    let csv = std::fs::read_to_string(&poses).unwrap();
    assert_eq!(
        csv,
        "name,x,y,z\nros1_corridor.bag:/points:000000,0,0,0\nros1_corridor.bag:/points:000001,0.5,0.25,0\n"
    );
    // The poses file is one the map reads, matched by name.
    let parsed = placecat::io::poses::parse(&csv).unwrap();
    assert_eq!(parsed.poses[1].name.as_deref(), Some(names[1].as_str()));

    // Every second cloud: the names keep their index.
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(bag("ros1_corridor.bag"))
        .args(["--every", "2", "-o"])
        .arg(&d));
    assert!(ok, "{err}");
    assert_eq!(described(&d).0, ["ros1_corridor.bag:/points:000000"]);
}

#[test]
fn describe_reports_bad_clouds_and_bags_on_stderr_and_under_errors() {
    let dir = tmp("bad");
    let d = dir.join("d.json");
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(bag("ros1_corridor.bag"))
        .arg(bag("bad_no_xyz.bag"))
        .arg(bag("bad_no_cloud.bag"))
        .args(["--tf-frame", "velodyne", "-o"])
        .arg(&d));
    // The corridor's two clouds are described, so the run succeeds.
    assert!(ok, "{err}");
    assert!(
        err.contains("bad_no_xyz.bag: ROS bag: topic /points: cloud 2"),
        "{err}"
    );
    assert!(
        err.contains("bad_no_cloud.bag: ROS bag: no sensor_msgs/PointCloud2 topic"),
        "{err}"
    );
    // The corridor bag has no tf: with --tf-frame that is said, not hidden.
    assert!(
        err.contains("ros1_corridor.bag: ROS bag: no tf topic"),
        "{err}"
    );
    let (names, errors) = described(&d);
    assert_eq!(names.len(), 2, "{names:?}");
    assert!(
        errors.iter().any(|e| e.contains("placecat needs x, y, z")),
        "{errors:?}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.contains("no sensor_msgs/PointCloud2 topic")),
        "{errors:?}"
    );

    // --every and --every-metres do not go together.
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(bag("ros1_corridor.bag"))
        .args(["--every", "2", "--every-metres", "1", "-o"])
        .arg(&d));
    assert!(!ok && err.contains("--every-metres"), "{err}");
}

/// OUT.json carries each scan's pose where the recording has one: every
/// station of an E57 survey (tests/data/survey, written by pye57, with the
/// translations and headings make_survey.py wrote) and every bag cloud;
/// `--poses-out` writes them all as the CSV the map reads; loose files get
/// no `pose` key.
#[test]
fn e57_stations_and_bag_clouds_carry_their_poses() {
    let dir = tmp("poses");
    let (d, poses) = (dir.join("d.json"), dir.join("poses.csv"));
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(data.join("survey/survey.e57"))
        .arg(bag("ros1_corridor.bag"))
        .arg(data.join("real/pcl_room/room_scan1.pcd"))
        .arg("-o")
        .arg(&d)
        .arg("--poses-out")
        .arg(&poses));
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&d).unwrap()).unwrap();
    let expected: serde_json::Value =
        serde_json::from_slice(&std::fs::read(data.join("survey/expected.json")).unwrap()).unwrap();
    let files = v["files"].as_array().unwrap();
    let by_name = |n: &str| files.iter().find(|f| f["name"] == n).unwrap();
    let stations = expected["survey.e57"]["scans"].as_array().unwrap();
    for (name, want) in ["hall", "office", "hall (scan 2)", "store"]
        .iter()
        .zip(stations)
    {
        let pose = &by_name(&format!("survey/survey.e57:{name}"))["pose"];
        assert_eq!(pose["position"], want["translation"], "{name}");
        let yaw = pose["yaw"].as_f64().unwrap();
        let want_yaw = want["yaw"].as_f64().unwrap();
        // +pi and -pi are one heading.
        let d = (yaw - want_yaw).rem_euclid(std::f64::consts::TAU);
        assert!(
            d.min(std::f64::consts::TAU - d) < 1e-9,
            "{name}: {yaw} vs {want_yaw}"
        );
    }
    let cloud = by_name("bags/ros1_corridor.bag:/points:000001");
    assert_eq!(
        cloud["pose"]["position"],
        serde_json::json!([0.5, 0.25, 0.0])
    );
    assert_eq!(cloud["pose"]["time"], 100.5);
    assert!(by_name("real/pcl_room/room_scan1.pcd")
        .get("pose")
        .is_none());
    let csv = std::fs::read_to_string(&poses).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 1 + 4 + 2, "{csv}");
    assert_eq!(rows[0], "name,x,y,z");
    assert!(rows.contains(&"survey/survey.e57:office,10,2,0.5"), "{csv}");
    assert!(
        rows.contains(&"bags/ros1_corridor.bag:/points:000001,0.5,0.25,0"),
        "{csv}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A rosbag2 folder (metadata.yaml beside its storage files) is read
/// through its .mcap files; SQLite storage (.db3) is refused naming the
/// file and saying what to do, while the other bags are described.
#[test]
fn a_rosbag2_folder_is_read_through_its_mcap_files_and_db3_is_refused() {
    let dir = tmp("rosbag2");
    let (walk, old) = (dir.join("walk"), dir.join("old"));
    std::fs::create_dir_all(&walk).unwrap();
    std::fs::create_dir_all(&old).unwrap();
    std::fs::copy(bag("walk.mcap"), walk.join("walk_0.mcap")).unwrap();
    std::fs::write(
        walk.join("metadata.yaml"),
        "rosbag2_bagfile_information:\n  storage_identifier: mcap\n",
    )
    .unwrap();
    std::fs::write(old.join("old_0.db3"), b"SQLite format 3\0").unwrap();
    std::fs::write(
        old.join("metadata.yaml"),
        "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n",
    )
    .unwrap();
    let d = dir.join("d.json");
    let (ok, _, err) = run(placecat()
        .arg("describe")
        .arg(&walk)
        .arg(&old)
        .args(["--every-metres", "1", "-o"])
        .arg(&d));
    assert!(ok, "{err}");
    let (names, errors) = described(&d);
    assert_eq!(
        names,
        [0, 2, 4, 6].map(|i| format!("walk/walk_0.mcap:/points:00000{i}"))
    );
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("old_0.db3")
            && errors[0].contains("SQLite")
            && errors[0].contains("ros2 bag convert"),
        "{errors:?}"
    );
    let (ok, _, err) = run(placecat().arg("topics").arg(old.join("old_0.db3")));
    assert!(
        !ok && err.contains("old_0.db3") && err.contains(".db3) is not read"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
