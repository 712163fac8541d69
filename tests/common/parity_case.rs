// Shared by tests/it/parity.rs (native) and tests/wasm_api (wasm), kept out of
// tests/ itself so cargo does not build it as a test of its own: the same
// inputs and seeds must give the same labels on both. Included with
// `include!`, so it has no module of its own.

/// Real scans embedded at compile time (the harness reads them, then
/// passes the bytes in).
pub const PARITY_FILES: [(&str, &[u8]); 6] = [
    (
        "scan_000.bin",
        include_bytes!("../data/real/ouster_os0_sequence/scan_000.bin"),
    ),
    (
        "scan_005.bin",
        include_bytes!("../data/real/ouster_os0_sequence/scan_005.bin"),
    ),
    (
        "scan_009.bin",
        include_bytes!("../data/real/ouster_os0_sequence/scan_009.bin"),
    ),
    (
        "room_scan1.pcd",
        include_bytes!("../data/real/pcl_room/room_scan1.pcd"),
    ),
    (
        "room_scan2.pcd",
        include_bytes!("../data/real/pcl_room/room_scan2.pcd"),
    ),
    (
        "251370668.pcd",
        include_bytes!("../data/real/velodyne_pair/251370668.pcd"),
    ),
];

/// Labels from every method on the real files plus a small simulated set.
pub fn parity_case() -> serde_json::Value {
    use placecat::cluster::hkmeans::HkMeansParams;
    use placecat::cluster::*;
    use placecat::sim::{SceneKind, SimParams, Simulation};
    use placecat::*;
    let params = DescriptorParams::indoor();
    let mut ds: Vec<Descriptor> = PARITY_FILES
        .iter()
        .map(|(name, bytes)| {
            describe(
                &io::read_scan(bytes, name, &Default::default())
                    .unwrap()
                    .points,
                &params,
            )
            .unwrap()
        })
        .collect();
    let mut sp = SimParams::new(SceneKind::Indoor, 7);
    sp.scans = 2;
    let sim = Simulation::new(&sp).unwrap();
    let mut sim_points = 0usize;
    for i in 0..sim.len() {
        let s = sim.scan(i);
        sim_points += s.points.len();
        ds.push(describe(&s.points, &params).unwrap());
    }
    let opts = DistanceOptions::from(&params);
    let space = Space::new(&ds, opts).unwrap();
    let m = delta_matrix(&ds, opts).unwrap();
    let km = |s: Seeding| {
        KMeans::fit(&space, &KMeansParams::new(4).seeding(s).seed(3))
            .unwrap()
            .labels
    };
    let tree = HierarchicalKMeans::fit(&space, &m, &HkMeansParams::new(3)).unwrap();
    serde_json::json!({
        "sim_points": sim_points,
        "totals": ds.iter().map(|d| d.total()).collect::<Vec<_>>(),
        "kmeans_random": km(Seeding::Random),
        "kmeans_stride": km(Seeding::Stride),
        "kmeans_plusplus": km(Seeding::PlusPlus),
        "hkmeans_cut4": tree.cut_k(4).unwrap().labels,
        "dbscan": Dbscan::fit(&m, &DbscanParams::new(0.5, 2)).unwrap(),
        "spectral_k4": Spectral::fit(&m, &SpectralParams::new(4).seed(3)).unwrap().labels,
    })
}
