//! A vehicle's route through a site: straight legs between waypoints,
//! corners rounded to the vehicle's turning radius, each stretch labelled
//! with the kind of place it runs through.

/// The route as a dense polyline (one point per [`STEP`] metres or less).
#[derive(Debug, Clone)]
pub struct Route {
    /// The polyline's points in the site frame (x, y in m).
    pub points: Vec<[f64; 2]>,
    /// Kind of place of the stretch from point i to i + 1.
    pub kinds: Vec<&'static str>,
    grid: Grid,
}

/// Spacing of the dense polyline (m).
pub const STEP: f64 = 0.5;

/// One place along the route where a scan is taken.
#[derive(Debug, Clone, PartialEq)]
pub struct Stop {
    /// Where the vehicle stands (x, y in m).
    pub position: [f64; 2],
    /// Its heading along the route (radians, counter-clockwise from +x).
    pub heading: f64,
    /// The kind of place of the stretch it stands on (its ground-truth label).
    pub kind: &'static str,
}

impl Route {
    /// From `start` through each waypoint in turn; a waypoint's kind is that
    /// of the leg leading to it. Corners are arcs of `radius` metres (less
    /// where legs are too short for it).
    pub fn new(start: [f64; 2], legs: &[([f64; 2], &'static str)], radius: f64) -> Route {
        let mut points = vec![start];
        let mut kinds = vec![];
        fn line(
            points: &mut Vec<[f64; 2]>,
            kinds: &mut Vec<&'static str>,
            p: [f64; 2],
            kind: &'static str,
        ) {
            let last = *points.last().expect("start");
            let n = (dist(last, p) / STEP).ceil().max(1.0) as usize;
            for i in 1..=n {
                let t = i as f64 / n as f64;
                points.push([
                    last[0] + t * (p[0] - last[0]),
                    last[1] + t * (p[1] - last[1]),
                ]);
                kinds.push(kind);
            }
        }
        let mut from = start;
        for (i, &(corner, kind)) in legs.iter().enumerate() {
            let Some(&(next, next_kind)) = legs.get(i + 1) else {
                line(&mut points, &mut kinds, corner, kind);
                break;
            };
            let (a, b) = (dist(from, corner), dist(corner, next));
            let u = unit(from, corner);
            let v = unit(corner, next);
            let turn = (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1]);
            // Tangent length of the arc, kept within the legs.
            let tangent = (radius * (turn.abs() / 2.0).tan()).min(0.45 * a.min(b));
            if turn.abs() < 1e-6 || tangent < 1e-6 {
                line(&mut points, &mut kinds, corner, kind);
                from = corner;
                continue;
            }
            let r = tangent / (turn.abs() / 2.0).tan();
            let entry = [corner[0] - u[0] * tangent, corner[1] - u[1] * tangent];
            line(&mut points, &mut kinds, entry, kind);
            // Centre on the inside of the turn.
            let side = turn.signum();
            let centre = [entry[0] - side * u[1] * r, entry[1] + side * u[0] * r];
            let a0 = (entry[1] - centre[1]).atan2(entry[0] - centre[0]);
            let n = ((r * turn.abs()) / STEP).ceil().max(1.0) as usize;
            for k in 1..=n {
                let a = a0 + turn * k as f64 / n as f64;
                points.push([centre[0] + r * a.cos(), centre[1] + r * a.sin()]);
                kinds.push(if 2 * k <= n { kind } else { next_kind });
            }
            from = *points.last().expect("arc");
        }
        let grid = Grid::new(&points);
        Route {
            points,
            kinds,
            grid,
        }
    }

    /// Length of the route (m).
    pub fn length(&self) -> f64 {
        self.points.windows(2).map(|w| dist(w[0], w[1])).sum()
    }

    /// `n` scans taken at a fixed rate while the vehicle drives at
    /// `speed(kind)` (any unit: only the ratios matter): slower stretches
    /// get more scans per metre.
    pub fn stops(&self, n: usize, speed: impl Fn(&str) -> f64) -> Vec<Stop> {
        let mut time = vec![0.0];
        for (i, w) in self.points.windows(2).enumerate() {
            let dt = dist(w[0], w[1]) / speed(self.kinds[i]);
            time.push(time[i] + dt);
        }
        let total = *time.last().expect("points");
        (0..n)
            .map(|i| {
                let t = total * (i as f64 + 0.5) / n as f64;
                let j = time.partition_point(|&x| x <= t).clamp(1, time.len() - 1) - 1;
                let f = ((t - time[j]) / (time[j + 1] - time[j])).clamp(0.0, 1.0);
                let (p, q) = (self.points[j], self.points[j + 1]);
                Stop {
                    position: [p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])],
                    heading: (q[1] - p[1]).atan2(q[0] - p[0]),
                    kind: self.kinds[j],
                }
            })
            .collect()
    }

    /// Distance from (x, y) to the nearest stretch of the route of a kind in
    /// `kinds` (any kind if empty), if one lies within `within` metres.
    pub fn distance(&self, p: [f64; 2], within: f64, kinds: &[&str]) -> Option<f64> {
        self.nearest(p, within, kinds).map(|(d, _)| d)
    }

    /// The distance from p to the nearest stretch of the route of a kind in
    /// `kinds` (any kind if empty) and the point of the route where it is
    /// nearest, if that lies within `within` metres.
    pub fn nearest(&self, p: [f64; 2], within: f64, kinds: &[&str]) -> Option<(f64, [f64; 2])> {
        let mut best: Option<(f64, [f64; 2])> = None;
        for i in self.grid.near(p, within) {
            if !kinds.is_empty() && !kinds.contains(&self.kinds[i]) {
                continue;
            }
            let q = segment_closest(p, self.points[i], self.points[i + 1]);
            let d = dist(p, q);
            if d <= within && best.is_none_or(|(b, _)| d < b) {
                best = Some((d, q));
            }
        }
        best
    }

    /// The least of `distance_to` over points of the route's stretches
    /// that may lie within `within` metres of `centre`, taken every
    /// [`STEP`] / 4 (infinite if there are none): how near a shape whose
    /// footprint is not a disc comes to the route's centre line.
    pub fn least_along(
        &self,
        centre: [f64; 2],
        within: f64,
        distance_to: impl Fn([f64; 2]) -> f64,
    ) -> f64 {
        let mut least = f64::INFINITY;
        for i in self.grid.near(centre, within) {
            let (a, b) = (self.points[i], self.points[i + 1]);
            for k in 0..=4 {
                let t = k as f64 / 4.0;
                least = least.min(distance_to([
                    a[0] + t * (b[0] - a[0]),
                    a[1] + t * (b[1] - a[1]),
                ]));
            }
        }
        least
    }

    /// Whether any stretch of the route lies within `within` metres of p.
    pub fn near(&self, p: [f64; 2], within: f64) -> bool {
        self.grid
            .near(p, within)
            .any(|i| segment_distance(p, self.points[i], self.points[i + 1]) <= within)
    }

    /// The bounding box of the route: min and max corners.
    pub fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        bounds(&self.points)
    }
}

