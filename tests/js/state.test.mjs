// The page's state transitions: pure (the old state is never changed), and
// the behaviour the page relies on: categories from labels, names anchored
// to central scans, shared colours, the categories CSV round trip.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';

/** Freeze an object graph (typed arrays cannot be frozen; they are left). */
function deepFreeze(o) {
  if (o && typeof o === 'object' && !ArrayBuffer.isView(o) && !Object.isFrozen(o)) {
    Object.freeze(o);
    for (const v of o instanceof Map ? o.values() : Object.values(o)) deepFreeze(v);
  }
  return o;
}

const scan = (name, extra = {}) => ({ name, format: 'ply', descriptorJson: `{"n":"${name}"}`, summary: {}, preview: new Float32Array(3), ...extra });

/** Six described scans in two categories (labels 4 and 7), medoids 1 and 4, scan 5 noise. */
function clustered(anchors = {}) {
  let s = S.initialState();
  s = S.beginRun(s, { datasetId: 'files-6-x', demo: null, inputs: [], anchors, params: /** @type {any} */ ({}) });
  s = S.finishRun(s, ['a', 'b', 'c', 'd', 'e', 'f'].map((n) => scan(`dir/${n}.ply`)));
  s = S.withSet(s, { size: 6, usesMatrix: true, matrixLimit: 5000, spectralLimit: 2000 });
  return S.withLabels(s, Int32Array.from([4, 4, 4, 7, 7, -1]), new Map([[7, 4], [4, 1]]));
}

test('categories come from labels: sorted by label, noise left out, the medoid given', () => {
  const s = clustered();
  assert.deepEqual(s.categories, [{ label: 4, members: [0, 1, 2], medoid: 1 }, { label: 7, members: [3, 4], medoid: 4 }]);
  assert.deepEqual([...S.categoryIndex(s)], [0, 0, 0, 1, 1, -1]);
  assert.deepEqual(s.scans.map((r) => r.name), ['a.ply', 'b.ply', 'c.ply', 'd.ply', 'e.ply', 'f.ply']);
});

test('transitions return a new state and never change the old one', () => {
  const s = deepFreeze(clustered({ 'e.ply': 'office' }));
  const before = JSON.stringify({ ...s, labels: [...(s.labels ?? [])] });
  const steps = [
    S.withName(s, 0, 'lab'),
    S.withNames(s, new Map([[0, 'x']])),
    S.withNamesCsv(s, 'file,category\nb.ply,kitchen\n'),
    S.withError(s, 'a.ply', 'bad'),
    S.withTruthCsv(s, 'a.ply,room\n'),
    S.withLabels(s, Int32Array.from([0, 0, 0, 0, 0, 0]), new Map([[0, 2]])),
    S.beginRun(s, { datasetId: 'y', demo: 'indoor', inputs: [], anchors: {}, params: /** @type {any} */ ({}) }),
    S.withSet(s, null),
    S.withoutResults(s),
  ];
  for (const t of steps) assert.notEqual(t, s);
  assert.equal(JSON.stringify({ ...s, labels: [...(s.labels ?? [])] }), before);
});

test('a name is anchored to the medoid, and a category takes it back after re-clustering', () => {
  let s = S.withName(clustered({ 'a.ply': 'old' }), 0, '  lab  ');
  assert.deepEqual(s.anchors, { 'b.ply': 'lab' }, 'one anchor per category, trimmed, on its medoid');
  assert.equal(S.nameOf(s, s.categories[0]), 'lab');
  assert.equal(S.displayName(s, 1), 'category 2');
  // Re-clustered: scan b is in a category whose medoid is c; the name follows.
  s = S.withLabels(s, Int32Array.from([1, 1, 1, 1, 0, 0]), new Map([[0, 5], [1, 2]]));
  assert.equal(S.nameOf(s, s.categories[1]), 'lab');
  assert.equal(S.nameOf(s, s.categories[0]), '');
  // Clearing a name removes its anchor.
  assert.deepEqual(S.withName(s, 1, ' ').anchors, {});
});

test('categories given one name share the colour of the first of them', () => {
  let s = clustered();
  assert.deepEqual(S.colourSlots(s), [0, 1]);
  s = S.withName(S.withName(s, 0, 'same'), 1, 'same');
  assert.deepEqual(S.colourSlots(s), [0, 0]);
  assert.deepEqual(S.colourSlots(S.withName(s, 1, 'other')), [0, 1]);
});

