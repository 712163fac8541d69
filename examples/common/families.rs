//! The scene families and sensors of issue 18's evaluation, shared by
//! every example of its rounds (from `examples/descriptors.rs`, rounds
//! 1-3, to the searches and the development looks).

use placecat::sim::{Buildings, LidarParams, SceneKind, SimParams};

/// Scans along a route here (a third of `placecat simulate`'s 300, to keep
/// the run near 15 minutes on a shared machine).
pub const ROUTE_SCANS: usize = 100;
/// Indoor: scans per kind and per room.
pub const KIND_SCANS: usize = 9;
pub const ROOM_SCANS: usize = 3;

/// A scene family: how to simulate it from a seed, and the paper preset
/// it is compared with.
#[derive(Clone)]
pub struct Family {
    pub name: &'static str,
    pub scene: SceneKind,
    pub buildings: Buildings,
    /// Indoor: scans per kind; routes: scans along the route.
    pub scans: usize,
    pub scans_per_room: usize,
    pub paper: &'static str,
    /// The other sensors it is run with, besides its own.
    pub sensors: &'static [Sensor],
    /// Room scenes: list the scans in a random order (`SimParams.shuffle`;
    /// from the twentieth round, docs/stride-order.md). The families here
    /// list them kind by kind, as every earlier round ran them.
    pub shuffle: bool,
}

/// A sensor variant: a beam count or a height, else the scene's own.
#[derive(Clone, Copy)]
pub enum Sensor {
    Own,
    Beams(usize),
    Height(f64),
}

impl Sensor {
    pub fn name(self) -> String {
        match self {
            Sensor::Own => "own".into(),
            Sensor::Beams(b) => format!("{b} beams"),
            Sensor::Height(h) => format!("at {h} m"),
        }
    }
}

/// The whole sensor grid, for the family written last (the school).
pub const ALL_SENSORS: &[Sensor] = &[
    Sensor::Beams(16),
    Sensor::Beams(32),
    Sensor::Beams(64),
    Sensor::Height(0.3),
    Sensor::Height(1.8),
];
/// Subsamples of the grid for the other families, to keep the run's
/// time: the sparsest sensor, the lowest mount.
pub const SPARSE_SENSOR: &[Sensor] = &[Sensor::Beams(16)];
pub const LOW_SENSOR: &[Sensor] = &[Sensor::Height(0.3)];
/// The warehouse also with the 32-beam sensor of issue 18's table.
pub const WAREHOUSE_SENSORS: &[Sensor] = &[Sensor::Beams(32)];

/// The families. Scan counts are smaller than `placecat simulate`'s
/// defaults (indoor 12 a kind in rooms of 3, routes 150 scans) to keep the
/// whole run near 15 minutes on a shared two-core machine.
pub fn families() -> Vec<Family> {
    let indoor = |name, buildings| Family {
        name,
        scene: SceneKind::Indoor,
        buildings,
        scans: KIND_SCANS,
        scans_per_room: ROOM_SCANS,
        paper: "indoor",
        sensors: SPARSE_SENSOR,
        shuffle: false,
    };
    vec![
        Family {
            sensors: &[],
            ..indoor("indoor (one building)", Buildings::One)
        },
        indoor("indoor (many buildings)", Buildings::Many),
        Family {
            sensors: &[],
            ..indoor("indoor (varied plans)", Buildings::Varied)
        },
        Family {
            scene: SceneKind::OfficeFloor,
            sensors: LOW_SENSOR,
            ..indoor("office floor", Buildings::One)
        },
        Family {
            scene: SceneKind::School,
            sensors: ALL_SENSORS,
            ..indoor("school (fresh)", Buildings::One)
        },
        Family {
            name: "warehouse",
            scene: SceneKind::Warehouse,
            buildings: Buildings::One,
            scans: ROUTE_SCANS,
            scans_per_room: 1,
            paper: "indoor",
            sensors: WAREHOUSE_SENSORS,
            shuffle: false,
        },
        Family {
            name: "outdoor",
            scene: SceneKind::Outdoor,
            buildings: Buildings::One,
            scans: ROUTE_SCANS,
            scans_per_room: 1,
            paper: "outdoor",
            sensors: SPARSE_SENSOR,
            shuffle: false,
        },
    ]
}

