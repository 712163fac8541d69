//! The scene families and sensors of the descriptor evaluation (issue 18):
//! sensors by beam count, sensor heights, other room plans and the office,
//! school, hospital, hotel, mall, home, institute and gym floors, checked
//! against geometry known in advance.

use crate::cli_common::{fails, placecat, succeeds, tmp};
use placecat::sim::geometry::{Ray, Shape};
use placecat::sim::gym::{GYM, GYM_KINDS};
use placecat::sim::home::{HOME, HOME_KINDS};
use placecat::sim::hospital::{HOSPITAL, HOSPITAL_KINDS};
use placecat::sim::hotel::{HOTEL, HOTEL_KINDS};
use placecat::sim::institute::{INSTITUTE, INSTITUTE_KINDS};
use placecat::sim::mall::{MALL, MALL_KINDS};
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
fn office_school_hospital_and_hotel_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for plan in [&OFFICE, &SCHOOL, &HOSPITAL, &HOTEL] {
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
        // Above the doors and the furniture, below the ceiling, rays
        // from the room's middle line meet a wall where the room ends:
        // none goes past it, and one at least (the one from the centre
        // but where a full-height partition or a column stands in the
        // way, as a hotel's bathroom box or a lobby's column) reaches it.
        let c = [
            (room.min[0] + room.max[0]) / 2.0,
            (room.min[1] + room.max[1]) / 2.0,
            floor.height - 0.15,
        ];
        let (w, d) = (width(k), depth(k));
        for (dir, expect, across) in [
            ([1.0, 0.0, 0.0], room.max[0] - c[0], [0.0, d]),
            ([-1.0, 0.0, 0.0], c[0] - room.min[0], [0.0, d]),
            ([0.0, 1.0, 0.0], room.max[1] - c[1], [w, 0.0]),
            ([0.0, -1.0, 0.0], c[1] - room.min[1], [w, 0.0]),
        ] {
            let reach = [0.0, -0.35, -0.2, 0.2, 0.35].map(|f| {
                let o = [c[0] + f * across[0], c[1] + f * across[1], c[2]];
                nearest(&floor.shapes, &Ray::towards(o, dir))
            });
            let far = reach.iter().copied().fold(0.0, f64::max);
            assert!(
                (far - expect).abs() < 1e-6,
                "seed {seed}: {} {dir:?}: {reach:?} vs {expect}",
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

/// `placecat simulate` of a floor `scene` into `dir`, two scans a kind
/// in rooms of one, 16 beams, and `extra`: its labels.csv.
fn simulate_floor(dir: &std::path::Path, scene: &str, seed: &str, extra: &[&str]) -> String {
    succeeds(
        placecat()
            .args(["simulate", "--scene", scene, "--seed", seed, "--scans", "2"])
            .args(["--scans-per-room", "1", "--beams", "16"])
            .args(extra)
            .arg("-o")
            .arg(dir),
    );
    std::fs::read_to_string(dir.join("labels.csv")).unwrap()
}

#[test]
fn simulate_takes_a_sensor_a_height_and_the_office_floor() {
    let dir = tmp("families");
    let labels = simulate_floor(&dir, "office-floor", "4", &["--sensor-height", "0.3"]);
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
            .args(["simulate", "--scene", "airport", "-o"])
            .arg(&dir),
    );
    assert!(
        err.contains("office-floor")
            && err.contains("school")
            && err.contains("hospital")
            && err.contains("hotel")
            && err.contains("mall")
            && err.contains("home")
            && err.contains("institute")
            && err.contains("gym"),
        "{err}"
    );
}

#[test]
fn hospital_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Hospital, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * HOSPITAL_KINDS.len());
    assert_eq!(
        "hospital".parse::<SceneKind>().unwrap(),
        SceneKind::Hospital
    );
    assert_eq!(HOSPITAL_KINDS[0], "corridor");
    assert_eq!(HOSPITAL_KINDS.len(), 5);
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&HOSPITAL, &mut r);
        // A ward: more patient rooms than any other room kind, one nurse
        // station open to the corridor, a corridor two beds wide.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert!(count("patient_room") >= 2, "seed {seed}");
        for kind in ["nurse_station", "treatment_room", "day_room"] {
            assert!(count("patient_room") > count(kind), "seed {seed}: {kind}");
        }
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((2.4..=3.0).contains(&cw), "seed {seed}: corridor {cw} m");
        assert!((2.7..=3.1).contains(&floor.height), "seed {seed}");
        // Handrails at 0.86-0.92 m run along both corridor walls.
        for wall in [0.0, cw - 0.09] {
            let rail: f64 = floor
                .shapes
                .iter()
                .filter_map(|s| match *s {
                    Shape::Cuboid { min, max }
                        if min[2] == 0.86
                            && (min[1] - wall).abs() < 1e-9
                            && max[1] - min[1] < 0.1 =>
                    {
                        Some(max[0] - min[0])
                    }
                    _ => None,
                })
                .sum();
            let length = floor.rooms[0].max[0];
            assert!(
                rail > 0.6 * length,
                "seed {seed}: {rail} of {length} m at {wall}"
            );
        }
    }
}

