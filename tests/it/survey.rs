//! E57 and LAS/LAZ, read back from files that pye57 (libE57Format) and
//! laspy/lazrs wrote (tests/data/survey/make_survey.py): point counts and
//! float64 sums against the figures the writer recorded in expected.json,
//! and damaged files refused with a message naming the file.
//!
//! The files are embedded, so the same tests run natively and in wasm
//! (`wasm-pack test --node -- --no-default-features --test it survey`);
//! reading from paths and the panic guard around the LAZ decoder are
//! native only.

use placecat::io::e57::{for_each_scan, read_scans, SurveyScans};
use placecat::io::recording::RecordedScan;
use placecat::io::source::SourceReader;
use placecat::io::{is_scan_name, read_scan_at, read_scan_named, ReadLimits};
use placecat::{Format, PointCloud};
use serde_json::Value;
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// The fixtures, embedded.
fn bytes(name: &str) -> &'static [u8] {
    macro_rules! files {
        ($($f:literal),*) => {
            match name {
                $($f => include_bytes!(concat!("../data/survey/", $f)),)*
                _ => panic!("no fixture {name}"),
            }
        };
    }
    files!(
        "expected.json",
        "las12_fmt0.las",
        "las12_fmt1.las",
        "las12_fmt3.las",
        "las14_fmt6.las",
        "laz12_fmt1.laz",
        "laz14_fmt6.laz",
        "geo14_fmt6.las",
        "survey.e57",
        "truncated.las",
        "corrupt_chunk.laz",
        "truncated.e57",
        "single.e57"
    )
}

fn expected() -> Value {
    serde_json::from_slice(bytes("expected.json")).unwrap()
}

fn triple(v: &Value) -> [f64; 3] {
    let a = v.as_array().unwrap();
    [0, 1, 2].map(|i| a[i].as_f64().unwrap())
}

/// Compare count, finite count and sums of `points` with an expected.json
/// entry. The reader hands out float32, so each coordinate may be off by
/// half a float32 step: 1e-6 per point is ample for coordinates of ~10 m.
fn check(what: &str, points: &[[f32; 3]], want: &Value) {
    let n = want["points"].as_u64().unwrap() as usize;
    assert_eq!(points.len(), n, "{what}: point count");
    let finite: Vec<&[f32; 3]> = points
        .iter()
        .filter(|p| placecat::cloud::is_finite(p))
        .collect();
    assert_eq!(
        finite.len() as u64,
        want["finite"].as_u64().unwrap(),
        "{what}: finite points"
    );
    let sum = finite.iter().fold([0f64; 3], |mut s, p| {
        for a in 0..3 {
            s[a] += f64::from(p[a]);
        }
        s
    });
    let want = triple(&want["sum"]);
    for a in 0..3 {
        assert!(
            (sum[a] - want[a]).abs() < 1e-6 * n as f64,
            "{what}: sum of axis {a} is {}, the writer's is {}",
            sum[a],
            want[a]
        );
    }
}

fn read_at(name: &str, origin: Option<[f64; 3]>) -> placecat::Result<PointCloud> {
    read_scan_at(bytes(name), name, &ReadLimits::default(), origin).map_err(|e| e.in_file(name))
}

fn read(name: &str) -> placecat::Result<PointCloud> {
    read_scan_named(bytes(name), name, &ReadLimits::default())
}

fn survey(name: &str, limits: &ReadLimits) -> placecat::Result<Vec<RecordedScan>> {
    read_scans(bytes(name), name, limits)
}

fn refused(result: placecat::Result<impl std::fmt::Debug>, file: &str, says: &str) -> String {
    let msg = result.expect_err(file).to_string();
    assert!(msg.contains(file), "the error does not name {file}: {msg}");
    assert!(
        msg.contains(says),
        "the error for {file} does not say {says:?}: {msg}"
    );
    msg
}

#[test]
fn las_and_laz_of_every_version_and_point_format_read_back_the_writers_points() {
    let exp = expected();
    let files = [
        ("las12_fmt0.las", Format::Las),
        ("las12_fmt1.las", Format::Las),
        ("las12_fmt3.las", Format::Las),
        ("las14_fmt6.las", Format::Las),
        ("laz12_fmt1.laz", Format::Laz),
        ("laz14_fmt6.laz", Format::Laz),
    ];
    for (name, format) in files {
        let cloud = read(name).unwrap();
        assert_eq!(cloud.format, format, "{name}");
        check(name, &cloud.points, &exp[name]);
    }
    assert_eq!(Format::Las.name(), "las");
    assert_eq!(Format::Laz.name(), "laz");
}

