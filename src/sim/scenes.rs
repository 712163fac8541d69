//! Procedural scenes. Every size and count is drawn from ranges with the
//! seeded RNG, so each room instance differs. Coordinates: metres, z up,
//! floor at z = 0.

use super::geometry::{cuboid, Shape};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

pub(crate) fn u(r: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    r.random_range(lo..hi)
}

const WALL: f64 = 0.2;

/// Floor, ceiling and four walls around the interior [x0, x0+l] x [y0, y0+w].
pub fn room_shell(x0: f64, y0: f64, l: f64, w: f64, h: f64) -> Vec<Shape> {
    vec![
        cuboid(
            [x0 - WALL, y0 - WALL, -WALL],
            [l + 2.0 * WALL, w + 2.0 * WALL, WALL],
        ),
        cuboid(
            [x0 - WALL, y0 - WALL, h],
            [l + 2.0 * WALL, w + 2.0 * WALL, WALL],
        ),
        cuboid([x0 - WALL, y0 - WALL, 0.0], [WALL, w + 2.0 * WALL, h]),
        cuboid([x0 + l, y0 - WALL, 0.0], [WALL, w + 2.0 * WALL, h]),
        cuboid([x0, y0 - WALL, 0.0], [l, WALL, h]),
        cuboid([x0, y0 + w, 0.0], [l, WALL, h]),
    ]
}

/// A table or desk: a top slab and two side panels.
fn table(out: &mut Vec<Shape>, x: f64, y: f64, l: f64, w: f64, h: f64) {
    out.push(cuboid([x, y, h - 0.03], [l, w, 0.03]));
    out.push(cuboid([x, y, 0.0], [0.04, w, h - 0.03]));
    out.push(cuboid([x + l - 0.04, y, 0.0], [0.04, w, h - 0.03]));
}

/// A chair: seat and back.
fn chair(out: &mut Vec<Shape>, x: f64, y: f64) {
    out.push(cuboid([x, y, 0.42], [0.45, 0.45, 0.05]));
    out.push(cuboid([x, y, 0.0], [0.05, 0.05, 0.42]));
    out.push(cuboid([x + 0.4, y + 0.4, 0.0], [0.05, 0.05, 0.42]));
    out.push(cuboid([x, y + 0.4, 0.47], [0.45, 0.05, 0.45]));
}

/// An open shelf unit along x: back panel, sides and `levels` shelves.
fn shelf(out: &mut Vec<Shape>, x: f64, y: f64, l: f64, depth: f64, h: f64, levels: usize) {
    out.push(cuboid([x, y, 0.0], [l, 0.02, h]));
    out.push(cuboid([x, y, 0.0], [0.02, depth, h]));
    out.push(cuboid([x + l - 0.02, y, 0.0], [0.02, depth, h]));
    for i in 0..levels {
        let z = h * i as f64 / (levels - 1).max(1) as f64;
        out.push(cuboid([x, y, z.min(h - 0.02)], [l, depth, 0.02]));
    }
}

/// A generated room: its shapes, interior and the footprints to keep the
/// sensor out of.
pub struct Room {
    pub shapes: Vec<Shape>,
    pub size: [f64; 2],
}

/// The indoor kinds (KyushuIndoor's categories).
pub const INDOOR_KINDS: [&str; 5] = ["office", "kitchen", "lab", "study_room", "corridor"];

