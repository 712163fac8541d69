// The page: load scans, describe them in a worker pool, cluster, show the
// dendrogram and the map, and let the user name categories.
import init, { DescriptorSet, Model, parsePoses, presetParams, validateParams } from './pkg/placecat.js';
import { WorkerPool } from './pool.js';
import { Dendrogram } from './dendrogram.js';
import { TrajectoryMap } from './map.js';
import { renderSweep, f32String } from './sweep.js';
import { colour, drawThumbnail, shareColours } from './colours.js';
import { loadNames, saveNames, datasetId } from './store.js';
import { beginSession, saveScan, lastSession } from './session.js';
import { filesFromDrop, filesFromInput, isScan, isTruth, isPoses, baseName } from './files.js';

const $ = (id) => document.getElementById(id);

const state = {
  datasetId: '',
  inputs: [], // [{name, file} | {name, sim}] in scan order
  scans: [], // described scans, in order: {name, descriptorJson, summary, preview, pose?, truth?}
  errors: [],
  poses: null,
  truth: null, // Map name -> label
  params: null,
  set: null,
  tree: null,
  cutBy: undefined, // 'threshold' | 'categories': what the user set last
  labels: null,
  categories: [], // [{label, members, medoid}]
  anchors: {},
  model: null,
  modelJson: '',
  running: false,
};

const pool = new WorkerPool(new URL('./worker.js', import.meta.url));
const dendrogram = new Dendrogram($('dendrogram'), {
  onThreshold: (t) => {
    state.cutBy = 'threshold';
    setThreshold(t);
  },
  onHover: (c, e) => hover(c, e),
});
const map = new TrajectoryMap($('map'), { onSelect: (i) => selectScan(i) });

// ---- parameters -----------------------------------------------------------

function currentParams() {
  return validateParams(JSON.parse($('advanced').value || '{}'), $('preset').value);
}

function showPreset() {
  const p = presetParams($('preset').value);
  $('advanced').value = JSON.stringify(p, null, 1);
}

// ---- loading and describing -----------------------------------------------

function resetResults() {
  state.scans = [];
  state.errors = [];
  state.set?.free();
  state.set = null;
  state.tree?.free();
  state.tree = null;
  state.labels = null;
  clearSweep();
  state.categories = [];
  $('errors').replaceChildren();
  $('errors-box').hidden = true;
  $('accuracy').textContent = '';
  $('info').textContent = '';
}

function addError(name, message) {
  state.errors.push({ name, message });
  const li = document.createElement('li');
  li.textContent = message.startsWith(name) ? message : `${name}: ${message}`;
  $('errors').append(li);
  $('errors-box').hidden = false;
  $('errors-summary').textContent = `${state.errors.length} file(s) skipped`;
}

async function loadFiles(list) {
  const scans = list.filter((f) => isScan(f.name)).sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
  const others = list.filter((f) => !isScan(f.name));
  for (const f of others) {
    if (isTruth(f.name)) await loadTruth(f.file);
    else if (isPoses(f.name)) await loadPoses(f.file, f.name);
  }
  if (scans.length === 0) {
    // Only a poses file or labels.csv is fine (they apply to the scans shown).
    if (others.some((f) => !isTruth(f.name) && !isPoses(f.name))) addError('input', 'no PLY, PCD or .bin scans among the files');
    if (state.scans.length) render();
    return;
  }
  state.datasetId = datasetId(scans.map((s) => baseName(s.name)));
  state.demo = null;
  state.inputs = scans.map((s) => ({ name: baseName(s.name), file: s.file }));
  await describeAll();
}

async function loadTruth(file) {
  const text = await file.text();
  const truth = new Map();
  for (const [i, line] of text.split(/\r?\n/).entries()) {
    const [f, l] = line.split(',').map((s) => s?.trim());
    if (!f || !l || (i === 0 && f.toLowerCase() === 'file')) continue;
    truth.set(baseName(f), l);
  }
  state.truth = truth;
  if (state.scans.length) render();
  if ($('sweep-table').childElementCount) runSweep(); // now with S
}

async function loadPoses(file, name) {
  try {
    state.poses = parsePoses(await file.text(), name);
  } catch (e) {
    state.poses = null;
    addError(name, e.message);
  }
  if (state.scans.length) render();
}

