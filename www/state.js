// The page's whole state in one shape, and pure transitions: each takes a
// state and returns a new one (the old is never changed), with no DOM and
// no wasm. What the views show is derived here too.
import { fileRows, formatCsv } from './csv.js';
import { baseName, isSurvey } from './files.js';
import { defaultScale } from './scale.js';
import { siteSubsample, OUTDOOR_PRESET } from './suggest.js';

/** @typedef {import('./engine.js').ScanResult} ScanResult */
/** @typedef {import('./engine.js').Params} Params */
/** @typedef {import('./engine.js').Poses} Poses */
/** @typedef {import('./engine.js').Pose} Pose */
/** @typedef {import('./engine.js').TreeData} TreeData */
/** @typedef {import('./engine.js').CutData} CutData */

/** A simulated demo scene (src/sim): indoor rooms, or a route through a site.
 * @typedef {'indoor' | 'warehouse' | 'outdoor'} Scene */
/** A scan to describe: a file, a scan of the simulated demo, or a ROS bag (many scans, bag.js).
 * @typedef {{name: string, file?: File, sim?: {scene: Scene, seed: number, scans: number, index: number},
 *   bag?: import('./bag.js').BagChoice}} Input */
/** A category: its label, member scans (indices) and most central member.
 * @typedef {{label: number, members: number[], medoid: number}} Category */
/** How to cluster (the form's values).
 * @typedef {{method: 'hkmeans' | 'kmeans' | 'dbscan' | 'spectral', hkSeed: number, hkSplits: 'auto' | number, k: number,
 *   seeding: import('./engine.js').Seeding, restarts: number, kmSeed: number, spK: number, spSeed: number,
 *   eps: number, minPoints: number}} Method */

/**
 * @typedef {object} State
 * @property {string} datasetId names are kept per data set (file names, or the demo's settings)
 * @property {Scene | null} demo
 * @property {Input[]} inputs every scan asked for, in order
 * @property {ScanResult[]} scans the described ones, in order (base names)
 * @property {{name: string, message: string}[]} errors
 * @property {Poses | null} poses
 * @property {string | null} posesFor the data set the poses belong to; null: loaded before any scans, for the next
 * @property {Map<string, string> | null} truth ground truth, scan name -> label
 * @property {Params | null} params
 * @property {number} run the current run (a newer one supersedes it)
 * @property {boolean} running
 * @property {{size: number, usesMatrix: boolean, matrixLimit: number, spectralLimit: number} | null} set
 * @property {TreeData | null} tree
 * @property {CutData | null} cut
 * @property {'threshold' | 'categories' | undefined} cutBy what the user set last
 * @property {{threshold: number, count: number} | null} lastCut the last cut of a tree, kept
 *   while another method is shown so that coming back cuts as before
 * @property {Int32Array | null} labels each scan's category (-1: noise)
 * @property {Category[]} categories by label
 * @property {Record<string, string>} anchors category names, by the scan that carries them
 * @property {string} modelJson the loaded model, '' for none
 * @property {Suggestion | null} suggestion the preset the data suggest (per data set)
 * @property {import('./scale.js').Scale | null} scale the dendrogram axis the user chose (null: the tree's default)
 * @property {{k: number, why: string} | null} firstCut how the first cut of the current tree was chosen
 */
/** The preset suggested for a data set, from the share of far points of its first scan.
 * @typedef {{preset: import('./suggest.js').SuggestedPreset, far: number, from: string}} Suggestion */

/** @returns {State} */
export function initialState() {
  return {
    datasetId: '', demo: null, inputs: [], scans: [], errors: [], poses: null, posesFor: null, truth: null, params: null,
    run: 0, running: false, set: null, tree: null, cut: null, cutBy: undefined, lastCut: null, labels: null, categories: [],
    anchors: {}, modelJson: '', suggestion: null, scale: null, firstCut: null,
  };
}

/** No results: what a new run or a new set starts from. */
const NO_RESULTS = { scans: [], errors: [], set: null, tree: null, cut: null, labels: null, categories: [] };