#[test]
fn a_given_origin_is_subtracted_from_every_point() {
    let exp = &expected()["las14_fmt6.las"];
    let origin = [1.5, -2.0, 0.25];
    let cloud = read_at("las14_fmt6.las", Some(origin)).unwrap();
    let n = cloud.points.len() as f64;
    let sum = triple(&exp["sum"]);
    let shifted = serde_json::json!({
        "points": exp["points"],
        "finite": exp["finite"],
        "sum": ([0, 1, 2].map(|a| sum[a] - n * origin[a])),
    });
    check("las14_fmt6.las at an origin", &cloud.points, &shifted);
    // Other formats are shifted the same way (after their own reading).
    let single = read_at("single.e57", Some(origin)).unwrap();
    let exp = &expected()["single.e57"];
    let sum = triple(&exp["sum"]);
    let n = single.points.len() as f64;
    let shifted = serde_json::json!({
        "points": exp["points"],
        "finite": exp["finite"],
        "sum": ([0, 1, 2].map(|a| sum[a] - n * origin[a])),
    });
    check("single.e57 at an origin", &single.points, &shifted);
    refused(
        read_at("las14_fmt6.las", Some([f64::NAN, 0.0, 0.0])),
        "las14_fmt6.las",
        "not finite",
    );
}

#[test]
fn georeferenced_las_is_centred_on_the_sensor_in_float64_and_keeps_its_millimetres() {
    let exp = &expected()["geo14_fmt6.las"];
    let cloud = read_at("geo14_fmt6.las", Some(triple(&exp["origin"]))).unwrap();
    check("geo14_fmt6.las centred", &cloud.points, &exp["centred"]);
    // At 6.1e6 m a float32 has a step of 0.5 m: subtracting after the
    // conversion would be off by decimetres. Here the first point is within
    // a float32 step of ~2 m (2.4e-7) of the writer's, 1 micrometre allowed.
    let first = triple(&exp["first_centred"]);
    for (got, want) in cloud.points[0].iter().zip(first) {
        assert!((f64::from(*got) - want).abs() < 1e-6, "{got} vs {want}");
    }
    // Without a sensor position the file is refused, saying what to give and
    // that the bounding box centre is not one.
    let msg = refused(
        read("geo14_fmt6.las"),
        "geo14_fmt6.las",
        "no sensor position",
    );
    assert!(msg.contains("--origin"), "{msg}");
    assert!(msg.contains("is not a sensor position"), "{msg}");
}

fn angle_between(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

#[test]
fn every_scan_of_an_e57_survey_comes_with_its_own_pose_in_its_own_frame() {
    let exp = expected();
    let want = exp["survey.e57"]["scans"].as_array().unwrap();
    let scans = survey("survey.e57", &ReadLimits::default()).unwrap();
    let names: Vec<&str> = scans.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "survey.e57:hall",
            "survey.e57:office",
            "survey.e57:hall (scan 2)",
            "survey.e57:store"
        ]
    );
    assert_eq!(scans.len(), want.len());
    for (scan, w) in scans.iter().zip(want) {
        // Sums in the scan's own frame: the pose is not applied to the points.
        // The fourth station is in spherical coordinates.
        check(&scan.name, &scan.points, w);
        let pose = scan.pose.as_ref().expect("every station has a pose");
        assert_eq!(pose.position, triple(&w["translation"]), "{}", scan.name);
        let yaw = w["yaw"].as_f64().unwrap();
        assert!(
            angle_between(pose.yaw, yaw) < 1e-9,
            "{}: yaw {} vs {yaw}",
            scan.name,
            pose.yaw
        );
        assert_eq!(pose.name.as_deref(), Some(scan.name.as_str()));
    }
    // The scanner's invalid points (no return) are NaN, ten in the office.
    assert_eq!(scans[1].points.iter().filter(|p| p[0].is_nan()).count(), 10);
}

#[test]
fn a_survey_can_be_read_one_scan_at_a_time_and_stopped() {
    let mut seen = Vec::new();
    let stopped = for_each_scan(
        bytes("survey.e57"),
        "survey.e57",
        &ReadLimits::default(),
        |scan| {
            seen.push((scan.name, scan.points.len()));
            if seen.len() == 2 {
                return Err(placecat::Error::InvalidParameter("enough".into()));
            }
            Ok(())
        },
    );
    refused(stopped, "survey.e57", "enough");
    assert_eq!(
        seen,
        [
            ("survey.e57:hall".to_string(), 900),
            ("survey.e57:office".to_string(), 700)
        ]
    );
}

