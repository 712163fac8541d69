//! The JS API end to end, run by `wasm-pack test` in headless Chromium
//! (tests/web.rs) and in Node (tests/node.rs).

use placecat::wasm::*;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;

include!("../common/parity_case.rs");
include!("../common/bad_corpus.rs");

mod descriptor_digests;

fn message(e: JsError) -> String {
    let v: JsValue = e.into();
    let err: js_sys::Error = v.dyn_into().expect("a JS Error");
    err.message().into()
}

fn get(v: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(v, &key.into()).unwrap()
}

/// Bytes as JS passes them most often: a Uint8Array.
fn u8a(bytes: &[u8]) -> JsValue {
    js_sys::Uint8Array::from(bytes).into()
}

fn labels_of(v: &JsValue) -> Vec<i32> {
    serde_wasm_bindgen::from_value(get(v, "labels")).unwrap()
}

#[wasm_bindgen_test]
fn core_labels_match_the_native_fixture() {
    let want: serde_json::Value =
        serde_json::from_str(include_str!("../fixtures/parity.json")).unwrap();
    assert_eq!(parity_case(), want);
}

fn real_set() -> (DescriptorSet, Vec<DescribedScan>) {
    let mut set = DescriptorSet::new(JsValue::UNDEFINED, Some("indoor".into())).unwrap();
    let mut scans = Vec::new();
    for (name, bytes) in PARITY_FILES {
        let s = describe_scan(u8a(bytes), name, None, Some("indoor".into()), Some(2000)).unwrap();
        set.add(&s).unwrap();
        scans.push(s);
    }
    (set, scans)
}

#[wasm_bindgen_test]
fn describe_real_bytes_and_cluster_through_the_api() {
    let (mut set, scans) = real_set();
    assert_eq!(set.length(), 6);
    assert_eq!(scans[3].format(), "pcd_binary_compressed");
    let summary = scans[3].summary().unwrap();
    assert_eq!(get(&summary, "points").as_f64(), Some(112586.0));
    assert!(get(&summary, "planar").as_f64().unwrap() > 100.0);
    let preview = scans[3].preview();
    assert!(
        preview.length() <= 3 * 2000 && preview.length() > 3 * 1500,
        "{}",
        preview.length()
    );
    let m = set.delta_matrix().unwrap().to_vec();
    assert_eq!(m.len(), 36);
    for i in 0..6 {
        assert_eq!(m[i * 6 + i], 0.0);
        for j in 0..6 {
            assert_eq!(m[i * 6 + j], m[j * 6 + i]);
        }
    }
    // The two room scans are nearer each other than to the ouster scans.
    assert!(m[3 * 6 + 4] < m[3 * 6]);
    // Same labels as the core computes on the same bytes.
    let km = set.kmeans(3.0, "stride", 1.0, None).unwrap();
    let labels = labels_of(&km);
    assert_eq!(labels[0], labels[1]);
    assert_eq!(labels[3], labels[4]);
    let tree = set.hkmeans(2.0, None).unwrap();
    let linkage = tree.linkage().to_vec();
    assert_eq!(linkage.len(), 5 * 4);
    let cut = tree.cut_k(3.0).unwrap();
    let e = message(tree.cut_k(2.5).err().unwrap());
    assert!(e.contains("k must be a whole number, got 2.5"), "{e}");
    assert_eq!(labels_of(&cut).len(), 6);
    assert_eq!(tree.count_at(tree.root_height()).unwrap(), 1);
    assert!(message(tree.count_at(f32::NAN).err().unwrap()).contains("threshold"));
    let db = set.dbscan(0.5, 2.0).unwrap().to_vec();
    assert_eq!(db.len(), 6);
    // The choice of categories with its reference sets computed elsewhere
    // (another set of the same scans, in two shares, as the page's workers):
    // the same choice; a share missing or a set out of range is an Error.
    let (mut other, _) = real_set();
    assert_eq!(set.reference_sets(), 10);
    let (even, odd) = (
        other
            .reference_dispersions(2.0, &[0, 2, 4, 6, 8], None)
            .unwrap()
            .to_vec(),
        other
            .reference_dispersions(2.0, &[1, 3, 5, 7, 9], None)
            .unwrap()
            .to_vec(),
    );
    assert_eq!(even.len(), 5 * 6, "K = 1 to 6 for six scans");
    let all: Vec<f64> = (0..10)
        .flat_map(|b| [&even, &odd][b % 2][b / 2 * 6..b / 2 * 6 + 6].to_vec())
        .collect();
    let with = set.choose_categories_with(&tree, &all, 2.0, None).unwrap();
    let own = set.choose_categories(&tree).unwrap();
    assert_eq!(
        js_sys::JSON::stringify(&with).unwrap(),
        js_sys::JSON::stringify(&own).unwrap()
    );
    let e = message(
        set.choose_categories_with(&tree, &all[6..], 2.0, None)
            .err()
            .unwrap(),
    );
    assert!(e.contains("9 reference sets"), "{e}");
    // Drawn for a tree of another seed: refused, not another choice.
    let e = message(
        set.choose_categories_with(&tree, &all, 3.0, None)
            .err()
            .unwrap(),
    );
    assert!(
        e.contains("seed 3, restarts 1; this tree's: seed 2, restarts 1"),
        "{e}"
    );
    // Or for a tree of other trial splits (a tree of 10 trials a split).
    let trials = set.hkmeans(2.0, Some(10.0)).unwrap();
    let e = message(
        set.choose_categories_with(&trials, &all, 2.0, None)
            .err()
            .unwrap(),
    );
    assert!(
        e.contains("seed 2, restarts 1; this tree's: seed 2, restarts 10"),
        "{e}"
    );
    let e = message(set.hkmeans(2.0, Some(0.0)).err().unwrap());
    assert!(e.contains("restarts must be at least 1"), "{e}");
    // Not a whole number: refused, not truncated (a u32 would take 2.5 as 2).
    for bad in [2.5, -1.0, f64::NAN, f64::INFINITY] {
        let e = message(set.hkmeans(2.0, Some(bad)).err().unwrap());
        assert!(
            e.contains("restarts must be a whole number of runs"),
            "{bad}: {e}"
        );
    }
    let e = message(set.kmeans(3.0, "plusplus", 1.0, Some(2.5)).err().unwrap());
    assert!(
        e.contains("restarts must be a whole number of runs from 1, got 2.5"),
        "{e}"
    );
    let e = message(set.choose_k("plusplus", 1.0, Some(-1.0)).err().unwrap());
    assert!(e.contains("got -1.0"), "{e}");
    // Spectral seeding needs k (docs/spectral-seeding-k-dev.md).
    let e = message(set.choose_k("spectral", 1.0, None).err().unwrap());
    assert!(
        e.contains("not chosen from the data for k-means with spectral seeding"),
        "{e}"
    );
    let e = message(set.hkmeans(2.0, Some(-0.0)).err().unwrap());
    assert!(e.contains("restarts must be at least 1"), "{e}");
    for huge in [2f64.powi(40), 1e300] {
        let e = message(set.hkmeans(2.0, Some(huge)).err().unwrap());
        assert!(e.contains("is more than the limit of 1000"), "{e}");
        assert!(e.len() < 120, "{e}");
    }
    let e = message(other.reference_dispersions(2.0, &[10], None).err().unwrap());
    assert!(e.contains("reference set 10 asked for, of 10"), "{e}");
}

