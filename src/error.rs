//! One error type for the whole core. Every fallible function returns
//! [`Result`]; the wasm boundary turns these into JS `Error`s with the same
//! message, so the message must name the file and what is wrong with it.

use thiserror::Error;

/// Everything that can go wrong in placecat's core.
#[derive(Debug, Error)]
pub enum Error {
    /// Wraps another error with the name of the file it concerns.
    #[error("{file}: {source}")]
    InFile {
        /// The file's name as the user gave it (or a scan's name).
        file: String,
        /// What went wrong with it.
        #[source]
        source: Box<Error>,
    },
    /// A PLY file that does not follow the format (or lies about its size).
    #[error("PLY: {0}")]
    Ply(String),
    /// A PCD file that does not follow the format (or lies about its size).
    #[error("PCD: {0}")]
    Pcd(String),
    /// A KITTI `.bin` file whose size is not a whole number of points.
    #[error("KITTI .bin: {0}")]
    Kitti(String),
    /// A ROS bag (ROS 1 `.bag` or rosbag2 MCAP) that cannot be read, or a
    /// cloud, pose or chunk in it that cannot be; the message names the topic.
    #[error("ROS bag: {0}")]
    Bag(String),
    /// A LAS/LAZ file that does not follow the format, is damaged, or has no
    /// usable sensor position.
    #[error("LAS/LAZ: {0}")]
    Las(String),
    /// An E57 file (or one of its scans) that cannot be read.
    #[error("E57: {0}")]
    E57(String),
    /// A poses file that is neither KITTI, TUM nor CSV, or a bad row.
    #[error("poses: {0}")]
    Poses(String),
    /// A CSV file (labels, names) with a bad row.
    #[error("CSV: {0}")]
    Csv(String),
    /// Neither the bytes nor the file name tell which format this is.
    #[error("unrecognised point-cloud format: {0}")]
    UnknownFormat(String),
    /// A configured limit (points per scan, bytes per file) was exceeded.
    #[error("over limit: {0}")]
    Limit(String),
    /// The scan has no voxel that could be classified, so no descriptor.
    #[error("no descriptor: {0}")]
    NoDescriptor(String),
    /// A parameter outside its valid range (k = 0, negative epsilon, ...).
    #[error("invalid parameter: {0}")]
    InvalidParameter(String),
    /// Inputs that do not fit together (descriptors of different shapes, ...).
    #[error("mismatch: {0}")]
    Mismatch(String),
    /// Reading or writing a file failed (not found, permission, cut short).
    #[error("I/O: {0}")]
    Io(#[from] std::io::Error),
    /// JSON that does not parse, or does not fit the expected shape.
    #[error("JSON: {0}")]
    Json(#[from] serde_json::Error),
}

/// The core's result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// Attach the file name to this error (idempotent for the same name).
    pub fn in_file(self, file: impl Into<String>) -> Error {
        let file = file.into();
        match self {
            Error::InFile { file: f, source } if f == file => Error::InFile { file: f, source },
            other => Error::InFile {
                file,
                source: Box::new(other),
            },
        }
    }
}

/// Shorthand for `Err(Error::InvalidParameter(..))`.
pub(crate) fn invalid<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::InvalidParameter(msg.into()))
}