#[test]
fn a_single_station_e57_reads_as_one_scan() {
    let cloud = read("single.e57").unwrap();
    assert_eq!(cloud.format, Format::E57);
    assert_eq!(Format::E57.name(), "e57");
    check("single.e57", &cloud.points, &expected()["single.e57"]);
}

#[test]
fn reading_a_multi_scan_e57_as_one_scan_is_refused_with_the_count() {
    refused(read("survey.e57"), "survey.e57", "holds 4 scans");
}

#[test]
fn damaged_files_are_refused_naming_the_file() {
    refused(read("truncated.las"), "truncated.las", "truncated");
    refused(
        read("corrupt_chunk.laz"),
        "corrupt_chunk.laz",
        "LAZ data damaged",
    );
    refused(
        survey("truncated.e57", &ReadLimits::default()),
        "truncated.e57",
        "truncated",
    );
    // A name that promises LAS on bytes that are not.
    refused(
        read_scan_named(
            b"PK\x03\x04 not a point cloud",
            "x.laz",
            &ReadLimits::default(),
        ),
        "x.laz",
        "LASF",
    );
}

#[test]
fn a_damaged_page_of_an_e57_scan_is_refused_naming_the_file_and_the_scan() {
    // Flip a byte inside the second scan's binary section: the page
    // checksum catches it when that scan is read.
    let good = bytes("survey.e57");
    let at = e57::E57Reader::new(std::io::Cursor::new(good))
        .unwrap()
        .pointclouds()[1]
        .file_offset as usize
        + 2000;
    let mut damaged = good.to_vec();
    damaged[at] ^= 0xff;
    refused(
        read_scans(&damaged, "flipped.e57", &ReadLimits::default()),
        "flipped.e57",
        "scan 1 (office)",
    );
}

#[test]
fn a_survey_read_by_byte_ranges_is_the_survey_and_a_damaged_scan_is_skipped() {
    // The page's way (E57Scans over File.slice): a byte source as Read +
    // Seek, one scan at a time. The same scans as from the bytes whole.
    let whole = read_scans(bytes("survey.e57"), "survey.e57", &ReadLimits::default()).unwrap();
    let source = SourceReader::new(bytes("survey.e57"));
    let scans = SurveyScans::open(source, "survey.e57", ReadLimits::default()).unwrap();
    assert_eq!((scans.len(), scans.met()), (4, 0));
    let streamed: Vec<RecordedScan> = scans.map(Result::unwrap).collect();
    // Bit for bit (the office's invalid points are NaN, never equal as floats).
    let bits = |s: &[RecordedScan]| -> Vec<(String, Vec<u32>, Option<[f64; 3]>)> {
        s.iter()
            .map(|s| {
                let p = s.points.iter().flatten().map(|v| v.to_bits()).collect();
                (s.name.clone(), p, s.pose.as_ref().map(|p| p.position))
            })
            .collect()
    };
    assert_eq!(bits(&streamed), bits(&whole));
    // The second scan's page damaged: its error names the file and the
    // scan, and the scans after it are still read.
    let at = e57::E57Reader::new(std::io::Cursor::new(bytes("survey.e57")))
        .unwrap()
        .pointclouds()[1]
        .file_offset as usize
        + 2000;
    let mut damaged = bytes("survey.e57").to_vec();
    damaged[at] ^= 0xff;
    let mut scans = SurveyScans::open(
        SourceReader::new(damaged),
        "flipped.e57",
        ReadLimits::default(),
    )
    .unwrap();
    assert_eq!(scans.next().unwrap().unwrap().name, "flipped.e57:hall");
    refused(scans.next().unwrap(), "flipped.e57", "scan 1 (office)");
    assert_eq!(scans.met(), 2);
    let rest: Vec<String> = scans.map(|s| s.unwrap().name).collect();
    assert_eq!(rest, ["flipped.e57:hall (scan 2)", "flipped.e57:store"]);
    // A file that is no survey is refused when opened, naming it.
    refused(
        SurveyScans::open(
            SourceReader::new(bytes("las12_fmt0.las")),
            "x.e57",
            ReadLimits::default(),
        )
        .map(|s| s.len()),
        "x.e57",
        "E57",
    );
}