function startDemo(scene) {
  $('preset').value = scene;
  showPreset();
  const scans = scene === 'indoor' ? 8 : 90;
  const seed = 1;
  state.poses = null;
  state.truth = null;
  state.datasetId = `demo-${scene}-${seed}-${scans}`;
  state.demo = scene;
  state.inputs = [];
  const total = scene === 'indoor' ? scans * 5 : scans;
  for (let i = 0; i < total; i++) state.inputs.push({ name: `scan_${String(i).padStart(5, '0')}.ply`, sim: { scene, seed, scans, index: i } });
  describeAll();
}

async function describeAll() {
  if (state.running) pool.cancel();
  resetResults();
  state.anchors = loadNames(state.datasetId);
  let params;
  try {
    params = currentParams();
  } catch (e) {
    addError('parameters', e.message);
    return;
  }
  state.params = params;
  state.running = true;
  // A newer run supersedes this one: it stops touching the page.
  const token = (state.runToken = (state.runToken || 0) + 1);
  const current = () => token === state.runToken;
  $('progress').dataset.state = 'running';
  const total = state.inputs.length;
  const results = new Array(total);
  let done = 0;
  const t0 = performance.now();
  $('progress').hidden = false;
  const tick = () => {
    if (!current()) return;
    const secs = (performance.now() - t0) / 1000;
    const rate = done / Math.max(secs, 1e-3);
    const left = rate > 0 ? (total - done) / rate : 0;
    $('progress-bar').value = done / total;
    $('progress-text').textContent = `${done} / ${total} scans, ${rate.toFixed(1)} scans/s, ${left.toFixed(0)} s left`;
  };
  tick();
  const session = beginSession(state.datasetId, { total, preset: $('preset').value, params, demo: state.demo });
  const jobs = state.inputs.map((input, i) => {
    const task = input.sim
      ? { type: 'simulate', ...input.sim, params }
      : { type: 'describe', file: input.file, name: input.name, params };
    // Test hook: make the worker die on this file (see tests/e2e).
    if (window.placecat.crashOn && input.name === window.placecat.crashOn) task.crash = true;
    return pool.run(task).then(
      (r) => {
        results[i] = r;
        if (current()) session.then(() => saveScan(state.datasetId, i, r));
        done++;
      },
      (e) => {
        if (e.message === 'cancelled') return;
        if (current()) addError(input.name, e.message);
        done++;
      },
    ).finally(tick);
  });
  await Promise.all(jobs);
  if (!current()) return;
  state.running = false;
  tick();
  $('progress-text').textContent += done < total ? ' (cancelled)' : ' (done)';
  $('progress-bar').value = 1;
  $('progress').dataset.state = 'done';
  state.scans = results.filter(Boolean).map((r) => ({ ...r, name: baseName(r.name) }));
  if (state.scans.some((s) => s.label)) state.truth = new Map(state.scans.map((s) => [s.name, s.label]));
  buildSet();
  // Finished runs, for tests and scripts that drive the page.
  document.body.dataset.runs = String(Number(document.body.dataset.runs || 0) + 1);
}

function cancel() {
  if (!state.running) return;
  pool.cancel();
}

// ---- clustering -----------------------------------------------------------

function buildSet() {
  state.set?.free();
  state.set = new DescriptorSet(state.params, undefined);
  for (const s of state.scans) state.set.addJson(s.descriptorJson);
  clearSweep();
  state.tree?.free();
  state.tree = null;
  $('threshold').value = '';
  state.cutBy = undefined;
  cluster();
}

function cluster() {
  const n = state.scans.length;
  const method = $('method').value;
  state.tree?.free();
  state.tree = null;
  if (n === 0) {
    $('cluster-status').textContent = 'No described scans yet.';
    return render();
  }
  try {
    if (method === 'hkmeans') {
      state.tree = state.set.hkmeans(Number($('hk-seed').value) >>> 0);
      // Fetched once per tree: every threshold drag re-renders with them.
      state.treeNodes = state.tree.nodes();
      // Keep what the user chose last: a number of categories or a threshold.
      const t = Number($('threshold').value);
      if (state.cutBy === 'categories') return setCategories(Number($('categories').value));
      if ($('threshold').value === '' || !(t >= 0)) return setCategories(5);
      return setThreshold(t);
    }
    if (method === 'kmeans') {
      const r = state.set.kmeans(Number($('k').value), $('seeding').value, Number($('km-seed').value) >>> 0);
      state.labels = Int32Array.from(r.labels);
    } else {
      state.labels = state.set.dbscan(Number($('eps').value), Number($('minpts').value));
    }
    $('cluster-status').textContent = '';
  } catch (e) {
    $('cluster-status').textContent = e.message;
    return;
  }
  render();
}

