// One wasm instance per worker. Each task describes one scan (its bytes,
// read and moved here by the page, pool.js; memory holds the bytes of the
// tasks the worker holds: up to eight, within 32 MB, with the page's pool),
// simulates one demo scan, computes rows of the Delta matrix or reference
// sets of the choice of categories (matrix.js), clusters a set spectrally
// (app.js), or classifies one scan with a model; the engine does the wasm
// work. A ROS bag is read in slices and its clouds posted one at a time as
// partial replies, and so is an E57 survey's stations (bagreader.js).
import init, * as wasm from './pkg/placecat.js';
import { Describer } from './engine.js';
import { bagTopics, describeBag, describeSurvey } from './bagreader.js';

const ready = init().then(() => new Describer(wasm));

/** Wall-clock ms, comparable across the page and its workers (performance.now() is not). */
const now = () => performance.timeOrigin + performance.now();

/**
 * @param {any} task @param {(p: any, transfer: Transferable[]) => void} partial
 * @param {{arrived: number, start: number, read: number, end: number}} clock when the task came, started, had its file's bytes, ended
 * @param {Promise<ArrayBuffer> | null} file the task's file, being read
 */
async function run(task, partial, clock, file) {
  const describer = await ready;
  describer.taskArrives(task.type);
  if (task.type === 'bag') return describeBag(wasm, task, partial);
  if (task.type === 'survey') return describeSurvey(wasm, task, partial);
  if (task.type === 'bagTopics') return bagTopics(wasm, task.file, task.name);
  if (task.type === 'describe') {
    const bytes = new Uint8Array(await /** @type {Promise<ArrayBuffer>} */ (file));
    clock.read = now();
    if (task.byPreset) return describer.describeSuggesting(bytes, task.name, task.byPreset, task.previewPoints);
    return describer.describe(bytes, task.name, task.params, task.previewPoints);
  }
  if (task.type === 'deltaRows') return describer.deltaRows(task.key, task.params, task.descriptorJsons, task.rows);
  if (task.type === 'references') return describer.referenceDispersions(task.key, task.params, task.descriptorJsons, task.seed, task.which, task.restarts);
  if (task.type === 'spectral') return describer.spectral(task.params, task.descriptorJsons, task.matrix, task.k, task.seed, task.kmeansSeeded);
  if (task.type === 'simulate') return describer.simulate(task, task.params, task.previewPoints);
  if (task.type === 'classify') {
    return describer.classify(new Uint8Array(await /** @type {Promise<ArrayBuffer>} */ (file)), task.name, task.modelJson);
  }
  throw new Error(`unknown task ${task.type}`);
}

/** The tasks run one after another, in the order they came. */
let queue = Promise.resolve();

self.onmessage = (e) => {
  const { id, task } = e.data;
  // The file's bytes, read by the page (pool.js) or read here now, while the task before is described.
  const reads = task.type === 'describe' || task.type === 'classify';
  const file = task.bytes ? Promise.resolve(/** @type {ArrayBuffer} */ (task.bytes)) : reads ? /** @type {File} */ (task.file).arrayBuffer() : null;
  file?.catch(() => {}); // its error is the task's, when the task awaits it
  const arrived = now();
  queue = queue.then(() => runAndReply(id, task, file, arrived));
};

/** @param {number} id @param {any} task @param {Promise<ArrayBuffer> | null} file @param {number} arrived */
async function runAndReply(id, task, file, arrived) {
  const clock = { arrived, start: now(), read: 0, end: 0 };
  try {
    const r = await run(task, (p, transfer) => self.postMessage({ id, partial: p }, { transfer }), clock, file);
    clock.end = now();
    const transfer = r instanceof Float32Array || r instanceof Float64Array || r instanceof Int32Array ? [r.buffer] : r && 'preview' in r ? [r.preview.buffer, ...(r.site ? [r.site.buffer] : [])] : [];
    self.postMessage({ id, ok: true, result: r, clock }, { transfer });
  } catch (err) {
    self.postMessage({ id, ok: false, error: String(/** @type {any} */ (err)?.message ?? err) });
  }
}
