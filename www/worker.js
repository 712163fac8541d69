// One wasm instance per worker. Each task reads and describes one scan
// (a File, so memory holds one file per worker) or simulates one demo scan.
import init, { describeScan, Simulator, Model } from './pkg/placecat.js';

const ready = init();
let simulator = null; // cached per (scene, seed, scans)
let simKey = '';
let model = null;
let modelJson = '';

function result(scan, extra = {}) {
  const preview = scan.preview();
  const out = {
    name: scan.name,
    format: scan.format,
    descriptorJson: scan.descriptorJson(),
    summary: scan.summary(),
    preview,
    ...extra,
  };
  scan.free();
  return out;
}

async function run(task) {
  await ready;
  if (task.crash || task.type === 'crash') {
    // For the fault tests: die as a worker does when it runs out of
    // memory, outside any handler, leaving the task unanswered.
    setTimeout(() => { throw new Error('worker crashed on purpose'); });
    return new Promise(() => {});
  }
  if (task.type === 'describe') {
    const bytes = new Uint8Array(await task.file.arrayBuffer());
    return result(describeScan(bytes, task.name, task.params, undefined, task.previewPoints ?? 3000));
  }
  if (task.type === 'simulate') {
    const key = `${task.scene}/${task.seed}/${task.scans}`;
    if (key !== simKey) {
      simulator?.free();
      simulator = new Simulator(task.scene, task.seed, task.scans);
      simKey = key;
    }
    const s = simulator.scan(task.index);
    return result(describeScan(s.bytes, s.name, task.params, undefined, task.previewPoints ?? 3000), {
      label: s.label,
      pose: s.pose,
    });
  }
  if (task.type === 'classify') {
    if (task.modelJson !== modelJson) {
      model?.free();
      model = Model.fromJson(task.modelJson);
      modelJson = task.modelJson;
    }
    const bytes = new Uint8Array(await task.file.arrayBuffer());
    const scan = describeScan(bytes, task.name, model.params(), undefined, 0);
    const c = model.classify(scan);
    scan.free();
    return { name: task.name, ...c };
  }
  throw new Error(`unknown task ${task.type}`);
}

self.onmessage = async (e) => {
  const { id, task } = e.data;
  try {
    const r = await run(task);
    const transfer = r.preview ? [r.preview.buffer] : [];
    self.postMessage({ id, ok: true, result: r }, transfer);
  } catch (err) {
    self.postMessage({ id, ok: false, error: String(err?.message ?? err) });
  }
};