function setThreshold(t) {
  if (!state.tree) return;
  showCut(state.tree.cut(t), t);
}

/** Exactly k categories (where two splits share a height, no threshold
 * gives k; the tree's k - 1 highest splits still do). */
function setCategories(k) {
  if (!state.tree) return;
  const cut = state.tree.cutK(Math.max(1, Math.min(Math.round(k) || 1, state.scans.length)));
  showCut(cut, cut.threshold);
}

function showCut(cut, t) {
  state.labels = Int32Array.from(cut.labels);
  state.cutNodes = cut.nodes;
  $('threshold').value = t.toFixed(4);
  $('categories').value = String(cut.nodes.length);
  render();
}

/** Categories from labels: members and the most central member (medoid). */
function categoriesOf(labels) {
  const medoid = new Map();
  const flat = state.set.medoids(labels);
  for (let k = 0; k < flat.length; k += 2) medoid.set(flat[k], flat[k + 1]);
  const members = new Map([...medoid.keys()].map((l) => [l, []]));
  labels.forEach((l, i) => l >= 0 && members.get(l).push(i));
  return [...medoid.keys()].sort((a, b) => a - b).map((label) => ({ label, members: members.get(label), medoid: medoid.get(label) }));
}

function nameOf(cat) {
  const anchors = state.anchors;
  const at = anchors[state.scans[cat.medoid].name];
  if (at) return at;
  for (const m of cat.members) if (anchors[state.scans[m].name]) return anchors[state.scans[m].name];
  return '';
}

// ---- rendering --------------------------------------------------------------

function render() {
  const n = state.scans.length;
  if (!state.labels || state.labels.length !== n) {
    dendrogram.data = null;
    dendrogram.draw();
    return;
  }
  state.categories = categoriesOf(state.labels);
  // Category index (for colours) per scan.
  const index = new Map(state.categories.map((c, i) => [c.label, i]));
  const colourIdx = Int32Array.from(state.labels, (l) => (l >= 0 ? index.get(l) : -1));
  state.colourIdx = colourIdx;
  shareColours(colourSlots());
  renderLegend();
  if (state.tree) {
    const nodes = state.treeNodes;
    // Category order of the dendrogram = order of the cut nodes; map to ours.
    const central = state.cutNodes.map((node) => {
      const l = state.labels[nodes[node].members[0]];
      const c = state.categories[index.get(l)];
      return state.scans[c.medoid].preview;
    });
    const reorder = state.cutNodes.map((node) => index.get(state.labels[nodes[node].members[0]]));
    dendrogram.set({ nodes, rootHeight: state.tree.rootHeight(), threshold: Number($('threshold').value), cutNodes: state.cutNodes, central });
    dendrogram.catIndex = reorder;
  } else {
    dendrogram.data = null;
    dendrogram.draw();
  }
  const usePoses = attachPoses();
  $('map-caption').textContent = usePoses
    ? 'Trajectory map: drag to pan, wheel to zoom, click a scan'
    : 'Categories along the scan sequence (no poses file): click a scan';
  map.set({ scans: state.scans, labels: colourIdx, usePoses });
  const noise = state.labels.filter((l) => l < 0).length;
  const path = state.set.usesMatrix ? '' : ` (centre-based path: more than ${state.set.matrixLimit} scans, no Delta matrix)`;
  $('cluster-status').textContent = `${state.categories.length} categories${noise ? `, ${noise} noise` : ''} from ${n} scans${path}`;
  $('cluster-status').dataset.categories = String(state.categories.length);
  renderAccuracy();
}

