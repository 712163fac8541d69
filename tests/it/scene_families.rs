//! The scene families and sensors of the descriptor evaluation (issue 18):
//! sensors by beam count, sensor heights, other room plans and the office
//! floors, checked against geometry known in advance.

use crate::cli_common::{fails, placecat, succeeds, tmp};
use placecat::sim::geometry::{Ray, Shape};
use placecat::sim::office_floor::{self, FloorPlan, OFFICE, OFFICE_FLOOR_KINDS};
use placecat::sim::school::{SCHOOL, SCHOOL_KINDS};
use placecat::sim::sensors::BEAM_COUNTS;
use placecat::sim::{Buildings, LidarParams, SceneKind, SimParams, Simulation};

fn sim(scene: SceneKind, seed: u64, edit: impl FnOnce(&mut SimParams)) -> Simulation {
    let mut p = SimParams::new(scene, seed);
    edit(&mut p);
    Simulation::new(&p).unwrap()
}

/// The elevation rings of a scan (degrees, mean of each): elevations
/// sorted and split where two neighbours differ by more than 0.1 degree.
fn rings(points: &[[f32; 3]]) -> Vec<f64> {
    let mut e: Vec<f64> = points
        .iter()
        .map(|p| {
            let (x, y, z) = (p[0] as f64, p[1] as f64, p[2] as f64);
            z.atan2(x.hypot(y)).to_degrees()
        })
        .collect();
    e.sort_by(f64::total_cmp);
    let mut rings: Vec<Vec<f64>> = vec![];
    for v in e {
        match rings.last_mut() {
            Some(r) if v - r[r.len() - 1] < 0.1 => r.push(v),
            _ => rings.push(vec![v]),
        }
    }
    rings
        .iter()
        .map(|r| r.iter().sum::<f64>() / r.len() as f64)
        .collect()
}

#[test]
fn each_sensor_gives_its_beam_count_of_rings_over_its_field_of_view() {
    for beams in BEAM_COUNTS {
        let lidar = LidarParams::with_beams(beams).unwrap();
        let s = sim(SceneKind::Indoor, 1, |p| {
            p.scans = 1;
            p.lidar = Some(lidar.clone());
        });
        let r = rings(&s.scan(0).points);
        // Rays are exact directions times a noisy range, so a ring keeps
        // its elevation; every ring hits a wall, floor or ceiling indoors.
        assert_eq!(r.len(), beams, "{beams} beams: rings {r:?}");
        let (lo, hi) = (r[0], r[r.len() - 1]);
        assert!((lo - lidar.fov_down).abs() < 0.02, "{beams}: {lo}");
        assert!((hi - lidar.fov_up).abs() < 0.02, "{beams}: {hi}");
    }
    let e = placecat::sim::LidarParams::with_beams(40).unwrap_err();
    assert!(e.to_string().contains("40 beams"), "{e}");
}

/// The 2nd percentile of z: the floor, seen from the sensor.
fn floor_z(points: &[[f32; 3]]) -> f64 {
    let mut z: Vec<f32> = points.iter().map(|p| p[2]).collect();
    z.sort_by(f32::total_cmp);
    z[z.len() / 50] as f64
}

#[test]
fn the_sensor_height_moves_the_floor_by_as_much() {
    for scene in [
        SceneKind::Indoor,
        SceneKind::OfficeFloor,
        SceneKind::Warehouse,
    ] {
        let mut floors = vec![];
        for h in [0.3, 1.0, 1.8] {
            let s = sim(scene, 2, |p| {
                p.scans = 1;
                p.scans_per_room = 1;
                p.sensor_height = Some(h);
            });
            assert_eq!(s.sensor_pose(0).position[2], h, "{scene:?}");
            let z = floor_z(&s.scan(0).points);
            assert!((z + h).abs() < 0.03, "{scene:?} at {h} m: floor at {z}");
            floors.push(z);
        }
        assert!((floors[0] - floors[2] - 1.5).abs() < 0.04, "{floors:?}");
    }
    let bad = SimParams {
        sensor_height: Some(3.5),
        ..SimParams::new(SceneKind::Indoor, 1)
    };
    let e = Simulation::new(&bad).err().unwrap().to_string();
    assert!(e.contains("sensor height") && e.contains("3.5"), "{e}");
}

/// Distance along `ray` to the nearest of `shapes`.
fn nearest(shapes: &[Shape], ray: &Ray) -> f64 {
    shapes
        .iter()
        .filter_map(|s| s.hit(ray, 0.0))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn office_and_school_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for plan in [&OFFICE, &SCHOOL] {
        for seed in 1..=4 {
            check_floor(plan, seed);
        }
    }
}

