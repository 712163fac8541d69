//! The two sequence sites, each a map with a vehicle's route through it.
//!
//! - [`outdoor`]: like EskilstunaField (Magnusson et al. 2017, Fig. 1): a
//!   field ringed by forest, with gravel heaps, parked machines, single
//!   trees, rocks, hay bales and a power line on it; a forest road leaves it
//!   and a narrower forest path leads back. The vehicle loops over the
//!   field, drives the road and the path, and crosses the field again.
//!   The forest is mixed as Swedish production forest is (spruce, pine,
//!   birch), with young spruces under the canopy: at the height a vehicle's
//!   sensor sees (below about 2.5 m within 20 m), a spruce stand is a wall
//!   of branches, not bare trunks.
//! - [`warehouse`]: like ArlaWarehouse: an AGV goes round a small hall,
//!   through an airlock, up and down the aisles of a large hall between
//!   loaded pallet racks, and back.
//!
//! Sizes, counts and densities are drawn per seed from ranges typical of
//! such places; nothing is placed to help or hinder the clustering. A scan
//! is labelled with the place the vehicle stands in ([`Site::place`]), not
//! with the kind of the route's leg.

use super::geometry::{cuboid, Shape};
use super::route::Route;
use super::scenes::u;
use super::terrain::{Chassis, Terrain, Wave};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, TAU};

/// A site: what the sensor can hit, the ground (None: a flat floor at z = 0
/// made of shapes), the route and the vehicle driving it.
pub struct Site {
    /// Everything the sensor can hit besides the ground.
    pub shapes: Vec<Shape>,
    /// The uneven ground outdoors; None where the floor is one of `shapes`.
    pub ground: Option<Terrain>,
    /// The vehicle's route, labelled with the kind of place of each stretch.
    pub route: Route,
    /// The vehicle: how its sensor sits above the ground.
    pub chassis: Chassis,
    /// Relative driving speed on a kind of place.
    pub speed: fn(&str) -> f64,
    /// The kind of place a point of the route lies in: a scan's
    /// ground-truth label. The route's stretches change kind at waypoints,
    /// which need not be where one place ends and the next begins (a path
    /// leaves from the road's centre line, inside the road's clearing; the
    /// field's edge is wavy); the label is the place the vehicle stands in.
    pub place: Box<dyn Fn([f64; 2]) -> &'static str>,
}

/// The kinds of place of the outdoor site, its ground-truth labels.
pub const OUTDOOR_KINDS: [&str; 3] = ["open_plain", "forest_road", "forest_path"];
/// The kinds of place of the warehouse site, its ground-truth labels.
pub const WAREHOUSE_KINDS: [&str; 3] = ["small_hall", "airlock", "large_hall"];

/// Forest is generated this far from the route (m); beyond it the trees
/// in front hide what stands behind (mean free path in the stand ~25 m).
const REACH: f64 = 45.0;

/// An oriented box standing at `ground` height: local centre (x, y) in the
/// frame at `at` turned by `yaw`, footprint `size`, bottom `z0` above the
/// ground and height `h`.
#[allow(clippy::too_many_arguments)]
fn part(
    out: &mut Vec<Shape>,
    at: [f64; 2],
    yaw: f64,
    ground: f64,
    local: [f64; 2],
    size: [f64; 2],
    z0: f64,
    h: f64,
) {
    let (s, c) = yaw.sin_cos();
    out.push(Shape::OrientedBox {
        centre: [
            at[0] + c * local[0] - s * local[1],
            at[1] + s * local[0] + c * local[1],
            ground + z0 + h / 2.0,
        ],
        half: [size[0] / 2.0, size[1] / 2.0, h / 2.0],
        yaw,
    });
}

/// The kinds of tree, as they look to a sensor near the ground.
#[derive(Clone, Copy, PartialEq)]
enum Species {
    /// Birch and other broadleaves: a clean trunk, the crown above head
    /// height.
    Broadleaf,
    /// Pine: a clean trunk, a narrow crown from about half height.
    Pine,
    /// Spruce: a cone of branches, living or dead, from near the ground to
    /// the top (they are rarely pruned in managed stands): what makes a
    /// spruce stand a wall at sensor height.
    Spruce,
}