/// Min and max corners of points.
fn bounds(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    points.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    )
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

fn unit(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    let d = dist(a, b).max(1e-12);
    [(b[0] - a[0]) / d, (b[1] - a[1]) / d]
}

fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    dist(p, segment_closest(p, a, b))
}

/// The point of the segment a-b nearest to p.
fn segment_closest(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    [a[0] + t * dx, a[1] + t * dy]
}

/// Route segments bucketed by square cells, so that placing thousands of
/// trees clear of the route does not test every segment.
#[derive(Debug, Clone)]
struct Grid {
    origin: [f64; 2],
    cols: usize,
    rows: usize,
    cells: Vec<Vec<usize>>,
}

const CELL: f64 = 10.0;

impl Grid {
    fn new(points: &[[f64; 2]]) -> Grid {
        let (lo, hi) = bounds(points);
        let cols = ((hi[0] - lo[0]) / CELL) as usize + 1;
        let rows = ((hi[1] - lo[1]) / CELL) as usize + 1;
        let mut g = Grid {
            origin: lo,
            cols,
            rows,
            cells: vec![vec![]; cols * rows],
        };
        // Segments are at most STEP long, far shorter than a cell: each goes
        // in its start's cell, and queries look one cell further.
        for (i, p) in points
            .iter()
            .enumerate()
            .take(points.len().saturating_sub(1))
        {
            let (c, r) = g.cell(*p);
            g.cells[r * cols + c].push(i);
        }
        g
    }