#[test]
fn hospital_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Hospital, &HOSPITAL, 2);
}

/// Four scans a kind, two a room, 16 beams, of a floor `scene` built to
/// `plan`: labelled kind by kind, rooms numbered in order, the same for
/// a seed and other for another, each in a room of its kind, 0.5 m from
/// its walls, corridor scans seeing along the corridor, and most seeing
/// the floor.
fn scans_are_labelled_counted_and_stand_in_their_rooms(
    scene: SceneKind,
    plan: &FloorPlan,
    seed: u64,
) {
    let edit = |p: &mut SimParams| {
        p.scans = 4;
        p.scans_per_room = 2;
        p.lidar = Some(LidarParams::with_beams(16).unwrap());
    };
    let s = sim(scene, seed, edit);
    assert_eq!(s.len(), 4 * plan.kinds.len());
    for (k, kind) in plan.kinds.iter().enumerate() {
        // The kinds in order, four scans each.
        for i in 4 * k..4 * k + 4 {
            assert_eq!(s.label(i), *kind, "scan {i}");
        }
    }
    // Two scans a room, rooms numbered in order: 0, 0, 1, 1, ...
    let rooms: Vec<usize> = (0..s.len()).map(|i| s.room(i)).collect();
    assert_eq!(rooms, (0..s.len()).map(|i| i / 2).collect::<Vec<_>>());
    // The same seed gives the same plan and the same points; another
    // seed other poses.
    let again = sim(scene, seed, edit);
    let other = sim(scene, seed + 1, edit);
    for i in 0..s.len() {
        assert_eq!(s.sensor_pose(i), again.sensor_pose(i));
        assert_eq!(s.room(i), again.room(i));
        assert_ne!(s.sensor_pose(i).position, other.sensor_pose(i).position);
    }
    for i in [0, 7, 19] {
        assert_eq!(s.scan(i), again.scan(i));
    }
    // Every scan stands in a room of its kind, 0.5 m from its walls, at
    // 1.0-1.3 m; the scans of a room id share one room. The floors are
    // the ones the simulation built: two (rooms of a kind), drawn first
    // from the seed's stream.
    let mut r = placecat::rng::rng(seed);
    let floors: Vec<_> = (0..2).map(|_| office_floor::floor(plan, &mut r)).collect();
    let (mut seen, mut on_floor) = (std::collections::BTreeMap::new(), 0);
    for i in 0..s.len() {
        let fi = floors
            .iter()
            .position(|f| f.shapes == s.shapes(i))
            .expect("a floor of the seed");
        let [x, y, z] = s.sensor_pose(i).position;
        assert!((1.0..1.3).contains(&z), "scan {i}: {z} m");
        let k = floors[fi]
            .rooms
            .iter()
            .position(|room| {
                room.kind == s.label(i)
                    && x >= room.min[0] + 0.5
                    && x <= room.max[0] - 0.5
                    && y >= room.min[1] + 0.5
                    && y <= room.max[1] - 0.5
            })
            .unwrap_or_else(|| {
                panic!(
                    "scan {i} ({}) at {x}, {y} in no room of its kind",
                    s.label(i)
                )
            });
        assert_eq!(
            *seen.entry(s.room(i)).or_insert((fi, k)),
            (fi, k),
            "scan {i}"
        );
        // A corridor scan sees along the corridor, near to its farther
        // end (over what is parked in it).
        let points = s.scan(i).points;
        assert!(points.len() > 1000, "scan {i}: {} points", points.len());
        let far = points
            .iter()
            .map(|p| (p[0] as f64).hypot(p[1] as f64))
            .fold(0.0, f64::max);
        if s.label(i) == "corridor" {
            let end = x.max(floors[fi].rooms[0].max[0] - x);
            assert!(
                far > 0.9 * end && end > 5.0,
                "scan {i}: {far} of {end} m at {x} {y}: {:?}",
                floors[fi].rooms[0]
            );
        }
        // Nothing below the floor; 16 beams (+-15 degrees) meet it 4-5 m
        // out, which furniture hides from a few spots.
        let lowest = points
            .iter()
            .map(|p| p[2] as f64)
            .fold(f64::INFINITY, f64::min);
        assert!(
            lowest > -z - 0.05,
            "scan {i}: {lowest} m under a sensor at {z} m"
        );
        if lowest < -z + 0.05 {
            on_floor += 1;
        }
    }
    assert_eq!(seen.len(), 2 * plan.kinds.len());
    assert!(
        on_floor >= s.len() * 3 / 4,
        "{scene:?}: {on_floor} scans see the floor"
    );
}