pub fn indoor_room(kind: &str, r: &mut ChaCha8Rng) -> Room {
    let mut s = Vec::new();
    let (l, w, h);
    match kind {
        "office" => {
            l = u(r, 6.0, 10.0);
            w = u(r, 5.0, 8.0);
            h = u(r, 2.6, 3.0);
            let rows = ((w - 2.0) / 2.2).floor().max(1.0) as usize;
            let cols = ((l - 2.5) / 1.8).floor().max(1.0) as usize;
            for i in 0..rows {
                for j in 0..cols {
                    if r.random::<f64>() < 0.8 {
                        let (x, y) = (1.5 + j as f64 * 1.8, 1.0 + i as f64 * 2.2);
                        table(&mut s, x, y, 1.4, 0.7, 0.74);
                        s.push(cuboid([x + 0.4, y + 0.1, 0.74], [0.55, 0.05, 0.38]));
                        chair(&mut s, x + 0.5, y + 0.8);
                    }
                }
            }
            let mut x = 0.3;
            while x < l - 1.2 {
                if r.random::<f64>() < 0.6 {
                    s.push(cuboid([x, w - 0.45, 0.0], [0.9, 0.45, u(r, 1.1, 2.0)]));
                }
                x += 1.0;
            }
        }
        "kitchen" => {
            l = u(r, 3.5, 6.0);
            w = u(r, 2.8, 4.2);
            h = u(r, 2.5, 2.8);
            let run = l - 0.8;
            s.push(cuboid([0.0, 0.0, 0.0], [run, 0.6, 0.9]));
            s.push(cuboid([0.0, 0.0, u(r, 1.4, 1.55)], [run, 0.35, 0.7]));
            s.push(cuboid([run + 0.05, 0.0, 0.0], [0.7, 0.7, 1.8]));
            if r.random::<f64>() < 0.6 {
                s.push(cuboid([0.0, 0.6, 0.0], [0.6, w * 0.5, 0.9]));
                s.push(cuboid([0.0, 0.6, 1.45], [0.35, w * 0.5, 0.7]));
            }
            if w > 3.2 {
                let (tx, ty) = (l * 0.45, w * 0.6);
                table(&mut s, tx, ty, 1.2, 0.8, 0.75);
                chair(&mut s, tx + 0.1, ty + 0.85);
                chair(&mut s, tx + 0.65, ty - 0.5);
            }
        }
        "lab" => {
            l = u(r, 9.0, 14.0);
            w = u(r, 6.5, 9.0);
            h = u(r, 3.0, 3.6);
            let spacing = u(r, 2.3, 2.8);
            let mut y = 1.6;
            while y < w - 1.8 {
                let depth = u(r, 0.9, 1.4);
                s.push(cuboid([2.0, y, 0.0], [l - 4.0, depth, 0.9]));
                // A reagent shelf above the bench on posts.
                let z = u(r, 1.5, 1.8);
                s.push(cuboid([2.0, y + depth * 0.4, z], [l - 4.0, 0.3, 0.03]));
                let mut px = 2.0;
                while px < l - 2.0 {
                    s.push(cuboid([px, y + depth * 0.45, 0.9], [0.05, 0.05, z - 0.9]));
                    px += 1.5;
                }
                y += depth + spacing;
            }
            let mut x = 0.5;
            while x < l - 1.5 {
                if r.random::<f64>() < 0.7 {
                    s.push(cuboid([x, 0.0, 0.0], [1.0, 0.6, u(r, 1.9, 2.4)]));
                }
                x += 1.3;
            }
        }
        "study_room" => {
            l = u(r, 3.0, 4.5);
            w = u(r, 2.5, 3.5);
            h = u(r, 2.4, 2.7);
            table(&mut s, 0.2, w - 0.65, 1.2, 0.6, 0.75);
            chair(&mut s, 0.6, w - 1.2);
            let units = (l / 0.85).floor() as usize;
            for i in 0..units.min(4) {
                shelf(&mut s, 0.05 + i as f64 * 0.85, 0.0, 0.8, 0.3, u(r, 1.8, 2.2), 6);
            }
            if r.random::<f64>() < 0.5 {
                s.push(cuboid([l - 0.9, w * 0.35, 0.0], [0.9, 1.9f64.min(w * 0.6), 0.5]));
            } else {
                s.push(cuboid([l - 0.85, 0.5, 0.0], [0.8, 0.8, 0.45]));
                s.push(cuboid([l - 0.15, 0.5, 0.45], [0.1, 0.8, 0.45]));
            }
        }
        _ /* corridor */ => {
            l = u(r, 20.0, 40.0);
            w = u(r, 1.8, 2.6);
            h = u(r, 2.5, 3.0);
            let mut x = u(r, 1.0, 3.0);
            while x < l - 1.0 {
                // Pilasters and door frames along both walls.
                let side = if r.random::<bool>() { 0.0 } else { w - 0.15 };
                s.push(cuboid([x, side, 0.0], [0.3, 0.15, h]));
                x += u(r, 2.5, 5.0);
            }
            if r.random::<f64>() < 0.5 {
                s.push(cuboid([l * 0.5, 0.0, 0.0], [1.5, 0.4, 0.45]));
            }
        }
    }
    s.extend(room_shell(0.0, 0.0, l, w, h));
    Room {
        shapes: s,
        size: [l, w],
    }
}

