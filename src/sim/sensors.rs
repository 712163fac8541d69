//! Sensors by beam count, for evaluations that must not hang on one sensor
//! (issue 18): each is a real product's vertical field of view and
//! resolution, from its data sheet.

use super::lidar::LidarParams;
use crate::error::{invalid, Result};

/// The beam counts [`LidarParams::with_beams`] knows.
pub const BEAM_COUNTS: [usize; 4] = [16, 32, 64, 128];

impl LidarParams {
    /// A sensor with `beams` rows:
    /// - 16: Velodyne VLP-16, +-15 degrees, 0.2 degree azimuth steps, 100 m;
    /// - 32: Velodyne HDL-32E, -30.67 to +10.67 degrees, 0.2 degree steps, 100 m;
    /// - 64: Ouster OS1-64, +-22.5 degrees, 1024 columns, 120 m;
    /// - 128: Ouster OS0-128, +-45 degrees, 1024 columns (the indoor default).
    ///
    /// Other counts are an error naming the ones there are.
    pub fn with_beams(beams: usize) -> Result<Self> {
        let base = LidarParams::indoor();
        Ok(match beams {
            16 => LidarParams {
                beams,
                fov_down: -15.0,
                fov_up: 15.0,
                azimuth_steps: 1800,
                min_range: 0.5,
                max_range: 100.0,
                range_noise: 0.03,
                ..base
            },
            32 => LidarParams {
                beams,
                fov_down: -30.67,
                fov_up: 10.67,
                azimuth_steps: 1800,
                min_range: 0.5,
                max_range: 100.0,
                range_noise: 0.02,
                ..base
            },
            64 => LidarParams {
                beams,
                fov_down: -22.5,
                fov_up: 22.5,
                azimuth_steps: 1024,
                min_range: 0.5,
                max_range: 120.0,
                range_noise: 0.02,
                ..base
            },
            128 => base,
            other => {
                return invalid(format!(
                    "no sensor with {other} beams (there are {BEAM_COUNTS:?})"
                ))
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_beam_count_gives_a_valid_sensor_and_others_an_error() {
        for b in BEAM_COUNTS {
            let l = LidarParams::with_beams(b).unwrap();
            assert_eq!(l.beams, b);
            l.validate().unwrap();
        }
        let e = LidarParams::with_beams(24).unwrap_err().to_string();
        assert!(e.contains("24") && e.contains("128"), "{e}");
    }
}