/// `placecat simulate --scene SCENE --seed 5` with two scans a kind: its
/// labels hold two scans of each of `kinds`. Returns the output folder.
fn writes_two_scans_of_each_kind(scene: &str, kinds: &[&str]) -> std::path::PathBuf {
    let dir = tmp(scene);
    let labels = simulate_floor(&dir, scene, "5", &[]);
    assert_eq!(labels.lines().count(), 1 + 2 * kinds.len());
    for kind in kinds {
        assert_eq!(
            labels
                .lines()
                .filter(|l| l.ends_with(&format!(",{kind}")))
                .count(),
            2,
            "{kind}"
        );
    }
    dir
}

#[test]
fn simulate_writes_hospital_floors() {
    writes_two_scans_of_each_kind("hospital", &HOSPITAL_KINDS);
}

#[test]
fn hotel_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Hotel, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * HOTEL_KINDS.len());
    assert_eq!("hotel".parse::<SceneKind>().unwrap(), SceneKind::Hotel);
    assert_eq!(
        serde_json::to_string(&SceneKind::Hotel).unwrap(),
        "\"hotel\""
    );
    assert_eq!(HOTEL_KINDS[0], "corridor");
    assert_eq!(HOTEL_KINDS.len(), 5);
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&HOTEL, &mut r);
        // A ground floor: one lobby and one breakfast room, two
        // conference rooms, guest rooms in both rows (filling them), the
        // lobby open to the corridor.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert_eq!(count("lobby"), 1, "seed {seed}");
        assert_eq!(count("breakfast_room"), 1, "seed {seed}");
        assert_eq!(count("conference_room"), 2, "seed {seed}");
        assert!(count("guest_room") >= 2, "seed {seed}");
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((1.8..=2.3).contains(&cw), "seed {seed}: corridor {cw} m");
        assert!((2.6..=2.9).contains(&floor.height), "seed {seed}");
        let lobby = floor.rooms.iter().find(|r| r.kind == "lobby").unwrap();
        // The lobby's opening: a ray from the corridor into the lobby at
        // 2.2 m, across the corridor wall somewhere along it, passes.
        let y = floor.rooms[0].max[1] - 0.1;
        let open = (0..200).any(|i| {
            let x = lobby.min[0] + (lobby.max[0] - lobby.min[0]) * i as f64 / 200.0;
            let t = nearest(&floor.shapes, &Ray::towards([x, y, 2.2], [0.0, 1.0, 0.0]));
            t > 1.0
        });
        assert!(open, "seed {seed}: the lobby is shut off");
    }
}