fn check_floor(plan: &FloorPlan, seed: u64) {
    let mut r = placecat::rng::rng(seed);
    let floor = office_floor::floor(plan, &mut r);
    assert_eq!(floor.rooms[0].kind, "corridor");
    let width = |k: usize| floor.rooms[k].max[0] - floor.rooms[k].min[0];
    let depth = |k: usize| floor.rooms[k].max[1] - floor.rooms[k].min[1];
    let cw = depth(0);
    let (lo, hi) = plan.corridor_width;
    assert!((lo..=hi).contains(&cw), "seed {seed}: corridor {cw} m wide");
    for kind in plan.kinds {
        assert!(
            floor.rooms.iter().any(|room| room.kind == kind),
            "seed {seed}: no {kind}"
        );
    }
    for k in 1..floor.rooms.len() {
        let room = &floor.rooms[k];
        let (lo, hi) = (plan.width)(room.kind);
        let (w, d) = (width(k), depth(k));
        assert!(
            w >= lo - 1e-9 && w <= hi + 1e-9,
            "seed {seed}: {} {w} m wide",
            room.kind
        );
        let (lo, hi) = plan.row_depth;
        assert!(
            (lo..=hi).contains(&d),
            "seed {seed}: {} {d} m deep",
            room.kind
        );
        // Above the doors and the furniture, below the ceiling, a ray
        // from the room's centre meets a wall where the room ends.
        let c = [
            (room.min[0] + room.max[0]) / 2.0,
            (room.min[1] + room.max[1]) / 2.0,
            floor.height - 0.15,
        ];
        for (dir, expect) in [
            ([1.0, 0.0, 0.0], room.max[0] - c[0]),
            ([-1.0, 0.0, 0.0], c[0] - room.min[0]),
            ([0.0, 1.0, 0.0], room.max[1] - c[1]),
            ([0.0, -1.0, 0.0], c[1] - room.min[1]),
        ] {
            let t = nearest(&floor.shapes, &Ray::towards(c, dir));
            assert!(
                (t - expect).abs() < 1e-6,
                "seed {seed}: {} {dir:?}: {t} vs {expect}",
                room.kind
            );
        }
    }
}

#[test]
fn office_floor_scans_come_a_few_per_room_from_rooms_of_every_kind() {
    let school = sim(SceneKind::School, 3, |p| {
        p.scans = 3;
        p.scans_per_room = 1;
        p.lidar = Some(LidarParams::with_beams(16).unwrap());
    });
    assert_eq!(school.len(), 3 * SCHOOL_KINDS.len());
    for kind in SCHOOL_KINDS {
        assert_eq!(
            (0..school.len())
                .filter(|&i| school.label(i) == kind)
                .count(),
            3
        );
    }
    let s = sim(SceneKind::OfficeFloor, 3, |p| {
        p.scans = 4;
        p.scans_per_room = 2;
        p.lidar = Some(LidarParams::with_beams(16).unwrap());
    });
    assert_eq!(s.len(), 4 * OFFICE_FLOOR_KINDS.len());
    let mut rooms = std::collections::BTreeMap::new();
    for i in 0..s.len() {
        let label = rooms
            .entry(s.room(i))
            .or_insert_with(|| s.label(i).to_string());
        assert_eq!(label, s.label(i), "a room holds one kind");
        let z = s.sensor_pose(i).position[2];
        assert!((1.0..1.3).contains(&z), "{z}");
    }
    // Two rooms per kind, two scans each.
    assert_eq!(rooms.len(), 2 * OFFICE_FLOOR_KINDS.len());
    // A corridor scan sees along the corridor: its farthest return is
    // farther than a restroom scan's (doors open into it or not).
    let far = |kind: &str| {
        (0..s.len())
            .filter(|&i| s.label(i) == kind)
            .map(|i| {
                s.scan(i)
                    .points
                    .iter()
                    .map(|p| (p[0] as f64).hypot(p[1] as f64))
                    .fold(0.0, f64::max)
            })
            .fold(f64::INFINITY, f64::min)
    };
    assert!(far("corridor") > 15.0, "{}", far("corridor"));
}

#[test]
fn varied_plans_give_l_shaped_rooms_and_keep_scans_out_of_the_cut() {
    let s = sim(SceneKind::Indoor, 1, |p| {
        p.buildings = Buildings::Varied;
        p.scans = 6;
        p.scans_per_room = 1;
        p.lidar = Some(LidarParams::with_beams(16).unwrap());
    });
    assert_eq!(s.len(), 30);
    let mut l_shaped = 0;
    for i in 0..s.len() {
        // The walled-off corner is the first shape of an L-shaped room: a
        // full-height block standing on the floor.
        if let Shape::Cuboid { min, max } = s.shapes(i)[0] {
            if min[2] == 0.0 && max[2] > 2.3 && s.label(i) != "corridor" {
                l_shaped += 1;
                let p = s.sensor_pose(i).position;
                let inside = (min[0]..=max[0]).contains(&p[0]) && (min[1]..=max[1]).contains(&p[1]);
                assert!(!inside, "scan {i} stands in the walled-off corner");
            }
        }
    }
    assert!(
        (4..=20).contains(&l_shaped),
        "{l_shaped} of 24 rooms L-shaped"
    );
}

#[test]
fn simulate_takes_a_sensor_a_height_and_the_office_floor() {
    let dir = tmp("families");
    succeeds(
        placecat()
            .args([
                "simulate",
                "--scene",
                "office-floor",
                "--seed",
                "4",
                "--scans",
                "2",
                "--scans-per-room",
                "1",
                "--beams",
                "16",
                "--sensor-height",
                "0.3",
                "-o",
            ])
            .arg(&dir),
    );
    let labels = std::fs::read_to_string(dir.join("labels.csv")).unwrap();
    assert_eq!(labels.lines().count(), 1 + 2 * OFFICE_FLOOR_KINDS.len());
    assert!(labels.contains("open_plan") && labels.contains("restroom"));
    let err = fails(
        placecat()
            .args(["simulate", "--scene", "indoor", "--beams", "24", "-o"])
            .arg(&dir),
    );
    assert!(err.contains("24 beams"), "{err}");
    let err = fails(
        placecat()
            .args(["simulate", "--scene", "hospital", "-o"])
            .arg(&dir),
    );
    assert!(
        err.contains("office-floor") && err.contains("school"),
        "{err}"
    );
}
