use crate::error::{invalid, Result};
use serde::{Deserialize, Serialize};

/// How the k initial centres are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Seeding {
    /// k distinct scans drawn from the seeded RNG.
    Random,
    /// "Deterministic": cluster i starts at scan i * n / k.
    Stride,
    /// k-means++: each next seed drawn with probability proportional to the
    /// squared Delta to the nearest seed so far.
    PlusPlus,
}

impl std::str::FromStr for Seeding {
    type Err = crate::Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "random" => Ok(Seeding::Random),
            "stride" | "deterministic" => Ok(Seeding::Stride),
            "plusplus" | "kmeans++" | "++" => Ok(Seeding::PlusPlus),
            other => invalid(format!(
                "unknown seeding {other:?} (random, stride, plusplus)"
            )),
        }
    }
}

/// Validated k-means parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KMeansParams {
    pub k: usize,
    pub seeding: Seeding,
    pub seed: u64,
    pub max_iterations: usize,
}

impl KMeansParams {
    pub fn new(k: usize) -> Self {
        KMeansParams {
            k,
            seeding: Seeding::PlusPlus,
            seed: 0,
            max_iterations: 100,
        }
    }
    pub fn seeding(mut self, s: Seeding) -> Self {
        self.seeding = s;
        self
    }
    pub fn seed(mut self, s: u64) -> Self {
        self.seed = s;
        self
    }
    pub fn max_iterations(mut self, m: usize) -> Self {
        self.max_iterations = m;
        self
    }
    /// Check against the number of scans.
    pub fn check(&self, n: usize) -> Result<()> {
        crate::cluster::lloyd::check_k(self.k, n)?;
        if self.max_iterations == 0 {
            return invalid("max_iterations must be at least 1");
        }
        Ok(())
    }
}
