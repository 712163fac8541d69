//! The extra descriptor parts (issue 18) on known geometry, their distance,
//! and JSON round trips of descriptors and models that hold them.

use crate::common::*;
use placecat::descriptor::parts::parts_distance;
use placecat::descriptor::{slice, Part, PartKind, PRESETS};
use placecat::model::LabelledModel;
use placecat::{delta, describe, Descriptor, DescriptorParams, DistanceOptions};

/// The indoor preset with every part at weight 1 and the NDT at `ndt`.
fn every_part(ndt: f64) -> DescriptorParams {
    DescriptorParams {
        ndt_weight: ndt,
        parts: PartKind::ALL
            .iter()
            .map(|&kind| Part { kind, weight: 1.0 })
            .collect(),
        ..DescriptorParams::indoor()
    }
}

/// One part alone, at weight 1, the NDT not counted.
fn alone(kind: PartKind) -> DescriptorParams {
    DescriptorParams {
        ndt_weight: 0.0,
        parts: vec![Part { kind, weight: 1.0 }],
        ..DescriptorParams::indoor()
    }
}

fn box_room(seed: u64, size: [f32; 3]) -> Vec<[f32; 3]> {
    room(seed, size, -1.2, &[], 300.0)
}

/// An empty 8 x 5 m room: the free-space polygon is the room's floor plan,
/// 40 m² and 26 m round, compactness 4 pi 40 / 26² = 0.744 and elongation
/// 5 / 8 (within the 2-degree sectors' and the wall sampling's error).
#[test]
fn the_slice_of_a_box_room_is_its_floor_plan() {
    let ranges = slice::sector_points(&box_room(1, [8.0, 5.0, 3.0])).unwrap();
    let f = slice::features(&ranges);
    assert!((f.area - 40.0).abs() < 1.2, "area {}", f.area);
    assert!(
        (f.perimeter - 26.0).abs() < 0.6,
        "perimeter {}",
        f.perimeter
    );
    assert!(
        (f.compactness - 0.744).abs() < 0.02,
        "compactness {}",
        f.compactness
    );
    assert!(
        (f.elongation - 0.625).abs() < 0.02,
        "elongation {}",
        f.elongation
    );
    // A square room of the same area is not elongated, and a long corridor is.
    let square = slice::features(&slice::sector_points(&box_room(2, [6.3, 6.3, 3.0])).unwrap());
    assert!(square.elongation > 0.97, "{square:?}");
    let corridor = slice::features(&slice::sector_points(&corridor(3)).unwrap());
    assert!(corridor.elongation < 0.1, "{corridor:?}");
    assert!((corridor.area - 66.0).abs() < 3.0, "{corridor:?}");
}

/// Rotating a scan about z changes no part beyond the noise of its voxel
/// grid and sector edges; a room of another size is far away. M2DP is
/// scale-free (its rings are shares of the farthest point's distance, as
/// in the paper): the 16 x 12 m hall has nearly the office's shape, and
/// M2DP puts it at 0.0036 against 0.0028 for the turned office, so M2DP
/// is held to a place of another shape (a corridor), and its distances
/// (a mean over 192 values of |u - v| / 2, median 0.01-0.016 on the dev
/// scenes) to bounds of its own.
#[test]
fn every_part_is_invariant_to_rotation_about_z() {
    let pts = office(4);
    let turned = rotate_points(&pts, &rotation([0.0, 0.0, 1.0], 1.1));
    let other = box_room(5, [16.0, 12.0, 5.0]);
    let narrow = corridor(5);
    for kind in PartKind::ALL {
        let p = alone(kind);
        let opts = DistanceOptions::from(&p);
        let d = |a: &[[f32; 3]], b: &[[f32; 3]]| {
            delta(&describe(a, &p).unwrap(), &describe(b, &p).unwrap(), opts).unwrap()
        };
        let same = d(&pts, &turned);
        if kind == PartKind::M2dp {
            // Rotated 0.0028, corridor 0.028 (9.8 times) measured; the part
            // without its PCA turn puts the rotated office at 0.0045 (6.1
            // times), and both bounds fail then. M2DP's median distance
            // between scans indoors is 0.009-0.016 (docs/parts.md).
            let far = d(&pts, &narrow);
            assert!(same < 0.0035, "{kind:?}: rotated {same}");
            assert!(far > 7.0 * same, "{kind:?}: rotated {same}, corridor {far}");
            continue;
        }
        if kind == PartKind::ObjectLayout {
            // This office has three pieces; turned by 1.1 rad one of them
            // is no longer elongated (roundness across 0.5), and the angle
            // channel goes from three pairs to none: 0.33 measured. The
            // spacing channel holds (first half of the distance).
            let (a, b) = (kind.describe(&pts), kind.describe(&turned));
            let spacing = emd(&a[..10], &b[..10]) / 9.0;
            assert!(spacing < 0.03, "{kind:?}: spacing rotated {spacing}");
            assert!(
                same > 0.25,
                "{kind:?}: the angles held ({same}): tighten this"
            );
            continue;
        }
        assert!(same < 0.03, "{kind:?}: rotated {same}");
        let far = d(&pts, &other);
        assert!(
            far > 4.0 * same && far > 0.05,
            "{kind:?}: rotated {same}, other {far}"
        );
    }
}