impl Species {
    /// A stem of a Swedish production forest: by the National Forest
    /// Inventory about 40 % spruce, 40 % pine, 20 % birch and other
    /// broadleaves.
    fn draw(r: &mut ChaCha8Rng) -> Species {
        match r.random::<f64>() {
            x if x < 0.2 => Species::Broadleaf,
            x if x < 0.6 => Species::Spruce,
            _ => Species::Pine,
        }
    }
}

/// Half the width kept clear along the route from the ground to above the
/// vehicle's roof (m): a vehicle 1.5-1.8 m wide (track) with its body. A
/// forest path a vehicle drives is open to its width and height: branches
/// that reach in are cut back or broken off by the traffic.
const CORRIDOR: f64 = 1.0;
/// Height above the ground up to which the corridor is clear (m): the
/// sensor rides at 1.6-1.95 m.
const CORRIDOR_HEIGHT: f64 = 2.5;

/// How far the edge of anything solid (a trunk's bark, a boulder or bush,
/// a parked machine, a timber pile) stays from the route's centre line
/// (m): the corridor's half width and 0.1 m more, so that nothing solid
/// grazes the corridor's edge (before the fourth round of issue 14, bark
/// stood 0.97-0.99 m and the edges of bushes and boulders 0.53-1.09 m
/// from the centre line of the path).
/// Branches and crowns keep to the corridor's edge (CORRIDOR), as the
/// third round had them.
const SOLID_CLEAR: f64 = CORRIDOR + 0.1;

/// How far a crown at p may reach before it enters the vehicle's corridor
/// (infinite away from the route).
fn crown_reach(route: &Route, p: [f64; 2]) -> f64 {
    route
        .distance(p, CORRIDOR + 3.0, &[])
        .map_or(f64::INFINITY, |d| (d - CORRIDOR).max(0.0))
}

/// Where a stem, boulder or bush drawn near the route may stand: the
/// route whose corridor it keeps clear of, the ground, and whether a point
/// is still the place it was drawn for (the forest: off the field and out
/// of the road's clearing).
struct Lot<'a> {
    route: &'a Route,
    ground: &'a Terrain,
    allowed: &'a dyn Fn([f64; 2]) -> bool,
}

impl Lot<'_> {
    /// p, or p moved straight away from the route until a disc of `radius`
    /// about it keeps SOLID_CLEAR from the centre line (a stem or boulder
    /// drawn by the path stands just outside the corridor its traffic keeps
    /// clear; moving it keeps the stand's density, where leaving it out
    /// would widen the path). None if the moved point is not allowed or
    /// the route's bends give no room.
    fn place(&self, p: [f64; 2], radius: f64) -> Option<[f64; 2]> {
        let need = SOLID_CLEAR + radius;
        let mut p = p;
        // A move away from one stretch can bring p nearer another on the
        // inside of a bend: look again.
        for _ in 0..4 {
            match self.route.nearest(p, need, &[]) {
                Some((d, q)) if d < need => {
                    let d = d.max(1e-9);
                    // 1 mm more, so that rounding leaves it outside.
                    let k = (need + 1e-3) / d;
                    p = [q[0] + k * (p[0] - q[0]), q[1] + k * (p[1] - q[1])];
                }
                _ => return (self.allowed)(p).then_some(p),
            }
        }
        None
    }

    fn height(&self, p: [f64; 2]) -> f64 {
        self.ground.height(p[0], p[1])
    }
}

/// Whether every shape's footprint keeps SOLID_CLEAR from the route's
/// centre line (the shapes lie within `reach` of `centre`).
fn clear_footprint(route: &Route, centre: [f64; 2], reach: f64, shapes: &[Shape]) -> bool {
    let nearest = route.least_along(centre, reach + SOLID_CLEAR, |q| {
        shapes
            .iter()
            .map(|s| s.horizontal_distance(q[0], q[1]))
            .fold(f64::INFINITY, f64::min)
    });
    nearest >= SOLID_CLEAR
}

