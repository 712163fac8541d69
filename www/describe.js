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
import { suggestPreset } from './suggest.js';
import { taskOf } from './state.js';

/** @typedef {import('./engine.js').ScanResult} ScanResult */
/** @typedef {import('./engine.js').Params} Params */
/** @typedef {import('./state.js').Suggestion} Suggestion */

/**
 * @param {import('./pool.js').WorkerPool} pool @param {import('./state.js').Input[]} inputs
 * @param {{params: Params, byPreset: Record<'indoor' | 'outdoor', Params> | null}} how
 * @param {{onPreset: (preset: 'indoor' | 'outdoor', params: Params) => void, onResult: (i: number, r: ScanResult) => void,
 *   onError: (i: number, e: Error) => void, onSettled: (done: number) => void}} on
 * @returns {Promise<{results: (ScanResult | undefined)[], done: number, suggestion: Suggestion | null}>}
 */
export async function describeInputs(pool, inputs, { params, byPreset }, on) {
  /** @type {(ScanResult | undefined)[]} */
  const results = new Array(inputs.length);
  let first = 0;
  while (byPreset && first < inputs.length) {
    try {
      const r = /** @type {ScanResult} */ (await pool.run({ ...taskOf(inputs[first], params), byPreset }));
      params = byPreset[r.preset ?? 'indoor'];
      on.onPreset(r.preset ?? 'indoor', params);
      results[first] = r;
      on.onResult(first, r);
      on.onSettled(++first);
      break;
    } catch (e) {
      if (e.message === 'cancelled') return { results, done: first, suggestion: null };
      on.onError(first, e);
      on.onSettled(++first);
    }
  }
  const tasks = inputs.slice(first).map((input, i) => ({ ...taskOf(input, params), probe: i === 0 && first === 0 }));
  const rest = await pool.runAll(tasks, {
    onResult: (i, r) => on.onResult(first + i, r),
    onError: (i, e) => on.onError(first + i, e),
    onSettled: (n) => on.onSettled(first + n),
  });
  rest.results.forEach((r, i) => (results[first + i] = r));
  const measured = results.find((r) => r?.far !== undefined);
  const suggestion = measured ? { preset: suggestPreset(measured.far ?? 0), far: measured.far ?? 0, from: measured.name } : null;
  return { results, done: first + rest.done, suggestion };
}