/// The combined distance is 0 from a scan to itself, symmetric, and the
/// weighted sum of its parts and the NDT's Delta.
#[test]
fn the_combined_distance_is_the_weighted_sum_of_its_parts() {
    let p = every_part(1.0);
    let (a, b) = (
        describe(&office(6), &p).unwrap(),
        describe(&box_room(7, [12.0, 9.0, 4.0]), &p).unwrap(),
    );
    let opts = DistanceOptions::from(&p);
    assert_eq!(delta(&a, &a, opts).unwrap(), 0.0);
    let ab = delta(&a, &b, opts).unwrap();
    assert_eq!(ab, delta(&b, &a, opts).unwrap());
    let paper = DescriptorParams::indoor();
    let mut sum = delta(&a, &b, DistanceOptions::from(&paper)).unwrap();
    for kind in PartKind::ALL {
        let d = delta(&a, &b, DistanceOptions::from(&alone(kind))).unwrap();
        assert!(d > 0.0 && d <= 1.0, "{kind:?}: {d}");
        sum += d;
    }
    assert!((ab - sum).abs() < 1e-4 * sum, "{ab} vs {sum}");
    // Weights scale their parts: doubling the slice's adds its distance once more.
    let mut heavier = p.clone();
    heavier.parts[1].weight = 2.0;
    let slice_d = delta(&a, &b, DistanceOptions::from(&alone(PartKind::Slice))).unwrap();
    let h = delta(&a, &b, DistanceOptions::from(&heavier)).unwrap();
    assert!((h - ab - slice_d).abs() < 1e-4 * h);
}

/// Descriptors with and without parts do not compare (an error, not a
/// number), and the paper's presets write no part fields.
#[test]
fn parts_must_match_and_the_paper_presets_are_unchanged() {
    let with = describe(&office(8), &every_part(1.0)).unwrap();
    let without = describe(&office(8), &DescriptorParams::indoor()).unwrap();
    let e = delta(&with, &without, DistanceOptions::default()).unwrap_err();
    assert!(e.to_string().contains("different parts"), "{e}");
    for name in ["indoor", "outdoor", "indoor_bands", "perception_oru"] {
        let json = serde_json::to_string(&DescriptorParams::preset(name).unwrap()).unwrap();
        assert!(
            !json.contains("parts") && !json.contains("ndt_weight"),
            "{json}"
        );
    }
    assert!(serde_json::to_string(&without)
        .unwrap()
        .find("parts")
        .is_none());
    // Every preset with parts validates, and describes a room.
    for (name, make) in PRESETS {
        let p = make();
        p.validate().unwrap();
        if !p.parts.is_empty() {
            let d = describe(&office(9), &p).unwrap();
            d.validate_for(&p).unwrap();
            assert_eq!(d.parts.len(), p.parts.len(), "{name}");
        }
    }
}

