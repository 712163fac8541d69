// A run of the worker pool over a data set's inputs, with the preset
// suggestion. For the files of a new data set (`byPreset` given), the
// first scan goes alone: the worker that reads it measures how far its
// points lie, picks the preset (suggest.js) and describes it with that
// preset; the rest then follow with the same preset. So no file is read
// twice, at the cost of one scan's time on one worker. One scan decides:
// the scans of one data set come from one sensor in one kind of place, and
// the user can change the preset (the whole set is then described again).
// If the first scan fails, the next one decides. For the demo the scene's
// preset is known; its first scan is only measured, to show the suggestion.
// A recording (a bag, an E57 survey) is one input of many scans.
import { suggestPreset } from './suggest.js';
import { taskOf } from './state.js';

/** @typedef {import('./engine.js').ScanResult} ScanResult */
/** @typedef {import('./engine.js').Params} Params */
/** @typedef {import('./state.js').Suggestion} Suggestion */

/**
 * Describe the inputs. A file or demo scan is one result; a bag (bag.js) is
 * many, each sent as it is described (a partial reply), and counts in the
 * progress as its clouds read (`total`: the topic's clouds, known once the
 * worker opened the bag), where any other input counts one.
 * `results[i]`: the input's scan, or a bag's scans so far (kept when the
 * run is cancelled or the bag fails half way).
 * @param {import('./pool.js').WorkerPool} pool @param {import('./state.js').Input[]} inputs
 * @param {{params: Params, byPreset: Record<import('./suggest.js').SuggestedPreset, Params> | null}} how
 * @param {{onPreset: (preset: import('./suggest.js').SuggestedPreset, params: Params) => void, onResult: (i: number, r: ScanResult, j: number) => void,
 *   onError: (i: number, e: Error) => void, onProgress: (done: number, total: number) => void}} on
 * @returns {Promise<{results: (ScanResult | ScanResult[] | undefined)[], done: number, total: number, suggestion: Suggestion | null,
 *   bags: (import('./bag.js').BagInfo | undefined)[]}>} `bags`: what each bag's worker said of it at the end
 */
export async function describeInputs(pool, inputs, { params, byPreset }, on) {
  /** @type {(ScanResult | ScanResult[] | undefined)[]} */
  const results = new Array(inputs.length);
  /** @type {(import('./bag.js').BagInfo | undefined)[]} */
  const bags = new Array(inputs.length);
  // What each input counts in the progress and how much of it is done, and
  // their running sums (summed again at every result, they cost O(n^2) a run).
  const units = inputs.map(() => 1);
  const met = inputs.map(() => 0);
  let allUnits = inputs.length, allMet = 0;
  /** @param {number} i @param {number} value */
  const setUnits = (i, value) => ((allUnits += value - units[i]), (units[i] = value));
  /** @param {number} i @param {number} value */
  const setMet = (i, value) => ((allMet += value - met[i]), (met[i] = value));
  const progress = () => on.onProgress(allMet, allUnits);
  /** @param {number} i @param {import('./bagreader.js').BagPartial} p */
  const partial = (i, p) => {
    setUnits(i, Math.max(1, p.total));
    setMet(i, p.met);
    if (p.scan) {
      const list = /** @type {ScanResult[]} */ (results[i] ??= []);
      list.push(p.scan);
      on.onResult(i, p.scan, list.length - 1);
    }
    if (p.error) on.onError(i, new Error(p.error));
    progress();
  };
  /** @type {{far: number, from: string} | null} the scan (or bag) whose far points were measured */
  let measured = null;
  /** @param {number} i @param {any} r */
  const finished = (i, r) => {
    setMet(i, units[i]);
    if (r.far !== undefined) measured ??= { far: r.far, from: r.recording ? inputs[i].name : r.name };
    if (r.recording) return (bags[i] = r);
    results[i] = r;
    on.onResult(i, r, 0);
  };
  /** @param {number} i @param {Error} e */
  const failed = (i, e) => {
    setMet(i, units[i]);
    on.onError(i, e);
  };
  let first = 0;
  while (byPreset && first < inputs.length) {
    const i = first;
    try {
      const r = await pool.run({ ...taskOf(inputs[i], params), byPreset }, (p) => partial(i, p));
      params = byPreset[r.preset ?? 'indoor'];
      on.onPreset(r.preset ?? 'indoor', params);
      finished(i, r);
      first++;
      progress();
      break;
    } catch (e) {
      if (e.message === 'cancelled') return { results, done: allMet, total: allUnits, suggestion: null, bags };
      failed(i, e);
      first++;
      progress();
    }
  }
  const tasks = inputs.slice(first).map((input, i) => ({ ...taskOf(input, params), probe: i === 0 && first === 0 }));
  await pool.runAll(tasks, {
    onResult: (i, r) => finished(first + i, r),
    onError: (i, e) => failed(first + i, e),
    onSettled: progress,
    onPartial: (i, p) => partial(first + i, p),
  });
  const m = /** @type {{far: number, from: string} | null} */ (measured); // set in callbacks, which the type check does not follow
  const suggestion = m ? { preset: suggestPreset(m.far), ...m } : null;
  return { results, done: allMet, total: allUnits, suggestion, bags };
}