/**
 * Scans along the outdoor and warehouse demos' routes: the simulator's
 * default site (src/sim/sites.rs; issue 14 asks for a site of at least 300).
 */
export const DEMO_ROUTE_SCANS = 300;

/**
 * Each demo scene's preset: the one the page suggests for such scans. The
 * warehouse is a building: the paper describes ArlaWarehouse with the
 * indoor preset, and so do the site's figures in docs/experiments.md. The
 * outdoor site gets the suggested OUTDOOR_PRESET (the paper's outdoor
 * parameters, Hellinger distance; docs/hellinger.md).
 * @type {Record<Scene, import('./suggest.js').SuggestedPreset>}
 */
export const DEMO_PRESET = { indoor: 'indoor', warehouse: 'indoor', outdoor: OUTDOOR_PRESET };

/**
 * The inputs of the demo: 8 rooms x 5 indoor scans, or 300 scans along the
 * route through the outdoor site (field, forest road, forest path) or the
 * warehouse (small hall, airlock, large hall). Seed 1 is a development
 * seed of the simulator (docs/seeds.md): the demo shows, it is no evidence.
 * @param {Scene} scene
 */
export function demoInputs(scene, seed = 1) {
  const scans = scene === 'indoor' ? 8 : DEMO_ROUTE_SCANS;
  const total = scene === 'indoor' ? scans * 5 : scans;
  const inputs = Array.from({ length: total }, (_, index) => ({ name: `scan_${String(index).padStart(5, '0')}.ply`, sim: { scene, seed, scans, index } }));
  return { datasetId: `demo-${scene}-${seed}-${scans}`, inputs };
}

/** The worker task that describes an input. @param {Input} input @param {Params} params */
export function taskOf(input, params) {
  if (input.sim) return { type: 'simulate', ...input.sim, params };
  if (input.bag) {
    const { topic, every, everyMetres } = input.bag;
    return { type: 'bag', file: input.file, name: input.name, topic, every, everyMetres, params };
  }
  // An E57 file is a survey (one scan a station, each with its pose); one of a single station too.
  if (input.file && isSurvey(input.name)) return { type: 'survey', file: input.file, name: input.name, params };
  return { type: 'describe', file: input.file, name: input.name, params };
}

/**
 * A new run over `inputs`: results cleared, names of this data set loaded.
 * A new data set forgets the last one's poses (they would be drawn as this
 * one's trajectory, issue 16) unless a poses file came with it
 * (`withPosesFile`) or they were loaded while no scans were shown (for the
 * scans to come); and it forgets the last one's preset suggestion and the
 * dendrogram axis the user picked (each tree has its own default).
 * @param {State} s @param {{datasetId: string, demo: State['demo'], inputs: Input[], anchors: Record<string, string>, params: Params,
 *   withPosesFile?: boolean}} run
 * @returns {State}
 */
export function beginRun(s, { datasetId, demo, inputs, anchors, params, withPosesFile = false }) {
  const demoReset = demo ? { poses: null, truth: null } : {};
  const keep = withPosesFile || s.posesFor === null;
  const newSet = datasetId !== s.datasetId ? { poses: keep ? s.poses : null, posesFor: datasetId, suggestion: null, scale: null } : {};
  return { ...s, ...NO_RESULTS, ...newSet, ...demoReset, datasetId, demo, inputs, anchors, params, run: s.run + 1, running: true };
}

/** The parameters the run describes with (the suggested preset's). @param {State} s @param {Params} params @returns {State} */
export function withParams(s, params) {
  return { ...s, params };
}

/** @param {State} s @param {Suggestion | null} suggestion @returns {State} */
export function withSuggestion(s, suggestion) {
  return { ...s, suggestion };
}

/** @param {State} s @param {State['scale']} scale @returns {State} */
export function withScale(s, scale) {
  return { ...s, scale };
}

/** @param {State} s @returns {State} */
export function withoutResults(s) {
  return { ...s, ...NO_RESULTS };
}

/** @param {State} s @param {string} name @param {string} message @returns {State} */
export function withError(s, name, message) {
  return { ...s, errors: [...s.errors, { name, message }] };
}

