//! A lidar simulator, to give placecat data with known ground truth: a
//! spinning multi-beam sensor ray-cast into procedurally generated scenes.
//!
//! - `indoor`: rooms of the five KyushuIndoor kinds (office, kitchen, lab,
//!   study room, corridor); several room instances per kind, several scans
//!   per room, each at a free spot with a random heading.
//! - `warehouse`: one trajectory through a small hall, an airlock and a large
//!   hall with pallet racks.
//! - `outdoor`: one trajectory over an open plain, along a forest road and
//!   down a forest path.

pub mod geometry;
pub mod lidar;
pub mod scenes;

pub use lidar::LidarParams;

use crate::error::{invalid, Result};
use crate::io::poses::Pose;
use rand::Rng;
use serde::{Deserialize, Serialize};

/// The scene kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SceneKind {
    Indoor,
    Warehouse,
    Outdoor,
}

impl std::str::FromStr for SceneKind {
    type Err = crate::Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "indoor" => Ok(SceneKind::Indoor),
            "warehouse" => Ok(SceneKind::Warehouse),
            "outdoor" => Ok(SceneKind::Outdoor),
            other => invalid(format!(
                "unknown scene {other:?} (indoor, warehouse, outdoor)"
            )),
        }
    }
}

/// What to simulate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimParams {
    pub scene: SceneKind,
    pub seed: u64,
    /// Indoor: scans per kind. Warehouse, outdoor: scans along the trajectory.
    pub scans: usize,
    /// Indoor: scans taken in each room instance.
    pub scans_per_room: usize,
    /// None: the scene's default sensor.
    pub lidar: Option<LidarParams>,
    /// Indoor: where the rooms come from.
    #[serde(default)]
    pub buildings: Buildings,
}

/// Where the simulated indoor rooms come from.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Buildings {
    /// A survey of one building: the rooms of a kind are built to one plan
    /// (sides within +-10 % of it) and differ in their furniture and where
    /// the sensor stands.
    #[default]
    One,
    /// Every room drawn afresh over its kind's whole size range, as if each
    /// came from another building: a harder set.
    Many,
}

impl std::str::FromStr for Buildings {
    type Err = crate::Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "one" => Ok(Buildings::One),
            "many" => Ok(Buildings::Many),
            other => invalid(format!("unknown buildings {other:?} (one, many)")),
        }
    }
}

impl SimParams {
    pub fn new(scene: SceneKind, seed: u64) -> Self {
        SimParams {
            scene,
            seed,
            scans: if scene == SceneKind::Indoor { 40 } else { 150 },
            scans_per_room: 5,
            lidar: None,
            buildings: Buildings::One,
        }
    }

    /// Total number of scans this will make.
    pub fn total(&self) -> usize {
        match self.scene {
            SceneKind::Indoor => self.scans * scenes::INDOOR_KINDS.len(),
            _ => self.scans,
        }
    }

    pub fn lidar(&self) -> LidarParams {
        self.lidar.clone().unwrap_or_else(|| match self.scene {
            SceneKind::Outdoor => LidarParams::outdoor(),
            _ => LidarParams::indoor(),
        })
    }

    pub fn validate(&self) -> Result<()> {
        if self.scans == 0 || self.scans > 100_000 {
            return invalid(format!("scans must be in 1..=100000, got {}", self.scans));
        }
        if self.scans_per_room == 0 {
            return invalid("scans_per_room must be at least 1");
        }
        self.lidar().validate()
    }
}

/// One simulated scan: points in the sensor frame, its pose and label.
#[derive(Debug, Clone, PartialEq)]
pub struct SimScan {
    pub name: String,
    pub label: String,
    pub pose: Pose,
    pub points: Vec<[f32; 3]>,
}

/// A plan of what to scan, cheap to make; scans are cast one at a time
/// with [`Simulation::scan`] so callers can show progress and keep memory
/// bounded by one scan.
pub struct Simulation {
    params: SimParams,
    lidar: LidarParams,
    /// (scene index, position, yaw, label)
    shots: Vec<(usize, [f64; 3], f64, String)>,
    scenes: Vec<Vec<geometry::Shape>>,
}