#[test]
fn bad_weights_are_refused_by_name() {
    let mut p = every_part(0.0);
    p.parts.iter_mut().for_each(|q| q.weight = 0.0);
    assert!(p
        .validate()
        .unwrap_err()
        .to_string()
        .contains("nothing to compare"));
    let mut p = every_part(1.0);
    p.parts[2].weight = f64::NAN;
    assert!(p.validate().unwrap_err().to_string().contains("Esf"));
    let mut p = every_part(1.0);
    p.parts.push(p.parts[0]);
    assert!(p.validate().is_err());
    p.parts.pop();
    p.parts[3].kind = PartKind::Slice;
    assert!(p.validate().unwrap_err().to_string().contains("twice"));
    // A kind placecat does not have (LiDAR Iris) is named in the error.
    let e = serde_json::from_str::<DescriptorParams>(r#"{"parts":[{"kind":"iris","weight":1}]}"#)
        .unwrap_err();
    assert!(e.to_string().contains("iris"), "{e}");
}

/// A descriptor with parts and a model made from such descriptors read
/// back from JSON as they were, and the model classifies as before; a
/// part whose histogram does not sum to 1 is refused.
#[test]
fn descriptors_and_models_with_parts_round_trip() {
    let p = every_part(0.5);
    let scans = [
        office(10),
        office(11),
        box_room(12, [20.0, 14.0, 6.0]),
        box_room(13, [21.0, 15.0, 6.0]),
    ];
    let ds: Vec<Descriptor> = scans.iter().map(|s| describe(s, &p).unwrap()).collect();
    let text = serde_json::to_string(&ds[0]).unwrap();
    let back: Descriptor = serde_json::from_str(&text).unwrap();
    assert_eq!(back, ds[0]);
    back.validate_for(&p).unwrap();
    let mut bad = back.clone();
    bad.parts[1].values[0] += 0.5;
    assert!(bad.validate().unwrap_err().to_string().contains("sum to 1"));

    let names = [(0, "office".to_string()), (1, "hall".to_string())];
    let model = LabelledModel::build(&p, &ds, &[0, 0, 1, 1], &names).unwrap();
    let again = LabelledModel::from_json(&model.to_json().unwrap()).unwrap();
    assert_eq!(again, model);
    for (d, want) in ds.iter().zip(["office", "office", "hall", "hall"]) {
        assert_eq!(again.classify(d).unwrap().name, want);
    }
    let fresh = describe(&box_room(14, [19.0, 13.0, 6.0]), &p).unwrap();
    assert_eq!(again.classify(&fresh).unwrap().name, "hall");
    // A model whose categories lost their parts is refused, naming them.
    let mut v: serde_json::Value = serde_json::from_str(&model.to_json().unwrap()).unwrap();
    v["categories"][0]["parts"] = serde_json::json!([]);
    let e = LabelledModel::from_json(&v.to_string()).unwrap_err();
    assert!(e.to_string().contains("part values"), "{e}");
}

/// The presets with extra parts; `free_space` has NDT weight 0, so its
/// NDT histogram is never compared (the combined distance skips it).
const PARTS_PRESETS: [&str; 5] = [
    "indoor_plus",
    "warehouse",
    "outdoor_plus",
    "free_space",
    "indoor_clutter",
];

/// A few simulated warehouse scans along the aisles (every preset, the
/// outdoor ones too, describes them), simulated once for the tests here.
fn warehouse_points() -> &'static [Vec<[f32; 3]>] {
    use placecat::sim::{SceneKind, SimParams, Simulation};
    static POINTS: std::sync::OnceLock<Vec<Vec<[f32; 3]>>> = std::sync::OnceLock::new();
    POINTS.get_or_init(|| {
        let mut p = SimParams::new(SceneKind::Warehouse, 5);
        p.scans = 10;
        let sim = Simulation::new(&p).unwrap();
        (0..sim.len()).map(|i| sim.scan(i).points).collect()
    })
}

fn warehouse_scans(preset: &DescriptorParams) -> Vec<Descriptor> {
    warehouse_points()
        .iter()
        .map(|points| describe(points, preset).unwrap())
        .collect()
}

fn close(a: f32, b: f32) -> bool {
    (a - b).abs() <= 1e-5 * a.abs().max(b.abs()).max(1e-3)
}

