//! Writes small seed files for the fuzzers (fuzz/seed-corpus.sh): one
//! simulated scan, decimated, in every format placecat reads; and the JSON
//! of its descriptor and of a model made from two scans.
use placecat::io::write::{self, PcdData, PlyEncoding};
use placecat::model::LabelledModel;
use placecat::sim::{SceneKind, SimParams, Simulation};
use placecat::{describe, DescriptorParams};

fn main() {
    let dir = std::path::PathBuf::from(std::env::args().nth(1).expect("corpus dir"));
    let sim = Simulation::new(&SimParams::new(SceneKind::Indoor, 1)).unwrap();
    let pts: Vec<[f32; 3]> = sim.scan(0).points.into_iter().step_by(200).collect();
    let put = |sub: &str, name: &str, bytes: Vec<u8>| {
        std::fs::write(dir.join(sub).join(name), bytes).unwrap()
    };
    for (name, enc, double) in [
        ("ascii.ply", PlyEncoding::Ascii, false),
        ("le.ply", PlyEncoding::BinaryLittleEndian, false),
        ("be_double.ply", PlyEncoding::BinaryBigEndian, true),
    ] {
        put("ply", name, write::ply(&pts, enc, double));
        let mut d = vec![1u8];
        d.extend(write::ply(&pts, enc, double));
        put("describe", name, d);
    }
    for (name, data) in [
        ("ascii.pcd", PcdData::Ascii),
        ("binary.pcd", PcdData::Binary),
        ("compressed.pcd", PcdData::BinaryCompressed),
    ] {
        put("pcd", name, write::pcd(&pts, data).unwrap());
        let mut d = vec![2u8];
        d.extend(write::pcd(&pts, data).unwrap());
        put("describe", name, d);
    }
    put("kitti", "sim.bin", write::kitti(&pts));
    let mut d = vec![0u8];
    d.extend(write::kitti(&pts));
    put("describe", "sim.bin", d);

    let params = DescriptorParams::indoor();
    let descriptors: Vec<_> = [0, 45]
        .iter()
        .map(|&i| describe(&sim.scan(i).points, &params).unwrap())
        .collect();
    put(
        "json",
        "descriptor.json",
        serde_json::to_vec(&descriptors[0]).unwrap(),
    );
    let names = [(0, "office".to_string()), (1, "kitchen".to_string())];
    let model = LabelledModel::build(&params, &descriptors, &[0, 1], &names).unwrap();
    put("json", "model.json", model.to_json().unwrap().into_bytes());
}