/// A floor's default counts (16 beams, seed 4): 24 scans a kind, in
/// rooms of 3 (8 rooms a kind).
fn default_counts(scene: SceneKind, kinds: &[&str]) {
    let s = sim(scene, 4, |p| {
        p.lidar = Some(LidarParams::with_beams(16).unwrap());
    });
    assert_eq!(s.len(), 24 * kinds.len());
    for kind in kinds {
        assert_eq!((0..s.len()).filter(|&i| s.label(i) == *kind).count(), 24);
    }
    let rooms: std::collections::BTreeSet<usize> = (0..s.len()).map(|i| s.room(i)).collect();
    assert_eq!(rooms.len(), 8 * kinds.len());
}

#[test]
fn hotel_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Hotel, &HOTEL, 2);
    default_counts(SceneKind::Hotel, &HOTEL_KINDS);
}

#[test]
fn simulate_writes_hotel_floors() {
    writes_two_scans_of_each_kind("hotel", &HOTEL_KINDS);
}

#[test]
fn mall_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for seed in 1..=4 {
        check_floor(&MALL, seed);
    }
}

#[test]
fn mall_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Mall, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * MALL_KINDS.len());
    assert_eq!("mall".parse::<SceneKind>().unwrap(), SceneKind::Mall);
    assert_eq!(serde_json::to_string(&SceneKind::Mall).unwrap(), "\"mall\"");
    assert_eq!(MALL_KINDS[0], "corridor");
    assert_eq!(MALL_KINDS.len(), 5);
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&MALL, &mut r);
        // One supermarket, one electronics store, two cafés, clothing
        // stores in both rows (filling them); a wide concourse, a high
        // ceiling.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert_eq!(count("supermarket"), 1, "seed {seed}");
        assert_eq!(count("electronics_store"), 1, "seed {seed}");
        assert_eq!(count("cafe"), 2, "seed {seed}");
        assert!(count("clothing_store") >= 2, "seed {seed}");
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((5.0..=8.0).contains(&cw), "seed {seed}: concourse {cw} m");
        assert!((3.5..=4.5).contains(&floor.height), "seed {seed}");
        // Every shop's front is glazed: from the concourse, level rays at
        // 1.5 m pass into the shop through most of its front (between
        // the mullions) and through its entrance; at 0.15 m the base
        // stops them but for the entrance, 2.4-3.5 m wide; at 3.3 m the
        // fascia stops every one.
        for shop in floor
            .rooms
            .iter()
            .filter(|r| r.kind != "corridor" && r.kind != "storage")
        {
            let north = shop.min[1] > 0.0;
            let (y, dir) = if north {
                (floor.rooms[0].max[1] - 0.1, [0.0, 1.0, 0.0])
            } else {
                (0.1, [0.0, -1.0, 0.0])
            };
            let n = 400;
            let through = |z: f64| {
                (0..n)
                    .filter(|&i| {
                        let x =
                            shop.min[0] + (shop.max[0] - shop.min[0]) * (i as f64 + 0.5) / n as f64;
                        nearest(&floor.shapes, &Ray::towards([x, y, z], dir)) > 0.5
                    })
                    .count() as f64
                    / n as f64
            };
            let w = shop.max[0] - shop.min[0];
            let (glass, base, fascia) = (through(1.5), through(0.15), through(3.3));
            assert!(
                glass > 0.9,
                "seed {seed}: {} {glass} seen through",
                shop.kind
            );
            let open = base * w;
            assert!(
                (2.3..=3.6).contains(&open),
                "seed {seed}: {} entrance {open} m",
                shop.kind
            );
            assert_eq!(fascia, 0.0, "seed {seed}: {}", shop.kind);
        }
    }
}

#[test]
fn mall_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Mall, &MALL, 2);
    default_counts(SceneKind::Mall, &MALL_KINDS);
}