test('the categories CSV: export, import into a page with no names, export again gives the same bytes', () => {
  const hostile = ['lab, "wet"', 'first line\nsecond line', 'Küche – 2. Stock, 東京'];
  for (const name of hostile) {
    const named = S.withName(clustered(), 0, name);
    const csv = S.categoriesCsv(named);
    const back = S.withNamesCsv(clustered(), csv);
    assert.equal(S.nameOf(back, back.categories[0]), name);
    assert.equal(S.categoriesCsv(back), csv, `round trip of ${JSON.stringify(name)}`);
  }
  const csv = S.categoriesCsv(S.withName(clustered(), 0, 'lab, "wet"'));
  assert.equal(csv, 'file,category\na.ply,"lab, ""wet"""\nb.ply,"lab, ""wet"""\nc.ply,"lab, ""wet"""\nd.ply,category 2\ne.ply,category 2\nf.ply,noise\n');
});

test('importing names: each category takes its members\' most common name; a bad file throws', () => {
  const s = S.withNamesCsv(clustered(), '\ufefffile,category\r\nx/a.ply,dock\r\nb.ply,hall\r\nc.ply,dock\r\nd.ply,\r\n');
  assert.equal(S.nameOf(s, s.categories[0]), 'dock');
  assert.equal(S.nameOf(s, s.categories[1]), '');
  assert.deepEqual(S.unnamed(s), [[1, '{"n":"dir/e.ply"}']]);
  assert.throws(() => S.withNamesCsv(clustered(), 'file,category\n'), /no rows/);
  assert.throws(() => S.withNamesCsv(clustered(), 'a.ply,"open\n'), /quote/);
});

test('ground truth: labels.csv by base name, or the labels the demo scans carry', () => {
  let s = S.withTruthCsv(clustered(), 'file,label\n"data/a.ply",room\nb.ply,"room, big"\n');
  assert.equal(s.truth?.get('b.ply'), 'room, big');
  assert.equal(S.truthLabels(s), undefined, 'labels.csv does not cover every scan');
  s = S.withTruthCsv(s, ['a', 'b', 'c', 'd', 'e', 'f'].map((n) => `${n}.ply,${n < 'd' ? 'x' : 'y'}`).join('\n'));
  assert.deepEqual(S.truthLabels(s), ['x', 'x', 'x', 'y', 'y', 'y']);
  const demo = S.finishRun(S.initialState(), [scan('s0.ply', { label: 'office' }), undefined, scan('s2.ply', { label: 'lab' })]);
  assert.deepEqual(S.truthLabels(demo), ['office', 'lab']);
});

test('a new tree is cut as the user cut the last: as the engine suggests at first, then by count or threshold', () => {
  let s = clustered();
  assert.deepEqual(S.nextCut(s), { auto: true });
  s = S.withTree(s, { nodes: [], rootHeight: 1 });
  s = S.withLabels(s, Int32Array.from([0, 0, 1, 1, 2, 2]), new Map([[0, 0], [1, 2], [2, 4]]), { labels: Int32Array.from([0, 0, 1, 1, 2, 2]), nodes: [1, 2, 3], threshold: 0.25 });
  assert.deepEqual(S.nextCut(s), { threshold: 0.25 });
  assert.deepEqual(S.nextCut(S.withCutBy(s, 'categories')), { k: 3 });
  // k-means in between keeps the last cut for when the tree comes back.
  s = S.withLabels(S.withCutBy(s, 'categories'), Int32Array.from([0, 0, 0, 0, 0, 0]), new Map([[0, 1]]));
  assert.equal(s.tree, null);
  assert.deepEqual(S.nextCut(s), { k: 3 });
  assert.equal(S.clampCategories(s, 99), 6);
  assert.equal(S.clampCategories(s, NaN), 1);
});

