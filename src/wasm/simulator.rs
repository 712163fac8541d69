//! `Simulator`: simulated scans with ground truth.

use super::*;

/// A simulated data set; scans are made one at a time.
#[wasm_bindgen]
pub struct Simulator {
    sim: sim::Simulation,
}

#[wasm_bindgen]
impl Simulator {
    /// `scene`: `indoor`, `warehouse` or `outdoor` (the paper's scenes), or
    /// the floors `office-floor`, `school`, `hospital`, `hotel`, `mall`, `home`, `institute` or `gym` (rooms along
    /// corridors, as `placecat simulate --scene`); `scans`: per kind for
    /// the room scenes, along the path otherwise; `buildings` (indoor):
    /// `one` (the default: rooms of a kind share a plan), `many` or
    /// `varied`; `shuffle` (room scenes): list the scans in a random order
    /// from the seed instead of kind by kind (the same rooms, poses and
    /// points), so that an order-dependent method such as stride seeding
    /// does not start from one scan of each kind; routes keep their order
    /// and refuse it.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(
            unchecked_param_type = "\"indoor\" | \"warehouse\" | \"outdoor\" | \"office-floor\" | \"school\" | \"hospital\" | \"hotel\" | \"mall\" | \"home\" | \"institute\" | \"gym\""
        )]
        scene: &str,
        seed: f64,
        scans: Option<f64>,
        buildings: Option<String>,
        shuffle: Option<bool>,
    ) -> WasmResult<Simulator> {
        let kind: sim::SceneKind = scene.parse()?;
        let mut p = sim::SimParams::new(kind, super::set::seed_of(seed)?);
        if let Some(n) = scans {
            p.scans = super::set::count("scans", n)?;
        }
        if let Some(b) = buildings {
            p.buildings = b.parse()?;
        }
        p.shuffle = shuffle.unwrap_or(false);
        Ok(Simulator {
            sim: sim::Simulation::new(&p)?,
        })
    }
    #[wasm_bindgen(getter)]
    /// Number of scans the simulation will make.
    pub fn length(&self) -> usize {
        self.sim.len()
    }
    /// Every scan's true label, in the order the scans are listed: the
    /// ground truth for `DescriptorSet.evaluate`, known without making a
    /// scan.
    #[wasm_bindgen(getter)]
    pub fn labels(&self) -> Vec<String> {
        (0..self.sim.len())
            .map(|i| self.sim.label(i).to_string())
            .collect()
    }
    /// The room each scan was made in (room scenes: scans of a room share
    /// the number, for leave-one-room-out checks; 0 along a route).
    #[wasm_bindgen(getter)]
    pub fn rooms(&self) -> Vec<u32> {
        (0..self.sim.len())
            .map(|i| self.sim.room(i) as u32)
            .collect()
    }
    /// Scan i as binary PLY bytes plus `{name, label, pose}`:
    /// returns `{name, label, pose, bytes}`.
    #[wasm_bindgen(unchecked_return_type = "SimulatedScan")]
    pub fn scan(&self, i: usize) -> WasmResult<JsValue> {
        if i >= self.sim.len() {
            return Err(Error::InvalidParameter(format!("scan {i} of {}", self.sim.len())).into());
        }
        let s = self.sim.scan(i);
        #[derive(Serialize)]
        struct Meta<'a> {
            name: &'a str,
            label: &'a str,
            pose: &'a crate::io::poses::Pose,
        }
        let (name, label, pose) = (&s.name, &s.label, &s.pose);
        let obj = to_js(&Meta { name, label, pose })?;
        let bytes = write::ply(&s.points, write::PlyEncoding::BinaryLittleEndian, false);
        js_sys::Reflect::set(&obj, &"bytes".into(), &js_sys::Uint8Array::from(&bytes[..]))
            .map_err(|_| JsError::new("cannot build object"))?;
        Ok(obj)
    }
}