    fn cell(&self, p: [f64; 2]) -> (usize, usize) {
        let c = ((p[0] - self.origin[0]) / CELL).floor().max(0.0) as usize;
        let r = ((p[1] - self.origin[1]) / CELL).floor().max(0.0) as usize;
        (c.min(self.cols - 1), r.min(self.rows - 1))
    }

    /// Segments that may lie within `within` of p.
    fn near(&self, p: [f64; 2], within: f64) -> impl Iterator<Item = usize> + '_ {
        let reach = within + CELL;
        let lo = self.cell([p[0] - reach, p[1] - reach]);
        let hi = self.cell([p[0] + reach, p[1] + reach]);
        let outside = p[0] + reach < self.origin[0]
            || p[1] + reach < self.origin[1]
            || p[0] - reach > self.origin[0] + CELL * self.cols as f64
            || p[1] - reach > self.origin[1] + CELL * self.rows as f64;
        let (rows, cols) = if outside {
            (1..1, 1..1)
        } else {
            (lo.1..hi.1 + 1, lo.0..hi.0 + 1)
        };
        rows.flat_map(move |r| cols.clone().map(move |c| r * self.cols + c))
            .flat_map(move |k| self.cells[k].iter().copied())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_are_rounded_and_kinds_follow_the_legs() {
        // 40 m east, then 30 m north: a quarter turn of radius 5 m.
        let r = Route::new([0.0, 0.0], &[([40.0, 0.0], "a"), ([40.0, 30.0], "b")], 5.0);
        let arc = std::f64::consts::FRAC_PI_2 * 5.0;
        assert!(
            (r.length() - (35.0 + arc + 25.0)).abs() < 0.01,
            "{}",
            r.length()
        );
        // The corner is cut: nothing comes near (40, 0).
        assert!(r
            .points
            .iter()
            .all(|p| dist(*p, [40.0, 0.0]) > 5.0 * (2f64.sqrt() - 1.0) - 0.01));
        assert_eq!(r.kinds.first(), Some(&"a"));
        assert_eq!(r.kinds.last(), Some(&"b"));
        assert_eq!(r.points.len(), r.kinds.len() + 1);
        // Distances to the route and to one kind of it.
        assert!((r.distance([20.0, 3.0], 10.0, &[]).unwrap() - 3.0).abs() < 1e-9);
        assert!(r.distance([20.0, 3.0], 10.0, &["b"]).is_none());
        assert!((r.distance([43.0, 20.0], 10.0, &["b"]).unwrap() - 3.0).abs() < 1e-9);
        assert!(r.distance([200.0, 200.0], 10.0, &[]).is_none());
    }

    #[test]
    fn slower_stretches_get_more_scans() {
        let r = Route::new(
            [0.0, 0.0],
            &[([50.0, 0.0], "fast"), ([100.0, 0.0], "slow")],
            5.0,
        );
        let stops = r.stops(90, |k| if k == "slow" { 0.5 } else { 1.0 });
        let slow = stops.iter().filter(|s| s.kind == "slow").count();
        assert_eq!(slow, 60);
        assert!(stops
            .windows(2)
            .all(|w| w[1].position[0] > w[0].position[0]));
        assert!(stops.iter().all(|s| s.heading.abs() < 1e-9));
    }
}
