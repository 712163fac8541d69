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