/// A free sensor position inside a room: away from walls and furniture.
pub fn free_position(room: &Room, r: &mut ChaCha8Rng, margin: f64) -> [f64; 2] {
    let [l, w] = room.size;
    let mut best = [l / 2.0, w / 2.0];
    let mut best_clear = -1.0;
    for _ in 0..200 {
        let p = [
            u(r, margin, (l - margin).max(margin + 0.01)),
            u(r, margin, (w - margin).max(margin + 0.01)),
        ];
        // Clearance to furniture below head height (shell slabs excluded).
        let clear = room.shapes[..room.shapes.len() - 6]
            .iter()
            .map(|s| s.horizontal_distance(p[0], p[1]))
            .fold(f64::INFINITY, f64::min);
        if clear > 0.4 {
            return p;
        }
        if clear > best_clear {
            best_clear = clear;
            best = p;
        }
    }
    best
}

/// The warehouse: small hall (x 0..20), airlock (20..26), large hall (26..86),
/// joined by doorways on y = 0. Returns the shapes and the label at x.
pub fn warehouse(r: &mut ChaCha8Rng) -> Vec<Shape> {
    let mut s = vec![
        // Floors and ceilings.
        cuboid([-0.2, -8.2, -0.2], [20.2, 16.4, 0.2]),
        cuboid([-0.2, -8.2, 6.0], [20.2, 16.4, 0.2]),
        cuboid([20.0, -2.7, -0.2], [6.0, 5.4, 0.2]),
        cuboid([20.0, -2.7, 4.0], [6.0, 5.4, 0.2]),
        cuboid([26.0, -25.2, -0.2], [60.2, 50.4, 0.2]),
        cuboid([26.0, -25.2, 10.0], [60.2, 50.4, 0.2]),
        // Small hall walls (x = 0 closed; x = 20 with a door).
        cuboid([-0.2, -8.2, 0.0], [0.2, 16.4, 6.0]),
        cuboid([0.0, -8.2, 0.0], [20.0, 0.2, 6.0]),
        cuboid([0.0, 8.0, 0.0], [20.0, 0.2, 6.0]),
    ];
    let door = |s: &mut Vec<Shape>, x: f64, half: f64, h: f64| {
        s.push(cuboid([x, -half, 0.0], [0.2, half - 1.5, h]));
        s.push(cuboid([x, 1.5, 0.0], [0.2, half - 1.5, h]));
        s.push(cuboid([x, -1.5, 3.5], [0.2, 3.0, h - 3.5]));
    };
    door(&mut s, 19.9, 8.0, 6.0);
    // Airlock side walls, door into the large hall.
    s.push(cuboid([20.0, -2.7, 0.0], [6.0, 0.2, 4.0]));
    s.push(cuboid([20.0, 2.5, 0.0], [6.0, 0.2, 4.0]));
    door(&mut s, 26.0, 25.0, 10.0);
    // Large hall walls.
    s.push(cuboid([26.0, -25.2, 0.0], [60.0, 0.2, 10.0]));
    s.push(cuboid([26.0, 25.0, 0.0], [60.0, 0.2, 10.0]));
    s.push(cuboid([86.0, -25.2, 0.0], [0.2, 50.4, 10.0]));
    // Racks: shelves on posts.
    let rack = |s: &mut Vec<Shape>, x0: f64, y: f64, len: f64, h: f64, levels: usize| {
        for i in 1..=levels {
            s.push(cuboid(
                [x0, y, h * i as f64 / levels as f64 - 0.05],
                [len, 1.1, 0.05],
            ));
        }
        let mut x = x0;
        while x <= x0 + len {
            s.push(cuboid([x, y, 0.0], [0.1, 0.1, h]));
            s.push(cuboid([x, y + 1.0, 0.0], [0.1, 0.1, h]));
            x += 2.7;
        }
    };
    for y in [-6.5, 5.4] {
        rack(&mut s, 2.0, y, u(r, 12.0, 15.0), 4.0, 3);
    }
    let mut y: f64 = -23.0;
    while y < 23.0 {
        if y.abs() > 3.0 {
            rack(&mut s, 30.0, y, u(r, 45.0, 52.0), u(r, 7.0, 8.5), 5);
        }
        y += u(r, 3.8, 4.6);
    }
    s
}

