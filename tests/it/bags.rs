//! ROS bags written by independent tools (tests/data/bags/make_bags.py, with
//! the Python `rosbags` and `mcap-ros2-support` packages): point counts,
//! sums, stamps and poses must match what the writer wrote.
#![cfg(not(target_arch = "wasm32"))]

use placecat::io::bag::{topics, topics_path, BagOptions, BagReader, PoseSource};
use placecat::io::recording::RecordedScan;
use serde_json::Value;
use std::path::PathBuf;

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/bags")
}

fn expected() -> Value {
    let text = std::fs::read_to_string(dir().join("expected.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

const GOOD: &[&str] = &[
    "ros1_plain.bag",
    "ros1_bz2.bag",
    "ros1_lz4.bag",
    "ros2_rosbags.mcap",
    "ros2_rosbags_zstd.mcap",
    "ros2_rosbags_cdr_be.mcap",
    "ros2_mcap_lz4.mcap",
    "ros2_mcap_none.mcap",
    "ros1_corridor.bag",
];

/// Every item: clouds and error messages apart.
fn read(name: &str, opts: BagOptions) -> (Vec<RecordedScan>, Vec<String>) {
    let reader = BagReader::open_path(&dir().join(name), opts).unwrap();
    let mut clouds = Vec::new();
    let mut errors = Vec::new();
    for item in reader {
        match item {
            Ok(c) => clouds.push(c),
            Err(e) => errors.push(e.to_string()),
        }
    }
    (clouds, errors)
}

fn index_of(c: &RecordedScan) -> usize {
    c.name.rsplit(':').next().unwrap().parse().unwrap()
}

/// Count, finite count and x/y/z sums of a cloud against the writer's.
fn check_cloud(bag: &str, c: &RecordedScan, want: &Value) {
    let what = format!("{bag} {} ({})", c.name, want["layout"]);
    assert_eq!(
        c.points.len() as u64,
        want["count"].as_u64().unwrap(),
        "{what}"
    );
    let finite: Vec<&[f32; 3]> = c
        .points
        .iter()
        .filter(|p| p.iter().all(|v| v.is_finite()))
        .collect();
    assert_eq!(
        finite.len() as u64,
        want["finite"].as_u64().unwrap(),
        "{what}"
    );
    for k in 0..3 {
        let sum: f64 = finite.iter().map(|p| p[k] as f64).sum();
        let w = want["sum"][k].as_f64().unwrap();
        // float32 layouts match to rounding; float64 ones are narrowed to f32.
        assert!((sum - w).abs() < 1e-3, "{what}: sum[{k}] {sum} != {w}");
    }
    assert!(
        (c.stamp.unwrap() - want["stamp"].as_f64().unwrap()).abs() < 1e-6,
        "{what}"
    );
}

fn check_pose(c: &RecordedScan, want: &Value) {
    let p = c
        .pose
        .as_ref()
        .unwrap_or_else(|| panic!("{}: no pose", c.name));
    let w: Vec<f64> = want
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    for k in 0..3 {
        assert!(
            (p.position[k] - w[k]).abs() < 1e-6,
            "{}: position {:?} != {w:?}",
            c.name,
            p.position
        );
    }
    assert!(
        (p.yaw - w[3]).abs() < 1e-6,
        "{}: yaw {} != {}",
        c.name,
        p.yaw,
        w[3]
    );
    assert_eq!(p.name.as_deref(), Some(c.name.as_str()));
}

#[test]
fn topics_match_the_writer() {
    let exp = expected();
    for bag in GOOD.iter().chain(&["bad_no_cloud.bag"]) {
        let got = topics_path(&dir().join(bag)).unwrap();
        let want = exp[bag]["topics"].as_object().unwrap();
        assert_eq!(got.len(), want.len(), "{bag}: {got:?}");
        for t in &got {
            let w = &want[&t.name];
            assert_eq!(t.msgtype, w[0].as_str().unwrap(), "{bag} {}", t.name);
            assert_eq!(t.count, w[1].as_u64().unwrap(), "{bag} {}", t.name);
        }
    }
}

#[test]
fn clouds_of_every_layout_and_compression_match_the_writer_with_odometry_poses() {
    let exp = expected();
    for bag in GOOD {
        let (clouds, errors) = read(bag, BagOptions::default());
        assert!(errors.is_empty(), "{bag}: {errors:?}");
        let want = exp[bag]["clouds"].as_array().unwrap();
        assert_eq!(clouds.len(), want.len(), "{bag}");
        for (i, (c, w)) in clouds.iter().zip(want).enumerate() {
            assert_eq!(c.name, format!("{bag}:/points:{i:06}"));
            check_cloud(bag, c, w);
            // Auto: the only Odometry topic, base_link in odom.
            check_pose(c, &w["odom_pose"]);
        }
    }
}

#[test]
fn tf_poses_chain_static_and_dynamic_transforms_to_the_chosen_frame() {
    let exp = expected();
    for bag in ["ros1_lz4.bag", "ros2_mcap_lz4.mcap", "ros2_rosbags.mcap"] {
        for pose in [
            PoseSource::TfFrame("velodyne".into()),
            PoseSource::Topic("/tf".into()),
        ] {
            let opts = BagOptions {
                pose: pose.clone(),
                ..BagOptions::default()
            };
            let (clouds, errors) = read(bag, opts);
            assert!(errors.is_empty(), "{bag} {pose:?}: {errors:?}");
            for (c, w) in clouds.iter().zip(exp[bag]["clouds"].as_array().unwrap()) {
                check_pose(c, &w["tf_pose"]);
            }
        }
        // base_link through tf is the odometry pose.
        let opts = BagOptions {
            pose: PoseSource::TfFrame("base_link".into()),
            ..BagOptions::default()
        };
        let (clouds, _) = read(bag, opts);
        for (c, w) in clouds.iter().zip(exp[bag]["clouds"].as_array().unwrap()) {
            check_pose(c, &w["odom_pose"]);
        }
    }
}

#[test]
fn thinning_keeps_every_nth_cloud_or_one_every_d_metres_with_stable_names() {
    let every = |n, metres| BagOptions {
        every: n,
        every_metres: metres,
        ..BagOptions::default()
    };
    let kept = |opts| -> Vec<usize> { read("ros1_bz2.bag", opts).0.iter().map(index_of).collect() };
    let r = BagReader::open_path(&dir().join("ros1_bz2.bag"), every(2, None)).unwrap();
    assert_eq!(
        (r.topic(), r.topic_len(), r.clouds_met()),
        ("/points", 5, 0)
    );
    assert_eq!(kept(every(2, None)), [0, 2, 4]);
    assert_eq!(kept(every(3, None)), [0, 3]);
    // The robot moves sqrt(1 + 0.25) = 1.118 m between clouds 0.5 s apart... per
    // second: 0.559 m per cloud.
    assert_eq!(kept(every(1, Some(1.0))), [0, 2, 4]);
    assert_eq!(kept(every(1, Some(1.5))), [0, 3]);
    assert_eq!(kept(every(1, Some(0.5))), [0, 1, 2, 3, 4]);
    // Without poses there is no path to measure.
    let e = BagReader::open_path(
        &dir().join("ros1_bz2.bag"),
        BagOptions {
            pose: PoseSource::None,
            ..every(1, Some(1.0))
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        e.contains("ros1_bz2.bag") && e.contains("needs poses"),
        "{e}"
    );
}

fn open_err(bag: &str, opts: BagOptions) -> String {
    BagReader::open_path(&dir().join(bag), opts)
        .err()
        .unwrap()
        .to_string()
}

#[test]
fn a_bag_without_a_cloud_topic_or_a_wrong_topic_is_refused_with_the_topics_listed() {
    let e = open_err("bad_no_cloud.bag", BagOptions::default());
    assert!(
        e.contains("bad_no_cloud.bag") && e.contains("no sensor_msgs/PointCloud2"),
        "{e}"
    );
    assert!(
        e.contains("/odom (nav_msgs/Odometry)") && e.contains("/tf"),
        "{e}"
    );
    let topic = |t: &str| BagOptions {
        topic: Some(t.into()),
        ..BagOptions::default()
    };
    let e = open_err("ros1_plain.bag", topic("/odom"));
    assert!(
        e.contains("topic /odom is nav_msgs/Odometry, not sensor_msgs/PointCloud2"),
        "{e}"
    );
    let e = open_err("ros2_mcap_lz4.mcap", topic("/velodyne_points"));
    assert!(
        e.contains("no topic /velodyne_points")
            && e.contains("/points (sensor_msgs/msg/PointCloud2)"),
        "{e}"
    );
}

/// The bad bag gives one error naming the file, the topic and `what`; the
/// other clouds come out as the writer wrote them.
fn report_and_skip(
    bag: &str,
    opts: BagOptions,
    what: &str,
    min_clouds: usize,
) -> Vec<RecordedScan> {
    let exp = expected();
    let (clouds, errors) = read(bag, opts);
    assert_eq!(errors.len(), 1, "{bag}: {errors:?}");
    let e = &errors[0];
    assert!(
        e.contains(bag) && (e.contains("/points") || e.contains("/tf")),
        "{e}"
    );
    assert!(e.contains(what), "{bag}: {e} lacks {what:?}");
    assert!(clouds.len() >= min_clouds, "{bag}: {} clouds", clouds.len());
    for c in &clouds {
        check_cloud(bag, c, &exp[bag]["clouds"][index_of(c)]);
    }
    clouds
}

#[test]
fn a_cloud_without_xyz_is_reported_and_the_others_read() {
    let clouds = report_and_skip(
        "bad_no_xyz.bag",
        BagOptions::default(),
        "no field \"x\" (fields: a, b, c); placecat needs x, y, z",
        4,
    );
    assert_eq!(
        clouds.iter().map(index_of).collect::<Vec<_>>(),
        [0, 1, 3, 4]
    );
    let (_, errors) = read("bad_no_xyz.bag", BagOptions::default());
    assert!(
        errors[0].contains("topic /points: cloud 2 (bad_no_xyz.bag:/points:000002)"),
        "{}",
        errors[0]
    );
}

#[test]
fn a_truncated_chunk_is_reported_and_the_other_chunks_read() {
    let clouds = report_and_skip("bad_truncated.bag", BagOptions::default(), "chunk", 4);
    // Cloud 1 was in the cut chunk; the index records after it keep the
    // later clouds' names true.
    assert_eq!(
        clouds.iter().map(index_of).collect::<Vec<_>>(),
        [0, 2, 3, 4]
    );
    let (_, errors) = read("bad_truncated.bag", BagOptions::default());
    assert!(
        errors[0].contains("chunk at byte") && errors[0].contains("truncated or corrupt"),
        "{}",
        errors[0]
    );
}

#[test]
fn an_unknown_compression_is_reported_and_the_other_chunks_read() {
    let clouds = report_and_skip(
        "bad_compression.bag",
        BagOptions::default(),
        "unknown chunk compression \"zip\"",
        4,
    );
    assert_eq!(
        clouds.iter().map(index_of).collect::<Vec<_>>(),
        [0, 1, 2, 4]
    );
    let (clouds, errors) = read("bad_compression.mcap", BagOptions::default());
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("bad_compression.mcap") && errors[0].contains("topic /points"),
        "{}",
        errors[0]
    );
    assert!(
        errors[0].contains("unknown chunk compression \"lz5\""),
        "{}",
        errors[0]
    );
    assert!(
        !clouds.is_empty() && clouds.len() < 5,
        "{} clouds",
        clouds.len()
    );
    let exp = expected();
    for c in &clouds {
        check_cloud(
            "bad_compression.mcap",
            c,
            &exp["bad_compression.mcap"]["clouds"][index_of(c)],
        );
    }
}

#[test]
fn a_tf_tree_without_the_chosen_frame_is_reported_and_the_clouds_read_without_pose() {
    for pose in [
        PoseSource::TfFrame("velodyne".into()),
        PoseSource::Topic("/tf".into()),
    ] {
        let opts = BagOptions {
            pose,
            ..BagOptions::default()
        };
        let clouds = report_and_skip(
            "bad_tf.bag",
            opts,
            "topic /tf: the tf tree has no frame \"velodyne\" (frames: base_link, odom)",
            5,
        );
        assert!(clouds.iter().all(|c| c.pose.is_none()));
    }
    // Auto does not insist: no error, no pose.
    let (clouds, errors) = read("bad_tf.bag", BagOptions::default());
    assert!(errors.is_empty() && clouds.len() == 5 && clouds.iter().all(|c| c.pose.is_none()));
}

/// Clouds of a bag held in memory (the slice source the page's would be).
fn read_bytes(bytes: Vec<u8>, name: &str) -> Vec<RecordedScan> {
    let reader = BagReader::open(bytes, name, BagOptions::default()).unwrap();
    reader.map(|c| c.unwrap()).collect()
}

fn same_clouds(bag: &str, got: &[RecordedScan]) {
    let exp = expected();
    let want = exp[bag]["clouds"].as_array().unwrap();
    assert_eq!(got.len(), want.len(), "{bag}");
    for (c, w) in got.iter().zip(want) {
        check_cloud(bag, c, w);
        check_pose(c, &w["odom_pose"]);
    }
}

#[test]
fn a_bag_without_index_or_summary_is_read_by_walking_it() {
    // ROS 1 as a recorder leaves it when stopped hard: index_pos 0.
    let mut b = std::fs::read(dir().join("ros1_lz4.bag")).unwrap();
    let at = b.windows(10).position(|w| w == b"index_pos=").unwrap() + 10;
    b[at..at + 8].fill(0);
    let t = topics(b.clone(), "ros1_lz4.bag").unwrap();
    let points = t.iter().find(|t| t.name == "/points").unwrap();
    assert_eq!(
        (points.msgtype.as_str(), points.count),
        ("sensor_msgs/PointCloud2", 5)
    );
    same_clouds("ros1_lz4.bag", &read_bytes(b, "ros1_lz4.bag"));

    // MCAP whose footer points to no summary.
    let mut b = std::fs::read(dir().join("ros2_mcap_lz4.mcap")).unwrap();
    let footer = b.len() - 8 - 29;
    assert_eq!(b[footer], 0x02);
    b[footer + 9..footer + 17].fill(0);
    let t = topics(b.clone(), "ros2_mcap_lz4.mcap").unwrap();
    let odom = t.iter().find(|t| t.name == "/odom").unwrap();
    assert_eq!(
        odom.count,
        expected()["ros2_mcap_lz4.mcap"]["topics"]["/odom"][1]
            .as_u64()
            .unwrap()
    );
    same_clouds("ros2_mcap_lz4.mcap", &read_bytes(b, "ros2_mcap_lz4.mcap"));
}

#[test]
fn not_a_bag_is_refused_naming_the_file() {
    let e = topics(b"ply\nformat ascii 1.0\n".to_vec(), "scan.bag")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("scan.bag: ROS bag: not a ROS bag"), "{e}");
    let mut b = std::fs::read(dir().join("ros1_plain.bag")).unwrap();
    b.truncate(3000);
    let e = topics(b, "cut.bag").unwrap_err().to_string();
    assert!(e.contains("cut.bag") && e.contains("file ends"), "{e}");
}

#[test]
fn a_tf_frame_asked_of_a_bag_without_tf_is_reported_and_the_clouds_read() {
    let opts = BagOptions {
        pose: PoseSource::TfFrame("velodyne".into()),
        ..BagOptions::default()
    };
    let clouds = report_and_skip(
        "ros1_corridor.bag",
        opts,
        "no tf topic (tf2_msgs/TFMessage) for frame \"velodyne\"",
        2,
    );
    assert!(clouds.iter().all(|c| c.pose.is_none()));
}

/// Damaged bags (cut anywhere, a byte changed anywhere) give errors, never a
/// panic or a hang; what can be read still is.
#[test]
fn damaged_bags_never_panic() {
    for bag in [
        "ros1_bz2.bag",
        "ros1_plain.bag",
        "ros2_mcap_lz4.mcap",
        "ros2_rosbags_zstd.mcap",
    ] {
        let good = std::fs::read(dir().join(bag)).unwrap();
        let step = good.len() / 60;
        for at in (0..good.len()).step_by(step) {
            let mut flipped = good.clone();
            flipped[at] ^= 0xA5;
            for bytes in [good[..at].to_vec(), flipped] {
                let _ = topics(bytes.clone(), bag);
                if let Ok(reader) = BagReader::open(bytes, bag, BagOptions::default()) {
                    assert!(
                        reader.take(1000).count() < 1000,
                        "{bag} damaged at {at}: no end"
                    );
                }
            }
        }
    }
}

#[test]
fn two_cloud_topics_need_a_choice_and_each_reads_alone() {
    let e = open_err("two_cloud_topics.bag", BagOptions::default());
    assert!(
        e.contains("two_cloud_topics.bag")
            && e.contains(
                "2 PointCloud2 topics (/front/points, /rear/points): choose one with --topic"
            ),
        "{e}"
    );
    let exp = expected();
    for (i, topic) in ["/front/points", "/rear/points"].into_iter().enumerate() {
        let opts = BagOptions {
            topic: Some(topic.into()),
            ..BagOptions::default()
        };
        let (clouds, errors) = read("two_cloud_topics.bag", opts);
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(clouds.len(), 1);
        assert_eq!(
            clouds[0].name,
            format!("two_cloud_topics.bag:{topic}:000000")
        );
        assert!(clouds[0].pose.is_none());
        check_cloud(
            "two_cloud_topics.bag",
            &clouds[0],
            &exp["two_cloud_topics.bag"]["clouds"][i],
        );
    }
}