/// k-means and the tree without a matrix measure a scan against a centre
/// put at another scan with `Space::to_centre`. A centre holds one
/// orientation (scan i's first candidate) while the matrix's Delta is the
/// best over both scans' candidates, so the guarantee is: to_centre from
/// scan i is Delta from i reduced to its first candidate, never below
/// Delta(i, j), and equal to it for the parts alone (`free_space`), which
/// have no orientations.
#[test]
fn a_centre_at_a_scan_is_its_first_orientation_at_the_matrix_delta() {
    use placecat::distance::Space;
    for name in PARTS_PRESETS {
        let params = DescriptorParams::preset(name).unwrap();
        let opts = DistanceOptions::from(&params);
        let ds = warehouse_scans(&params);
        let space = Space::new(&ds, opts).unwrap();
        let m = space.matrix();
        let (mut apart, mut above, mut most) = (0, 0, 1f32);
        for i in 0..ds.len() {
            let centre = space.centre_of(i);
            let first = Descriptor {
                matrices: ds[i].matrices[..1].to_vec(),
                ..ds[i].clone()
            };
            for (j, dj) in ds.iter().enumerate() {
                let (d, _) = space.to_centre(&centre, j);
                let delta = m.get(i, j);
                let one = Space::new(&[first.clone(), dj.clone()], opts)
                    .unwrap()
                    .delta(0, 1);
                assert!(
                    close(d, one),
                    "{name}: to_centre(centre_of({i}), {j}) = {d}, first orientation {one}"
                );
                assert!(
                    d >= delta || close(d, delta),
                    "{name}: {d} below Delta({i}, {j}) = {delta}"
                );
                if params.ndt_weight == 0.0 {
                    assert!(
                        close(d, delta),
                        "{name}: {d} against Delta({i}, {j}) = {delta}"
                    );
                }
                apart += usize::from(d > 0.0);
                above += usize::from(!close(d, delta));
                if delta > 0.0 {
                    most = most.max(d / delta);
                }
            }
        }
        // Distinct scans: every off-diagonal pair is apart.
        assert_eq!(apart, ds.len() * (ds.len() - 1), "{name}");
        eprintln!(
            "{name}: to_centre above Delta for {above} of {} pairs, at most {most:.3} times",
            ds.len() * ds.len()
        );
    }
}

/// Above MATRIX_LIMIT the collection runs hierarchical k-means++ without
/// the matrix (`fit_without_matrix`) and k-means as below it. On the same
/// scans the tree has to be the one the matrix path builds (nodes up to
/// EXACT_DIAMETER_LIMIT get exact diameters), and k-means on every scan
/// repeated in place past the limit has to give each copy its scan's label
/// (stride seeds fall on the same scans) and r times the cost.
#[test]
fn above_the_matrix_limit_parts_presets_cluster_as_below_it() {
    use placecat::cluster::hkmeans::HkMeansParams;
    use placecat::cluster::{HierarchicalKMeans, KMeansParams, Seeding};
    use placecat::collection::MATRIX_LIMIT;
    use placecat::distance::Space;
    use placecat::Collection;
    for name in PARTS_PRESETS {
        let params = DescriptorParams::preset(name).unwrap();
        let ds = warehouse_scans(&params);
        let space = Space::new(&ds, DistanceOptions::from(&params)).unwrap();
        let m = space.matrix();
        for seed in 0..3 {
            let with = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(seed)).unwrap();
            let without =
                HierarchicalKMeans::fit_without_matrix(&space, &HkMeansParams::new(seed)).unwrap();
            assert_eq!(with.nodes.len(), without.nodes.len(), "{name} seed {seed}");
            for (a, b) in with.nodes.iter().zip(&without.nodes) {
                assert_eq!(a.members, b.members, "{name} seed {seed}");
                assert!(
                    close(a.height, b.height),
                    "{name}: {} {}",
                    a.height,
                    b.height
                );
            }
            for k in 2..=4 {
                assert_eq!(
                    with.cut_k(k).unwrap().labels,
                    without.cut_k(k).unwrap().labels,
                    "{name} seed {seed} k {k}"
                );
            }
        }

        let r = MATRIX_LIMIT / ds.len() + 1;
        let named = |copies: usize| {
            ds.iter()
                .enumerate()
                .flat_map(move |(i, d)| (0..copies).map(move |c| (format!("s{i}_{c}"), d.clone())))
        };
        let mut small = Collection::from_parts(params.clone(), named(1)).unwrap();
        let mut big = Collection::from_parts(params.clone(), named(r)).unwrap();
        assert!(small.uses_matrix() && !big.uses_matrix());
        let kp = KMeansParams::new(3).seeding(Seeding::Stride);
        let (a, b) = (small.kmeans(&kp).unwrap(), big.kmeans(&kp).unwrap());
        let mut kinds = a.labels.clone();
        kinds.sort();
        kinds.dedup();
        assert_eq!(kinds, [0, 1, 2], "{name}: {:?}", a.labels);
        for (i, &l) in b.labels.iter().enumerate() {
            assert_eq!(l, a.labels[i / r], "{name}: copy {i} of scan {}", i / r);
        }
        // Centres are means summed in f32 over r copies of each scan, so
        // they differ from the small set's by rounding: 1e-3, not exact.
        let want = a.cost * r as f64;
        assert!(
            (b.cost - want).abs() <= 1e-3 * want,
            "{name}: cost {} above the limit, {want} = {r} x {} below",
            b.cost,
            a.cost
        );
    }
}

