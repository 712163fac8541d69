//! Uneven ground for outdoor sites, and where a vehicle standing on it holds
//! its sensor.
//!
//! The ground is a plane plus a few plane waves (long swells of a field,
//! shorter bumps of a forest floor). It is smooth, and its steepest slope is
//! known in closed form, which lets a ray find the ground by stepping
//! without ever stepping through it (see [`Terrain::hit`]).

use super::geometry::Ray;

/// One plane wave of the ground: `amplitude * sin(k . p + phase)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wave {
    /// Wave vector (rad/m); its length is 2 pi / wavelength.
    pub k: [f64; 2],
    /// Height of a crest above the mean (m).
    pub amplitude: f64,
    /// Phase at the origin (radians).
    pub phase: f64,
}

impl Wave {
    /// A wave of `wavelength` metres running along `direction` (radians).
    pub fn new(amplitude: f64, wavelength: f64, direction: f64, phase: f64) -> Wave {
        let k = std::f64::consts::TAU / wavelength;
        let (s, c) = direction.sin_cos();
        Wave {
            k: [k * c, k * s],
            amplitude,
            phase,
        }
    }
}

/// Ground height z = base + slope . (x, y) + sum of waves.
#[derive(Debug, Clone, PartialEq)]
pub struct Terrain {
    /// Height at the origin of the site (m), before slope and waves.
    pub base: f64,
    /// Overall gradient (dz/dx, dz/dy).
    pub slope: [f64; 2],
    /// The swells and bumps added to the plane.
    pub waves: Vec<Wave>,
    /// Bound on |grad h|, for stepping rays safely.
    max_slope: f64,
}

impl Terrain {
    /// Ground of the given plane and waves; the bound on its slope, which
    /// [`Terrain::hit`] steps by, is computed here once.
    pub fn new(base: f64, slope: [f64; 2], waves: Vec<Wave>) -> Terrain {
        let max_slope = slope[0].hypot(slope[1])
            + waves
                .iter()
                .map(|w| w.amplitude.abs() * w.k[0].hypot(w.k[1]))
                .sum::<f64>();
        Terrain {
            base,
            slope,
            waves,
            max_slope,
        }
    }

    /// Level ground at height `base` (m): indoor floors and the warehouse.
    pub fn flat(base: f64) -> Terrain {
        Terrain::new(base, [0.0, 0.0], vec![])
    }

    /// Ground height z (m) under the point (x, y) of the site frame.
    pub fn height(&self, x: f64, y: f64) -> f64 {
        self.base
            + self.slope[0] * x
            + self.slope[1] * y
            + self
                .waves
                .iter()
                .map(|w| w.amplitude * (w.k[0] * x + w.k[1] * y + w.phase).sin())
                .sum::<f64>()
    }

    /// (dz/dx, dz/dy) at (x, y).
    pub fn gradient(&self, x: f64, y: f64) -> [f64; 2] {
        self.waves.iter().fold(self.slope, |g, w| {
            let c = w.amplitude * (w.k[0] * x + w.k[1] * y + w.phase).cos();
            [g[0] + c * w.k[0], g[1] + c * w.k[1]]
        })
    }

    /// An upper bound on |grad h| anywhere (the plane's slope plus each wave's
    /// amplitude times its wavenumber).
    pub fn max_slope(&self) -> f64 {
        self.max_slope
    }

    /// Distance along the ray to the ground, in (t_min, t_max).
    ///
    /// The height of the ray above the ground, f(t), changes by at most
    /// `|d_z| + max_slope * |d_xy|` per metre, so a step of f divided by that
    /// bound never passes the first crossing (Lipschitz ray marching). A
    /// Newton step from a guess could land on a far crossing or behind a
    /// crest when the ray grazes the ground, as far rays over a swell do.
    pub fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        let (o, d) = (ray.o, ray.d);
        // The steepest the ground can climb along this ray's direction, per
        // metre of the ray: each wave only along its own direction.
        let climb = (self.slope[0] * d[0] + self.slope[1] * d[1]).abs()
            + self
                .waves
                .iter()
                .map(|w| (w.amplitude * (w.k[0] * d[0] + w.k[1] * d[1])).abs())
                .sum::<f64>();
        // f falls at most this fast; if it cannot fall, the ray climbs away.
        let rate = climb - d[2];
        if rate <= 0.0 {
            return None;
        }
        // Skip to where the ray enters the band the waves can reach above
        // the plane.
        let band: f64 = self.waves.iter().map(|w| w.amplitude.abs()).sum();
        let plane = |t: f64| {
            self.base + self.slope[0] * (o[0] + t * d[0]) + self.slope[1] * (o[1] + t * d[1])
        };
        let mut t = t_min;
        let above = o[2] + t * d[2] - plane(t) - band;
        if above > 0.0 {
            let fall = self.slope[0] * d[0] + self.slope[1] * d[1] - d[2];
            if fall <= 0.0 {
                return None;
            }
            t += above / fall;
        }
        for _ in 0..MAX_STEPS {
            let f = o[2] + t * d[2] - self.height(o[0] + t * d[0], o[1] + t * d[1]);
            if f < 0.0 {
                // The ray starts under the ground (within min range).
                return None;
            }
            if f < TOLERANCE {
                return Some(t);
            }
            t += f / rate;
            if t >= t_max {
                return None;
            }
        }
        None
    }
}