#[test]
fn points_outside_the_headers_bounding_box_are_refused_as_damage() {
    // LAZ has no checksums: damaged chunks decode to points anywhere, and
    // the header's bounding box is the check. Shrink the declared box of a
    // good file (max X, a float64 at byte 179 of every LAS header) to -3 m:
    // the room reaches x = 4 m.
    let mut shrunk = bytes("las12_fmt0.las").to_vec();
    shrunk[179..187].copy_from_slice(&(-3.0f64).to_le_bytes());
    let msg = refused(
        read_scan_named(&shrunk, "shrunk.las", &ReadLimits::default()),
        "shrunk.las",
        "outside the header's bounding box",
    );
    assert!(msg.contains("x = "), "{msg}");
    // Read leniently, the box is not checked (a writer that left it stale).
    let lenient = ReadLimits {
        lenient: true,
        ..ReadLimits::default()
    };
    let cloud = read_scan_named(&shrunk, "shrunk.las", &lenient).unwrap();
    check(
        "shrunk.las, lenient",
        &cloud.points,
        &expected()["las12_fmt0.las"],
    );
}

#[test]
fn the_point_limit_holds_for_las_laz_and_every_e57_scan() {
    let small = ReadLimits {
        max_points: 600,
        ..ReadLimits::default()
    };
    refused(
        read_scan_named(bytes("laz12_fmt1.laz"), "laz12_fmt1.laz", &small),
        "laz12_fmt1.laz",
        "limit of 600",
    );
    // The first two stations have 900 and 700 points.
    refused(survey("survey.e57", &small), "survey.e57", "scan 0 (hall)");
}

#[test]
fn folder_walks_take_las_laz_and_e57() {
    for name in ["a.las", "B.LAZ", "site/s.e57"] {
        assert!(is_scan_name(name), "{name}");
    }
    assert!(!is_scan_name("expected.json"));
}

