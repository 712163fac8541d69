// The page's wiring: user events and worker results become state
// transitions (state.js) and engine calls (engine.js, the only wasm user);
// the view (view.js) shows the state. Load scans, describe them in a worker
// pool, cluster, and let the user name categories.
import init, * as wasm from './pkg/placecat.js';
import { Engine } from './engine.js';
import { WorkerPool } from './pool.js';
import { describeInputs } from './describe.js';
import { importNames } from './imports.js';
import { View, $, download } from './view.js';
import * as S from './state.js';
import { loadNames, saveNames, datasetId } from './store.js';
import { beginSession, saveScans, lastSession } from './session.js';
import { Batch } from './batch.js';
import { dropZone, filesFromInput, sortFiles, baseName, isSurvey } from './files.js';
import { chooseBagReading, rethinned, showBags, onThinning } from './bag.js';
import { stage, stageSince, clearStages } from './stages.js';
import { matrixInWorkers, referencesInWorkers, tailKey, oneAtATime } from './matrix.js';
import { OUTDOOR_PRESET } from './suggest.js';

/** @typedef {import('./state.js').State} State */
/** How often a run shows its progress and saves its results (ms). */
const TICK_MS = 200;
/** From this many scans the workers compute the Delta matrix and the choice's reference sets (below, they take milliseconds). */
const WORKER_MATRIX_FROM = 200;
let state = S.initialState();
/**
 * The run (state.run) whose tail (Delta matrix, reference sets) the workers
 * compute, until its last task settled: its describing is over (state.running is false) but the
 * pool still works for it, so a new run or Cancel must cancel the pool then too.
 * @type {number | null}
 */
let tailOf = null;
/**
 * The reference sets of the choice of categories that the workers compute
 * for a set (state.set) and a tree seed and trials a split (matrix.js); null where they failed.
 * @type {{set: State['set'], seed: number, restarts: number, dispersions: Promise<Float64Array | null>} | null}
 */
let references = null;
/**
 * A cut the user asked for before the tree existed (while the scans were
 * described or the workers computed the matrix): the next tree is cut so,
 * not by the automatic choice. A new run forgets it.
 * @type {{how: {k: number} | {threshold: number}, by: State['cutBy']} | null}
 */
let askedCut = null;
/** Clusterings asked for so far (and new runs): a clustering that ends after a newer one was asked for is dropped. */
let clusterings = 0;
/**
 * The spectral clusterings the workers run for the page, until each settles:
 * a newer clustering stops them (pool.stop), a new run or Cancel cancels them.
 * @type {Set<Promise<Int32Array>>}
 */
const spectralTasks = new Set();
/** Whether the pool works for the page (describing, the run's Delta matrix or reference sets, a spectral clustering). */
const poolBusy = () => state.running || tailOf !== null || spectralTasks.size > 0;
/** A new run cancels what the pool does for the page; a spectral clustering it stops is superseded, not "cancelled". */
function cancelForNewRun() {
  clusterings++;
  // Nothing is left to wait for (scripts wait until clustered reaches asked).
  document.body.dataset.asked = document.body.dataset.clustered = String(clusterings);
  if (poolBusy()) pool.cancel();
}
/** The running run's batch of results to save, flushed when the page is hidden (a reload, a closed tab). @type {Batch<any> | null} */
let unsaved = null;
const engine = new Engine(wasm);
// A scan's file is read here and its bytes moved to the worker (not
// copied): a worker reads a File only between two descriptions (the bytes
// come in through its own event loop), so reading there made the workers
// wait; the main thread is idle meanwhile. Each worker holds eight tasks,
// so the next files are read while it describes: with six reads at once a
// file took ~30 ms to come (median, 1,000 scans of 1.3 MB, a loaded
// machine), three descriptions' time, and with four tasks a worker the
// workers still waited ~1.1 s of a 1,000-scan run for their next task (the
// reads, on the browser's threads, get the cores in bursts); eight halved
// that. Memory: at most eight files a worker, and more than one only while
// they total 32 MB (large scans, e.g. 1M points, are held one or two at a
// time). A bag or an E57 survey (or the listing of a bag's topics)
// has a worker to itself and reads the file itself, in slices; a reference
// set of the tail is held alone too, so that it goes to a free worker (matrix.js).
const pool = new WorkerPool(new URL('./worker.js', import.meta.url), undefined, {
  depth: 8,
  bytes: (task) => task.file?.size ?? 0,
  maxBytes: 32 * 2 ** 20,
  alone: (task) => task.type === 'bag' || task.type === 'survey' || task.type === 'bagTopics' || task.type === 'spectral' || oneAtATime(task),
  prepare: (task) => task.type === 'describe' && task.file
    ? task.file.arrayBuffer().then((/** @type {ArrayBuffer} */ bytes) => ({ task: { ...task, file: undefined, bytes }, transfer: [bytes] }))
    : null,
  // A spectral clustering's matrix (a copy, up to 16 MB) is moved, not copied again.
  transfer: (task) => task.type === 'spectral' ? [task.matrix.buffer] : [],
});
const view = new View({
  onThreshold: (t) => cutTree({ threshold: t }, 'threshold'),
  onName: (i, name) => {
    state = S.withName(state, i, name);
    if (!saveNames(state.datasetId, state.anchors)) $('import-status').textContent = 'Could not save names in this browser; export them.';
    view.recolour(state);
  },
  onSweepPick: () => cluster(),
  onScale: (scale) => { state = S.withScale(state, scale); render(); },
});