impl Simulation {
    pub fn new(params: &SimParams) -> Result<Simulation> {
        params.validate()?;
        let mut r = crate::rng::rng(params.seed);
        let mut scenes_out = Vec::new();
        let mut shots = Vec::new();
        match params.scene {
            SceneKind::Indoor => {
                for kind in scenes::INDOOR_KINDS {
                    let plan = scenes::room_size(kind, &mut r);
                    let mut left = params.scans;
                    while left > 0 {
                        let size = match params.buildings {
                            Buildings::One => scenes::room_from_plan(plan, &mut r),
                            Buildings::Many => scenes::room_size(kind, &mut r),
                        };
                        let room = scenes::indoor_room(kind, size, &mut r);
                        let take = left.min(params.scans_per_room);
                        for _ in 0..take {
                            let margin = if kind == "corridor" { 0.7 } else { 0.6 };
                            let p = scenes::free_position(&room, &mut r, margin);
                            let z = scenes::u(&mut r, 1.0, 1.3);
                            let yaw = r.random_range(0.0..std::f64::consts::TAU);
                            shots.push((scenes_out.len(), [p[0], p[1], z], yaw, kind.to_string()));
                        }
                        scenes_out.push(room.shapes);
                        left -= take;
                    }
                }
            }
            SceneKind::Warehouse | SceneKind::Outdoor => {
                let outdoor = params.scene == SceneKind::Outdoor;
                scenes_out.push(if outdoor {
                    scenes::outdoor(&mut r)
                } else {
                    scenes::warehouse(&mut r)
                });
                let (x0, x1, z) = if outdoor {
                    (2.0, 298.0, 1.73)
                } else {
                    (2.0, 84.0, 1.2)
                };
                let n = params.scans;
                for i in 0..n {
                    let x = x0 + (x1 - x0) * (i as f64 + 0.5) / n as f64;
                    // A gentle wiggle in y, heading along the track.
                    let y = 0.4 * (x / 9.0).sin();
                    let yaw = (0.4 / 9.0 * (x / 9.0).cos()).atan() + scenes::u(&mut r, -0.05, 0.05);
                    let label = if outdoor {
                        scenes::outdoor_label(x)
                    } else {
                        scenes::warehouse_label(x)
                    };
                    shots.push((0, [x, y, z], yaw, label.to_string()));
                }
            }
        }
        Ok(Simulation {
            params: params.clone(),
            lidar: params.lidar(),
            shots,
            scenes: scenes_out,
        })
    }

    pub fn len(&self) -> usize {
        self.shots.len()
    }

    pub fn is_empty(&self) -> bool {
        self.shots.is_empty()
    }

    /// Cast scan i (deterministic: its own RNG stream from the seed).
    pub fn scan(&self, i: usize) -> SimScan {
        let (scene, pos, yaw, ref label) = self.shots[i];
        let mut r = crate::rng::rng(
            self.params.seed ^ (0x9E37_79B9_7F4A_7C15u64.wrapping_mul(i as u64 + 1)),
        );
        let points = lidar::scan(&self.scenes[scene], pos, yaw, &self.lidar, &mut r);
        SimScan {
            name: format!("scan_{i:05}.ply"),
            label: label.clone(),
            pose: Pose {
                name: None,
                time: Some(i as f64 * 0.1),
                position: pos,
                yaw,
            },
            points,
        }
    }
}

/// `n` descriptors for scaling studies and benchmarks: 20 simulated indoor
/// scans (seed 3, 4 per kind) described with `params`, reused in turn with
/// 0..=2 added to every count (seeded), so no two are identical.
pub fn reused_descriptors(
    n: usize,
    params: &crate::DescriptorParams,
    seed: u64,
) -> Result<Vec<crate::Descriptor>> {
    let mut sp = SimParams::new(SceneKind::Indoor, 3);
    sp.scans = 4;
    let sim = Simulation::new(&sp)?;
    let base = (0..sim.len())
        .map(|i| crate::describe(&sim.scan(i).points, params))
        .collect::<Result<Vec<_>>>()?;
    let mut r = crate::rng::rng(seed);
    Ok((0..n)
        .map(|i| {
            let mut d = base[i % base.len()].clone();
            for m in &mut d.matrices {
                for v in m.iter_mut() {
                    *v += r.random_range(0..3);
                }
            }
            d
        })
        .collect())
}