/** The error as shown: prefixed by the file unless it names it. @param {{name: string, message: string}} e */
export const errorText = (e) => (e.message.startsWith(e.name) ? e.message : `${e.name}: ${e.message}`);

/**
 * The run ended (done or cancelled) with these results (holes: failed or
 * cancelled; a bag's: its scans, in recording order).
 * @param {State} s @param {(ScanResult | ScanResult[] | undefined)[]} results @returns {State}
 */
export function finishRun(s, results) {
  const scans = results.flatMap((r) => r ?? []).map((r) => ({ ...r, name: baseName(r.name) }));
  return { ...s, running: false, scans, truth: truthOfScans(scans) ?? s.truth };
}

/**
 * The last session's scans, restored.
 * @param {State} s @param {{datasetId: string, params: Params, demo?: State['demo'], scans: ScanResult[]}} last
 * @param {Record<string, string>} anchors @returns {State}
 */
export function restoreSession(s, last, anchors) {
  // Sessions stored before the map kept a site subsample get one from the preview.
  const scans = last.scans.map((r) => ({ ...r, site: r.site ?? siteSubsample(r.preview) }));
  return { ...s, ...NO_RESULTS, datasetId: last.datasetId, anchors, params: last.params, demo: last.demo ?? null, inputs: [], scans, truth: truthOfScans(scans) ?? s.truth };
}

/** Simulated scans carry their true kind: ground truth for the demo. @param {ScanResult[]} scans */
function truthOfScans(scans) {
  return scans.some((r) => r.label) ? new Map(scans.map((r) => [r.name, r.label ?? ''])) : null;
}

/** Ground truth from labels.csv text (throws on a malformed file). @param {State} s @param {string} text @returns {State} */
export function withTruthCsv(s, text) {
  return { ...s, truth: new Map(fileRows(text).filter(([, l]) => l !== '').map(([f, l]) => [baseName(f), l])) };
}

/** Poses for the scans shown, or (none shown) for the next data set. @param {State} s @param {Poses | null} poses @returns {State} */
export function withPoses(s, poses) {
  return { ...s, poses, posesFor: s.scans.length ? s.datasetId : null };
}

/** A new descriptor set: no clustering yet. @param {State} s @param {State['set']} set @returns {State} */
export function withSet(s, set) {
  return { ...s, set, tree: null, cut: null, labels: null, categories: [], cutBy: undefined, lastCut: null, firstCut: null };
}

/**
 * The page's tree takes the cheapest of 10 2-means++ trials a split (issues
 * 14 and 18, fifth round: better trees on the development seeds) for sets of
 * up to this many scans; above, one run a split, the paper's, because ten
 * cost more (1000 scans, Node's wasm: the tree 0.81 s instead of 0.09 s,
 * its reference trees 1.5 s instead of 0.5 s; bench/tree_trials.mjs, docs/seeds.md).
 */
export const TRIAL_SPLITS_UP_TO = 500;

/**
 * 2-means++ runs a split of the tree for `n` scans under the form's "Splits".
 * @param {'auto' | number} splits @param {number} n @returns {number}
 */
export function treeRestarts(splits, n) {
  if (splits !== 'auto') return splits;
  return n <= TRIAL_SPLITS_UP_TO ? 10 : 1;
}

/** A new tree (hierarchical k-means), not yet cut. @param {State} s @param {TreeData} tree @returns {State} */
export function withTree(s, tree) {
  return { ...s, tree, cut: null, labels: null, categories: [], firstCut: null };
}

/** The first cut of a tree, and why. @param {State} s @param {{k: number, why: string}} firstCut @returns {State} */
export function withFirstCut(s, firstCut) {
  return { ...s, firstCut };
}

/**
 * Labels and their categories: from a cut of the tree, or (cut null) from
 * k-means or DBSCAN. `medoids` maps each label to its most central scan.
 * @param {State} s @param {Int32Array} labels @param {Map<number, number>} medoids
 * @param {CutData | null} cut @returns {State}
 */