const preset = () => /** @type {import('./engine.js').Preset} */ ($('preset').value);
const showPreset = () => ($('advanced').value = JSON.stringify(engine.presetParams(preset()), null, 1));
/** @param {string} p */
const setPreset = (p) => { $('preset').value = p; showPreset(); };

/** @param {string} name @param {string} message */
const addError = (name, message) => view.errors((state = S.withError(state, name, message)));

/** @param {{file: File, name: string}[]} list */
async function loadFiles(list) {
  clearStages();
  performance.mark('placecat:files');
  const { scans, truth, poses, other } = sortFiles(list);
  for (const f of truth) await loadTruth(f.file);
  for (const f of poses) await loadPoses(f.file, f.name);
  if (scans.length === 0) {
    // Only a poses file or labels.csv is fine (they apply to the scans shown).
    if (other.length) addError('input', 'no scans (PLY, PCD, KITTI .bin, LAS/LAZ, E57) or ROS bags among the files');
    if (state.scans.length) render();
    return;
  }
  const names = scans.map((s) => baseName(s.name));
  cancelForNewRun(); // a bag's topics are listed in the pool, before the run
  const inputs = await chooseBagReading(pool, scans.map((s, i) => ({ name: names[i], file: s.file })));
  if (!inputs) return; // files dropped again while a bag's topic was asked for
  const run = { datasetId: datasetId(names), demo: null, inputs };
  // The data suggest indoor or outdoor unless the user chose another preset (the paper's two and the suggested ones do not stick) or edited the parameters.
  const own = !['indoor', 'outdoor', OUTDOOR_PRESET].includes(preset()) || $('advanced').value !== JSON.stringify(engine.presetParams(preset()), null, 1);
  await describeAll(run, { suggest: !own, withPosesFile: poses.length > 0, fromFiles: true });
}

/** @param {File} file */
async function loadTruth(file) {
  try {
    state = S.withTruthCsv(state, await file.text());
  } catch (e) {
    return addError(file.name, e.message);
  }
  if (state.scans.length) render();
  if ($('sweep-table').childElementCount) runSweep(); // now with S
}

/** @param {File} file @param {string} name */
async function loadPoses(file, name) {
  const text = await file.text();
  try {
    state = S.withPoses(state, engine.parsePoses(text, name));
  } catch (e) {
    addError(name, e.message);
    state = S.withPoses(state, null);
  }
  if (state.scans.length) render();
}

/** @param {S.Scene} scene */
function startDemo(scene) {
  setPreset(S.DEMO_PRESET[scene]);
  describeAll({ ...S.demoInputs(scene), demo: scene });
}

/**
 * Describe every input in the worker pool, with progress; a newer run supersedes this one.
 * `suggest`: a new data set of files, whose first scan picks the preset (describe.js);
 * `fromFiles`: files just given (their mark, placecat:files, is this run's).
 * @param {{datasetId: string, demo: State['demo'], inputs: import('./state.js').Input[]}} [run]
 */
