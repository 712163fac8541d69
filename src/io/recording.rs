//! Scans that come many to a file: ROS bags (a cloud topic), E57 surveys (a
//! scan per station). Each carries a name that says where it came from and,
//! where the recording holds one, its time stamp and pose, so that the map
//! and the thinning along the path need no separate poses file.

use super::poses::Pose;

/// One scan taken out of a recording.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordedScan {
    /// Where the scan came from, unique within the recording: e.g.
    /// `run.bag:/points:000042` or `survey.e57:scan 3`.
    pub name: String,
    /// Points in the sensor frame (as the descriptor needs), file order,
    /// non-finite points included as in [`crate::PointCloud`].
    pub points: Vec<[f32; 3]>,
    /// Time stamp in seconds, where the recording has one.
    pub stamp: Option<f64>,
    /// Pose of the sensor in the recording's world frame, where known.
    pub pose: Option<Pose>,
}