/// A tree drawn at p: trunk into the ground and its crown. The trunk keeps
/// its bark SOLID_CLEAR from the route's centre line ([`Lot::place`];
/// nothing is added if it cannot, the draws made all the same); branches
/// below CORRIDOR_HEIGHT reach no nearer than CORRIDOR to it, and a
/// broadleaf crown hangs no lower than CORRIDOR_HEIGHT over the corridor
/// (its lowest branches broken off by the traffic: the crown sits higher).
fn tree(out: &mut Vec<Shape>, r: &mut ChaCha8Rng, p: [f64; 2], species: Species, lot: &Lot) {
    let (h, trunk) = match species {
        Species::Broadleaf => (u(r, 7.0, 16.0), u(r, 0.15, 0.45)),
        _ => (u(r, 10.0, 22.0), u(r, 0.1, 0.25)),
    };
    let placed = lot.place(p, trunk);
    let p = placed.unwrap_or(p);
    let ground = lot.height(p);
    let reach = crown_reach(lot.route, p);
    let mut shapes = vec![Shape::Cylinder {
        centre: p,
        radius: trunk,
        z0: ground - 0.5,
        z1: ground + h,
    }];
    match species {
        Species::Broadleaf => {
            // Crowns start above head height.
            let cr = u(r, 2.5, 4.5).min(0.4 * h);
            let mut z = ground + h - 0.7 * cr;
            // The crown's lowest point over the corridor is over the
            // corridor's point c nearest the crown's centre, e from it;
            // it keeps CORRIDOR_HEIGHT over the ground there, on the centre
            // line and at the stem, whichever is highest.
            if let Some((d, q)) = lot.route.nearest(p, CORRIDOR + cr, &[]) {
                let e = (d - CORRIDOR).max(0.0);
                let k = e / d.max(1e-9);
                let c = [p[0] + k * (q[0] - p[0]), p[1] + k * (q[1] - p[1])];
                let under = ground.max(lot.height(q)).max(lot.height(c));
                let low = z - (cr * cr - e * e).max(0.0).sqrt();
                z += (under + CORRIDOR_HEIGHT - low).max(0.0);
            }
            shapes.push(Shape::Sphere {
                centre: [p[0], p[1], z],
                radius: cr,
            });
        }
        Species::Pine => {
            // A narrow crown from about half height, made of two spheres
            // stacked.
            let cr = u(r, 1.2, 2.2);
            shapes.push(Shape::Sphere {
                centre: [p[0], p[1], ground + h * u(r, 0.5, 0.65)],
                radius: cr,
            });
            shapes.push(Shape::Sphere {
                centre: [p[0], p[1], ground + h * 0.85],
                radius: 0.7 * cr,
            });
        }
        Species::Spruce => {
            let (base, radius) = (u(r, 0.3, 2.0), u(r, 1.3, 2.3));
            spruce_crown(&mut shapes, p, ground, base, h, radius, reach)
        }
    }
    if placed.is_some() {
        out.extend(shapes);
    }
}

/// A spruce's cone of branches from `base` above the ground to the top
/// `h`, `radius` wide at the bottom: spheres stacked up the cone, each as
/// wide as the cone at its centre; the spheres that come down into the
/// vehicle's corridor height reach at most `reach` (the branches there cut
/// back; a simplification: all round the trunk, not only on the route's
/// side).
fn spruce_crown(
    out: &mut Vec<Shape>,
    p: [f64; 2],
    ground: f64,
    base: f64,
    h: f64,
    radius: f64,
    reach: f64,
) {
    let width = |z: f64| radius * (h - z) / (h - base);
    let mut z = base + 0.8 * radius;
    while z < h && width(z) > 0.2 {
        let rad = width(z);
        let kept = if z - rad < CORRIDOR_HEIGHT {
            rad.min(reach)
        } else {
            rad
        };
        if kept > 0.05 {
            out.push(Shape::Sphere {
                centre: [p[0], p[1], ground + z],
                radius: kept,
            });
        }
        z += rad.max(0.5);
    }
}

/// A young spruce of the understorey, 1-4 m: branches to the ground (at
/// most `reach` from its stem).
fn sapling(out: &mut Vec<Shape>, r: &mut ChaCha8Rng, p: [f64; 2], ground: f64, reach: f64) {
    let h = u(r, 1.0, 4.0);
    out.push(Shape::Cylinder {
        centre: p,
        radius: 0.05,
        z0: ground - 0.2,
        z1: ground + h,
    });
    spruce_crown(out, p, ground, 0.1, h, u(r, 0.25, 0.2 + 0.25 * h), reach);
}

/// A low sphere half in the ground (bush, boulder, heap).
fn mound(out: &mut Vec<Shape>, p: [f64; 2], ground: f64, radius: f64, sunk: f64) {
    out.push(Shape::Sphere {
        centre: [p[0], p[1], ground - sunk * radius],
        radius,
    });
}

