//! Readers: round trips through every format, the real files, and bad input.

use crate::common;
use common::*;
use placecat::io::write::{self, PcdData, PlyEncoding};
use placecat::io::{poses, read_scan, read_scan_named, ReadLimits};
use placecat::Format;

fn cloud() -> Vec<[f32; 3]> {
    let mut pts = office(1);
    pts.truncate(2000);
    pts.push([-1.5e-7, 123456.78, -0.0]);
    pts
}

fn read(bytes: &[u8], name: &str) -> placecat::Result<placecat::PointCloud> {
    read_scan(bytes, name, &ReadLimits::default())
}

#[test]
fn every_written_format_reads_back_identical_points() {
    let pts = cloud();
    let cases: Vec<(Vec<u8>, &str, Format)> = vec![
        (
            write::ply(&pts, PlyEncoding::Ascii, false),
            "a.ply",
            Format::PlyAscii,
        ),
        (
            write::ply(&pts, PlyEncoding::Ascii, true),
            "a.ply",
            Format::PlyAscii,
        ),
        (
            write::ply(&pts, PlyEncoding::BinaryLittleEndian, false),
            "a.ply",
            Format::PlyBinaryLittleEndian,
        ),
        (
            write::ply(&pts, PlyEncoding::BinaryLittleEndian, true),
            "a.ply",
            Format::PlyBinaryLittleEndian,
        ),
        (
            write::ply(&pts, PlyEncoding::BinaryBigEndian, false),
            "a.ply",
            Format::PlyBinaryBigEndian,
        ),
        (
            write::ply(&pts, PlyEncoding::BinaryBigEndian, true),
            "a.ply",
            Format::PlyBinaryBigEndian,
        ),
        (
            write::pcd(&pts, PcdData::Ascii).unwrap(),
            "a.pcd",
            Format::PcdAscii,
        ),
        (
            write::pcd(&pts, PcdData::Binary).unwrap(),
            "a.pcd",
            Format::PcdBinary,
        ),
        (
            write::pcd(&pts, PcdData::BinaryCompressed).unwrap(),
            "a.pcd",
            Format::PcdBinaryCompressed,
        ),
        (write::kitti(&pts), "a.bin", Format::KittiBin),
    ];
    for (bytes, name, format) in cases {
        let c = read(&bytes, name).unwrap_or_else(|e| panic!("{format:?}: {e}"));
        assert_eq!(c.format, format);
        assert_eq!(c.points, pts, "{format:?} changed the points");
    }
}

#[test]
fn incompressible_pcd_still_round_trips() {
    // Random bits do not compress: the stream is mostly literal runs.
    let mut r = rng(3);
    use rand::Rng;
    let pts: Vec<[f32; 3]> = (0..500)
        .map(|_| [r.random(), r.random(), r.random()])
        .collect();
    let bytes = write::pcd(&pts, PcdData::BinaryCompressed).unwrap();
    assert_eq!(read(&bytes, "r.pcd").unwrap().points, pts);
}