/// Every part of every scan, bit for bit as before the ranges and
/// azimuths were shared between parts (`descriptor::polar`): an FNV-1a
/// digest of each part's values (f32 bits) on the real files and on
/// simulated office and school scans, recorded by the code of commit
/// 20288a1 in tests/fixtures/parts_digests.json; the clutter part's
/// digests were recorded again when its voxel sample became the lowest
/// point of each voxel instead of the first seen (order-independent);
/// the m2dp part's were added when it came (round 3 of issue 18).
/// Re-recorded once more when the slice's vertex of a sector stopped
/// depending on the order of returns at the same range (ties go to the
/// larger x, y): 13 real files' slice and clutter parts changed, every
/// other digest stayed. The columns part's 28 were added when it came
/// (round 8), and the clutter part's room test moved into a function it
/// shares with it: every other digest stayed. The iron part's 28 were
/// added when it came (round 12); every other digest stayed. The objects
/// part's 28 were added when it came (round 16); every other digest
/// stayed.
/// With PLACECAT_WRITE_PARTS_DIGESTS=1 the test writes the file instead.
///
/// The digests pin exact f32 bits, and so the platform's `f32::hypot`,
/// `f32::atan2`, `f64::acos` and (objects) `f32::log10` (std calls the
/// C library's libm): the
/// fixture was recorded on x86-64 Linux (glibc); another libm (macOS,
/// musl, wasm32's) may differ in the last bit of an azimuth or a range
/// and fail this test without any change to placecat. Re-record there
/// rather than loosen it.
#[test]
fn parts_are_bit_identical_to_before_the_shared_polar_scan() {
    use placecat::io::{read_scan, ReadLimits};
    use placecat::sim::{SceneKind, SimParams, Simulation};
    use std::collections::BTreeMap;
    let fnv = |bits: &[u32]| {
        let mut h = 0xcbf2_9ce4_8422_2325u64;
        for b in bits.iter().flat_map(|w| w.to_le_bytes()) {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
        format!("{h:016x}")
    };
    let params = every_part(1.0);
    let mut scans: Vec<(String, Vec<[f32; 3]>)> = Vec::new();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/real");
    let groups = std::fs::read_to_string(format!("{root}/groups.csv")).unwrap();
    for file in groups.lines().skip(1).filter_map(|l| l.split(',').next()) {
        let bytes = std::fs::read(format!("{root}/{file}")).unwrap();
        let cloud = read_scan(&bytes, file, &ReadLimits::default()).unwrap();
        scans.push((file.to_string(), cloud.points));
    }
    for scene in [SceneKind::OfficeFloor, SceneKind::School] {
        let mut p = SimParams::new(scene, 1);
        p.scans = 1;
        let sim = Simulation::new(&p).unwrap();
        for i in 0..sim.len() {
            scans.push((format!("{scene:?}/{i}"), sim.scan(i).points));
        }
    }
    let mut got = BTreeMap::new();
    for (name, points) in &scans {
        let d = describe(points, &params).unwrap();
        for part in &d.parts {
            let bits: Vec<u32> = part.values.iter().map(|v| v.to_bits()).collect();
            got.insert(format!("{:?}/{name}", part.kind), fnv(&bits));
        }
    }
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/parts_digests.json"
    );
    if std::env::var_os("PLACECAT_WRITE_PARTS_DIGESTS").is_some() {
        std::fs::write(path, serde_json::to_string_pretty(&got).unwrap()).unwrap();
    }
    let want: BTreeMap<String, String> =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    assert_eq!(want.len(), PartKind::ALL.len() * (18 + 10));
    assert_eq!(got.len(), want.len());
    let differ: Vec<&String> = want
        .keys()
        .filter(|k| got.get(*k) != want.get(*k))
        .collect();
    assert!(differ.is_empty(), "parts changed: {differ:?}");
}