#[test]
fn simulate_writes_mall_floors() {
    let dir = writes_two_scans_of_each_kind("mall", &MALL_KINDS);
    for i in 0..2 * MALL_KINDS.len() {
        assert!(dir.join(format!("scan_{i:05}.ply")).is_file(), "scan {i}");
    }
}

#[test]
fn home_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for seed in 1..=4 {
        check_floor(&HOME, seed);
    }
}

#[test]
fn home_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Home, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * HOME_KINDS.len());
    assert_eq!("home".parse::<SceneKind>().unwrap(), SceneKind::Home);
    assert_eq!(serde_json::to_string(&SceneKind::Home).unwrap(), "\"home\"");
    assert_eq!(
        serde_json::from_str::<SceneKind>("\"home\"").unwrap(),
        SceneKind::Home
    );
    assert_eq!(HOME_KINDS[0], "corridor");
    assert_eq!(HOME_KINDS.len(), 5);
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&HOME, &mut r);
        // Two living rooms, a kitchen and a bathroom, bedrooms in both
        // rows (filling them); a residential corridor, ceiling and
        // room sizes.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert_eq!(count("living_room"), 2, "seed {seed}");
        assert_eq!(count("kitchen"), 1, "seed {seed}");
        assert_eq!(count("bathroom"), 1, "seed {seed}");
        assert!(count("bedroom") >= 2, "seed {seed}");
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((1.6..=2.1).contains(&cw), "seed {seed}: corridor {cw} m");
        assert!((2.5..=2.7).contains(&floor.height), "seed {seed}");
        for room in &floor.rooms[1..] {
            let w = room.max[0] - room.min[0];
            let (lo, hi) = match room.kind {
                "bathroom" => (1.7, 2.6),
                "bedroom" => (2.8, 4.0),
                "kitchen" => (2.4, 3.6),
                "living_room" => (3.8, 5.5),
                _ => (0.5, 2.8),
            };
            assert!((lo..=hi).contains(&w), "seed {seed}: {} {w} m", room.kind);
        }
    }
}

#[test]
fn home_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Home, &HOME, 2);
    default_counts(SceneKind::Home, &HOME_KINDS);
}

#[test]
fn simulate_writes_home_floors() {
    let dir = writes_two_scans_of_each_kind("home", &HOME_KINDS);
    for i in 0..2 * HOME_KINDS.len() {
        assert!(dir.join(format!("scan_{i:05}.ply")).is_file(), "scan {i}");
    }
}

#[test]
fn institute_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for seed in 1..=4 {
        check_floor(&INSTITUTE, seed);
    }
}

#[test]
fn institute_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Institute, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * INSTITUTE_KINDS.len());
    assert_eq!(
        "institute".parse::<SceneKind>().unwrap(),
        SceneKind::Institute
    );
    assert_eq!(
        serde_json::to_string(&SceneKind::Institute).unwrap(),
        "\"institute\""
    );
    assert_eq!(
        serde_json::from_str::<SceneKind>("\"institute\"").unwrap(),
        SceneKind::Institute
    );
    assert_eq!(
        INSTITUTE_KINDS,
        [
            "corridor",
            "laboratory",
            "workshop",
            "server_room",
            "seminar_room"
        ]
    );
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&INSTITUTE, &mut r);
        // One workshop, one server room and one seminar room,
        // laboratories in both rows (filling them); a laboratory
        // building's corridor, ceiling and room sizes.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert_eq!(count("workshop"), 1, "seed {seed}");
        assert_eq!(count("server_room"), 1, "seed {seed}");
        assert_eq!(count("seminar_room"), 1, "seed {seed}");
        assert!(count("laboratory") >= 2, "seed {seed}");
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((2.0..=2.8).contains(&cw), "seed {seed}: corridor {cw} m");
        assert!((2.9..=3.3).contains(&floor.height), "seed {seed}");
        for room in &floor.rooms[1..] {
            let w = room.max[0] - room.min[0];
            let d = room.max[1] - room.min[1];
            let (lo, hi) = match room.kind {
                "laboratory" => (5.6, 8.4),
                "workshop" => (6.5, 11.0),
                "server_room" => (4.0, 7.5),
                "seminar_room" => (6.0, 10.0),
                _ => (0.5, 5.6),
            };
            assert!((lo..=hi).contains(&w), "seed {seed}: {} {w} m", room.kind);
            assert!((6.0..=8.0).contains(&d), "seed {seed}: {} {d} m", room.kind);
        }
    }
}