async function describeAll({ datasetId, demo, inputs } = state, { suggest = false, withPosesFile = false, fromFiles = false } = {}) {
  cancelForNewRun();
  askedCut = null;
  clearStages(fromFiles ? ['placecat:files'] : []);
  let params;
  try {
    params = engine.validateParams(JSON.parse($('advanced').value || '{}'), preset());
  } catch (e) {
    view.reset((state = S.withoutResults(state)));
    return addError('parameters', e.message);
  }
  view.reset((state = S.beginRun(state, { datasetId, demo, inputs, anchors: loadNames(datasetId), params, withPosesFile })));
  const run = state.run;
  const current = () => run === state.run;
  pool.clocks = [];
  const began = performance.now();
  const total = inputs.length;
  // A bag counts its clouds read; any other input counts one, a survey its stations.
  const unit = inputs.some((i) => i.bag) ? 'clouds' : 'scans';
  // With a recording (a bag, a survey) among the inputs, `total` counts inputs, not scans.
  const recordings = inputs.some((i) => i.bag || isSurvey(i.name));
  view.progress(0, total, 'running', unit);
  /** @type {Promise<unknown> | null} the session starts once the preset is known */
  let session = null;
  /** @type {[number, number] | null} the progress to show at the next tick */
  let shown = null;
  /** @type {Promise<unknown>} the progress shown waits for the results it counts to be saved */
  let saved = Promise.resolve();
  let finished = false;
  // A few times a second: the results to save and the progress (batch.js).
  // The progress is shown once the results it counts are stored, so what
  // it says survives a reload.
  /** @type {Batch<[number, import('./engine.js').ScanResult]>} */
  const tick = new Batch(TICK_MS, (saves) => {
    if (!current()) return;
    if (saves.length) {
      // IndexedDB runs transactions on one store in the order they were made: the session's comes first.
      session ??= beginSession(datasetId, { total, counts: recordings ? 'inputs' : 'scans', preset: preset(), params: state.params, demo });
      saved = Promise.all([saved, saveScans(datasetId, saves).catch((e) => current() && addError('saving', e.message))]);
    }
    const show = shown;
    if (show) saved.then(() => current() && !finished && view.progress(show[0], show[1], 'running', unit));
  });
  unsaved = tick;
  const byPreset = suggest ? { indoor: engine.presetParams('indoor'), [OUTDOOR_PRESET]: engine.presetParams(OUTDOOR_PRESET) } : null;
  const described = describeInputs(pool, inputs, { params, byPreset }, {
    onPreset: (p, chosen) => current() && (setPreset(p), (state = S.withParams(state, chosen))),
    // A bag's jth cloud is stored at i + j / 1e7: after input i, before i + 1, in order.
    onResult: (i, r, j) => tick.add([i + j / 1e7, r]),
    onError: (i, e) => current() && addError(inputs[i].name, e.message),
    onProgress: (n, all) => ((shown = [n, all]), tick.add()),
  });
  knowSizes(inputs, current);
  const { results, done, total: all, suggestion, bags } = await described;
  tick.flush();
  finished = true;
  if (unsaved === tick) unsaved = null;
  if (!current()) return;
  stageSince('describe', began);
  if (suggestion) state = S.withSuggestion(state, suggestion);
  state = S.finishRun(state, results);
  view.progress(done, all, done < all ? 'cancelled' : 'done', unit);
  if (recordings) showBags(inputs, bags);
  loadSet();
  // A cancelled run leaves the workers alone: the set computes its matrix.
  if (done === all) await tailFromWorkers(current);
  if (!current()) return;
  view.sweep('');
  await cluster();
  if (!current()) return;
  stageSince('run', began);
  performance.mark('placecat:pool', { detail: pool.clocks });
  // Finished runs, for scripts that drive the page (and the e2e tests).
  document.body.dataset.runs = String(Number(document.body.dataset.runs || 0) + 1);
}

/**
 * Ask each file's size now, once the first task is posted (the pool needs
 * them to keep a worker's files within maxBytes). A File from the input
 * asks the browser for its size synchronously the first time, then keeps
 * it: 1,000 files take ~0.17 s now, while the browser is idle, but took
 * the main thread 1.5-1.6 s when asked one by one during the run (the
 * browser's threads busy reading files; the workers waited for tasks).
 * In slices of 25 files, so that the results and reads that come meanwhile
 * are handled between them (in one loop they waited 0.2 s); stops when the
 * run is superseded.
 * @param {import('./state.js').Input[]} inputs @param {() => boolean} current @param {number} [from]
 */
function knowSizes(inputs, current, from = 0) {
  const to = Math.min(inputs.length, from + 25);
  for (let i = from; i < to; i++) void inputs[i].file?.size;
  if (to < inputs.length) setTimeout(() => current() && knowSizes(inputs, current, to));
}

function buildSet() {
  loadSet();
  view.sweep('');
  cluster();
}