/// Two returns of one sector at the same range (169 m: 119² + 120² = 169²,
/// both in the 2-degree sector about 45 degrees): the vertex is the same
/// whichever comes first. The first-come rule this replaces gave
/// `indoor_plus`'s slice part other last bits for a shuffled room (the
/// property test `delta_is_stable_under_rotation_and_point_order`, CI's
/// case seed 374, shuffle 576).
#[test]
fn a_tie_of_range_in_a_sector_does_not_depend_on_the_order() {
    let (a, b) = ([119.0f32, 120.0, 0.0], [120.0f32, 119.0, 0.0]);
    assert_eq!(a[0].hypot(a[1]), b[0].hypot(b[1]));
    let one = slice::sector_points(&[a, b]).unwrap();
    let other = slice::sector_points(&[b, a]).unwrap();
    let sector = placecat::descriptor::parts::sector_of(&a, slice::SECTORS);
    assert_eq!(
        sector,
        placecat::descriptor::parts::sector_of(&b, slice::SECTORS)
    );
    assert_eq!(one[sector], other[sector]);
    assert_eq!(one, other);
}

/// Weights made by hand in `DistanceOptions` (its fields are public) are
/// checked where a descriptor is prepared: a NaN or negative weight is an
/// error naming it, not a NaN Delta (`DescriptorParams` checks its own).
#[test]
fn hand_made_distance_weights_are_checked() {
    let params = every_part(1.0);
    let a = describe(&box_room(1, [8.0, 5.0, 3.0]), &params).unwrap();
    let b = describe(&box_room(2, [6.3, 6.3, 3.0]), &params).unwrap();
    let good = DistanceOptions::from(&params);
    assert!(delta(&a, &b, good).unwrap().is_finite());
    for (ndt, part, want) in [
        (f32::NAN, 1.0, "got NaN"),
        (-1.0, 1.0, "got -1"),
        (1.0, f32::INFINITY, "got inf"),
        (1.0, -0.5, "got -0.5"),
    ] {
        let mut opts = good;
        opts.ndt_weight = ndt;
        opts.part_weights[0] = part;
        let e = delta(&a, &b, opts).unwrap_err().to_string();
        assert!(
            e.contains("distance weights must be finite and not negative") && e.contains(want),
            "{e}"
        );
    }
}

