//! Poses from the recording: a `nav_msgs/Odometry` topic, or the tf tree
//! (`/tf` and `/tf_static`) chained from its root down to a chosen frame.
//! Each series is interpolated at a cloud's stamp (position linearly,
//! rotation by slerp) and clamped to its ends outside the recorded span.
//! Poses are gathered as the walk meets them, in the same pass as the
//! clouds; [`Poses::horizon`] says up to when they are known.

use super::msg::{self, Encoding, Transform};
use crate::error::Result;
use nalgebra::Isometry3;
use std::collections::HashMap;

/// Timed poses of one frame relative to its parent, sorted by time.
#[derive(Debug, Default, Clone)]
pub(crate) struct Series(Vec<(f64, Isometry3<f64>)>);

impl Series {
    /// Insert in time order (messages mostly come in order: cheap).
    pub(crate) fn push(&mut self, t: f64, iso: Isometry3<f64>) {
        let i = self.0.partition_point(|(u, _)| *u <= t);
        self.0.insert(i, (t, iso));
    }

    fn last(&self) -> f64 {
        self.0.last().map_or(f64::NEG_INFINITY, |p| p.0)
    }

    pub(crate) fn at(&self, t: f64) -> Option<Isometry3<f64>> {
        let s = &self.0;
        let i = s.partition_point(|(u, _)| *u <= t);
        match (i.checked_sub(1).map(|j| &s[j]), s.get(i)) {
            (Some(a), Some(b)) if b.0 > a.0 => {
                let f = (t - a.0) / (b.0 - a.0);
                Some(a.1.lerp_slerp(&b.1, f))
            }
            (Some(a), _) => Some(a.1),
            (None, Some(b)) => Some(b.1),
            (None, None) => None,
        }
    }
}

/// The tf tree: for each child frame, its parent and the series of
/// transforms parent -> child.
#[derive(Debug)]
pub(crate) struct TfTree {
    edges: HashMap<String, (String, Series)>,
    /// Latest stamp of a moving (not static) transform.
    latest: f64,
}

impl Default for TfTree {
    fn default() -> Self {
        TfTree {
            edges: HashMap::new(),
            latest: f64::NEG_INFINITY,
        }
    }
}

impl TfTree {
    pub(crate) fn add(&mut self, t: Transform, fixed: bool) {
        if !fixed {
            self.latest = self.latest.max(t.stamp);
        }
        let e = self
            .edges
            .entry(t.child)
            .or_insert_with(|| (t.parent.clone(), Series::default()));
        // A frame re-parented mid-recording keeps its latest parent.
        e.0 = t.parent;
        e.1.push(t.stamp, t.iso);
    }

    pub(crate) fn has(&self, frame: &str) -> bool {
        self.edges.contains_key(frame) || self.edges.values().any(|(p, _)| p == frame)
    }

    /// Every frame the tree names, sorted (for error messages).
    pub(crate) fn frames(&self) -> Vec<String> {
        let mut v: Vec<String> = self.edges.keys().cloned().collect();
        for (p, _) in self.edges.values() {
            if !v.contains(p) {
                v.push(p.clone());
            }
        }
        v.sort();
        v
    }

    /// Pose of `frame` in the root of its tree at time `t`.
    pub(crate) fn at(&self, frame: &str, t: f64) -> Option<Isometry3<f64>> {
        if !self.has(frame) {
            return None;
        }
        let mut pose = Isometry3::identity();
        let mut f = frame;
        // Bounded walk up the tree, so a cycle in a broken tree ends.
        for _ in 0..64 {
            let Some((parent, series)) = self.edges.get(f) else {
                return Some(pose);
            };
            pose = series.at(t)? * pose;
            f = parent;
        }
        Some(pose)
    }
}

/// Yaw (about z) of a rotation, radians.
pub(crate) fn yaw(iso: &Isometry3<f64>) -> f64 {
    iso.rotation.euler_angles().2
}

/// The poses of a bag, as far as the walk has read them.
pub(crate) enum Poses {
    None,
    /// An odometry topic's connections and its series.
    Odometry(Vec<u32>, Series),
    Tf(TfPoses),
}