/** Give each scan its pose; true when every scan has one (draw a map). */
function attachPoses() {
  // Demo scans carry their simulated poses; the indoor demo's rooms are
  // separate places, so it gets the strip instead of a map.
  if (state.demo) return state.demo === 'outdoor';
  const p = state.poses;
  if (!p) return false;
  const byName = new Map(p.poses.filter((q) => q.name).map((q) => [baseName(q.name), q]));
  state.scans.forEach((s, i) => {
    s.pose = p.format === 'csv' ? byName.get(s.name) : p.poses[state.inputs.findIndex((x) => x.name === s.name)];
  });
  if (p.format !== 'csv' && p.poses.length !== state.inputs.length) {
    $('info').textContent = `poses: ${p.poses.length} poses for ${state.inputs.length} scans, matched in name order`;
  }
  return state.scans.every((s) => s.pose);
}

function renderLegend() {
  const ol = $('legend');
  ol.replaceChildren();
  state.categories.forEach((c, i) => {
    const li = document.createElement('li');
    li.dataset.category = String(i);
    const sw = document.createElement('span');
    sw.className = 'swatch';
    sw.style.background = colour(i);
    const thumb = document.createElement('canvas');
    thumb.width = thumb.height = 96;
    drawThumbnail(thumb, state.scans[c.medoid].preview, colour(i));
    const input = document.createElement('input');
    input.type = 'text';
    input.value = nameOf(c);
    input.placeholder = `category ${i + 1}`;
    input.setAttribute('aria-label', `Name of category ${i + 1}`);
    input.addEventListener('input', () => setName(c, input.value));
    const size = document.createElement('span');
    size.className = 'size';
    size.textContent = `${c.members.length} scans`;
    li.append(sw, thumb, input, size);
    li.addEventListener('mouseenter', () => highlight(i));
    li.addEventListener('mouseleave', () => highlight(-1));
    ol.append(li);
  });
}

function setName(cat, name) {
  // One anchor per category: the medoid carries the name.
  for (const m of cat.members) delete state.anchors[state.scans[m].name];
  if (name.trim()) state.anchors[state.scans[cat.medoid].name] = name.trim();
  if (!saveNames(state.datasetId, state.anchors)) $('import-status').textContent = 'Could not save names in this browser; export them.';
  recolour();
}

/** For each category, the first category with the same name (colour slot). */
function colourSlots() {
  const first = new Map();
  return state.categories.map((c, i) => {
    const name = nameOf(c);
    if (!name) return i;
    if (!first.has(name)) first.set(name, i);
    return first.get(name);
  });
}

/** After a name changed: recolour the legend in place (keeping the focus
 * in the name being typed), the map and the dendrogram. */
function recolour() {
  shareColours(colourSlots());
  for (const li of $('legend').children) {
    const i = Number(li.dataset.category);
    li.querySelector('.swatch').style.background = colour(i);
    drawThumbnail(li.querySelector('canvas'), state.scans[state.categories[i].medoid].preview, colour(i));
  }
  map.draw();
  dendrogram.draw();
}

/** Ground truth per scan, or undefined when there is none for some scan. */
function truthLabels() {
  const truth = state.truth && state.scans.map((s) => state.truth.get(s.name));
  return truth && !truth.some((t) => t === undefined) ? truth : undefined;
}

function renderAccuracy() {
  if (!state.truth) return ($('accuracy').textContent = '');
  const truth = truthLabels();
  if (!truth) return ($('accuracy').textContent = 'labels.csv does not cover every scan');
  const ev = DescriptorSet.evaluate(truth, state.labels);
  $('accuracy').textContent = `Against ground truth: accuracy ${(100 * ev.accuracy).toFixed(1)} %, ARI ${ev.ari.toFixed(3)}${ev.inliers < ev.total ? `, S ${ev.score.toFixed(3)}` : ''}`;
}

/** DBSCAN over the set's own epsilon grid x a few min points; a cell click clusters with it. */
function runSweep() {
  clearSweep();
  if (!state.set || state.scans.length < 2) return ($('sweep-status').textContent = 'Describe at least two scans first.');
  try {
    const truth = truthLabels();
    const points = state.set.dbscanSweep(state.set.epsilonGrid(), Uint32Array.from([2, 3, 5, 8, 12]) /* placecat sweep's default */, truth);
    const best = renderSweep($('sweep-table'), points, (eps, minPoints) => {
      $('eps').value = eps;
      $('minpts').value = String(minPoints);
      cluster();
    });
    $('sweep-status').textContent = best
      ? `Cells: clusters · inliers, shaded by S; best S ${best.score.toFixed(3)} at epsilon ${f32String(best.epsilon)}, min points ${best.min_points} (outlined). Click a cell to use it.`
      : 'Cells: clusters · share of scans in one. Click a cell to use it (with labels.csv, cells are shaded by S).';
  } catch (e) {
    $('sweep-status').textContent = e.message;
  }
}