/// `sensor_height` is the sensor's height above the floor: refused unless
/// in (0, 20] m, out of JSON when not given (so earlier parameters files
/// keep their bytes) and read back when given, and it moves only the
/// parts that measure from the floor (`clutter`, `columns`, `objects`): the NDT
/// histogram and the other parts stay bit for bit the same.
#[test]
fn a_given_sensor_height_moves_only_the_parts_that_measure_from_the_floor() {
    for bad in [0.0, -1.0, 20.01, f64::NAN, f64::INFINITY] {
        let p = DescriptorParams {
            sensor_height: Some(bad),
            ..every_part(1.0)
        };
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("sensor_height"), "{bad}: {e}");
    }
    let highest = DescriptorParams {
        sensor_height: Some(20.0),
        ..every_part(1.0)
    };
    assert!(highest.validate().is_ok());
    // Nothing would read it: refused, naming the parts that would.
    let e = DescriptorParams {
        sensor_height: Some(1.2),
        ..DescriptorParams::indoor()
    }
    .validate()
    .unwrap_err()
    .to_string();
    assert!(
        e.contains(
            "sensor_height is read only by the clutter, columns, objects, object_types and object_layout parts"
        ),
        "{e}"
    );
    let json = serde_json::to_string(&every_part(1.0)).unwrap();
    assert!(!json.contains("sensor_height"), "{json}");
    let given = DescriptorParams {
        sensor_height: Some(1.05),
        ..every_part(1.0)
    };
    let back: DescriptorParams =
        serde_json::from_str(&serde_json::to_string(&given).unwrap()).unwrap();
    assert_eq!(back, given);
    // The office's floor lies 1.2 m below the sensor: measured from 1.05 m
    // below it, every height reads 0.15 m higher.
    let pts = office(7);
    let (a, b) = (
        describe(&pts, &every_part(1.0)).unwrap(),
        describe(&pts, &given).unwrap(),
    );
    assert_eq!(a.matrices, b.matrices);
    for (x, y) in a.parts.iter().zip(&b.parts) {
        // object_layout reads the floor only to cut the band its pieces
        // lie in: spacings and angles do not move with it (on this office
        // no piece enters or leaves the band), bit for bit.
        if x.kind == PartKind::ObjectLayout {
            assert_eq!(x.values, y.values, "object_layout moved with the floor");
            continue;
        }
        assert_eq!(
            x.values == y.values,
            !x.kind.measures_from_floor(),
            "{:?}",
            x.kind
        );
    }
    // Given as its true 1.2 m, the floor is where the estimate found it:
    // the parts that measure from it stay near the estimate's, nearer
    // than at 1.05 m.
    let true_height = describe(
        &pts,
        &DescriptorParams {
            sensor_height: Some(1.2),
            ..every_part(1.0)
        },
    )
    .unwrap();
    for ((x, y), z) in a.parts.iter().zip(&b.parts).zip(&true_height.parts) {
        if x.kind.measures_from_floor() && x.kind != PartKind::ObjectLayout {
            let (off, right) = (
                parts_distance(&x.values, &y.values),
                parts_distance(&x.values, &z.values),
            );
            assert!(
                right < 0.05 && right < off / 2.0,
                "{:?}: {right} against {off}",
                x.kind
            );
        }
    }
}

/// `describe` hands the NDT histogram's cells to the `iron` part when its
/// grid is the part's own (0.4 m, 5 points, eigen threshold 0.05: the
/// paper's indoor values), so the grid is built once; with another grid
/// the part builds its own. Either way its values must be the part's
/// alone, bit for bit: this checks the values on both paths (a grid of
/// other settings handed over would change them), not which path ran;
/// `iron::shares_grid`'s unit test checks the choice, and the digests
/// above pin the shared path on 28 scans.
#[test]
fn the_iron_part_is_the_same_whether_or_not_it_shares_the_histograms_grid() {
    use placecat::sim::{SceneKind, SimParams, Simulation};
    let mut p = SimParams::new(SceneKind::School, 2);
    p.scans = 1;
    let sim = Simulation::new(&p).unwrap();
    let points = sim.scan(0).points;
    let alone = PartKind::Iron.describe(&points);
    let iron_of = |params: &DescriptorParams| {
        let d = describe(&points, params).unwrap();
        let part = d.parts.iter().find(|p| p.kind == PartKind::Iron).unwrap();
        part.values.clone()
    };
    let shared = DescriptorParams::indoor_searched();
    assert_eq!((shared.voxel_size, shared.min_points_per_voxel), (0.4, 5));
    assert_eq!(shared.eigen_threshold, 0.05);
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&iron_of(&shared)), bits(&alone));
    for other in [
        DescriptorParams {
            voxel_size: 0.5,
            ..shared.clone()
        },
        DescriptorParams {
            min_points_per_voxel: 6,
            ..shared.clone()
        },
        DescriptorParams {
            eigen_threshold: 0.1,
            ..shared.clone()
        },
    ] {
        assert_eq!(bits(&iron_of(&other)), bits(&alone));
    }
    // The part is not trivially the same everywhere: another scan differs.
    let mut p = SimParams::new(SceneKind::Hospital, 2);
    p.scans = 1;
    let other = Simulation::new(&p).unwrap().scan(0).points;
    assert_ne!(bits(&PartKind::Iron.describe(&other)), bits(&alone));
}

/// The 1-D earth mover's distance of two histograms of equal mass, in bins.
fn emd(a: &[f32], b: &[f32]) -> f32 {
    let (mut ca, mut cb, mut sum) = (0f32, 0f32, 0f32);
    for (x, y) in a.iter().zip(b) {
        ca += x;
        cb += y;
        sum += (ca - cb).abs();
    }
    sum
}