/// A hit is taken when the ray is this close above the ground (m): well
/// under the sensor's range noise.
const TOLERANCE: f64 = 2e-3;
/// Grazing rays converge slowly; one that has not met the ground in this
/// many steps is taken to pass over it.
const MAX_STEPS: usize = 400;

/// Where and how a sensor stands: position of its optical centre and its
/// orientation, R = Rz(yaw) Ry(pitch) Rx(roll) (radians; positive pitch
/// points the nose down, positive roll lifts the left side).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorPose {
    /// Optical centre in the site frame (m, z up).
    pub position: [f64; 3],
    /// Heading about z (radians, counter-clockwise from +x).
    pub yaw: f64,
    /// Nose-down tilt (radians).
    pub pitch: f64,
    /// Left-side-up tilt (radians).
    pub roll: f64,
}

impl SensorPose {
    /// A level sensor (indoor floors, the warehouse).
    pub fn level(position: [f64; 3], yaw: f64) -> SensorPose {
        SensorPose {
            position,
            yaw,
            pitch: 0.0,
            roll: 0.0,
        }
    }

    /// The rotation matrix (rows), sensor frame to world.
    pub fn rotation(&self) -> [[f64; 3]; 3] {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        let (sr, cr) = self.roll.sin_cos();
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    }
}

/// A vehicle's wheel contact points: it rests on the plane through the
/// ground under its four wheels, not on the slope at one point, so bumps
/// shorter than the wheelbase tilt it less.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chassis {
    /// Distance between front and rear axles (m).
    pub wheelbase: f64,
    /// Distance between left and right wheels (m).
    pub track: f64,
    /// Sensor height above the ground plane, along the vehicle's up axis.
    pub height: f64,
}

