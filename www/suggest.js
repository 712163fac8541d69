// Defaults suggested from the data, as pure functions (no DOM, no wasm):
// the descriptor preset from how far the points of a scan lie, and the
// site subsample the trajectory map keeps of each scan.

/** Beyond this horizontal range (m) a point counts as far: where the indoor preset's resolved ranges end. */
export const FAR = 15;
/** From this share of far points on, outdoor is suggested. */
export const OUTDOOR_SHARE = 0.14;
/**
 * The preset suggested for open space: the paper's outdoor parameters with
 * the Hellinger distance (docs/hellinger.md; chosen on development seeds of
 * the outdoor site, docs/seeds.md, sixth round). The paper's `outdoor`
 * stays in the menu.
 */
export const OUTDOOR_PRESET = 'outdoor_hellinger';
/** @typedef {'indoor' | 'outdoor_hellinger'} SuggestedPreset */

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
 * mean (paper Tab. II): `indoor` resolves structure from 1 to 15 m in 3-4 m
 * intervals and puts everything beyond 14 m into one open interval;
 * `outdoor` ignores the first 5 m (ground, the vehicle) and resolves up to
 * 20 m. When a good part of a scan lies beyond 15 m, indoor would lump it
 * together and outdoor resolves it: outdoor from 14 % of the points on.
 * Why 15 m and 14 %: the share beyond 15 m separates the scans in tests
 * with a gap; beyond 10 m it does not. Measured (beyond 15 m / beyond 10 m):
 * KITTI 00, a road: 17-26 % / 36-45 %; the outdoor demo (the site of
 * src/sim/sites.rs, seed 1, every 9th scan): 18-34 % / 31-48 % (the old
 * strip it replaced: 18-27 % / 29-43 %); an Ouster OS0 in an enclosed space
 * with walls ~12 m away: 9-11 % / 26-28 %; velodyne_pair (outdoors, but
 * half its points within 3.5 m, where the outdoor preset is blind): 4 % /
 * 9 %; pcl_room and the indoor demo's rooms: under 1 %. 14 % lies in the
 * gap 11-17 % (near its geometric middle). The warehouse demo's scans
 * spread over it (0-16 % / 6-36 %: a large hall's far racks); its first
 * scan, in the small hall, has 2 %, and the demo uses indoor anyway.
 * Outdoor means OUTDOOR_PRESET, the paper's outdoor ranges with the
 * Hellinger distance.
 * @param {number} farShare @returns {SuggestedPreset}
 */
export function suggestPreset(farShare) {
  return farShare >= OUTDOOR_SHARE ? OUTDOOR_PRESET : 'indoor';
}

/** What the page says about a suggestion. @param {{preset: string, far: number, from: string}} s */
export function suggestionText(s) {
  const pct = Math.round(100 * s.far);
  const limit = Math.round(100 * OUTDOOR_SHARE);
  return `${s.preset} suggested: ${pct} % of the points of ${s.from} lie beyond ${FAR} m (${s.preset === OUTDOOR_PRESET ? `${limit} % or more: open space` : `under ${limit} %: a room or hall`})`;
}

/** Points of a scan the map keeps (x, y pairs, sensor frame). */
export const SITE_POINTS = 400;
/** ... within this horizontal range (m): the place around the scan, not the sparse far rings that blur the map. */
export const SITE_RANGE = 30;

/**
 * A top-down subsample of interleaved x, y, z points: at most `max`
 * (x, y) pairs within SITE_RANGE, evenly strided, so the map holds a few
 * kilobytes per scan whatever the scans' size.
 * @param {Float32Array} xyz @param {number} [max] @returns {Float32Array}
 */
export function siteSubsample(xyz, max = SITE_POINTS) {
  const near = [];
  const r2 = SITE_RANGE * SITE_RANGE;
  // Squares, not Math.hypot (V8's is slow): 0.11 -> 0.03 ms a 3,000-point preview in Node.
  for (let i = 0; i + 2 < xyz.length; i += 3) if (xyz[i] * xyz[i] + xyz[i + 1] * xyz[i + 1] <= r2) near.push(i);
  const step = Math.max(1, Math.ceil(near.length / max));
  const out = new Float32Array(2 * Math.ceil(near.length / step));
  let j = 0;
  for (let k = 0; k < near.length; k += step) {
    out[j++] = xyz[near[k]];
    out[j++] = xyz[near[k] + 1];
  }
  return out.subarray(0, j);
}

/**
 * Why the first cut has k categories, from the rule that chose k (the
 * core's `choose_k` Choice): for the default rule, the best mean
 * silhouette that decided between one category and more.
 * @param {{k: number, rule: string, one_category?: number | null}} choice
 */
export function choiceReason({ k, rule, one_category: best }) {
  if (rule === 'silhouette_gap' && typeof best === 'number') {
    const s = best.toFixed(2);
    return k === 1
      ? `the scans are alike under this descriptor, no grouping stands out (best mean silhouette ${s}, under 0.5)`
      : `the gap statistic's choice (best mean silhouette ${s})`;
  }
  const name = rule.replaceAll('_', ' ');
  return k === 1 ? `the ${name} rule finds no structure to split` : `the ${name} rule's best score`;
}