#[wasm_bindgen_test]
fn simulated_demo_model_round_trip_and_classify() {
    let sim = Simulator::new("indoor", 4.0, Some(2.0), None, None).unwrap();
    assert_eq!(sim.length(), 10);
    // The labels getter is each scan's label, known without casting it.
    let listed = sim.labels();
    assert_eq!(listed.len(), 10);
    for i in [0, 3, 9] {
        let label = get(&sim.scan(i).unwrap(), "label").as_string().unwrap();
        assert_eq!(label, listed[i]);
    }
    // Listed kind by kind (a, a, b, b, ...), rooms of the default 3 scans
    // numbered in order.
    assert!(
        listed.chunks(2).all(|kind| kind[0] == kind[1]),
        "{listed:?}"
    );
    assert_eq!(sim.rooms().len(), 10);
    // Shuffled: the same labels in another order, and each scan keeps its
    // room with its label.
    let shuffled = Simulator::new("indoor", 4.0, Some(2.0), None, Some(true)).unwrap();
    let pairs = |s: &Simulator| -> Vec<(String, u32)> {
        let mut v: Vec<_> = s.labels().into_iter().zip(s.rooms()).collect();
        v.sort();
        v
    };
    assert_ne!(shuffled.labels(), listed);
    assert_eq!(pairs(&shuffled), pairs(&sim));
    // The floors are scenes of the wasm API too (one kind in a room).
    let school = Simulator::new("school", 4.0, Some(2.0), None, None).unwrap();
    let kinds: std::collections::BTreeSet<String> = school.labels().into_iter().collect();
    assert_eq!(kinds.len(), 5, "{kinds:?}");
    assert!(school.rooms().windows(2).all(|w| w[0] <= w[1]));
    let e = message(
        Simulator::new("outdoor", 4.0, None, None, Some(true))
            .err()
            .unwrap(),
    );
    assert!(e.contains("shuffle") && e.contains("outdoor"), "{e}");
    let mut set = DescriptorSet::new(JsValue::UNDEFINED, None).unwrap();
    let mut truth = Vec::new();
    let mut scans = Vec::new();
    for i in 0..sim.length() {
        let s = sim.scan(i).unwrap();
        let bytes: Vec<u8> = js_sys::Uint8Array::new(&get(&s, "bytes")).to_vec();
        let name = get(&s, "name").as_string().unwrap();
        truth.push(get(&s, "label").as_string().unwrap());
        let d = describe_scan(u8a(&bytes), &name, None, None, None).unwrap();
        set.add_json(&d.descriptor_json().unwrap()).unwrap();
        scans.push(d);
    }
    let km = set.kmeans(5.0, "plusplus", 1.0, None).unwrap();
    // Restarts: run 0 is the single run, the cheapest of 10 is kept (and
    // the kept run's index comes back); stride restarts are refused.
    let one = set.kmeans(5.0, "plusplus", 1.0, Some(1.0)).unwrap();
    assert_eq!(labels_of(&one), labels_of(&km));
    assert_eq!(get(&one, "restart").as_f64(), Some(0.0));
    let ten = set.kmeans(5.0, "plusplus", 1.0, Some(10.0)).unwrap();
    let cost = |v: &JsValue| get(v, "cost").as_f64().unwrap();
    // Measured (as `placecat cluster --restarts 10` on the same scans):
    // run 9 is kept, cost 0.7291 against the single run's 0.8646.
    assert_eq!(get(&ten, "restart").as_f64(), Some(9.0));
    assert!((cost(&km) - 0.8646).abs() < 1e-4, "{}", cost(&km));
    assert!((cost(&ten) - 0.7291).abs() < 1e-4, "{}", cost(&ten));
    let e = message(set.kmeans(5.0, "stride", 1.0, Some(10.0)).err().unwrap());
    assert!(e.contains("restarts = 10 with stride"), "{e}");
    // A huge count is an Error, not a trap (it used to run out of memory).
    let e = message(
        set.kmeans(5.0, "plusplus", 1.0, Some(u32::MAX as f64))
            .err()
            .unwrap(),
    );
    assert!(e.contains("is more than the limit of 1000"), "{e}");
    let labels = labels_of(&km);
    let ev = DescriptorSet::evaluate(truth.clone(), &labels).unwrap();
    let acc = get(&ev, "accuracy").as_f64().unwrap();
    assert!((0.0..=1.0).contains(&acc));
    // The DBSCAN sweep over the set's own grid: each point is what dbscan
    // and evaluate give at its parameters.
    let grid = set.epsilon_grid().unwrap().to_vec();
    assert!(
        grid.len() >= 2 && grid.windows(2).all(|w| w[0] < w[1]),
        "{grid:?}"
    );
    let sweep = set
        .dbscan_sweep(&grid, &[2, 3], Some(truth.clone()))
        .unwrap();
    let sweep = js_sys::Array::from(&sweep);
    assert_eq!(sweep.length() as usize, 2 * grid.len());
    for p in sweep.iter() {
        let e = get(&p, "epsilon").as_f64().unwrap() as f32;
        let c = get(&p, "min_points").as_f64().unwrap() as usize;
        let db = set.dbscan(e, c as f64).unwrap().to_vec();
        let ev = DescriptorSet::evaluate(truth.clone(), &db).unwrap();
        assert_eq!(get(&p, "score").as_f64(), get(&ev, "score").as_f64());
        let clusters = db.iter().copied().max().unwrap_or(-1) + 1;
        assert_eq!(get(&p, "clusters").as_f64(), Some(clusters as f64));
    }
    let plain = set.dbscan_sweep(&grid[..1], &[2], None).unwrap();
    assert!(get(&js_sys::Array::from(&plain).get(0), "ari").is_null());
    let names = js_sys::JSON::parse(r#"{"0": "first", "1": "second"}"#).unwrap();
    let model = set.build_model(&labels, names).unwrap();
    let json = model.to_json().unwrap();
    let again = Model::from_json(&json).unwrap();
    assert_eq!(again.to_json().unwrap(), json);
    // A scan of the set is classified into its own cluster, at distance <= radius.
    let c = again.classify(&scans[0]).unwrap();
    assert_eq!(get(&c, "label").as_f64(), Some(labels[0] as f64));
    assert!(get(&c, "relative").as_f64().unwrap() <= 1.0 + 1e-6);
    let cats = again.categories().unwrap();
    assert_eq!(js_sys::Array::from(&cats).length(), 5);
    let poses = parse_poses(
        "0 0 0 1 0 0 0 1\n1 2 0 1 0 0 0.7071068 0.7071068\n",
        Some("p.txt".into()),
    )
    .unwrap();
    assert_eq!(get(&poses, "format").as_string().as_deref(), Some("tum"));
}

#[wasm_bindgen_test]
fn wrong_arguments_throw_errors_naming_the_problem_and_the_module_stays_usable() {
    let e = message(
        describe_scan(
            u8a(b"ply\nformat ascii 1.0\nelement vertex 3\n"),
            "bad.ply",
            None,
            None,
            None,
        )
        .err()
        .unwrap(),
    );
    assert!(e.contains("bad.ply") && e.contains("end_header"), "{e}");
    let e = message(
        describe_scan(u8a(&[1, 2, 3]), "odd.bin", None, None, None)
            .err()
            .unwrap(),
    );
    assert!(e.contains("odd.bin") && e.contains("16-byte"), "{e}");
    let e = message(preset_params("attic").err().unwrap());
    assert!(e.contains("attic"), "{e}");
    // Every preset has its note, and the presets with parts carry them.
    let notes: js_sys::Array = preset_notes().unwrap().unchecked_into();
    assert_eq!(notes.length() as usize, placecat::descriptor::PRESETS.len());
    assert_eq!(notes.length(), 15);
    let hellinger = js_sys::JSON::stringify(&preset_params("outdoor_hellinger").unwrap()).unwrap();
    assert!(String::from(hellinger).contains("\"metric\":\"hellinger\""));
    let warehouse = js_sys::JSON::stringify(&preset_params("warehouse").unwrap()).unwrap();
    assert!(String::from(warehouse).contains("\"slice\""));
    let clutter = js_sys::JSON::stringify(&preset_params("indoor_clutter").unwrap()).unwrap();
    assert!(String::from(clutter).contains("\"clutter\""));
    let columns = js_sys::JSON::stringify(&preset_params("indoor_columns").unwrap()).unwrap();
    assert!(String::from(columns).contains("\"columns\""));
    let searched = js_sys::JSON::stringify(&preset_params("indoor_searched").unwrap()).unwrap();
    assert!(String::from(searched).contains("\"iron\""));
    let objects = js_sys::JSON::stringify(&preset_params("indoor_objects").unwrap()).unwrap();
    assert!(String::from(objects).contains("\"objects\""));
    let types = js_sys::JSON::stringify(&preset_params("indoor_object_types").unwrap()).unwrap();
    let types = String::from(types);
    assert!(types.contains("\"object_types\"") && types.contains("\"object_layout\""));
    // Withdrawn by the twenty-seventh round, and said so; the others not.
    let withdrawn: Vec<String> = (notes.iter())
        .filter(|n| js_sys::Reflect::get(n, &"withdrawn".into()).unwrap() == true)
        .map(|n| {
            js_sys::Reflect::get(&n, &"name".into())
                .unwrap()
                .as_string()
                .unwrap()
        })
        .collect();
    assert_eq!(withdrawn, ["indoor_object_types"]);
    let bad = js_sys::JSON::parse(r#"{"voxel_size": -2}"#).unwrap();
    let e = message(validate_params(bad, None).err().unwrap());
    assert!(e.contains("voxel_size"), "{e}");
    let typo = js_sys::JSON::parse(r#"{"voxel_sise": 2}"#).unwrap();
    assert!(message(validate_params(typo, None).err().unwrap()).contains("voxel_sise"));
    let (mut set, scans) = real_set();
    // A descriptor of the outdoor preset (5 ranges) into an indoor set (7):
    // named as made with other parameters, the ranges, before its shape;
    // and one whose counts are cut short.
    let outdoor = describe_scan(
        u8a(PARITY_FILES[0].1),
        "o.bin",
        None,
        Some("outdoor".into()),
        None,
    )
    .unwrap();
    let e = message(set.add(&outdoor).err().unwrap());
    assert!(
        e.contains("o.bin: ")
            && e.contains("other parameters than the collection's (ranges: [[5.0,8.0],"),
        "{e}"
    );
    // Its bare JSON carries no parameters: refused by its shape.
    let e = message(
        set.add_json(&outdoor.descriptor_json().unwrap())
            .err()
            .unwrap(),
    );
    assert!(
        e.contains("the descriptor is 11x5, the set's parameters make 11x7"),
        "{e}"
    );
    // Same shape, other parameters (a coarser voxel): refused by the set
    // and by a model, naming the scan and the field.
    let coarse = js_sys::JSON::parse(r#"{"voxel_size": 1.2}"#).unwrap();
    let other = describe_scan(
        u8a(PARITY_FILES[0].1),
        "coarse.bin",
        Some(coarse),
        Some("indoor".into()),
        None,
    )
    .unwrap();
    let e = message(set.add(&other).err().unwrap());
    assert!(
        e.contains("coarse.bin: ")
            && e.contains(
                "other parameters than the collection's (voxel_size: 1.2 against the expected 0.4)"
            ),
        "{e}"
    );
    let labels = [0, 0, 1, 1, 1, 1];
    let names = js_sys::JSON::parse(r#"{"0": "a", "1": "b"}"#).unwrap();
    let model = set.build_model(&labels, names).unwrap();
    assert!(model.classify(&scans[0]).is_ok());
    let e = message(model.classify(&other).err().unwrap());
    assert!(
        e.contains("coarse.bin: ") && e.contains("the model's (voxel_size: 1.2"),
        "{e}"
    );
    // The same check for descriptors given as bare JSON, on the parameters
    // alone.
    let coarse = js_sys::JSON::parse(r#"{"preset": "indoor", "voxel_size": 1.2}"#).unwrap();
    let e = message(model.check_made_with(coarse).err().unwrap());
    assert!(
        e.contains("the model's (voxel_size: 1.2 against the expected 0.4)"),
        "{e}"
    );
    let indoor = js_sys::JSON::parse(r#"{"preset": "indoor"}"#).unwrap();
    assert!(model.check_made_with(indoor).is_ok());
    let json = scans[0].descriptor_json().unwrap();
    let cut = json.replacen(",0,", ",", 1);
    let e = message(set.add_json(&cut).err().unwrap());
    assert!(e.contains("rows x cols = 11 x 7"), "{e}");
    let e = message(set.kmeans(0.0, "stride", 0.0, None).err().unwrap());
    assert!(e.contains("k must be at least 1"), "{e}");
    assert!(message(set.kmeans(2.0, "sideways", 0.0, None).err().unwrap()).contains("sideways"));
    // Counts are whole numbers: 2.5 is not taken as 2, nor -1 as 4294967295.
    let e = message(set.kmeans(2.5, "stride", 0.0, None).err().unwrap());
    assert!(e.contains("k must be a whole number, got 2.5"), "{e}");
    let e = message(set.kmedoids(-1.0, 0.0).err().unwrap());
    assert!(e.contains("k must be a whole number, got -1.0"), "{e}");
    let e = message(set.spectral(2.0, 0.0, Some(0.5), None).err().unwrap());
    assert!(
        e.contains("restarts must be a whole number, got 0.5"),
        "{e}"
    );
    let e = message(set.spectral(2.0, 0.0, None, Some(0.0)).err().unwrap());
    assert!(e.contains("neighbours must be at least 1"), "{e}");
    let e = message(set.dbscan(0.5, 1.5).err().unwrap());
    assert!(
        e.contains("minPoints must be a whole number, got 1.5"),
        "{e}"
    );
    let e = message(set.kmeans(1e300, "stride", 0.0, None).err().unwrap());
    assert!(e.contains("k = 1e300 is more than any set holds"), "{e}");
    // Seeds too: -1 is not taken as 4294967295, nor 2^32 as 0, nor 2.5 as 2;
    // seeds beyond 32 bits up to 2^53 - 1 are the CLI's --seed of that number.
    for bad in [-1.0, 2.5, f64::NAN, 9_007_199_254_740_992.0] {
        let e = message(set.kmeans(2.0, "stride", bad, None).err().unwrap());
        assert!(
            e.contains("seed must be a whole number from 0 to 2^53 - 1, got"),
            "{e}"
        );
        assert!(set.hkmeans(bad, None).is_err() && set.kmedoids(2.0, bad).is_err());
    }
    let wide = set.hkmeans(4_294_967_296.0, None).unwrap();
    let e = message(
        set.choose_categories_with(&wide, &[], 0.0, None)
            .err()
            .unwrap(),
    );
    assert!(
        e.contains("this tree's: seed 4294967296, restarts 1"),
        "{e}"
    );
    assert!(message(
        Simulator::new("indoor", -1.0, None, None, None)
            .err()
            .unwrap()
    )
    .contains("seed"));
    assert!(message(
        Simulator::new("indoor", 1.0, Some(2.5), None, None)
            .err()
            .unwrap()
    )
    .contains("scans must be a whole number, got 2.5"));
    assert!(message(set.dbscan(-1.0, 2.0).err().unwrap()).contains("epsilon"));
    assert!(message(set.dbscan_sweep(&[], &[2], None).err().unwrap()).contains("at least one"));
    assert!(message(
        set.dbscan_sweep(&[0.5], &[2], Some(vec!["a".into()]))
            .err()
            .unwrap()
    )
    .contains("ground-truth"));
    assert!(message(Model::from_json("{\"format\": 1}").err().unwrap()).starts_with("model:"));
    assert!(message(Simulator::new("moon", 0.0, None, None, None).err().unwrap()).contains("moon"));
    let e = message(
        Simulator::new("indoor", 0.0, None, Some("few".into()), None)
            .err()
            .unwrap(),
    );
    assert!(e.contains("few") && e.contains("one, many"), "{e}");
    // Still usable after the errors.
    assert_eq!(
        labels_of(&set.kmeans(2.0, "stride", 0.0, None).unwrap()).len(),
        6
    );
}

/// The corpus of damaged scans gives, in wasm32, exactly the messages the
/// native test (tests/it/bad_files.rs) checks: strict through the JS API's
/// readScan (a JS Error), lenient through the core compiled to wasm32.
#[wasm_bindgen_test]
fn damaged_files_give_the_native_messages() {
    let wrong = bad_mismatches(|bytes, name, lenient| {
        if lenient {
            let limits = placecat::io::ReadLimits {
                lenient,
                ..Default::default()
            };
            bad_outcome(placecat::io::read_scan_named(bytes, name, &limits).map(|c| c.points.len()))
        } else {
            bad_outcome(
                read_scan(u8a(bytes), name)
                    .map(|s| s.count())
                    .map_err(message),
            )
        }
    });
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Bytes come as a Uint8Array, a view into a larger buffer, or an
/// ArrayBuffer (what `File.arrayBuffer()` gives): the same points and the
/// same descriptor each way. Anything else is an Error naming the file.
#[wasm_bindgen_test]
fn bytes_as_array_buffer_or_uint8array_read_the_same() {
    let (name, bytes) = PARITY_FILES[0];
    let want = placecat::io::read_scan_named(bytes, name, &Default::default())
        .unwrap()
        .points
        .len();
    assert_eq!(want, 6156, "16 bytes a point");
    let buffer: JsValue = js_sys::Uint8Array::from(bytes).buffer().into();
    assert!(buffer.is_instance_of::<js_sys::ArrayBuffer>());
    // The same bytes 16 bytes into a bigger buffer, as a view.
    let padded = js_sys::Uint8Array::new_with_length(bytes.len() as u32 + 32);
    padded
        .subarray(16, 16 + bytes.len() as u32)
        .copy_from(bytes);
    let view: JsValue = padded.subarray(16, 16 + bytes.len() as u32).into();
    for b in [u8a(bytes), buffer.clone(), view.clone()] {
        let s = read_scan(b, name).unwrap();
        assert_eq!((s.count(), s.format().as_str()), (want, "kitti_bin"));
    }
    let json = |b: JsValue| {
        describe_scan(b, name, None, Some("outdoor".into()), Some(0))
            .unwrap()
            .descriptor_json()
            .unwrap()
    };
    let from_u8 = json(u8a(bytes));
    assert_eq!(json(buffer), from_u8);
    assert_eq!(json(view), from_u8);
    // Not bytes: the message names the file and what came instead.
    let e = message(
        read_scan(JsValue::from_str("scan_000.bin"), "000094.bin")
            .err()
            .unwrap(),
    );
    assert_eq!(
        e,
        "000094.bin: the bytes must be a Uint8Array or an ArrayBuffer, not a string"
    );
    let e = message(
        describe_scan(JsValue::UNDEFINED, "a.ply", None, None, None)
            .err()
            .unwrap(),
    );
    assert!(
        e.starts_with("a.ply: ") && e.ends_with("not undefined"),
        "{e}"
    );
    let floats: JsValue = js_sys::Float32Array::new_with_length(6).into();
    let e = message(read_scan(floats, "pts").err().unwrap());
    assert!(
        e.contains("not Float32Array") && e.contains("describePoints"),
        "{e}"
    );
}

/// Points already in memory describe exactly as the file they came from,
/// under the name given; a length that is not whole points is an Error
/// naming the scan.
#[wasm_bindgen_test]
fn describe_points_matches_the_file_and_names_the_scan() {
    let (name, bytes) = PARITY_FILES[3];
    let file = describe_scan(u8a(bytes), name, None, None, Some(500)).unwrap();
    let xyz = read_scan(u8a(bytes), name).unwrap().positions().to_vec();
    assert_eq!(xyz.len(), 3 * 112586);
    let mem = describe_points(&xyz, "room in memory", None, None, Some(500)).unwrap();
    assert_eq!(mem.name(), "room in memory");
    assert_eq!(mem.format(), "points");
    assert_eq!(
        mem.descriptor_json().unwrap(),
        file.descriptor_json().unwrap()
    );
    assert_eq!(mem.preview().to_vec(), file.preview().to_vec());
    let summary = mem.summary().unwrap();
    assert_eq!(get(&summary, "points").as_f64(), Some(112586.0));
    // In a set beside the file's: Delta 0 between them.
    let mut set = DescriptorSet::new(JsValue::UNDEFINED, None).unwrap();
    set.add(&file).unwrap();
    set.add(&mem).unwrap();
    assert_eq!(set.delta(0, 1).unwrap(), 0.0);
    // A point moved by a metre changes the descriptor.
    let mut moved = xyz.clone();
    for v in moved.iter_mut().step_by(3).take(20000) {
        *v += 1.0;
    }
    let other = describe_points(&moved, "moved", None, None, None).unwrap();
    assert_ne!(
        other.descriptor_json().unwrap(),
        file.descriptor_json().unwrap()
    );
    let e = message(
        describe_points(&xyz[..10], "ten.xyz", None, None, None)
            .err()
            .unwrap(),
    );
    assert_eq!(
        e,
        "ten.xyz: invalid parameter: the points must be flat x, y, z triples, \
         but 10 numbers is not a multiple of 3"
    );
    let bad = js_sys::JSON::parse(r#"{"voxel_size": 0}"#).unwrap();
    let e = message(
        describe_points(&xyz, "room", Some(bad), None, None)
            .err()
            .unwrap(),
    );
    assert!(e.contains("voxel_size"), "{e}");
}

/// A bag's bytes served a range at a time by a JS function, as a worker
/// serves them from `File.slice`; the ranges asked for are recorded.
fn bag_reader(
    bytes: &'static [u8],
    asked: std::rc::Rc<std::cell::RefCell<Vec<(f64, f64)>>>,
) -> js_sys::Function {
    let read =
        Closure::<dyn FnMut(f64, f64) -> js_sys::Uint8Array>::new(move |offset: f64, len: f64| {
            asked.borrow_mut().push((offset, len));
            let (o, n) = (offset as usize, len as usize);
            js_sys::Uint8Array::from(&bytes[o..o + n])
        });
    read.into_js_value().unchecked_into()
}

/// The E57 survey of tests/data/survey (written by pye57, see
/// make_survey.py): four stations, read a range at a time and described
/// with their poses, as the CLI's describe names and places them; the
/// ranges asked for are few and within the file; a file that is no E57
/// is refused naming it.
#[wasm_bindgen_test]
fn an_e57_survey_streams_through_a_read_function_into_described_stations_with_poses() {
    const SURVEY: &[u8] = include_bytes!("../data/survey/survey.e57");
    let asked = std::rc::Rc::new(std::cell::RefCell::new(Vec::new()));
    let size = SURVEY.len() as f64;
    let mut scans = E57Scans::new(
        size,
        bag_reader(SURVEY, asked.clone()),
        "survey.e57",
        None,
        None,
        Some(100),
    )
    .unwrap();
    assert_eq!((scans.total(), scans.met()), (4.0, 0.0));
    let mut got = Vec::new();
    while let Some(d) = scans.next_scan().unwrap() {
        let pose = d.pose().unwrap();
        let position: Vec<f64> = serde_wasm_bindgen::from_value(get(&pose, "position")).unwrap();
        let points = get(&d.summary().unwrap(), "points").as_f64().unwrap();
        assert_eq!(d.format(), "e57");
        assert!(d.preview().length() <= 300);
        got.push((d.name(), points, position));
    }
    assert_eq!(scans.met(), 4.0);
    let want = [
        ("survey.e57:hall", 900.0, [0.0, 0.0, 0.0]),
        ("survey.e57:office", 690.0, [10.0, 2.0, 0.5]),
        ("survey.e57:hall (scan 2)", 500.0, [-4.0, 6.0, 1.2]),
        ("survey.e57:store", 400.0, [3.0, -7.0, 0.0]),
    ];
    let want: Vec<(String, f64, Vec<f64>)> = want
        .iter()
        .map(|(n, p, x)| (n.to_string(), *p, x.to_vec()))
        .collect();
    assert_eq!(got, want);
    // Read ahead a block at a time: a 45 kB survey is one or two calls.
    let asked = asked.borrow();
    assert!(asked.len() <= 4, "{asked:?}");
    assert!(asked.iter().all(|&(o, n)| o + n <= size), "{asked:?}");
    let las = include_bytes!("../data/survey/las12_fmt0.las");
    let e = message(
        E57Scans::new(
            las.len() as f64,
            bag_reader(las, Default::default()),
            "x.e57",
            None,
            None,
            None,
        )
        .err()
        .unwrap(),
    );
    assert!(e.starts_with("x.e57: E57: "), "{e}");
    // A read that throws (a File gone from the disk) is an I/O error inside
    // the E57 reader's message, with the call and the JS message, under
    // one "E57:" prefix.
    let throws = Closure::<dyn Fn(f64, f64) -> Result<JsValue, JsValue>>::new(|_: f64, _: f64| {
        Err(js_sys::Error::new("the file is gone").into())
    });
    let e = message(
        E57Scans::new(
            size,
            throws.into_js_value().unchecked_into(),
            "gone.e57",
            None,
            None,
            None,
        )
        .err()
        .unwrap(),
    );
    assert!(e.starts_with("gone.e57: E57: "), "{e}");
    assert!(e.contains("threw: the file is gone"), "{e}");
    assert!(
        !e.contains("E57: E57:") && e.contains("I/O: read(0, "),
        "{e}"
    );
}

/// The corridor bag (written by the Python `rosbags` package, see
/// tests/data/bags/make_bags.py): its topics, then its two clouds of 2700
/// points each described with their odometry poses and names.
#[wasm_bindgen_test]
fn a_bag_streams_through_a_read_function_into_described_clouds_with_poses() {
    const BAG: &[u8] = include_bytes!("../data/bags/ros1_corridor.bag");
    let asked = std::rc::Rc::new(std::cell::RefCell::new(Vec::new()));
    let size = BAG.len() as f64;
    let topics = bag_topics(size, bag_reader(BAG, asked.clone()), "ros1_corridor.bag").unwrap();
    let topics: Vec<(String, String, u64)> = js_sys::Array::from(&topics)
        .iter()
        .map(|t| {
            let s = |k| get(&t, k).as_string().unwrap();
            (
                s("name"),
                s("type"),
                get(&t, "count").as_f64().unwrap() as u64,
            )
        })
        .collect();
    assert_eq!(
        topics,
        [
            ("/odom".into(), "nav_msgs/Odometry".into(), 2),
            ("/points".into(), "sensor_msgs/PointCloud2".into(), 2)
        ]
    );
    asked.borrow_mut().clear();
    let mut clouds = BagClouds::new(
        size,
        bag_reader(BAG, asked.clone()),
        "ros1_corridor.bag",
        None,
        None,
        None,
        None,
        Some(100),
        None,
    )
    .unwrap();
    assert_eq!((clouds.topic().as_str(), clouds.total()), ("/points", 2.0));
    let mut got = Vec::new();
    while let Some(d) = clouds.next_cloud().unwrap() {
        let pose = d.pose().unwrap();
        let position: Vec<f64> = serde_wasm_bindgen::from_value(get(&pose, "position")).unwrap();
        let summary = d.summary().unwrap();
        assert_eq!(get(&summary, "points").as_f64(), Some(2700.0));
        assert_eq!(d.format(), "ros_bag");
        assert!(d.preview().length() <= 300);
        got.push((d.name(), position));
    }
    assert_eq!(clouds.met(), 2.0);
    assert_eq!(
        got,
        [
            (
                "ros1_corridor.bag:/points:000000".to_string(),
                vec![0.0, 0.0, 0.0]
            ),
            (
                "ros1_corridor.bag:/points:000001".to_string(),
                vec![0.5, 0.25, 0.0]
            )
        ]
    );
    // One cloud a metre: the second cloud is 0.56 m on, so it goes (as
    // `--every-metres 1` in the CLI); half a metre keeps both.
    let kept = |metres: f64| {
        let mut c = BagClouds::new(
            size,
            bag_reader(BAG, Default::default()),
            "ros1_corridor.bag",
            None,
            None,
            None,
            None,
            Some(10),
            Some(metres),
        )
        .unwrap();
        let mut names = Vec::new();
        while let Some(d) = c.next_cloud().unwrap() {
            names.push(d.name());
        }
        names
    };
    assert_eq!(kept(1.0), ["ros1_corridor.bag:/points:000000"]);
    assert_eq!(kept(0.5).len(), 2);
    // Read in ranges, never past the end.
    let asked = asked.borrow();
    assert!(!asked.is_empty());
    assert!(
        asked.iter().all(|&(o, n)| n > 0.0 && o + n <= size),
        "{asked:?}"
    );
    // A bag with two cloud topics names them; a read function that lies is
    // an Error naming the bag; a file that is not a bag says so.
    const TWO: &[u8] = include_bytes!("../data/bags/two_cloud_topics.bag");
    let e = message(
        BagClouds::new(
            TWO.len() as f64,
            bag_reader(TWO, Default::default()),
            "two.bag",
            None,
            None,
            None,
            None,
            None,
            None,
        )
        .err()
        .unwrap(),
    );
    assert!(e.starts_with("two.bag: ") && e.contains("/points"), "{e}");
    let short: js_sys::Function =
        Closure::<dyn FnMut(f64, f64) -> js_sys::Uint8Array>::new(|_: f64, _: f64| {
            js_sys::Uint8Array::new_with_length(3)
        })
        .into_js_value()
        .unchecked_into();
    let e = message(bag_topics(size, short, "short.bag").err().unwrap());
    assert!(
        e.starts_with("short.bag: ") && e.contains("returned 3 bytes"),
        "{e}"
    );
    let e = message(
        bag_topics(
            PARITY_FILES[3].1.len() as f64,
            bag_reader(PARITY_FILES[3].1, Default::default()),
            "room.pcd",
        )
        .err()
        .unwrap(),
    );
    assert!(
        e.starts_with("room.pcd: ") && e.contains("not a ROS bag"),
        "{e}"
    );
}