#[test]
fn institute_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Institute, &INSTITUTE, 2);
    default_counts(SceneKind::Institute, &INSTITUTE_KINDS);
}

#[test]
fn simulate_writes_institute_floors() {
    let dir = writes_two_scans_of_each_kind("institute", &INSTITUTE_KINDS);
    for i in 0..2 * INSTITUTE_KINDS.len() {
        assert!(dir.join(format!("scan_{i:05}.ply")).is_file(), "scan {i}");
    }
}

#[test]
fn gym_rooms_have_the_sizes_they_say_and_walls_where_they_end() {
    for seed in 1..=4 {
        check_floor(&GYM, seed);
    }
}

#[test]
fn gym_floors_keep_the_school_defaults_and_hold_every_kind() {
    let p = SimParams::new(SceneKind::Gym, 1);
    assert_eq!((p.scans, p.scans_per_room), (24, 3));
    assert_eq!(p.total(), 24 * GYM_KINDS.len());
    assert_eq!("gym".parse::<SceneKind>().unwrap(), SceneKind::Gym);
    assert_eq!(serde_json::to_string(&SceneKind::Gym).unwrap(), "\"gym\"");
    assert_eq!(
        serde_json::from_str::<SceneKind>("\"gym\"").unwrap(),
        SceneKind::Gym
    );
    assert_eq!(
        GYM_KINDS,
        [
            "corridor",
            "cardio_room",
            "weight_room",
            "studio",
            "changing_room"
        ]
    );
    for seed in 1..=6 {
        let mut r = placecat::rng::rng(seed);
        let floor = office_floor::floor(&GYM, &mut r);
        // One cardio room, one weights room, two changing rooms (one a
        // row), studios in both rows (filling them); a sports centre's
        // corridor, ceiling and room sizes.
        let count = |kind: &str| floor.rooms.iter().filter(|r| r.kind == kind).count();
        assert_eq!(count("cardio_room"), 1, "seed {seed}");
        assert_eq!(count("weight_room"), 1, "seed {seed}");
        assert_eq!(count("changing_room"), 2, "seed {seed}");
        assert!(count("studio") >= 2, "seed {seed}");
        let cw = floor.rooms[0].max[1] - floor.rooms[0].min[1];
        assert!((2.0..=2.8).contains(&cw), "seed {seed}: corridor {cw} m");
        assert!((3.0..=3.6).contains(&floor.height), "seed {seed}");
        for room in &floor.rooms[1..] {
            let w = room.max[0] - room.min[0];
            let d = room.max[1] - room.min[1];
            let (lo, hi) = match room.kind {
                "cardio_room" | "weight_room" => (8.0, 14.0),
                "studio" => (7.0, 12.0),
                "changing_room" => (4.5, 8.0),
                _ => (0.5, 7.0),
            };
            assert!((lo..=hi).contains(&w), "seed {seed}: {} {w} m", room.kind);
            assert!((7.0..=9.5).contains(&d), "seed {seed}: {} {d} m", room.kind);
        }
    }
}

#[test]
fn gym_scans_are_labelled_counted_and_stand_in_their_rooms() {
    scans_are_labelled_counted_and_stand_in_their_rooms(SceneKind::Gym, &GYM, 2);
    default_counts(SceneKind::Gym, &GYM_KINDS);
}

#[test]
fn simulate_writes_gym_floors() {
    let dir = writes_two_scans_of_each_kind("gym", &GYM_KINDS);
    for i in 0..2 * GYM_KINDS.len() {
        assert!(dir.join(format!("scan_{i:05}.ply")).is_file(), "scan {i}");
    }
}