/// The 64 points on which the `lzf` crate's compress panicked (index out of
/// bounds) in the property test `readers_round_trip_what_the_writers_write`
/// (CI, 2026-11-30): the writer now compresses with placecat's own LZF.
#[test]
fn pcd_points_that_made_the_lzf_crate_panic_round_trip() {
    let pts: Vec<[f32; 3]> = vec![
        [0.0, -869207.5, 628377.4],
        [153358.98, 28132.514, -591491.0],
        [-159118.8, 80847.945, -113102.71],
        [846130.94, 461064.44, 567150.4],
        [158055.9, 391158.94, 475283.97],
        [-309747.75, -505913.53, -187555.66],
        [-539475.3, 334521.1, -573536.3],
        [434998.03, -201939.98, -705837.25],
        [-124368.38, 320012.34, -438058.2],
        [-786768.06, 186290.02, 166401.58],
        [558458.4, 838889.7, -749817.94],
        [-417617.9, -171309.83, 902803.5],
        [785147.8, -366324.7, 590267.1],
        [-515976.38, -262487.06, -688817.5],
        [974396.5, 287350.97, 497468.16],
        [-167411.39, 899734.4, -810743.2],
        [-543630.06, 988074.75, -222712.4],
        [-832683.06, 249535.88, 419931.2],
        [-327533.1, -420892.56, 545492.0],
        [-305173.1, 30185.678, 216582.11],
        [304387.0, -764084.8, 299098.88],
        [800029.75, 974548.06, -154604.27],
        [-433029.56, 134909.1, 979963.9],
        [-209764.64, -212200.27, -830962.44],
        [464703.16, -620397.0, 81409.83],
        [-604605.94, -979398.2, -478636.72],
        [-835974.75, -639110.2, 929013.7],
        [240167.84, -478474.38, -419582.16],
        [325197.47, -48322.355, -766666.25],
        [640293.56, 251949.38, -187590.23],
        [-124397.43, -640031.0, -400145.53],
        [652028.3, 770377.56, 732853.6],
        [857339.44, -792375.1, -621846.75],
        [108142.52, 385897.2, 592858.9],
        [137152.22, 207406.8, -767804.2],
        [849329.4, 501793.97, 712229.94],
        [229525.27, 156857.83, -868839.4],
        [959887.5, -490649.25, -343390.47],
        [-860744.1, 949973.44, 802680.3],
        [835464.3, 994574.5, 62883.06],
        [-983182.9, -961011.56, -616238.2],
        [-621565.3, -248343.31, -384735.94],
        [397551.8, -455893.9, -423215.63],
        [772094.2, 518337.56, -832523.4],
        [-42694.355, -786887.56, -146529.45],
        [1166.6056, -101661.32, -827212.1],
        [583088.5, -388300.56, 939264.0],
        [-134844.88, 540425.6, -219275.39],
        [220533.45, -204709.08, -242895.55],
        [-113603.086, -361970.44, 633564.3],
        [-98055.25, -286747.4, -299786.47],
        [-17875.875, 645245.7, -361883.3],
        [-82708.01, -399989.13, 623056.44],
        [213785.77, 591965.56, -273728.9],
        [554890.94, 733767.8, -894193.94],
        [-124550.516, -731326.25, -971141.9],
        [282840.72, 568043.3, -47905.223],
        [880768.5, 591810.8, 970851.9],
        [311317.1, -775570.44, -731316.94],
        [677985.3, -985050.44, 636634.9],
        [-238159.22, -598462.6, -989010.5],
        [168407.98, 122912.41, -837774.44],
        [-812607.5, -432822.6, 860702.7],
        [813334.56, 853018.3, -619330.56],
    ];
    assert_eq!(pts.len(), 64);
    let bytes = write::pcd(&pts, PcdData::BinaryCompressed).unwrap();
    assert_eq!(read(&bytes, "ci.pcd").unwrap().points, pts);
}

/// A PLY with every scalar type, a list property inside the vertex, and
/// elements before and after it; x, y, z of different types, out of order.
fn tricky_ply(encoding: &str) -> Vec<u8> {
    let header = format!(
        "ply\nformat {encoding} 1.0\ncomment tricky\nobj_info made by hand\nelement camera 2\nproperty list uchar int ids\nproperty double w\nelement vertex 3\nproperty uchar red\nproperty short z\nproperty list ushort float8 junk\nproperty double y\nproperty char c\nproperty ushort us\nproperty int i\nproperty uint ui\nproperty float32 x\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    )
    .replace("float8", "float");
    // red, z, junk list, y, c, us, i, ui, x
    type Vertex = (u8, i16, Vec<f32>, f64, i8, u16, i32, u32, f32);
    let verts: [Vertex; 3] = [
        (
            1,
            -3,
            vec![9.0, 8.0],
            1.25,
            -5,
            7,
            -70000,
            4_000_000_000,
            0.5,
        ),
        (2, 4, vec![], -2.5, 6, 8, 3, 9, -1.75),
        (3, 0, vec![1.0], 1e10, 0, 0, 0, 0, 3.0),
    ];
    if encoding == "ascii" {
        let mut s = header;
        s.push_str("2 10 20 0.5\n0 1.5\n");
        for v in &verts {
            let junk: Vec<String> = v.2.iter().map(|f| f.to_string()).collect();
            s.push_str(&format!(
                "{} {} {} {} {} {} {} {} {} {}\n",
                v.0,
                v.1,
                v.2.len(),
                junk.join(" "),
                v.3,
                v.4,
                v.5,
                v.6,
                v.7,
                v.8
            ));
        }
        s.push_str("3 0 1 2\n");
        return s.into_bytes();
    }
    let le = encoding == "binary_little_endian";
    let mut b = header.into_bytes();
    macro_rules! put {
        ($v:expr) => {
            if le {
                b.extend_from_slice(&$v.to_le_bytes())
            } else {
                b.extend_from_slice(&$v.to_be_bytes())
            }
        };
    }
    b.push(2);
    put!(10i32);
    put!(20i32);
    put!(0.5f64);
    b.push(0);
    put!(1.5f64);
    for v in &verts {
        b.push(v.0);
        put!(v.1);
        put!(v.2.len() as u16);
        for f in &v.2 {
            put!(*f);
        }
        put!(v.3);
        b.push(v.4 as u8);
        put!(v.5);
        put!(v.6);
        put!(v.7);
        put!(v.8);
    }
    b.push(3);
    for i in 0..3i32 {
        put!(i);
    }
    b
}

#[test]
fn ply_with_lists_other_elements_and_mixed_types() {
    for enc in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let c = read(&tricky_ply(enc), "t.ply").unwrap_or_else(|e| panic!("{enc}: {e}"));
        assert_eq!(
            c.points,
            vec![[0.5, 1.25, -3.0], [-1.75, -2.5, 4.0], [3.0, 1e10, 0.0]],
            "{enc}"
        );
    }
}