function clearSweep() {
  $('sweep-table').replaceChildren();
  $('sweep-status').textContent = '';
}

function highlight(i) {
  dendrogram.setHighlight(i);
  map.setHighlight(i);
  for (const li of $('legend').children) li.classList.toggle('hl', Number(li.dataset.category) === i);
}

function hover(c, e) {
  const tip = $('tooltip');
  if (c < 0 || !dendrogram.catIndex) {
    tip.hidden = true;
    if (state.hovered !== undefined) map.setHighlight(-1);
    state.hovered = undefined;
    return;
  }
  // The map highlights the category under the pointer.
  if (state.hovered !== dendrogram.catIndex[c]) {
    state.hovered = dendrogram.catIndex[c];
    map.setHighlight(state.hovered);
  }
  const cat = state.categories[dendrogram.catIndex[c]];
  tip.textContent = `${nameOf(cat) || `category ${dendrogram.catIndex[c] + 1}`}: ${cat.members.length} scans`;
  tip.style.left = `${e.clientX + 12}px`;
  tip.style.top = `${e.clientY + 12}px`;
  tip.hidden = false;
}

function selectScan(i) {
  if (i < 0) return ($('info').textContent = '');
  const s = state.scans[i];
  const ci = state.colourIdx[i];
  const name = ci >= 0 ? nameOf(state.categories[ci]) || `category ${ci + 1}` : 'noise';
  const unreliable = s.summary.unreliable ? ' (few voxels: unreliable)' : '';
  $('info').textContent = `${s.name}: ${name}${unreliable}`;
  highlight(ci);
}

// ---- export / import ----------------------------------------------------------

function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