/// A digest of every scan of a small simulation: labels, rooms, poses and
/// tilts to 1e-4 (m, radians) and returns to the millimetre (FNV-1a). Any
/// change to what a family draws or casts moves it. The rays' directions
/// come from the platform's sine and cosine, and a last bit of difference
/// can move a return across a millimetre, so the digests are pinned for
/// one platform: x86_64 Linux (glibc), this machine's and CI's.
#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
fn digest(scene: SceneKind, edit: impl FnOnce(&mut SimParams)) -> u64 {
    let s = sim(scene, 7, |p| {
        p.scans = if p.scans_per_room > 1 || scene == SceneKind::Indoor {
            3
        } else {
            4
        };
        edit(p);
    });
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for &b in bytes {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
    };
    for i in 0..s.len() {
        let scan = s.scan(i);
        eat(scan.label.as_bytes());
        eat(&(s.room(i) as u64).to_le_bytes());
        let pose = (scan.pose.position.iter()).chain([&scan.pose.yaw, &scan.pitch, &scan.roll]);
        for v in pose {
            eat(&((v * 1e4).round() as i64).to_le_bytes());
        }
        eat(&(scan.points.len() as u64).to_le_bytes());
        for p in &scan.points {
            for v in p {
                eat(&((v * 1e3).round() as i32).to_le_bytes());
            }
        }
    }
    h
}

/// Every scene family, and the variants the rounds ran (other buildings,
/// sensors, heights, a shuffled listing), casts the scans its rounds were
/// judged on: the test rounds of issues 14 and 18 ran these generators on
/// fixed seeds, and a report can be made again only while they draw the
/// same scenes. Pinned on 2026-12-06; the same digests came from the code
/// of the twenty-second round's test run (dbc39e2; the families it had),
/// of the hotel's (ebee06a) and of the mall's (377fcbf); the home's
/// were pinned as the family was written, before its round's one test
/// run, and so were the institute's and the gym's. A deliberate change
/// of a generator
/// changes its digest here, and the reports that ran it must be run
/// again.
#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
#[test]
fn every_scene_family_casts_the_scans_its_rounds_were_judged_on() {
    let beams = |b: usize| LidarParams::with_beams(b).unwrap();
    let got: Vec<(&str, u64)> = vec![
        ("indoor", digest(SceneKind::Indoor, |_| {})),
        (
            "indoor, many buildings",
            digest(SceneKind::Indoor, |p| p.buildings = Buildings::Many),
        ),
        (
            "indoor, varied plans",
            digest(SceneKind::Indoor, |p| p.buildings = Buildings::Varied),
        ),
        ("warehouse", digest(SceneKind::Warehouse, |_| {})),
        (
            "warehouse, 32 beams",
            digest(SceneKind::Warehouse, |p| p.lidar = Some(beams(32))),
        ),
        ("outdoor", digest(SceneKind::Outdoor, |_| {})),
        (
            "outdoor, 16 beams",
            digest(SceneKind::Outdoor, |p| p.lidar = Some(beams(16))),
        ),
        ("office floor", digest(SceneKind::OfficeFloor, |_| {})),
        (
            "office floor at 0.3 m",
            digest(SceneKind::OfficeFloor, |p| p.sensor_height = Some(0.3)),
        ),
        ("school", digest(SceneKind::School, |_| {})),
        (
            "school, 32 beams",
            digest(SceneKind::School, |p| p.lidar = Some(beams(32))),
        ),
        ("hospital", digest(SceneKind::Hospital, |_| {})),
        (
            "hospital, 16 beams, shuffled",
            digest(SceneKind::Hospital, |p| {
                p.lidar = Some(beams(16));
                p.shuffle = true;
            }),
        ),
        ("hotel", digest(SceneKind::Hotel, |_| {})),
        (
            "hotel, 64 beams",
            digest(SceneKind::Hotel, |p| p.lidar = Some(beams(64))),
        ),
        ("mall", digest(SceneKind::Mall, |_| {})),
        (
            "mall at 1.8 m",
            digest(SceneKind::Mall, |p| p.sensor_height = Some(1.8)),
        ),
        ("home", digest(SceneKind::Home, |_| {})),
        (
            "home, 16 beams",
            digest(SceneKind::Home, |p| p.lidar = Some(beams(16))),
        ),
        ("institute", digest(SceneKind::Institute, |_| {})),
        (
            "institute, 16 beams",
            digest(SceneKind::Institute, |p| p.lidar = Some(beams(16))),
        ),
        ("gym", digest(SceneKind::Gym, |_| {})),
        (
            "gym, 32 beams",
            digest(SceneKind::Gym, |p| p.lidar = Some(beams(32))),
        ),
    ];
    let pinned: Vec<(&str, u64)> = vec![
        ("indoor", 7042316121394205695),
        ("indoor, many buildings", 18275326378894259181),
        ("indoor, varied plans", 7559001555543360166),
        ("warehouse", 7089285538774520087),
        ("warehouse, 32 beams", 9961266475664669120),
        ("outdoor", 15099255189270838290),
        ("outdoor, 16 beams", 5039691306266747895),
        ("office floor", 18104524431723097896),
        ("office floor at 0.3 m", 18117437032987463382),
        ("school", 13857584892266667401),
        ("school, 32 beams", 16754921827019017862),
        ("hospital", 11486569704714992909),
        ("hospital, 16 beams, shuffled", 15462213942710962514),
        ("hotel", 10601863503506360216),
        ("hotel, 64 beams", 11440618482905221842),
        ("mall", 3998364358475336243),
        ("mall at 1.8 m", 3318734351154363825),
        ("home", 4898228458892765390),
        ("home, 16 beams", 1576060517157972008),
        ("institute", 11870764431139219717),
        ("institute, 16 beams", 5938898577027666444),
        ("gym", 3535176167417631734),
        ("gym, 32 beams", 3618785187795789647),
    ];
    assert_eq!(got, pinned);
}