/// A parked machine at p facing `yaw`: an excavator, a wheel loader, a
/// truck or a tractor with a trailer, about 8 m long at most.
fn machine(out: &mut Vec<Shape>, r: &mut ChaCha8Rng, p: [f64; 2], yaw: f64, g: f64) {
    match r.random_range(0..4) {
        0 => {
            // Excavator: tracks, turned upper body with cab, boom and stick
            // down to the bucket on the ground.
            for side in [-1.0, 1.0] {
                part(out, p, yaw, g, [0.0, side * 1.05], [3.8, 0.6], 0.0, 0.9);
            }
            let turn = yaw + u(r, -1.0, 1.0);
            part(out, p, turn, g, [-0.4, 0.0], [3.0, 2.5], 0.9, 1.1);
            part(out, p, turn, g, [0.6, 0.7], [1.0, 0.9], 2.0, 1.4);
            part(out, p, turn, g, [2.6, -0.3], [3.6, 0.45], 2.3, 0.5);
            part(out, p, turn, g, [4.4, -0.3], [0.4, 0.45], 0.6, 2.0);
            part(out, p, turn, g, [4.5, -0.3], [0.9, 1.1], 0.0, 0.7);
        }
        1 => {
            // Wheel loader: wheels, frame, cab, bucket.
            for (x, y) in [(1.1, 1.0), (1.1, -1.0), (-1.6, 1.0), (-1.6, -1.0)] {
                part(out, p, yaw, g, [x, y], [1.4, 0.6], 0.0, 1.4);
            }
            part(out, p, yaw, g, [-0.3, 0.0], [5.0, 1.6], 0.6, 1.2);
            part(out, p, yaw, g, [-0.4, 0.0], [1.5, 1.5], 1.8, 1.5);
            part(out, p, yaw, g, [3.3, 0.0], [1.2, 2.6], 0.1, 1.0);
        }
        2 => {
            // Truck: cab and a tipper body.
            part(out, p, yaw, g, [3.0, 0.0], [2.0, 2.5], 0.5, 2.6);
            part(out, p, yaw, g, [-1.2, 0.0], [6.0, 2.5], 1.1, 1.5);
            part(out, p, yaw, g, [0.0, 0.0], [8.0, 1.0], 0.4, 0.7);
        }
        _ => {
            // Tractor with a trailer behind it.
            part(out, p, yaw, g, [0.0, 0.0], [3.5, 1.2], 0.5, 1.0);
            part(out, p, yaw, g, [-0.6, 0.0], [1.4, 1.6], 1.4, 1.5);
            for y in [-0.9, 0.9] {
                part(out, p, yaw, g, [-0.8, y], [1.6, 0.5], 0.0, 1.6);
            }
            part(out, p, yaw, g, [-5.3, 0.0], [5.0, 2.3], 0.8, 0.9);
        }
    }
}