test('poses: CSV matched by name, KITTI by order with a note when the counts differ', () => {
  const pose = (x, name) => ({ position: [x, 0, 0], yaw: 0, ...(name ? { name } : {}) });
  let s = { ...clustered(), inputs: ['a', 'b', 'c', 'd', 'e', 'f'].map((n) => ({ name: `${n}.ply` })) };
  const csv = S.withPoses(s, /** @type {any} */ ({ format: 'csv', poses: ['f', 'e', 'd', 'c', 'b', 'a'].map((n, i) => pose(i, `x/${n}.ply`)) }));
  assert.deepEqual(S.posesOf(csv).poses.map((p) => p?.position[0]), [5, 4, 3, 2, 1, 0]);
  assert.equal(S.posesOf(csv).usePoses, true);
  const kitti = S.posesOf(S.withPoses(s, /** @type {any} */ ({ format: 'kitti', poses: [pose(0), pose(1)] })));
  assert.equal(kitti.usePoses, false);
  assert.equal(kitti.note, 'poses: 2 poses for 6 scans, matched in name order');
  assert.equal(S.posesOf(s).usePoses, false);
});

test('a run: results cleared, names and a counter set; the demo forgets poses and truth', () => {
  const s = S.withTruthCsv(clustered(), 'a.ply,x\n');
  const { datasetId, inputs } = S.demoInputs('indoor');
  const r = S.beginRun(s, { datasetId, demo: 'indoor', inputs, anchors: { 'scan_00001.ply': 'hall' }, params: /** @type {any} */ ({}) });
  assert.equal(datasetId, 'demo-indoor-1-8');
  assert.equal(inputs.length, 40);
  assert.deepEqual(inputs[3].sim, { scene: 'indoor', seed: 1, scans: 8, index: 3 });
  assert.equal(r.run, s.run + 1);
  assert.equal(r.running, true);
  assert.deepEqual([r.scans, r.categories, r.labels, r.truth], [[], [], null, null]);
  assert.deepEqual(S.taskOf(inputs[3], /** @type {any} */ ({ p: 1 })), { type: 'simulate', scene: 'indoor', seed: 1, scans: 8, index: 3, params: { p: 1 } });
  assert.equal(S.errorText({ name: 'a.ply', message: 'a.ply: PLY: truncated' }), 'a.ply: PLY: truncated');
  assert.equal(S.errorText({ name: 'a.ply', message: 'the worker failed' }), 'a.ply: the worker failed');
});

test('the outdoor and warehouse demos: 300 scans along a route, drawn by their poses, described with a preset that exists', () => {
  for (const scene of /** @type {const} */ (['outdoor', 'warehouse'])) {
    const { datasetId, inputs } = S.demoInputs(scene);
    assert.equal(datasetId, `demo-${scene}-1-300`);
    assert.equal(inputs.length, 300);
    assert.deepEqual(inputs[299].sim, { scene, seed: 1, scans: 300, index: 299 });
    const r = S.beginRun(S.initialState(), { datasetId, demo: scene, inputs, anchors: {}, params: /** @type {any} */ ({}) });
    const shown = S.finishRun(r, [scan('scan_00000.ply', { pose: { position: [0, 0, 0], yaw: 0 } })]);
    assert.equal(S.posesOf(shown).usePoses, true, `${scene}: a map of the site`);
  }
  assert.equal(S.posesOf(S.finishRun(S.beginRun(S.initialState(), { ...S.demoInputs('indoor'), demo: 'indoor', anchors: {}, params: /** @type {any} */ ({}) }), [scan('scan_00000.ply')])).usePoses, false, 'indoor: separate rooms');
  // The warehouse has no preset of its own: indoor, as for the paper's ArlaWarehouse.
  assert.deepEqual(S.DEMO_PRESET, { indoor: 'indoor', warehouse: 'indoor', outdoor: 'outdoor_hellinger' });
});

test('the dendrogram gets, per cut node, its category and central preview', () => {
  const nodes = [
    { id: 0, height: 1, children: [1, 2], members: [0, 1, 2, 3] },
    { id: 1, height: 0.5, children: [], members: [2, 3] },
    { id: 2, height: 0.4, children: [], members: [0, 1] },
  ];
  let s = S.finishRun(S.initialState(), ['a', 'b', 'c', 'd'].map((n, i) => scan(`${n}.ply`, { preview: new Float32Array([i, 0, 0]) })));
  s = S.withTree(s, /** @type {any} */ ({ nodes, rootHeight: 1 }));
  const labels = Int32Array.from([0, 0, 1, 1]);
  s = S.withLabels(s, labels, new Map([[0, 1], [1, 3]]), { labels, nodes: [1, 2], threshold: 0.6 });
  const d = S.dendrogramOf(s);
  assert.deepEqual(d?.catIndex, [1, 0]);
  assert.deepEqual(d?.central.map((p) => p[0]), [3, 1]);
  assert.equal(d?.threshold, 0.6);
});