/// Whether `s` reaches height `z` (m).
fn spans_height(s: &Shape, z: f64) -> bool {
    match *s {
        Shape::Cuboid { min, max } => (min[2]..=max[2]).contains(&z),
        Shape::OrientedBox { centre, half, .. } => (z - centre[2]).abs() <= half[2],
        Shape::Cylinder { z0, z1, .. } => (z0..=z1).contains(&z),
        Shape::Sphere { centre, radius } => (z - centre[2]).abs() <= radius,
    }
}

/// No room family puts its sensor in or against what stands in the room:
/// everything at the sensor's height is farther than the own sensors'
/// nearest range (0.3 m; nearer, a shelf would hide the room and return
/// nothing). The floor plans keep scans 0.5 m from walls and 0.4 m from
/// furniture where they can, which a fallback could break. The 16-, 32-
/// and 64-beam sensors see nothing nearer than 0.5 m, so what stands 0.4
/// to 0.5 m away goes unseen by them (0.41 m is the nearest on seeds 1-6).
#[test]
fn room_scans_stand_clear_of_what_reaches_the_sensor() {
    let scenes = [
        SceneKind::Indoor,
        SceneKind::OfficeFloor,
        SceneKind::School,
        SceneKind::Hospital,
        SceneKind::Hotel,
        SceneKind::Mall,
        SceneKind::Home,
        SceneKind::Institute,
        SceneKind::Gym,
    ];
    for scene in scenes {
        for seed in 1..=3 {
            let s = sim(scene, seed, |p| {
                p.scans = 9;
                p.scans_per_room = 3;
            });
            for i in 0..s.len() {
                let [x, y, z] = s.sensor_pose(i).position;
                let nearest = (s.shapes(i).iter())
                    .filter(|shape| spans_height(shape, z))
                    .map(|shape| shape.horizontal_distance(x, y))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    nearest > 0.3,
                    "{scene:?} seed {seed} scan {i} ({}): a shape {nearest} m from the sensor",
                    s.label(i)
                );
            }
        }
    }
}