/// The outdoor site. Coordinates: the field is [0, w] x [0, h].
pub fn outdoor(r: &mut ChaCha8Rng) -> Site {
    let (w, h) = (u(r, 130.0, 160.0), u(r, 90.0, 120.0));
    let ground = Terrain::new(
        0.0,
        [u(r, -0.01, 0.01), u(r, -0.01, 0.01)],
        vec![
            // Swells of the field, gentler undulation, bumps and ruts.
            Wave::new(
                u(r, 0.3, 1.0),
                u(r, 80.0, 160.0),
                u(r, 0.0, TAU),
                u(r, 0.0, TAU),
            ),
            Wave::new(
                u(r, 0.1, 0.4),
                u(r, 30.0, 60.0),
                u(r, 0.0, TAU),
                u(r, 0.0, TAU),
            ),
            Wave::new(
                u(r, 0.03, 0.1),
                u(r, 8.0, 16.0),
                u(r, 0.0, TAU),
                u(r, 0.0, TAU),
            ),
        ],
    );
    let gz = |p: [f64; 2]| ground.height(p[0], p[1]);
    // The route: waypoints drawn within a few metres of a plan.
    let inset = u(r, 15.0, 22.0);
    let (plain, road, path) = (OUTDOOR_KINDS[0], OUTDOOR_KINDS[1], OUTDOOR_KINDS[2]);
    let exit_y = 0.7 * h + u(r, -8.0, 8.0);
    let entry_x = 0.5 * w + u(r, -10.0, 10.0);
    let mut j = |x: f64, y: f64| [x + u(r, -5.0, 5.0), y + u(r, -5.0, 5.0)];
    let legs = [
        // A loop over the field, out at its east edge.
        (j(inset, inset), plain),
        (j(w - inset, inset), plain),
        ([w - inset, exit_y], plain),
        ([w, exit_y], plain),
        // The forest road east, then south.
        (j(w + 90.0, exit_y + 10.0), road),
        (j(w + 120.0, exit_y - 30.0), road),
        (j(w + 125.0, -40.0), road),
        (j(w + 100.0, -70.0), road),
        // The forest path back west, then north into the field.
        (j(w + 40.0, -55.0), path),
        (j(w - 20.0, -75.0), path),
        ([entry_x + 5.0, -45.0], path),
        ([entry_x, 0.0], path),
        // Across the field again.
        (j(0.5 * w, 0.45 * h), plain),
        (j(0.25 * w, 0.75 * h), plain),
        (j(0.75 * w, h - inset), plain),
    ];
    let route = Route::new(j(inset + 5.0, 0.5 * h), &legs, 8.0);
    // The road goes on past the junction where the vehicle turns onto the
    // path (roads do not end at paths): 80 m more of it, not driven.
    let (a, b) = (legs[6].0, legs[7].0);
    let along = [b[0] - a[0], b[1] - a[1]];
    let l = along[0].hypot(along[1]);
    let spur = Route::new(
        b,
        &[(
            [b[0] + 80.0 * along[0] / l, b[1] + 80.0 * along[1] / l],
            road,
        )],
        1.0,
    );
    let mut s = Vec::new();
    let clear = |p: [f64; 2], m: f64| route.distance(p, m, &[]).is_none();
    let in_field = |p: [f64; 2], margin: f64| {
        p[0] > margin && p[0] < w - margin && p[1] > margin && p[1] < h - margin
    };
    let field_point =
        |r: &mut ChaCha8Rng, margin: f64| [u(r, margin, w - margin), u(r, margin, h - margin)];

    // On the field: things a vehicle passes within the sensor's 20 m.
    for _ in 0..r.random_range(3..=6) {
        // Gravel heaps: a main cone and a smaller one beside it.
        let rad = u(r, 3.0, 6.0);
        let p = field_point(r, rad + 2.0);
        if clear(p, rad + 3.0) {
            mound(&mut s, p, gz(p), rad, 0.6);
            let a = u(r, 0.0, TAU);
            let q = [p[0] + 0.6 * rad * a.cos(), p[1] + 0.6 * rad * a.sin()];
            mound(&mut s, q, gz(q), 0.6 * rad, 0.55);
        }
    }
    for _ in 0..r.random_range(2..=5) {
        let p = field_point(r, 6.0);
        if clear(p, 7.0) {
            let yaw = u(r, 0.0, TAU);
            // A tractor's trailer reaches 7.9 m from p: left out (its draws
            // made all the same) where it would stand in the corridor.
            let mut parts = vec![];
            machine(&mut parts, r, p, yaw, gz(p));
            if clear_footprint(&route, p, 8.0, &parts) {
                s.extend(parts);
            }
        }
    }
    let anywhere = |_: [f64; 2]| true;
    let on_the_field = Lot {
        route: &route,
        ground: &ground,
        allowed: &anywhere,
    };
    for _ in 0..r.random_range(4..=10) {
        let p = field_point(r, 4.0);
        if clear(p, 5.0) {
            tree(&mut s, r, p, Species::Broadleaf, &on_the_field);
        }
    }
    for _ in 0..r.random_range(15..=35) {
        let p = field_point(r, 1.0);
        let rad = u(r, 0.3, 1.0);
        if clear(p, rad + 1.5) {
            mound(&mut s, p, gz(p), rad, 0.3);
        }
    }
    for _ in 0..r.random_range(0..=2) {
        // A row of round bales (standing on end, as stacked for storage).
        let (p, a) = (field_point(r, 10.0), u(r, 0.0, TAU));
        for k in 0..r.random_range(4..=8) {
            let q = [
                p[0] + 1.6 * k as f64 * a.cos(),
                p[1] + 1.6 * k as f64 * a.sin(),
            ];
            if clear(q, 2.5) {
                s.push(Shape::Cylinder {
                    centre: q,
                    radius: 0.75,
                    z0: gz(q) - 0.2,
                    z1: gz(q) + 1.2,
                });
            }
        }
    }
    for _ in 0..r.random_range(0..=2) {
        // A container or hut near the field edge.
        let p = [
            u(r, 5.0, w - 5.0),
            if r.random::<bool>() { 5.0 } else { h - 5.0 },
        ];
        if clear(p, 6.0) {
            part(
                &mut s,
                p,
                u(r, -0.2, 0.2),
                gz(p),
                [0.0, 0.0],
                [6.1, 2.45],
                -0.1,
                2.7,
            );
        }
    }
    // A power line across the field: poles every 40-60 m.
    let (a, spacing) = (u(r, 0.0, TAU), u(r, 40.0, 60.0));
    let centre = field_point(r, 20.0);
    for k in -6..=6 {
        let p = [
            centre[0] + k as f64 * spacing * a.cos(),
            centre[1] + k as f64 * spacing * a.sin(),
        ];
        if in_field(p, 0.0) && clear(p, 2.0) {
            s.push(Shape::Cylinder {
                centre: p,
                radius: 0.14,
                z0: gz(p) - 1.0,
                z1: gz(p) + 10.0,
            });
            part(
                &mut s,
                p,
                a + FRAC_PI_2,
                gz(p),
                [0.0, 0.0],
                [2.4, 0.12],
                9.2,
                0.12,
            );
        }
    }

    // The forest: everywhere near the route but on the field (its edge
    // wavy) and the corridors of the road (gravel, verges, ditches) and the
    // path. Stand density 500-900 stems a hectare.
    let stems = u(r, 0.05, 0.09);
    let undergrowth = u(r, 0.01, 0.03);
    let saplings = u(r, 0.02, 0.06);
    // Forest roads: 4-5 m of gravel, shoulders, ditches and cleared verges;
    // the stand begins 5-7.5 m from the centre line.
    let road_clear = u(r, 5.0, 7.5);
    let path_clear = u(r, 1.1, 1.6);
    let edge = [u(r, 0.0, TAU), u(r, 0.0, TAU)];
    let on_field = move |p: [f64; 2]| {
        let e = 3.0 + 3.0 * (p[0] / 11.0 + edge[0]).sin() * (p[1] / 13.0 + edge[1]).cos();
        p[0] > -e && p[0] < w + e && p[1] > -e && p[1] < h + e
    };
    let (lo, hi) = route.bounds();
    let (lo, hi) = (
        [lo[0] - REACH, lo[1] - REACH],
        [hi[0] + REACH, hi[1] + REACH],
    );
    let area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    // Cheap tests first: most candidates fail the field or the reach.
    let forest = |p: [f64; 2], clear_road: f64, clear_path: f64| {
        !on_field(p)
            && route.distance(p, clear_road, &[road]).is_none()
            && spur.distance(p, clear_road, &[]).is_none()
            && route.distance(p, clear_path, &[path]).is_none()
            && route.distance(p, 4.0, &[plain]).is_none()
            && route.near(p, REACH)
    };
    // Stems, boulders and bushes moved out of the vehicle's corridor stay
    // in the forest (Lot::place).
    let in_stand = |p: [f64; 2]| forest(p, road_clear, path_clear);
    let stand = Lot {
        route: &route,
        ground: &ground,
        allowed: &in_stand,
    };
    for _ in 0..(area * stems) as usize {
        let p = [u(r, lo[0], hi[0]), u(r, lo[1], hi[1])];
        let species = Species::draw(r);
        if in_stand(p) {
            tree(&mut s, r, p, species, &stand);
        }
    }
    // Undergrowth, boulders and saplings; thicker along the path, where
    // the canopy opens. A boulder's or bush's edge keeps SOLID_CLEAR from
    // the centre line, as a trunk's bark does.
    let in_undergrowth = |p: [f64; 2]| forest(p, road_clear - 0.5, path_clear);
    let undergrowth_lot = Lot {
        route: &route,
        ground: &ground,
        allowed: &in_undergrowth,
    };
    for _ in 0..(area * undergrowth) as usize {
        let p = [u(r, lo[0], hi[0]), u(r, lo[1], hi[1])];
        let rad = u(r, 0.3, 1.0);
        if in_undergrowth(p) {
            let sunk = u(r, 0.2, 0.5);
            if let Some(p) = undergrowth_lot.place(p, rad) {
                mound(&mut s, p, gz(p), rad, sunk);
            }
        }
    }
    // Young spruces under the canopy, 200-600 a hectare.
    for _ in 0..(area * saplings) as usize {
        let p = [u(r, lo[0], hi[0]), u(r, lo[1], hi[1])];
        if forest(p, road_clear - 0.5, path_clear + 0.3) {
            sapling(&mut s, r, p, gz(p), crown_reach(&route, p));
        }
    }
    let on = |kind: &str| -> Vec<usize> {
        (0..route.kinds.len())
            .filter(|&k| route.kinds[k] == kind)
            .collect()
    };
    let (on_road, on_path) = (on(road), on(path));
    let path_len = on_path.len() as f64 * super::route::STEP;
    for _ in 0..(path_len * u(r, 0.6, 1.2)) as usize {
        let k = on_path[r.random_range(0..on_path.len())];
        let (p, q) = (route.points[k], route.points[k + 1]);
        let len = (q[0] - p[0]).hypot(q[1] - p[1]).max(1e-9);
        let side = if r.random::<bool>() { 1.0 } else { -1.0 } * u(r, path_clear + 0.2, 5.0);
        let b = [
            p[0] - side * (q[1] - p[1]) / len,
            p[1] + side * (q[0] - p[0]) / len,
        ];
        if in_stand(b) {
            let rad = u(r, 0.3, 0.8);
            if let Some(b) = stand.place(b, rad) {
                mound(&mut s, b, gz(b), rad, 0.2);
            }
        }
    }
    // Timber stacked along the road, waiting for the truck.
    for _ in 0..r.random_range(1..=4) {
        let k = on_road[r.random_range(0..on_road.len())];
        let (p, q) = (route.points[k], route.points[k + 1]);
        let along = (q[1] - p[1]).atan2(q[0] - p[0]);
        let side = if r.random::<bool>() { 1.0 } else { -1.0 } * (road_clear + 1.0);
        let b = [p[0] - side * along.sin(), p[1] + side * along.cos()];
        let mut pile = vec![];
        part(
            &mut pile,
            b,
            along,
            gz(b),
            [0.0, 0.0],
            [u(r, 4.0, 10.0), 2.5],
            -0.1,
            u(r, 1.0, 2.0),
        );
        // Straight by a bend, a long pile could reach the road's centre
        // line: left out there.
        if clear_footprint(&route, b, 5.5, &pile) {
            s.extend(pile);
        }
    }
    let road_route = route.clone();
    Site {
        shapes: s,
        ground: Some(ground),
        route,
        chassis: Chassis {
            wheelbase: u(r, 2.5, 3.2),
            track: u(r, 1.5, 1.8),
            height: u(r, 1.6, 1.95),
        },
        speed: |kind| match kind {
            "forest_path" => 0.6,
            "forest_road" => 0.9,
            _ => 1.0,
        },
        // On the field inside its forest edge; else in the road's clearing
        // (gravel, shoulders, ditches, verges: up to where its stand
        // begins), past the junction too; else on the path.
        place: Box::new(move |p| {
            if on_field(p) {
                plain
            } else if road_route.distance(p, road_clear, &[road]).is_some()
                || spur.distance(p, road_clear, &[]).is_some()
            {
                road
            } else {
                path
            }
        }),
    }
}