function loadSet() {
  state = S.withSet(state, stage('load', () => engine.load(/** @type {S.State['params'] & {}} */ (state.params), state.scans.map((r) => r.descriptorJson))));
}

/**
 * The tail of the run in the workers (matrix.js): the set's Delta matrix,
 * when the set keeps one, and the reference sets of the first cut's choice,
 * when the tree's first cut is to be chosen; only from enough scans to
 * matter. Returns once the matrix is the set's: the reference sets come
 * while the tree is built (cluster). If the workers fail or the run is
 * superseded, the set computes its own.
 * @param {() => boolean} current whether the run is still the page's
 */
async function tailFromWorkers(current) {
  if (!state.set || state.scans.length < WORKER_MATRIX_FROM) return;
  const start = performance.now();
  const run = state.run;
  const params = /** @type {S.State['params'] & {}} */ (state.params);
  const jsons = state.scans.map((r) => r.descriptorJson);
  const key = tailKey();
  const m = view.method();
  // Every task of the tail, so that the pool counts as busy until the last
  // settles: the matrix's or the reference sets' promise settles at the
  // first failure, while the rest may still be queued (and then a Cancel or
  // a new run would leave them queued, and wait behind them).
  /** @type {Promise<unknown>[]} */
  const tasks = [];
  const tracked = { size: pool.size, run: (/** @type {any} */ task) => { const p = pool.run(task); tasks.push(p); return p; } };
  const matrix = state.set.usesMatrix ? matrixInWorkers(tracked, params, jsons, key) : null;
  const restarts = S.treeRestarts(m.hkSplits, state.scans.length);
  const dispersions = m.method === 'hkmeans' && 'auto' in S.nextCut(state)
    ? referencesInWorkers(tracked, params, jsons, { seed: m.hkSeed, restarts, sets: engine.referenceSets() }, key).catch(() => null)
    : null;
  if (dispersions) references = { set: state.set, seed: m.hkSeed, restarts, dispersions };
  if (!matrix && !dispersions) return;
  tailOf = run;
  Promise.allSettled(tasks).then(() => tailOf === run && (tailOf = null));
  if (!matrix) return;
  try {
    const values = await matrix;
    if (current()) engine.setMatrix(values);
  } catch {
    // cancelled (Cancel or a new run), or a worker died: the main thread computes it
  }
  if (current()) stageSince('matrix', start); // not into a newer run's measures
}

/**
 * The reference sets' dispersions the workers compute for this set's tree of `seed` and `restarts`, if any.
 * @param {number} seed @param {number} restarts
 */
function workersDispersions(seed, restarts) {
  const r = references;
  return r && r.set === state.set && r.seed === seed && r.restarts === restarts ? r.dispersions : null;
}

/**
 * Cluster the set by the method shown; the first cut of a tree waits for the
 * workers' reference sets, if they compute them, and a spectral clustering for
 * its worker. For scripts that drive the page (and the e2e tests), `body`'s
 * data: `asked`, the clusterings asked for; `clustered`, the same once the
 * latest has settled; `spectral`, spectral clusterings in flight; `stopped`,
 * those a newer clustering stopped.
 */
async function cluster() {
  const mine = ++clusterings;
  document.body.dataset.asked = String(mine);
  for (const task of spectralTasks) {
    pool.stop(task);
    document.body.dataset.stopped = String(Number(document.body.dataset.stopped || 0) + 1);
  }
  try {
    await clusterBy(view.method(), mine);
  } finally {
    if (mine === clusterings) document.body.dataset.clustered = String(mine);
  }
}