test('poses of the last data set are dropped by a new one, kept when a poses file comes with it or the same set is described again', () => {
  const poses = /** @type {any} */ ({ format: 'kitti', poses: [{ position: [0, 0, 0], yaw: 0 }] });
  const s = S.withSuggestion(S.withPoses(clustered(), poses), { preset: 'outdoor', far: 0.5, from: 'a.ply' });
  const run = (datasetId, withPosesFile = false) => S.beginRun(s, { datasetId, demo: null, inputs: [], anchors: {}, params: /** @type {any} */ ({}), withPosesFile });
  assert.equal(run('files-2-other').poses, null);
  assert.equal(run('files-2-other').suggestion, null);
  assert.equal(S.beginRun(S.withScale(s, 'log'), { datasetId: 'files-2-other', demo: null, inputs: [], anchors: {}, params: /** @type {any} */ ({}) }).scale, null);
  assert.equal(S.beginRun(S.withScale(s, 'log'), { datasetId: 'files-6-x', demo: null, inputs: [], anchors: {}, params: /** @type {any} */ ({}) }).scale, 'log');
  assert.equal(run('files-2-other', true).poses, poses);
  assert.equal(run('files-6-x').poses, poses, 'the same set again (a new preset)');
  assert.equal(run('files-6-x').suggestion?.preset, 'outdoor');
  // Poses picked before any scans are for the scans to come.
  const early = S.withPoses(S.initialState(), poses);
  assert.equal(S.beginRun(early, { datasetId: 'files-2-new', demo: null, inputs: [], anchors: {}, params: /** @type {any} */ ({}) }).poses, poses);
});

test('CSV poses have no heading: the map draws the trajectory but not the site', () => {
  const pose = (x, name) => ({ position: [x, 0, 0], yaw: 0, name });
  const s = { ...clustered(), inputs: ['a', 'b', 'c', 'd', 'e', 'f'].map((n) => ({ name: `${n}.ply` })) };
  const csv = S.posesOf(S.withPoses(s, /** @type {any} */ ({ format: 'csv', poses: ['a', 'b', 'c', 'd', 'e', 'f'].map((n, i) => pose(i, `${n}.ply`)) })));
  assert.deepEqual([csv.usePoses, csv.drawSite], [true, false]);
  const tum = S.posesOf(S.withPoses(s, /** @type {any} */ ({ format: 'tum', poses: [0, 1, 2, 3, 4, 5].map((i) => pose(i)) })));
  assert.deepEqual([tum.usePoses, tum.drawSite], [true, true]);
});

test('the dendrogram takes the user\'s scale, else the tree\'s default', () => {
  // Merges at 0.01 .. 0.05 under a root at 16: the root is 533 x the median.
  const nodes = [
    { height: 16, children: [1, 2], members: [0, 1, 2, 3] },
    { height: 0.01, children: [3, 4], members: [0, 1] }, { height: 0.03, children: [5, 6], members: [2, 3] },
    ...[0, 1, 2, 3].map((m) => ({ height: 0, children: [], members: [m] })),
  ];
  let s = S.withSet(clustered(), { size: 4, usesMatrix: true, matrixLimit: 5000, spectralLimit: 2000 });
  s = { ...s, scans: s.scans.slice(0, 4) };
  s = S.withTree(s, { nodes, rootHeight: 16 });
  s = S.withLabels(s, Int32Array.from([0, 0, 1, 1]), new Map([[0, 0], [1, 2]]), { labels: Int32Array.from([0, 0, 1, 1]), nodes: [1, 2], threshold: 1 });
  const d = S.dendrogramOf(s);
  assert.equal(d?.scale, 'log');
  assert.equal(Math.round(d?.auto.ratio ?? 0), 533);
  assert.equal(S.dendrogramOf(S.withScale(s, 'linear'))?.scale, 'linear');
});

test('the tree\'s splits: auto is ten trials a split up to 500 scans and the paper\'s one run above; a choice stands', () => {
  assert.equal(S.TRIAL_SPLITS_UP_TO, 500);
  assert.deepEqual([1, 2, 300, 500, 501, 1000].map((n) => S.treeRestarts('auto', n)), [10, 10, 10, 10, 1, 1]);
  assert.deepEqual([S.treeRestarts(1, 300), S.treeRestarts(10, 1000)], [1, 10]);
});