/// A pallet rack along x from `x0`: posts every 2.7 m bay, `levels` beams
/// and the loads on them (a loaded bay is one box: its two pallets).
#[allow(clippy::too_many_arguments)]
fn rack(
    s: &mut Vec<Shape>,
    r: &mut ChaCha8Rng,
    x0: f64,
    y: f64,
    len: f64,
    h: f64,
    levels: usize,
    fill: f64,
) {
    let bays = (len / 2.7).floor().max(1.0) as usize;
    for b in 0..=bays {
        let x = x0 + b as f64 * 2.7;
        s.push(cuboid([x, y, 0.0], [0.1, 0.1, h]));
        s.push(cuboid([x, y + 1.0, 0.0], [0.1, 0.1, h]));
    }
    let len = bays as f64 * 2.7 + 0.1;
    let level_h = h / levels as f64;
    for i in 0..levels {
        let z = level_h * i as f64;
        if i > 0 {
            s.push(cuboid([x0, y, z - 0.1], [len, 0.1, 0.1]));
            s.push(cuboid([x0, y + 1.0, z - 0.1], [len, 0.1, 0.1]));
        }
        for b in 0..bays {
            if r.random::<f64>() < fill {
                let top = u(r, 0.5, (level_h - 0.3).min(1.6));
                s.push(cuboid(
                    [x0 + b as f64 * 2.7 + 0.2, y + 0.05, z],
                    [2.4, 1.0, top],
                ));
            }
        }
    }
}

