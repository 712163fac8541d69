//! Poses from the recording: a `nav_msgs/Odometry` topic, or the tf tree
//! (`/tf` and `/tf_static`) chained from its root down to a chosen frame.
//! Each series is interpolated at a cloud's stamp (position linearly,
//! rotation by slerp) and clamped to its ends outside the recorded span.

use super::msg::Transform;
use nalgebra::Isometry3;
use std::collections::HashMap;

/// Timed poses of one frame relative to its parent, sorted by time.
#[derive(Debug, Default, Clone)]
pub(crate) struct Series(Vec<(f64, Isometry3<f64>)>);

impl Series {
    pub(crate) fn push(&mut self, t: f64, iso: Isometry3<f64>) {
        self.0.push((t, iso));
    }

    pub(crate) fn finish(&mut self) {
        self.0.sort_by(|a, b| a.0.total_cmp(&b.0));
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
#[derive(Debug, Default)]
pub(crate) struct TfTree {
    edges: HashMap<String, (String, Series)>,
}

impl TfTree {
    pub(crate) fn add(&mut self, t: Transform) {
        let e = self
            .edges
            .entry(t.child)
            .or_insert_with(|| (t.parent.clone(), Series::default()));
        // A frame re-parented mid-recording keeps its latest parent.
        e.0 = t.parent;
        e.1.push(t.stamp, t.iso);
    }

    pub(crate) fn finish(&mut self) {
        for e in self.edges.values_mut() {
            e.1.finish();
        }
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