export function withLabels(s, labels, medoids, cut = null) {
  const members = new Map([...medoids.keys()].map((l) => [l, /** @type {number[]} */ ([])]));
  labels.forEach((l, i) => l >= 0 && members.get(l)?.push(i));
  const categories = [...medoids.keys()].sort((a, b) => a - b).map((label) => ({ label, members: members.get(label) ?? [], medoid: /** @type {number} */ (medoids.get(label)) }));
  const lastCut = cut ? { threshold: cut.threshold, count: cut.nodes.length } : s.lastCut;
  return { ...s, labels, categories, cut, lastCut, tree: cut ? s.tree : null };
}

/**
 * How to cut a new tree: into as many categories as the user asked for,
 * at the threshold of the last cut, or (the first time) as the engine
 * suggests (`auto`).
 * @param {State} s @returns {{k: number} | {threshold: number} | {auto: true}}
 */
export function nextCut(s) {
  if (!s.lastCut) return { auto: true };
  if (s.cutBy === 'categories') return { k: clampCategories(s, s.lastCut.count) };
  return { threshold: s.lastCut.threshold };
}

/** @param {State} s @param {State['cutBy']} cutBy @returns {State} */
export function withCutBy(s, cutBy) {
  return { ...s, cutBy };
}

/** How many categories to cut into: what the user asked for, within 1..scans. @param {State} s @param {number} k */
export function clampCategories(s, k) {
  return Math.max(1, Math.min(Math.round(k) || 1, s.scans.length));
}

// ---- names ------------------------------------------------------------------

/** A category's name: the one anchored to its medoid, else to any member, else ''. @param {State} s @param {Category} cat */
export function nameOf(s, cat) {
  const at = s.anchors[s.scans[cat.medoid].name];
  if (at) return at;
  for (const m of cat.members) if (s.anchors[s.scans[m].name]) return s.anchors[s.scans[m].name];
  return '';
}

/** The name shown for category i (its own, or `category i+1`). @param {State} s @param {number} i */
export function displayName(s, i) {
  return nameOf(s, s.categories[i]) || `category ${i + 1}`;
}

/** Name category i: one anchor per category, on its medoid ('' clears). @param {State} s @param {number} i @param {string} name @returns {State} */
export function withName(s, i, name) {
  const cat = s.categories[i];
  const anchors = { ...s.anchors };
  for (const m of cat.members) delete anchors[s.scans[m].name];
  if (name.trim()) anchors[s.scans[cat.medoid].name] = name.trim();
  return { ...s, anchors };
}

/** Anchors set for some categories (index -> name), e.g. from a model. @param {State} s @param {Map<number, string>} names @returns {State} */
export function withNames(s, names) {
  const anchors = { ...s.anchors };
  for (const [i, name] of names) anchors[s.scans[s.categories[i].medoid].name] = name;
  return { ...s, anchors };
}

/** For each category, the first category with the same name (its colour slot). @param {State} s */
export function colourSlots(s) {
  /** @type {Map<string, number>} */
  const first = new Map();
  return s.categories.map((c, i) => {
    const name = nameOf(s, c);
    if (!name) return i;
    if (!first.has(name)) first.set(name, i);
    return /** @type {number} */ (first.get(name));
  });
}

/** Each scan's category index (position in `categories`), -1 for noise. @param {State} s */
export function categoryIndex(s) {
  const index = new Map(s.categories.map((c, i) => [c.label, i]));
  return Int32Array.from(s.labels ?? [], (l) => (l >= 0 ? index.get(l) ?? -1 : -1));
}

/** The categories export: `file,category` rows, noise as `noise`. @param {State} s */
export function categoriesCsv(s) {
  const ci = categoryIndex(s);
  return formatCsv([['file', 'category'], ...s.scans.map((r, i) => [r.name, ci[i] >= 0 ? displayName(s, ci[i]) : 'noise'])]);
}

/** [label, name] of every category, for a model. @param {State} s @returns {[number, string][]} */
export function modelNames(s) {
  return s.categories.map((c, i) => [c.label, displayName(s, i)]);
}