/// The warehouse: small hall (x 0..20, y -8..8), airlock (20..26, y
/// -2.5..2.5), large hall (26..86, y -25..25), doorways 3 m wide on y = 0.
pub fn warehouse(r: &mut ChaCha8Rng) -> Site {
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
    let fill = u(r, 0.5, 0.9);
    // Small hall: a rack along each long wall, pallets on the floor.
    for y in [-6.5, 5.4] {
        let len = u(r, 12.0, 15.0);
        rack(&mut s, r, 2.0, y, len, 4.0, 3, fill);
    }
    for _ in 0..r.random_range(2..=6) {
        let (x, y) = (
            u(r, 2.0, 17.0),
            u(r, 4.0, 4.6) * if r.random::<bool>() { 1.0 } else { -1.0 },
        );
        s.push(cuboid([x, y - 0.4, 0.0], [1.2, 0.8, u(r, 0.15, 1.5)]));
    }
    // Large hall: double racks (two back to back) in rows along x, aisles
    // between them, a 6 m main aisle on y = 0 and cross aisles at both ends.
    let (x0, len) = (30.5, u(r, 42.0, 47.0));
    let rack_h = u(r, 7.0, 8.5);
    let mut aisles = [vec![], vec![]];
    for (side, sign) in [(0, 1.0), (1, -1.0)] {
        let mut y: f64 = 3.0 + u(r, 0.0, 0.5);
        while y + 2.2 < 24.5 {
            let lo = if sign > 0.0 { y } else { -y - 2.2 };
            rack(&mut s, r, x0, lo, len, rack_h, 5, fill);
            rack(&mut s, r, x0, lo + 1.1, len, rack_h, 5, fill);
            let gap = u(r, 2.8, 3.6);
            aisles[side].push(sign * (y + 2.2 + gap / 2.0));
            y += 2.2 + gap;
        }
    }
    // The AGV: round the small hall, through the airlock, down the main
    // aisle, back along one aisle, out along another across the main one,
    // and home.
    let (small, lock, large) = (WAREHOUSE_KINDS[0], WAREHOUSE_KINDS[1], WAREHOUSE_KINDS[2]);
    let far = u(r, 80.0, 83.0);
    let near = u(r, 27.8, 28.8);
    let (up, down) = (
        aisles[0][r.random_range(0..2.min(aisles[0].len()))],
        aisles[1][r.random_range(0..2.min(aisles[1].len()))],
    );
    let legs = [
        ([16.5, -2.8], small),
        ([16.5, 2.8], small),
        ([3.5, 2.8], small),
        ([3.5, 0.0], small),
        ([20.0, 0.0], small),
        ([26.0, 0.0], lock),
        ([far, 0.0], large),
        ([far, up], large),
        ([near, up], large),
        ([near, down], large),
        ([far, down], large),
        ([far, 0.0], large),
        ([26.0, 0.0], large),
        ([20.0, 0.0], lock),
        ([9.0, 0.0], small),
    ];
    let route = Route::new([u(r, 5.0, 9.0), -2.8], &legs, 1.5);
    Site {
        shapes: s,
        ground: None,
        route,
        chassis: Chassis {
            wheelbase: 1.2,
            track: 0.8,
            height: u(r, 1.0, 1.4),
        },
        // AGVs slow down through doors and in the airlock.
        speed: |kind| if kind == "airlock" { 0.35 } else { 1.0 },
        // The halls and the airlock meet at the door walls, x = 20 and 26.
        place: Box::new(move |p| match p[0] {
            x if x < 20.0 => small,
            x if x < 26.0 => lock,
            _ => large,
        }),
    }
}