/// Reading from paths, and the guard around the LAZ decoder's panics
/// (wasm aborts on a panic, so there is nothing to catch there).
#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::*;
    use placecat::io::e57::read_scans_path;
    use placecat::io::{read_path, read_path_at};
    use std::path::PathBuf;

    fn path(name: &str) -> PathBuf {
        PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/survey")).join(name)
    }

    #[test]
    fn paths_read_as_the_bytes_do_and_errors_name_the_path() {
        for name in ["las14_fmt6.las", "laz14_fmt6.laz"] {
            assert_eq!(
                read_path(&path(name), &ReadLimits::default()).unwrap(),
                read(name).unwrap()
            );
        }
        let origin = Some([512345.678, 6123456.789, 98.765]);
        assert_eq!(
            read_path_at(&path("geo14_fmt6.las"), &ReadLimits::default(), origin).unwrap(),
            read_at("geo14_fmt6.las", origin).unwrap()
        );
        let p = path("survey.e57").display().to_string();
        let scans = read_scans_path(&path("survey.e57"), &ReadLimits::default()).unwrap();
        let from_bytes = survey("survey.e57", &ReadLimits::default()).unwrap();
        assert_eq!(scans.len(), 4);
        for (a, b) in scans.iter().zip(&from_bytes) {
            assert_eq!(a.name, b.name.replace("survey.e57", &p));
            assert_eq!(
                a.pose.as_ref().unwrap().position,
                b.pose.as_ref().unwrap().position
            );
            assert!(a
                .points
                .iter()
                .zip(&b.points)
                .all(|(p, q)| p == q || p[0].is_nan() && q[0].is_nan()));
        }
        let t = path("truncated.e57");
        refused(
            read_scans_path(&t, &ReadLimits::default()),
            &t.display().to_string(),
            "truncated",
        );
        // Streamed from disk, a survey is not held to the byte cap (only its
        // scans to the point cap); from bytes it is.
        let tiny = ReadLimits {
            max_bytes: 1000,
            ..ReadLimits::default()
        };
        assert_eq!(
            read_scans_path(&path("survey.e57"), &tiny).unwrap().len(),
            4
        );
        refused(survey("survey.e57", &tiny), "survey.e57", "limit of 1000");
        refused(
            read_path(&path("truncated.las"), &ReadLimits::default()),
            &path("truncated.las").display().to_string(),
            "truncated",
        );
    }

    #[test]
    fn a_recording_on_disk_is_a_survey_by_its_signature_or_a_bag_by_its_name() {
        use placecat::io::bag::BagOptions;
        use placecat::io::poses::Pose;
        use placecat::io::recording::Recording;
        let open = |p: &std::path::Path, opts| Recording::open_path(p, opts);
        // The survey as read_scans_path reads it, the counts as it goes.
        let mut survey = open(&path("survey.e57"), BagOptions::default()).unwrap();
        assert_eq!((survey.total(), survey.met(), survey.topic()), (4, 0, None));
        let first = survey.next().unwrap().unwrap();
        assert_eq!(survey.met(), 1);
        let rest: Vec<RecordedScan> = survey.map(|s| s.unwrap()).collect();
        let whole = read_scans_path(&path("survey.e57"), &ReadLimits::default()).unwrap();
        // Bit for bit (the office's NaN points, no return, are never equal as floats).
        let bits = |scans: &[RecordedScan]| -> Vec<(String, Option<Pose>, Vec<u32>)> {
            let bits = |s: &RecordedScan| s.points.iter().flatten().map(|v| v.to_bits()).collect();
            scans
                .iter()
                .map(|s| (s.name.clone(), s.pose.clone(), bits(s)))
                .collect()
        };
        let read: Vec<RecordedScan> = std::iter::once(first).chain(rest).collect();
        // Named by the file's base name, as a bag's clouds are (and the page
        // names them); read_scans_path names them by the path given.
        let mut whole = whole;
        let full = path("survey.e57").display().to_string();
        for s in &mut whole {
            s.name = s.name.replacen(&full, "survey.e57", 1);
            if let Some(p) = &mut s.pose {
                p.name = p.name.as_ref().map(|n| n.replacen(&full, "survey.e57", 1));
            }
        }
        assert_eq!(read[1].name, "survey.e57:office");
        assert_eq!(bits(&read), bits(&whole));
        // A bag by its name, its topic's clouds; thinning as the bag reader's.
        let bags = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/bags"));
        let bag = open(&bags.join("ros1_corridor.bag"), BagOptions::default()).unwrap();
        assert_eq!((bag.total(), bag.topic()), (2, Some("/points")));
        assert_eq!(bag.filter(|c| c.is_ok()).count(), 2);
        let every = BagOptions {
            every: 2,
            ..BagOptions::default()
        };
        assert_eq!(
            open(&bags.join("ros1_corridor.bag"), every.clone())
                .unwrap()
                .count(),
            1
        );
        // Refusals begin with the file, as the readers' errors do, and say why.
        let refused = |p: PathBuf, opts, why: &str| {
            let e = open(&p, opts).err().expect("refused").to_string();
            assert!(
                e.starts_with(&format!("{}: ", p.display())) && e.contains(why),
                "{e}"
            );
        };
        refused(path("survey.e57"), every, "read station by station");
        refused(path("truncated.e57"), BagOptions::default(), "truncated");
        refused(
            path("las14_fmt6.las"),
            BagOptions::default(),
            "not a recording",
        );
        refused(bags.join("walk.db3"), BagOptions::default(), "No such file");
        let db3 = std::env::temp_dir().join(format!("placecat-{}.db3", std::process::id()));
        std::fs::write(&db3, b"SQLite format 3\0").unwrap();
        refused(
            db3.clone(),
            BagOptions::default(),
            "SQLite storage (.db3) is not read",
        );
        std::fs::remove_file(db3).unwrap();
        let not_e57 = std::env::temp_dir().join(format!("placecat-{}.e57", std::process::id()));
        std::fs::write(&not_e57, b"ply\nformat ascii 1.0\n").unwrap();
        refused(not_e57.clone(), BagOptions::default(), "no E57 signature");
        std::fs::remove_file(not_e57).unwrap();
    }

    #[test]
    fn damaged_laz_never_panics_through_the_reader() {
        // The laz crate asserts on some damaged input (seen with random byte
        // changes: an arithmetic decoder symbol out of range, an overflow in
        // the GPS-time model); the reader turns that into an error. Each case
        // is a few random bytes changed and perhaps a cut, from a fixed
        // xorshift; 13 of these 60 panic inside laz in a debug build.
        let good = bytes("laz14_fmt6.laz");
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut refused_count = 0;
        for _ in 0..60 {
            let mut damaged = good.to_vec();
            for _ in 0..1 + next() % 8 {
                let i = next() as usize % damaged.len();
                damaged[i] = next() as u8;
            }
            if next() % 4 == 0 {
                damaged.truncate(next() as usize % damaged.len());
            }
            if let Err(e) = read_scan_named(&damaged, "fuzzed.laz", &ReadLimits::default()) {
                assert!(e.to_string().starts_with("fuzzed.laz: "), "{e}");
                refused_count += 1;
            }
        }
        // Most changes land in the compressed points and are refused.
        assert!(refused_count > 40, "{refused_count} of 60 refused");
    }
}