pub fn warehouse_label(x: f64) -> &'static str {
    if x < 20.0 {
        "small_hall"
    } else if x < 26.0 {
        "airlock"
    } else {
        "large_hall"
    }
}

/// The outdoor sequence along x: open plain (0..100), forest road
/// (100..200), forest path (200..300).
pub fn outdoor(r: &mut ChaCha8Rng) -> Vec<Shape> {
    let mut s = vec![Shape::Ground {
        height: 0.0,
        amplitude: 0.35,
        wavelength: 14.0,
    }];
    let tree = |s: &mut Vec<Shape>, r: &mut ChaCha8Rng, x: f64, y: f64| {
        let h = u(r, 6.0, 15.0);
        s.push(Shape::Cylinder {
            centre: [x, y],
            radius: u(r, 0.12, 0.35),
            z0: -1.0,
            z1: h,
        });
        s.push(Shape::Sphere {
            centre: [x, y, h],
            radius: u(r, 1.5, 3.0),
        });
    };
    // Plain: rocks and low bushes, trees only far from the track.
    for _ in 0..40 {
        let (x, y) = (u(r, -20.0, 100.0), u(r, -40.0, 40.0));
        s.push(Shape::Sphere {
            centre: [x, y, -0.2],
            radius: u(r, 0.3, 0.9),
        });
    }
    for _ in 0..30 {
        let x = u(r, -20.0, 100.0);
        let y = u(r, 30.0, 60.0) * if r.random::<bool>() { 1.0 } else { -1.0 };
        tree(&mut s, r, x, y);
    }
    // Forest road: 6 m of gravel, trees from 4 m out at ~0.08 per square
    // metre (800 a hectare, a managed conifer stand).
    for _ in 0..480 {
        let x = u(r, 100.0, 200.0);
        let y = u(r, 4.0, 35.0) * if r.random::<bool>() { 1.0 } else { -1.0 };
        tree(&mut s, r, x, y);
    }
    // Forest path: narrow, dense trees and bushes close to the track.
    for _ in 0..450 {
        let x = u(r, 200.0, 320.0);
        let y = u(r, 1.8, 30.0) * if r.random::<bool>() { 1.0 } else { -1.0 };
        tree(&mut s, r, x, y);
    }
    for _ in 0..120 {
        let x = u(r, 200.0, 320.0);
        let y = u(r, 1.4, 6.0) * if r.random::<bool>() { 1.0 } else { -1.0 };
        s.push(Shape::Sphere {
            centre: [x, y, 0.2],
            radius: u(r, 0.4, 0.9),
        });
    }
    s
}

pub fn outdoor_label(x: f64) -> &'static str {
    if x < 100.0 {
        "open_plain"
    } else if x < 200.0 {
        "forest_road"
    } else {
        "forest_path"
    }
}