#[test]
fn real_files_read_with_their_header_counts() {
    for (rel, count, format) in [
        (
            "pcl_room/room_scan1.pcd",
            112586,
            Format::PcdBinaryCompressed,
        ),
        ("velodyne_pair/251370668.pcd", 69088, Format::PcdBinary),
        ("kitti00/000094.bin", 1945888 / 16, Format::KittiBin),
        (
            "ouster_os0_sequence/scan_000.bin",
            std::fs::metadata(format!("{REAL}/ouster_os0_sequence/scan_000.bin"))
                .unwrap()
                .len() as usize
                / 16,
            Format::KittiBin,
        ),
    ] {
        let c = read(&real(rel), rel).unwrap();
        assert_eq!((c.points.len(), c.format), (count, format), "{rel}");
        assert!(
            c.finite_count() > count / 2,
            "{rel}: most points should be finite"
        );
    }
}

#[test]
fn real_pcd_converted_to_every_format_reads_back_the_same() {
    let pts = read(&real("pcl_room/room_scan1.pcd"), "x.pcd")
        .unwrap()
        .points;
    for bytes in [
        write::ply(&pts, PlyEncoding::BinaryBigEndian, true),
        write::ply(&pts, PlyEncoding::Ascii, false),
        write::pcd(&pts, PcdData::BinaryCompressed).unwrap(),
    ] {
        assert_eq!(read(&bytes, "x.ply").unwrap().points, pts);
    }
}

fn err_of(bytes: &[u8], name: &str) -> String {
    match read_scan_named(bytes, name, &ReadLimits::default()) {
        Ok(c) => panic!("{name}: read {} points from bad input", c.points.len()),
        Err(e) => e.to_string(),
    }
}

#[test]
fn truncated_bodies_are_errors_naming_the_file() {
    let pts = cloud();
    for (bytes, name) in [
        (
            write::ply(&pts, PlyEncoding::BinaryLittleEndian, false),
            "t.ply",
        ),
        (write::ply(&pts, PlyEncoding::Ascii, false), "t.ply"),
        (write::pcd(&pts, PcdData::Binary).unwrap(), "t.pcd"),
        (
            write::pcd(&pts, PcdData::BinaryCompressed).unwrap(),
            "t.pcd",
        ),
        (write::pcd(&pts, PcdData::Ascii).unwrap(), "t.pcd"),
        (write::kitti(&pts), "t.bin"),
    ] {
        let cut = &bytes[..bytes.len() - 100];
        let e = err_of(cut, name);
        assert!(
            e.starts_with(name) && (e.contains("truncated") || e.contains("not a whole number")),
            "{e}"
        );
    }
    for enc in ["binary_little_endian", "binary_big_endian", "ascii"] {
        let b = tricky_ply(enc);
        // Cut into the last vertex (the face element after it is 8 to 13 bytes).
        let e = err_of(&b[..b.len() - 24], "tricky.ply");
        assert!(e.contains("truncated"), "{enc}: {e}");
    }
}

#[test]
fn lying_headers_fail_before_allocating() {
    let ply = b"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n\0\0\0\0";
    let e = err_of(ply, "huge.ply");
    assert!(e.contains("limit"), "{e}");
    let limits = ReadLimits {
        max_points: usize::MAX,
        max_bytes: usize::MAX,
        ..Default::default()
    };
    let e = read_scan(ply, "huge.ply", &limits).unwrap_err().to_string();
    assert!(e.contains("truncated"), "{e}");
    let ascii = b"ply\nformat ascii 1.0\nelement vertex 40000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
    assert!(err_of(ascii, "a.ply").contains("truncated"));
    let pcd = b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 40000000\nHEIGHT 1\nPOINTS 40000000\nDATA binary_compressed\n\x10\0\0\0\0\x10\x27\x09\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0";
    let e = err_of(pcd, "c.pcd");
    assert!(e.contains("binary_compressed"), "{e}");
}