impl Chassis {
    /// The sensor pose of a vehicle centred over (x, y) heading `yaw`.
    pub fn pose_on(&self, ground: &Terrain, x: f64, y: f64, yaw: f64) -> SensorPose {
        let (s, c) = yaw.sin_cos();
        let (l, w) = (self.wheelbase / 2.0, self.track / 2.0);
        let front = ground.height(x + c * l, y + s * l);
        let rear = ground.height(x - c * l, y - s * l);
        let left = ground.height(x - s * w, y + c * w);
        let right = ground.height(x + s * w, y - c * w);
        let centre = (front + rear + left + right) / 4.0;
        // The plane's slopes along the heading and to the left.
        let forward = (front - rear) / self.wheelbase;
        let lateral = (left - right) / self.track;
        let pitch = -forward.atan();
        // Up axis = the plane's normal; in (forward, left, up) it is
        // (-forward, -lateral, 1)/n = (sin p cos r, -sin r, cos p cos r).
        let roll = (lateral * pitch.cos()).atan();
        let pose = SensorPose {
            position: [x, y, centre],
            yaw,
            pitch,
            roll,
        };
        let r = pose.rotation();
        let up = [r[0][2], r[1][2], r[2][2]];
        SensorPose {
            position: [
                x + self.height * up[0],
                y + self.height * up[1],
                centre + self.height * up[2],
            ],
            ..pose
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: [f64; 3], d: [f64; 3]) -> Ray {
        Ray::towards(o, d)
    }

    fn wavy() -> Terrain {
        Terrain::new(
            0.3,
            [0.02, -0.01],
            vec![
                Wave::new(0.8, 90.0, 0.3, 1.0),
                Wave::new(0.3, 35.0, 2.0, 0.2),
                Wave::new(0.08, 9.0, -1.0, 2.5),
            ],
        )
    }

    #[test]
    fn rays_land_on_the_ground_and_never_beyond_a_crest() {
        let g = wavy();
        let o = [10.0, -5.0, g.height(10.0, -5.0) + 1.7];
        let mut landed = 0;
        for i in 0..400 {
            let az = i as f64 * 0.37;
            let el = -0.45 + 0.45 * (i % 20) as f64 / 20.0;
            let r = ray(o, [az.cos() * el.cos(), az.sin() * el.cos(), el.sin()]);
            if let Some(t) = g.hit(&r, 0.5, 80.0) {
                landed += 1;
                let p = [o[0] + t * r.d[0], o[1] + t * r.d[1], o[2] + t * r.d[2]];
                assert!((p[2] - g.height(p[0], p[1])).abs() < 3e-3, "{i}: {p:?}");
                // No earlier crossing: the ray stays above the ground before t.
                for k in 1..200 {
                    let s = 0.5 + (t - 0.5) * k as f64 / 200.0;
                    let z = o[2] + s * r.d[2];
                    assert!(z > g.height(o[0] + s * r.d[0], o[1] + s * r.d[1]) - 1e-9);
                }
            }
        }
        // Most downward rays within 80 m meet the ground.
        assert!(landed > 300, "{landed}");
        assert!(g.hit(&ray(o, [1.0, 0.0, 0.3]), 0.5, 80.0).is_none());
    }

    #[test]
    fn the_gradient_is_the_derivative_of_the_height() {
        let g = wavy();
        let (x, y, e) = (7.0, 3.0, 1e-5);
        let gr = g.gradient(x, y);
        let dx = (g.height(x + e, y) - g.height(x - e, y)) / (2.0 * e);
        let dy = (g.height(x, y + e) - g.height(x, y - e)) / (2.0 * e);
        assert!((gr[0] - dx).abs() < 1e-6 && (gr[1] - dy).abs() < 1e-6);
        assert!(gr[0].hypot(gr[1]) <= g.max_slope());
    }

    #[test]
    fn on_a_plane_the_sensor_stands_on_the_normal_and_tilts_with_the_slope() {
        // 10 % up along x, 5 % down along y.
        let g = Terrain::new(2.0, [0.1, -0.05], vec![]);
        let car = Chassis {
            wheelbase: 2.7,
            track: 1.6,
            height: 1.73,
        };
        let n = {
            let v: [f64; 3] = [-0.1, 0.05, 1.0];
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            [v[0] / l, v[1] / l, v[2] / l]
        };
        for yaw in [0.0, 0.7, 2.0, -2.5] {
            let p = car.pose_on(&g, 5.0, 8.0, yaw);
            let r = p.rotation();
            for (k, nk) in n.iter().enumerate() {
                assert!((r[k][2] - nk).abs() < 1e-12, "yaw {yaw}: up {k}");
            }
            // Heading kept; forward axis along the slope in that heading.
            let fwd = [r[0][0], r[1][0], r[2][0]];
            assert!((fwd[1].atan2(fwd[0]) - yaw).sin().abs() < 1e-12);
            let along = 0.1 * yaw.cos() - 0.05 * yaw.sin();
            assert!((p.pitch + along.atan()).abs() < 1e-12, "pitch {}", p.pitch);
            // 1.73 m above the plane, measured along its normal.
            let ground = 2.0 + 0.1 * 5.0 - 0.05 * 8.0;
            let d = [
                p.position[0] - 5.0,
                p.position[1] - 8.0,
                p.position[2] - ground,
            ];
            let above = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
            assert!((above - 1.73).abs() < 1e-9, "{above}");
        }
        // Going up the 10 % slope the nose rises: pitch -5.7 degrees.
        let p = car.pose_on(&g, 0.0, 0.0, 0.0);
        assert!((p.pitch.to_degrees() + 5.711).abs() < 1e-3);
        // Heading +x, the left (+y) side is lower: roll negative.
        assert!(p.roll < -0.04, "{}", p.roll);
    }

    #[test]
    fn a_level_pose_is_a_turn_about_z() {
        let r = SensorPose::level([0.0; 3], 0.6).rotation();
        let (s, c) = 0.6f64.sin_cos();
        assert_eq!(r, [[c, -s, 0.0], [s, c, 0.0], [-0.0, 0.0, 1.0]]);
    }
}