/** @param {ReturnType<View['method']>} m @param {number} mine this clustering's number (`clusterings`) */
async function clusterBy(m, mine) {
  if (state.scans.length === 0) {
    view.status('No described scans yet.');
    return render();
  }
  try {
    if (m.method === 'hkmeans') {
      const next = S.nextCut(state);
      const restarts = S.treeRestarts(m.hkSplits, state.scans.length);
      state = S.withTree(state, stage('tree', () => engine.hkmeans(m.hkSeed, restarts)));
      const asked = askedCut;
      askedCut = null;
      if (asked) cutTree(asked.how, asked.by);
      if (!('auto' in next)) return asked ? undefined : cutTree(next);
      const start = performance.now();
      const tree = state.tree;
      const pending = workersDispersions(m.hkSeed, restarts);
      const dispersions = pending && (await pending);
      if (state.tree !== tree || mine !== clusterings) return; // clustered again meanwhile (a spectral clustering sets no tree until it ends)
      state = S.withFirstCut(state, engine.suggestCategories(dispersions, m.hkSeed, restarts));
      stageSince('choose', start); // with the wait for the workers
      // The user cut the tree meanwhile (or before it existed): their cut stays; the choice is only recorded.
      if (state.cut) return render();
      return cutTree({ k: state.firstCut?.k ?? 1 });
    }
    // k-means with spectral seeding clusters spectrally first: in a worker, as spectral clustering.
    const labels = m.method === 'kmeans' && m.seeding === 'spectral' ? await spectralInWorker(m.k, m.kmSeed, mine, true)
      : m.method === 'kmeans' ? engine.kmeans(m.k, m.seeding, m.kmSeed, m.restarts)
      : m.method === 'spectral' ? await spectralInWorker(m.spK, m.spSeed, mine)
        : engine.dbscan(m.eps, m.minPoints);
    if (!labels) return; // a spectral clustering superseded or cancelled
    state = S.withLabels(state, labels, engine.medoids(labels));
  } catch (e) {
    return view.status(e.message);
  }
  render();
}

/**
 * Spectral clustering of the page's set in a worker: it grows with the cube of
 * the scans (in Node's wasm 1.4 s for 1000, 11 s for 2000), so on the page's
 * thread it would hold the page. The worker gets the set's Delta matrix,
 * computed once already. Resolves to null when a newer clustering, a new run
 * or Cancel came meanwhile. With `kmeansSeeded`, k-means started from spectral
 * clustering's groups (the `spectral` seeding), which clusters spectrally first.
 * @param {number} k @param {number} seed @param {number} mine this clustering's number (`clusterings`)
 * @param {boolean} [kmeansSeeded] @returns {Promise<Int32Array | null>}
 */
async function spectralInWorker(k, seed, mine, kmeansSeeded = false) {
  const set = state.set;
  const superseded = () => mine !== clusterings || state.set !== set;
  const n = state.scans.length;
  const what = kmeansSeeded ? 'k-means with spectral seeding' : 'spectral clustering';
  const What = what[0].toUpperCase() + what.slice(1);
  // Refused here, before the matrix is copied out for a worker, at the core's own limit
  // (without a set, the engine refuses, as for the other methods).
  if (set && n > set.spectralLimit) throw new RangeError(`${what} takes at most ${set.spectralLimit} scans (it grows with the cube of their number), got ${n}; use the tree or k-means++`);
  const start = performance.now();
  const task = pool.run({
    type: 'spectral', params: /** @type {S.State['params'] & {}} */ (state.params), descriptorJsons: state.scans.map((r) => r.descriptorJson),
    matrix: engine.deltaMatrix(), k, seed, kmeansSeeded,
  });
  spectralTasks.add(task);
  document.body.dataset.spectral = String(spectralTasks.size);
  view.status(`${What} of ${n} ${n === 1 ? 'scan' : 'scans'} into ${k} in a worker...`);
  try {
    const labels = await task;
    if (superseded()) return null;
    stageSince(kmeansSeeded ? 'kmeans' : 'spectral', start);
    return labels;
  } catch (e) {
    if (superseded()) return null;
    if (/** @type {Error} */ (e).message === 'cancelled') {
      view.status(`${What} cancelled; choose k or the method again to run it.`);
      return null;
    }
    throw e;
  } finally {
    spectralTasks.delete(task);
    document.body.dataset.spectral = String(spectralTasks.size);
  }
}

/** Cut the tree into k categories (where two splits share a height no
 * threshold gives k; the k - 1 highest splits still do) or at a threshold.
 * @param {{k: number} | {threshold: number}} how @param {State['cutBy']} [by] what the user set */
function cutTree(how, by) {
  if (by) state = S.withCutBy(state, by);
  if (!state.tree) {
    if (by) askedCut = { how, by };
    return;
  }
  try {
    const cut = stage('cut', () => 'k' in how ? engine.cutK(S.clampCategories(state, how.k)) : engine.cut(how.threshold));
    state = S.withLabels(state, cut.labels, stage('medoids', () => engine.medoids(cut.labels)), cut);
  } catch (e) {
    return view.status(e.message);
  }
  render();
}

function render() {
  stage('draw', () => view.render(state, preset(), state.scans.length === 2 && state.set ? engine.delta(0, 1) : undefined));
  const labels = state.labels;
  if (!labels || labels.length !== state.scans.length) return;
  const truth = S.truthLabels(state);
  view.accuracy(!state.truth ? '' : truth ? engine.evaluate(truth, labels) : 'labels.csv does not cover every scan');
}