/** Names from a categories CSV: each category takes its members' most common name (throws on a malformed file). @param {State} s @param {string} text @returns {State} */
export function withNamesCsv(s, text) {
  const table = new Map(fileRows(text).map(([f, n]) => [baseName(f), n]));
  if (table.size === 0) throw new Error('no rows');
  /** @type {Map<number, string>} */
  const names = new Map();
  s.categories.forEach((c, i) => {
    /** @type {Map<string, number>} */
    const votes = new Map();
    for (const m of c.members) {
      const n = table.get(s.scans[m].name);
      if (n) votes.set(n, (votes.get(n) ?? 0) + 1);
    }
    const best = [...votes].sort((a, b) => b[1] - a[1])[0];
    if (best) names.set(i, best[0]);
  });
  return withNames(s, names);
}

/** @param {State} s @param {string} modelJson @returns {State} */
export function withModel(s, modelJson) {
  return { ...s, modelJson };
}

/** Categories with no name yet, for a model to name: [index, its medoid's descriptor JSON]. @param {State} s @returns {[number, string][]} */
export function unnamed(s) {
  return s.categories.flatMap((c, i) => (nameOf(s, c) ? [] : [[i, s.scans[c.medoid].descriptorJson]]));
}

// ---- derived views ----------------------------------------------------------

/** Ground truth per scan, or undefined when some scan has none. @param {State} s */
export function truthLabels(s) {
  if (!s.truth) return undefined;
  const truth = s.truth;
  const out = s.scans.map((r) => truth.get(r.name));
  return out.every((t) => t !== undefined) ? /** @type {string[]} */ (out) : undefined;
}

/**
 * Each scan's pose, and whether there is a map to draw (every scan has
 * one). The indoor demo's rooms are separate places: a strip, no map; the
 * outdoor and warehouse demos are routes through one site.
 * `drawSite`: the poses have headings to place the scans' points by (CSV
 * poses have none).
 * @param {State} s @returns {{poses: (Pose | undefined)[], usePoses: boolean, drawSite: boolean, note: string}}
 */
export function posesOf(s) {
  if (s.demo) return { poses: s.scans.map((r) => r.pose), usePoses: s.demo !== 'indoor', drawSite: true, note: '' };
  // A recording's scans carry the poses it recorded (a bag's odometry or tf, a survey's stations), with headings.
  const own = s.scans.filter((r) => r.pose).length;
  if (own) {
    const note = own < s.scans.length ? `poses: ${s.scans.length - own} of ${s.scans.length} scans have no pose in their recording; no map` : '';
    return { poses: s.scans.map((r) => r.pose), usePoses: own === s.scans.length, drawSite: true, note };
  }
  const p = s.poses;
  if (!p) return { poses: s.scans.map(() => undefined), usePoses: false, drawSite: false, note: '' };
  const byName = new Map(p.poses.filter((q) => q.name).map((q) => [baseName(q.name ?? ''), q]));
  const poses = s.scans.map((r) => (p.format === 'csv' ? byName.get(r.name) : p.poses[s.inputs.findIndex((x) => x.name === r.name)]));
  const note = p.format !== 'csv' && p.poses.length !== s.inputs.length ? `poses: ${p.poses.length} poses for ${s.inputs.length} scans, matched in name order` : '';
  return { poses, usePoses: poses.every(Boolean), drawSite: p.format !== 'csv', note };
}

/** The dendrogram's data: per cut node, its category index and central preview. @param {State} s */
export function dendrogramOf(s) {
  if (!s.tree || !s.cut || !s.labels) return null;
  const { nodes, rootHeight } = s.tree;
  const labels = s.labels;
  const index = new Map(s.categories.map((c, i) => [c.label, i]));
  const catIndex = s.cut.nodes.map((node) => /** @type {number} */ (index.get(labels[nodes[node].members[0]])));
  const central = catIndex.map((i) => s.scans[s.categories[i].medoid].preview);
  const auto = defaultScale(nodes, rootHeight);
  const scale = s.scale ?? auto.scale;
  return { nodes, rootHeight, threshold: s.cut.threshold, cutNodes: s.cut.nodes, central, catIndex, scale, auto };
}