#[test]
fn malformed_headers_are_clear_errors() {
    let cases: [(&[u8], &str, &str); 8] = [
        (b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "n.ply", "end_header"),
        (b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", "q.ply", "unknown property type"),
        (b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n", "z.ply", "no property z"),
        (b"ply\nformat ebcdic 1.0\nend_header\n", "f.ply", "unknown format"),
        (b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nCOUNT 1 1 1\nPOINTS 1\nDATA binary\n", "t.pcd", "unknown TYPE"),
        (b"VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nPOINTS 1\nDATA ascii\n1 2\n", "xy.pcd", "no field z"),
        (b"", "empty.bin", "empty"),
        (b"", "empty.ply", "does not start"),
    ];
    for (bytes, name, want) in cases {
        let e = err_of(bytes, name);
        assert!(e.starts_with(name) && e.contains(want), "{name}: {e}");
    }
    assert!(err_of(b"hello", "notes.txt").contains("unrecognised"));
    assert!(err_of(&[0u8; 17], "odd.bin").contains("16-byte"));
}

#[test]
fn nan_coordinates_are_kept_by_the_reader_and_dropped_by_the_descriptor() {
    let mut pts = office(2);
    pts[10] = [f32::NAN, 1.0, 1.0];
    let ascii = write::ply(&pts, PlyEncoding::Ascii, false);
    let c = read(&ascii, "nan.ply").unwrap();
    assert_eq!(c.points.len(), pts.len());
    assert_eq!(c.finite_count(), pts.len() - 1);
    let d = placecat::describe(&c.points, &placecat::DescriptorParams::indoor()).unwrap();
    assert_eq!(d.summary.dropped, 1);
}

#[test]
fn poses_in_three_formats() {
    let k = poses::parse(&String::from_utf8(real("kitti00/poses.txt")).unwrap()).unwrap();
    assert_eq!((k.format, k.poses.len()), (poses::PoseFormat::Kitti, 4));
    assert!((k.poses[0].position[0] - 81.6380864).abs() < 1e-9);
    let tum = poses::parse(&poses::to_tum(&k.poses)).unwrap();
    assert_eq!(tum.format, poses::PoseFormat::Tum);
    for (a, b) in k.poses.iter().zip(&tum.poses) {
        assert!((a.yaw - b.yaw).abs() < 1e-6 && (a.position[1] - b.position[1]).abs() < 1e-6);
    }
    let again = poses::parse(&poses::to_kitti(&k.poses)).unwrap();
    assert!((again.poses[3].yaw - k.poses[3].yaw).abs() < 1e-6);
    let csv = poses::parse("name,x,y,z\na.ply,1,2,3\nb.ply,4,5\n").unwrap();
    assert_eq!(csv.poses[1].name.as_deref(), Some("b.ply"));
    assert_eq!(csv.poses[1].position, [4.0, 5.0, 0.0]);
    for (bad, want) in [
        ("1 2 3\n", "3 numbers"),
        ("", "no pose rows"),
        ("0 1 2 3 0 0 0 5\n", "norm"),
        ("name,x,y\n", "header but no"),
        // A header has words where all the numbers go; these rows do not,
        // so they are bad rows, not headers.
        ("a,1,x\n", "line 1: x, y, z must be finite numbers"),
        ("a.pcd,NaN,1\n", "line 1: x, y, z must be finite numbers"),
        (
            "name,x,y\na.pcd,1,inf\n",
            "line 2: x, y, z must be finite numbers",
        ),
    ] {
        let e = poses::parse(bad).unwrap_err().to_string();
        assert!(e.contains(want), "{bad:?}: {e}");
    }
}

#[test]
fn padding_after_a_binary_body_is_bounded_and_blank() {
    let pts = cloud();
    let ply = write::ply(&pts, PlyEncoding::BinaryLittleEndian, false);
    let pcd = write::pcd(&pts, PcdData::Binary).unwrap();
    let max = placecat::io::MAX_PADDING;
    for (bytes, name) in [(ply, "p.ply"), (pcd, "p.pcd")] {
        let with = |tail: &[u8]| [&bytes[..], tail].concat();
        for pad in [&b"\n"[..], b"\r\n", &vec![0u8; max], &vec![b' '; max]] {
            assert_eq!(read(&with(pad), name).unwrap().points, pts, "{name}");
        }
        for bad in [&b"x"[..], b"\n\x01", &vec![0u8; max + 1]] {
            let e = err_of(&with(bad), name);
            assert!(
                e.starts_with(name) && e.contains("does not match the header"),
                "{e}"
            );
            let lenient = ReadLimits {
                lenient: true,
                ..Default::default()
            };
            let c = read_scan(&with(bad), name, &lenient).unwrap();
            assert_eq!(c.points, pts, "{name}");
        }
    }
}

#[test]
fn ascii_errors_name_the_line_in_the_file() {
    // Line 11 of the file: 8 header lines, a good row, a blank line.
    let ply = b"ply\nformat ascii 1.0\ncomment c\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n\n4 5 6 7\n";
    assert_eq!(
        err_of(ply, "l.ply"),
        "l.ply: PLY: line 11: 4 values where the header declares 3 (element vertex record 1 of 3)"
    );
    let pcd = b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n1 2 oops\n";
    assert_eq!(
        err_of(pcd, "l.pcd"),
        "l.pcd: PCD: line 11: \"oops\" is not a number (point 1 of 2)"
    );
}

#[test]
fn csv_poses_may_quote_names_that_hold_commas() {
    let p = poses::parse("name,x,y,z\n\"a,1.ply\",1,2,3\n\"b \"\"2\"\".ply\",4,5\n").unwrap();
    let names: Vec<_> = p.poses.iter().map(|p| p.name.clone().unwrap()).collect();
    assert_eq!(names, ["a,1.ply", "b \"2\".ply"]);
    assert_eq!(p.poses[0].position, [1.0, 2.0, 3.0]);
    let e = poses::parse("name,x,y\n\"a.ply,1,2\n")
        .unwrap_err()
        .to_string();
    assert_eq!(e, "poses: CSV: line 2: a quote opened here is not closed");
}

/// A binary PLY of only x, y, z as float32 LE is read by its own loop
/// (src/io/ply.rs); the bits must be those of the general loop's read of
/// the same values with one more property after them, NaN payloads,
/// -0.0, subnormals and infinities included.
#[test]
fn packed_float_ply_reads_the_bits_the_record_loop_reads() {
    let values: Vec<f32> = [
        f32::from_bits(0x7fc0_1234),
        f32::from_bits(0xffa0_0001),
        -0.0,
        1e-45,
        -1.1754942e-38,
        f32::INFINITY,
        f32::NEG_INFINITY,
        123456.78,
        -1.5e-7,
    ]
    .into_iter()
    .chain((0..300).map(|i| (i as f32 * 0.37).sin() * 40.0))
    .collect();
    let points: Vec<[f32; 3]> = values.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    let ply = |extra: bool| {
        let mut b = format!(
            "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n{}end_header\n",
            points.len(),
            if extra { "property float intensity\n" } else { "" }
        )
        .into_bytes();
        for p in &points {
            p.iter().for_each(|v| b.extend(v.to_le_bytes()));
            if extra {
                b.extend(7.5f32.to_le_bytes());
            }
        }
        b
    };
    let bits = |b: &[u8]| -> Vec<[u32; 3]> {
        let cloud = read_scan(b, "p.ply", &ReadLimits::default()).unwrap();
        cloud.points.iter().map(|p| p.map(f32::to_bits)).collect()
    };
    let want: Vec<[u32; 3]> = points.iter().map(|p| p.map(f32::to_bits)).collect();
    assert_eq!(bits(&ply(false)), want);
    assert_eq!(bits(&ply(true)), want);
    // One byte short is still a truncated file, not a shorter cloud.
    let packed = ply(false);
    let e = err_of(&packed[..packed.len() - 1], "p.ply");
    assert!(e.contains("truncated"), "{e}");
    // Four bytes that are not padding after the body: damaged, not read.
    let mut junk = packed.clone();
    junk.extend([0xde, 0xad, 0xbe, 0xef]);
    let e = err_of(&junk, "p.ply");
    assert!(e.contains("4 bytes follow"), "{e}");
    // A header claiming one vertex more than the body holds.
    let n = points.len();
    let (claim, more) = (
        format!("element vertex {n}\n"),
        format!("element vertex {}\n", n + 1),
    );
    let at = packed
        .windows(claim.len())
        .position(|w| w == claim.as_bytes())
        .unwrap();
    let lying = [&packed[..at], more.as_bytes(), &packed[at + claim.len()..]].concat();
    let e = err_of(&lying, "p.ply");
    assert!(
        e.contains(&format!(
            "truncated: the header claims {} vertices of 12 bytes",
            n + 1
        )),
        "{e}"
    );
}