/// The tf topics' connections (and which are static), the tree, the frame
/// asked for (None: each cloud's frame), the tf topic named in messages, and
/// whether a missing frame is an error (it is not when chosen by default).
pub(crate) struct TfPoses {
    pub(crate) ids: Vec<(u32, bool)>,
    pub(crate) tree: TfTree,
    pub(crate) frame: Option<String>,
    pub(crate) topic: String,
    pub(crate) strict: bool,
}

impl Poses {
    pub(crate) fn wants(&self, id: u32) -> bool {
        match self {
            Poses::None => false,
            Poses::Odometry(ids, _) => ids.contains(&id),
            Poses::Tf(tf) => tf.ids.iter().any(|&(i, _)| i == id),
        }
    }

    /// Add the poses of one message of connection `id`.
    pub(crate) fn add(&mut self, id: u32, data: &[u8], enc: Encoding) -> Result<()> {
        match self {
            Poses::None => {}
            Poses::Odometry(_, series) => {
                let t = msg::odometry(data, enc)?;
                series.push(t.stamp, t.iso);
            }
            Poses::Tf(tf) => {
                let fixed = tf.ids.iter().any(|&(i, f)| i == id && f);
                for t in msg::tf_message(data, enc)? {
                    tf.tree.add(t, fixed);
                }
            }
        }
        Ok(())
    }

    /// Poses are known up to this time: a cloud stamped later waits for the
    /// next pose message, so that it is interpolated, not extrapolated.
    pub(crate) fn horizon(&self) -> f64 {
        match self {
            Poses::None => f64::INFINITY,
            Poses::Odometry(_, s) => s.last(),
            Poses::Tf(tf) => tf.tree.latest,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion};

    fn iso(x: f64, yaw: f64) -> Isometry3<f64> {
        Isometry3::from_parts(
            Translation3::new(x, 0.0, 0.0),
            UnitQuaternion::from_euler_angles(0.0, 0.0, yaw),
        )
    }

    #[test]
    fn series_interpolates_inside_and_clamps_outside() {
        let mut s = Series::default();
        assert!(s.at(1.0).is_none());
        // Pushed out of order: kept sorted.
        s.push(2.0, iso(10.0, 0.4));
        s.push(1.0, iso(0.0, 0.0));
        let mid = s.at(1.25).unwrap();
        assert!((mid.translation.x - 2.5).abs() < 1e-12);
        assert!((yaw(&mid) - 0.1).abs() < 1e-12);
        assert!((s.at(0.0).unwrap().translation.x - 0.0).abs() < 1e-12);
        assert!((s.at(9.0).unwrap().translation.x - 10.0).abs() < 1e-12);
    }

    fn tf(parent: &str, child: &str, t: f64, iso: Isometry3<f64>) -> Transform {
        Transform {
            stamp: t,
            parent: parent.into(),
            child: child.into(),
            iso,
        }
    }

    #[test]
    fn tf_chains_to_the_root_and_survives_a_cycle() {
        let mut tree = TfTree::default();
        assert_eq!(tree.latest, f64::NEG_INFINITY);
        tree.add(tf("map", "odom", 0.0, iso(1.0, 0.0)), true);
        tree.add(tf("odom", "base", 0.0, iso(0.0, 0.0)), false);
        tree.add(
            tf("odom", "base", 1.0, iso(2.0, std::f64::consts::FRAC_PI_2)),
            false,
        );
        tree.add(tf("base", "laser", 0.0, iso(1.0, 0.0)), true);
        assert_eq!(tree.latest, 1.0);
        // At t = 1: map -> odom (1, 0) -> base (2, 0) turned 90 deg -> laser 1 ahead: (3, 1).
        let p = tree.at("laser", 1.0).unwrap();
        assert!((p.translation.x - 3.0).abs() < 1e-12 && (p.translation.y - 1.0).abs() < 1e-12);
        assert!(tree.at("camera", 1.0).is_none());
        assert_eq!(tree.frames(), ["base", "laser", "map", "odom"]);
        // A broken tree with a cycle ends (bounded walk) instead of looping.
        tree.add(tf("laser", "map", 0.0, iso(0.0, 0.0)), true);
        assert!(tree.at("laser", 1.0).is_some());
    }
}
