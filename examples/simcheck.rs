use placecat::cluster::*;
use placecat::sim::*;
use placecat::*;
fn main() {
    let preset = std::env::args().nth(1).unwrap_or("indoor".into());
    let seed: u64 = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1);
    let mut p = SimParams::new(SceneKind::Indoor, seed);
    if let Ok(b) = std::env::var("BEAMS") {
        let mut l = LidarParams::indoor();
        l.beams = b.parse().unwrap();
        p.lidar = Some(l);
    }
    let sim = Simulation::new(&p).unwrap();
    let mut params = DescriptorParams::preset(&preset).unwrap();
    if let Ok(j) = std::env::var("OVR") {
        let mut v = serde_json::to_value(&params).unwrap();
        let o: serde_json::Value = serde_json::from_str(&j).unwrap();
        for (k, x) in o.as_object().unwrap() {
            v[k] = x.clone();
        }
        params = serde_json::from_value(v).unwrap();
    }
    let t = std::time::Instant::now();
    let (ds, truth): (Vec<Descriptor>, Vec<String>) = (0..sim.len())
        .map(|i| {
            let s = sim.scan(i);
            (describe(&s.points, &params).unwrap(), s.label)
        })
        .unzip();
    println!("sim+describe {:?}", t.elapsed());
    let opts = DistanceOptions::from(&params);
    let space = Space::new(&ds, opts).unwrap();
    let m = delta_matrix(&ds, opts).unwrap();
    // leave-one-out NN
    let nn = (0..m.n)
        .filter(|&i| {
            let j = (0..m.n)
                .filter(|&j| j != i)
                .min_by(|&a, &b| m.get(i, a).total_cmp(&m.get(i, b)))
                .unwrap();
            truth[j] == truth[i]
        })
        .count();
    println!("1-NN accuracy {:.3}", nn as f64 / m.n as f64);
    let km = KMeans::fit(&space, &KMeansParams::new(5).seeding(Seeding::Stride)).unwrap();
    let ev = eval::evaluate(&truth, &km.labels).unwrap();
    println!("stride kmeans acc {:.3} ari {:.3}", ev.accuracy, ev.ari);
    for (r, row) in ev.confusion.rows.iter().zip(&ev.confusion.rates) {
        println!(
            "  {r:12} {:?}",
            row.iter().map(|v| format!("{v:.2}")).collect::<Vec<_>>()
        );
    }
    let mut accs = vec![];
    for s in 0..10 {
        let tree = HierarchicalKMeans::fit(&space, &m, &hkmeans::HkMeansParams::new(s)).unwrap();
        let cut = tree.cut_k(5).unwrap();
        accs.push(eval::evaluate(&truth, &cut.labels).unwrap().accuracy);
    }
    let mean = accs.iter().sum::<f64>() / 10.0;
    println!(
        "hkmeans acc mean {:.3} {:?}",
        mean,
        accs.iter().map(|v| format!("{v:.2}")).collect::<Vec<_>>()
    );
    for s in 0..3 {
        let km = KMeans::fit(
            &space,
            &KMeansParams::new(5).seeding(Seeding::PlusPlus).seed(s),
        )
        .unwrap();
        println!(
            "pp seed {s} acc {:.3}",
            eval::evaluate(&truth, &km.labels).unwrap().accuracy
        );
    }
}