/// The hospital ward floors (`--scene hospital`), written for issue 18's
/// eighth round by another hand, built as the school's entry: kept out of
/// [`families`] so that the rounds before it run the families they ran
/// (and none of their examples uses it).
#[allow(dead_code)]
pub fn hospital_family() -> Family {
    Family {
        name: "hospital (fresh)",
        scene: SceneKind::Hospital,
        buildings: Buildings::One,
        scans: KIND_SCANS,
        scans_per_room: ROOM_SCANS,
        paper: "indoor",
        sensors: SPARSE_SENSOR,
        shuffle: false,
    }
}

/// The hotel floors (`--scene hotel`), written for issue 18's
/// twenty-third round by another hand after every preset and method it
/// judges existed; run on the school's whole sensor grid. Only that
/// round's example uses it.
#[allow(dead_code)]
pub fn hotel_family() -> Family {
    Family {
        name: "hotel (fresh)",
        scene: SceneKind::Hotel,
        sensors: ALL_SENSORS,
        ..hospital_family()
    }
}

/// The shopping-mall floors (`--scene mall`), written for issue 18's
/// twenty-fourth round by another hand after the twenty-third round's
/// figures, on the hotel's sensor grid. Only that round's example uses it.
#[allow(dead_code)]
pub fn mall_family() -> Family {
    Family {
        name: "mall (fresh)",
        scene: SceneKind::Mall,
        ..hotel_family()
    }
}

/// The residential floors (`--scene home`), written for issue 18's
/// twenty-fifth round by another hand after the twenty-fourth round's
/// figures, on the hotel's sensor grid. Only that round's example uses it.
#[allow(dead_code)]
pub fn home_family() -> Family {
    Family {
        name: "home (fresh)",
        scene: SceneKind::Home,
        ..hotel_family()
    }
}

/// The research-institute floors (`--scene institute`), written for
/// issue 18's twenty-sixth round by another hand after the twenty-fifth
/// round's figures, on the hotel's sensor grid. That round's example and
/// the kinds look use it.
#[allow(dead_code)]
pub fn institute_family() -> Family {
    Family {
        name: "institute (fresh)",
        scene: SceneKind::Institute,
        ..hotel_family()
    }
}

/// The sports-centre fitness floors (`--scene gym`), written for issue
/// 18's twenty-seventh round by another hand, who chose the building and
/// its kinds, on the hotel's sensor grid. That round's example and the
/// kinds look use it.
#[allow(dead_code)]
pub fn gym_family() -> Family {
    Family {
        name: "gym (fresh)",
        scene: SceneKind::Gym,
        ..hotel_family()
    }
}

/// The room rows of issue 18's rounds 9-16: every family with rooms (the
/// hospital floors last) with its own sensor, then each of its others.
#[allow(dead_code)]
pub fn room_rows() -> Vec<(Family, Sensor)> {
    (families().into_iter().chain([hospital_family()]))
        .filter(|f| f.scans_per_room > 1)
        .flat_map(sensor_rows)
        .collect()
}

/// A family's rows: with its own sensor, then each of its others.
#[allow(dead_code)]
pub fn sensor_rows(f: Family) -> Vec<(Family, Sensor)> {
    (std::iter::once(Sensor::Own).chain(f.sensors.iter().copied()))
        .map(|s| (f.clone(), s))
        .collect()
}

pub fn sim_params(f: &Family, sensor: Sensor, seed: u64) -> placecat::Result<SimParams> {
    let mut p = SimParams::new(f.scene, seed);
    p.buildings = f.buildings;
    p.scans = f.scans;
    p.scans_per_room = f.scans_per_room;
    p.shuffle = f.shuffle;
    match sensor {
        Sensor::Own => {}
        Sensor::Beams(b) => p.lidar = Some(LidarParams::with_beams(b)?),
        Sensor::Height(h) => p.sensor_height = Some(h),
    }
    Ok(p)
}

/// A share in % with one decimal; `n/a` where the preset could not
/// describe the scans.
pub fn pct(x: f64) -> String {
    if x.is_nan() {
        "n/a".into()
    } else {
        format!("{:.1}", 100.0 * x)
    }
}

/// A JSON file of the examples' results, with its path in the error.
pub fn read_json<T: serde::de::DeserializeOwned>(
    path: &std::path::Path,
) -> Result<T, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()).into())
}