const csvCell = (s) => (/[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s);

function exportCsv() {
  if (!state.labels) return;
  const rows = ['file,category'];
  state.scans.forEach((s, i) => {
    const ci = state.colourIdx[i];
    const name = ci >= 0 ? nameOf(state.categories[ci]) || `category ${ci + 1}` : 'noise';
    rows.push(`${csvCell(s.name)},${csvCell(name)}`);
  });
  download('placecat-categories.csv', rows.join('\n') + '\n', 'text/csv');
}

function exportModel() {
  if (!state.labels) return;
  const names = state.categories.map((c, i) => [c.label, nameOf(c) || `category ${i + 1}`]);
  const model = state.set.buildModel(state.labels, names);
  download('placecat-model.json', model.toJson(), 'application/json');
  model.free();
}

async function importFile(file) {
  const text = await file.text();
  const status = $('import-status');
  try {
    if (file.name.toLowerCase().endsWith('.csv')) {
      const table = new Map();
      for (const [i, line] of text.split(/\r?\n/).entries()) {
        if (!line.trim() || (i === 0 && /^file,/i.test(line))) continue;
        const comma = line.indexOf(',');
        if (comma < 0) throw new Error(`line ${i + 1}: expected file,category`);
        table.set(baseName(line.slice(0, comma).trim()), line.slice(comma + 1).trim().replace(/^"|"$/g, ''));
      }
      if (table.size === 0) throw new Error('no rows');
      // Each category takes its members' most common name.
      const anchors = { ...state.anchors };
      for (const c of state.categories) {
        const votes = new Map();
        for (const m of c.members) {
          const n = table.get(state.scans[m].name);
          if (n) votes.set(n, (votes.get(n) || 0) + 1);
        }
        const best = [...votes].sort((a, b) => b[1] - a[1])[0];
        if (best) anchors[state.scans[c.medoid].name] = best[0];
      }
      state.anchors = anchors;
      status.textContent = `Names imported from ${file.name}.`;
    } else {
      const model = Model.fromJson(text); // throws on anything malformed
      state.model?.free();
      state.model = model;
      state.modelJson = text;
      $('classify').disabled = false;
      // Name current categories after the model's, where unnamed.
      const anchors = { ...state.anchors };
      for (const c of state.categories) {
        if (nameOf(c)) continue;
        const r = model.classifyJson(state.scans[c.medoid].descriptorJson);
        anchors[state.scans[c.medoid].name] = r.name;
      }
      state.anchors = anchors;
      status.textContent = `Model loaded from ${file.name}: ${model.categories().map((c) => c.name).join(', ')}. New scans can be classified.`;
    }
    saveNames(state.datasetId, state.anchors);
    render();
  } catch (e) {
    status.textContent = `Rejected ${file.name}: ${e.message}. Nothing was changed.`;
  }
}

async function classifyFiles(list) {
  const ul = $('classified');
  ul.replaceChildren();
  for (const { file, name } of filesFromInput(list)) {
    const li = document.createElement('li');
    ul.append(li);
    try {
      const r = await pool.run({ type: 'classify', file, name: baseName(name), modelJson: state.modelJson });
      li.textContent = `${baseName(name)} → ${r.name} (Delta ${r.distance.toFixed(3)}${r.relative > 1 ? ', farther than any member' : ''})`;
    } catch (e) {
      li.textContent = e.message;
    }
  }
}

// ---- wiring -------------------------------------------------------------------

function showMethod() {
  for (const div of document.querySelectorAll('[data-for]')) div.hidden = div.dataset.for !== $('method').value;
}

/** Show the scans of the last session (e.g. after a reload mid-run). */
async function restore() {
  const last = await lastSession();
  if (!last) return;
  state.datasetId = last.datasetId;
  state.anchors = loadNames(last.datasetId);
  state.params = last.params;
  state.demo = last.demo ?? null;
  if (last.preset) $('preset').value = last.preset;
  showPreset();
  state.scans = last.scans.map((s) => ({ ...s }));
  if (state.scans.some((s) => s.label)) state.truth = new Map(state.scans.map((s) => [s.name, s.label]));
  state.inputs = [];
  $('info').textContent = `Restored ${state.scans.length} of ${last.total} scans from the last session. Load the files again to describe the rest.`;
  buildSet();
}

async function main() {
  await init();
  window.placecat = { pool, state, crashOn: null };
  showPreset();
  showMethod();
  dendrogram.draw();
  map.draw();
  $('files').addEventListener('change', (e) => loadFiles(filesFromInput(e.target.files)));
  $('folder').addEventListener('change', (e) => loadFiles(filesFromInput(e.target.files)));
  $('poses').addEventListener('change', (e) => e.target.files[0] && loadPoses(e.target.files[0], e.target.files[0].name));
  $('truth').addEventListener('change', (e) => e.target.files[0] && loadTruth(e.target.files[0]));
  $('demo-indoor').addEventListener('click', () => startDemo('indoor'));
  $('demo-outdoor').addEventListener('click', () => startDemo('outdoor'));
  $('cancel').addEventListener('click', cancel);
  const drop = $('drop');
  drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
  drop.addEventListener('dragleave', () => drop.classList.remove('over'));
  drop.addEventListener('drop', async (e) => {
    e.preventDefault();
    drop.classList.remove('over');
    loadFiles(await filesFromDrop(e.dataTransfer));
  });
  $('preset').addEventListener('change', () => { showPreset(); if (state.inputs.length) describeAll(); });
  $('apply-advanced').addEventListener('click', () => state.inputs.length && describeAll());
  $('method').addEventListener('change', () => { showMethod(); cluster(); });
  for (const id of ['hk-seed', 'k', 'seeding', 'km-seed', 'eps', 'minpts']) $(id).addEventListener('change', cluster);
  $('threshold').addEventListener('change', () => {
    state.cutBy = 'threshold';
    setThreshold(Math.max(0, Number($('threshold').value) || 0));
  });
  $('categories').addEventListener('change', () => {
    state.cutBy = 'categories';
    setCategories(Number($('categories').value));
  });
  $('sweep').addEventListener('click', runSweep);
  $('export-csv').addEventListener('click', exportCsv);
  $('export-model').addEventListener('click', exportModel);
  $('import').addEventListener('change', (e) => e.target.files[0] && importFile(e.target.files[0]));
  $('classify').addEventListener('change', (e) => classifyFiles(e.target.files));
  await restore();
  document.body.dataset.ready = 'true';
}

main().catch((e) => {
  document.body.dataset.ready = 'error';
  $('info').textContent = `placecat failed to start: ${e.message}`;
});