/** DBSCAN over the set's own epsilon grid x a few min points (placecat sweep's default). */
function runSweep() {
  if (!state.set || state.scans.length < 2) return view.sweep('Describe at least two scans first.');
  try {
    view.sweep(engine.sweep([2, 3, 5, 8, 12], S.truthLabels(state)));
  } catch (e) {
    view.sweep(e.message);
  }
}

/** @param {File} file */
async function importFile(file) {
  try {
    const imported = importNames(state, engine, file.name, await file.text());
    state = imported.state;
    $('import-status').textContent = imported.said;
    saveNames(state.datasetId, state.anchors);
    render();
  } catch (e) {
    $('import-status').textContent = `Rejected ${file.name}: ${e.message}. Nothing was changed.`;
  }
}

/** Classify files with the loaded model, in the workers. @param {FileList} list */
function classifyFiles(list) {
  view.classified(filesFromInput(list).map(({ file, name }) => {
    const task = { type: 'classify', file, name: baseName(name), modelJson: state.modelJson };
    return { name: task.name, result: pool.run(task) };
  }));
}

/** Show the scans of the last session (e.g. after a reload mid-run). */
async function restore() {
  const last = await lastSession();
  if (!last) return;
  state = S.restoreSession(state, last, loadNames(last.datasetId));
  setPreset(last.preset ?? preset());
  const of = last.counts === 'inputs' ? `scans of ${last.total} ${last.total === 1 ? 'input' : 'inputs'}` : `of ${last.total} scans`;
  $('info').textContent = `Restored ${state.scans.length} ${of} from the last session. Load the files again to describe the rest.`;
  buildSet();
}

/** @param {string} id @param {string} type @param {(e: any) => void} fn */
const on = (id, type, fn) => $(id).addEventListener(type, fn);

async function main() {
  await init();
  showPreset();
  view.showMethod();
  on('files', 'change', (e) => loadFiles(filesFromInput(e.target.files)));
  on('folder', 'change', (e) => loadFiles(filesFromInput(e.target.files)));
  on('poses', 'change', (e) => e.target.files[0] && loadPoses(e.target.files[0], e.target.files[0].name));
  on('truth', 'change', (e) => e.target.files[0] && loadTruth(e.target.files[0]));
  on('demo-indoor', 'click', () => startDemo('indoor'));
  on('demo-outdoor', 'click', () => startDemo('outdoor'));
  on('demo-warehouse', 'click', () => startDemo('warehouse'));
  on('cancel', 'click', () => poolBusy() && pool.cancel());
  dropZone($('drop'), loadFiles);
  // A reload or a closed tab: store the results of the last fraction of a second too.
  addEventListener('pagehide', () => unsaved?.flush());
  document.addEventListener('visibilitychange', () => document.visibilityState === 'hidden' && unsaved?.flush());
  on('preset', 'change', () => { showPreset(); if (state.inputs.length) describeAll(); });
  on('apply-advanced', 'click', () => state.inputs.length && describeAll());
  onThinning(() => state.inputs.some((i) => i.bag) && describeAll({ ...state, inputs: rethinned(state.inputs) }));
  on('method', 'change', () => { view.showMethod(); cluster(); });
  for (const id of ['hk-seed', 'hk-splits', 'k', 'seeding', 'km-seed', 'sp-k', 'sp-seed', 'eps', 'minpts']) on(id, 'change', cluster);
  on('threshold', 'change', () => cutTree({ threshold: Math.max(0, Number($('threshold').value) || 0) }, 'threshold'));
  on('categories', 'change', () => cutTree({ k: Number($('categories').value) }, 'categories'));
  on('sweep', 'click', runSweep);
  on('export-csv', 'click', () => state.labels && download('placecat-categories.csv', S.categoriesCsv(state), 'text/csv'));
  on('export-model', 'click', () => state.labels && download('placecat-model.json', engine.modelJson(state.labels, S.modelNames(state)), 'application/json'));
  on('import', 'change', (e) => e.target.files[0] && importFile(e.target.files[0]));
  on('classify', 'change', (e) => classifyFiles(e.target.files));
  await restore();
  document.body.dataset.ready = 'true';
}

main().catch((e) => {
  document.body.dataset.ready = 'error';
  $('info').textContent = `placecat failed to start: ${e.message}`;
});
