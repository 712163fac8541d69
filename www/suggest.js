// Defaults suggested from the data, as pure functions (no DOM, no wasm):
// the descriptor preset from how far the points of a scan lie, and the
// site subsample the trajectory map keeps of each scan.

/** Beyond this horizontal range (m) a point counts as far. */
export const FAR = 10;

/**
 * The share of points beyond FAR metres of the sensor, horizontally (x, y
 * in the sensor frame), of interleaved x, y, z positions.
 * @param {ArrayLike<number>} xyz @returns {{far: number, points: number}}
 */
export function rangeShare(xyz) {
  let far = 0, points = 0;
  for (let i = 0; i + 2 < xyz.length; i += 3) {
    const r2 = xyz[i] * xyz[i] + xyz[i + 1] * xyz[i + 1];
    if (!Number.isFinite(r2)) continue;
    points++;
    if (r2 > FAR * FAR) far++;
  }
  return { far: points ? far / points : 0, points };
}

/**
 * The preset for a scan with this share of far points. What the presets
 * mean: `indoor` (paper Tab. II) counts structure from 1 m on, in 3-4 m
 * intervals up to 15 m and one open interval beyond; `outdoor` ignores the
 * first 5 m (ground and the vehicle) and reaches 20 m. A scan whose points
 * mostly lie within 10 m is a room or a hall: the outdoor preset would drop
 * its nearest structure and leave its far ranges empty. A scan with a third
 * or more of its points beyond 10 m is open space: outdoor. Why a third
 * and not a half: a vehicle's lidar puts most of its returns on the ground
 * close by. Measured on the real scans in tests (share beyond 10 m):
 * KITTI 00 (a road) 36-45 %; an Ouster OS0 in an enclosed space with walls
 * ~12 m away 26-28 %; velodyne_pair 9 % (outdoors, but half its points lie
 * within 3.5 m: the outdoor preset, blind below 5 m, would describe it by a
 * third of its points); pcl_room (a room) under 1 %. A third lies in the
 * gap between 28 and 36 %.
 * @param {number} farShare @returns {'indoor' | 'outdoor'}
 */
export function suggestPreset(farShare) {
  return farShare >= 1 / 3 ? 'outdoor' : 'indoor';
}

/** What the page says about a suggestion. @param {{preset: string, far: number, from: string}} s */
export function suggestionText(s) {
  const pct = Math.round(100 * s.far);
  return `${s.preset} suggested: ${pct} % of the points of ${s.from} lie beyond ${FAR} m (${s.preset === 'outdoor' ? 'a third or more: open space' : 'under a third: a room or hall'})`;
}

/** Points of a scan the map keeps (x, y pairs, sensor frame). */
export const SITE_POINTS = 400;

/**
 * A top-down subsample of interleaved x, y, z points: at most `max`
 * (x, y) pairs, evenly strided, so the map holds a few kilobytes per scan
 * whatever the scans' size.
 * @param {Float32Array} xyz @param {number} [max] @returns {Float32Array}
 */
export function siteSubsample(xyz, max = SITE_POINTS) {
  const n = Math.floor(xyz.length / 3);
  const step = Math.max(1, Math.ceil(n / max));
  const out = new Float32Array(2 * Math.ceil(n / step));
  let j = 0;
  for (let i = 0; i < n; i += step) {
    out[j++] = xyz[3 * i];
    out[j++] = xyz[3 * i + 1];
  }
  return out.subarray(0, j);
}
