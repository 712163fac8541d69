// The only code that touches wasm objects. Every object it makes is freed
// here (a Slot frees what it held when it takes another; `scoped` frees a
// temporary); callers get plain JS data. The wasm module is a parameter, so
// the page passes its web build and the unit tests the Node build.

/** @typedef {typeof import('./pkg/placecat.js')} Wasm */
/** @typedef {import('./pkg/placecat.js').DescriptorParams} DescriptorParams */
/** @typedef {Required<DescriptorParams>} Params */
/** @typedef {import('./pkg/placecat.js').TreeNode} TreeNode */
/** @typedef {import('./pkg/placecat.js').Summary} Summary */
/** @typedef {import('./pkg/placecat.js').Pose} Pose */
/** @typedef {import('./pkg/placecat.js').Poses} Poses */
/** @typedef {import('./pkg/placecat.js').SweepPoint} SweepPoint */
/** @typedef {import('./pkg/placecat.js').Evaluation} Evaluation */
/** @typedef {import('./pkg/placecat.js').Classification} Classification */
/** @typedef {import('./pkg/placecat.js').CategorySummary} CategorySummary */
/** @typedef {import('./pkg/placecat.js').Preset} Preset */
/** @typedef {import('./pkg/placecat.js').Seeding} Seeding */
import { choiceReason, rangeShare, siteSubsample, suggestPreset } from './suggest.js';

/**
 * One described scan as plain data (what a worker sends back). `site`: a
 * few hundred of its points, x, y (sensor frame), for the map; `far`: the
 * share of its points beyond 10 m, when asked for (the preset suggestion);
 * `preset`: the preset it was described with, when the describer chose it.
 * @typedef {{name: string, format: string, descriptorJson: string, summary: Summary,
 *   preview: Float32Array, site?: Float32Array, label?: string, pose?: Pose, far?: number, preset?: import('./suggest.js').SuggestedPreset}} ScanResult
 */
/** A tree as plain data: its nodes (node 0 is the root), the root's height, its 2-means++ trials a split.
 * @typedef {{nodes: TreeNode[], rootHeight: number, restarts: number}} TreeData */
/** A cut: each scan's category, the tree node of each category, the threshold.
 * @typedef {{labels: Int32Array, nodes: number[], threshold: number}} CutData */

/** @typedef {{free(): void}} Freeable */

/**
 * A count of runs: refused here as a RangeError unless a whole number from 1 (the wasm side
 * refuses the others too, as an Error; before it did, a `u32` took 2.5 as 2).
 * @param {number} restarts
 */
function checkRuns(restarts) {
  if (!Number.isInteger(restarts) || restarts < 1 || restarts > 0xffffffff) {
    throw new RangeError(`restarts must be a whole number of runs from 1, got ${restarts}`);
  }
}

/** Holds at most one wasm object; freed when replaced or cleared. @template {Freeable} T */
export class Slot {
  /** @type {T | null} */
  value = null;

  /** @param {T | null} next */
  set(next) {
    if (this.value !== next) this.value?.free();
    this.value = next;
  }

  clear() {
    this.set(null);
  }

  /** @param {string} what what the slot must hold, for the error */
  get(what) {
    if (!this.value) throw new Error(`no ${what} yet`);
    return this.value;
  }
}

/**
 * Run `fn` on a wasm object and free it afterwards, whatever happens.
 * @template {Freeable} T @template R
 * @param {T} obj @param {(obj: T) => R} fn @returns {R}
 */
export function scoped(obj, fn) {
  try {
    return fn(obj);
  } finally {
    obj.free();
  }
}

/**
 * The clustering side (the page's main thread): one descriptor set, its
 * last tree (kept while k-means or DBSCAN is shown, freed by the next tree
 * or set), a loaded model.
 */
export class Engine {
  /** @param {Wasm} wasm */
  constructor(wasm) {
    this.wasm = wasm;
    /** @type {Slot<import('./pkg/placecat.js').DescriptorSet>} */
    this.set = new Slot();
    /** @type {Slot<import('./pkg/placecat.js').ClusterTree>} */
    this.tree = new Slot();
    /** @type {Slot<import('./pkg/placecat.js').Model>} */
    this.model = new Slot();
  }

  /** @param {Preset} preset @returns {Params} */
  presetParams(preset) {
    return this.wasm.presetParams(preset);
  }

  /** Complete and check parameters; throws naming the bad one. @param {Partial<DescriptorParams>} partial @param {Preset} preset @returns {Params} */
  validateParams(partial, preset) {
    return this.wasm.validateParams(partial, preset);
  }

  /** @param {string} text @param {string} fileName @returns {Poses} */
  parsePoses(text, fileName) {
    return this.wasm.parsePoses(text, fileName);
  }

  /** Accuracy, ARI and S of labels against ground truth. @param {string[]} truth @param {Int32Array} labels @returns {Evaluation} */
  evaluate(truth, labels) {
    return this.wasm.DescriptorSet.evaluate(truth, labels);
  }

  /**
   * A new set from descriptors (the old set and tree are freed).
   * @param {Params} params @param {string[]} descriptorJsons
   * @returns {{size: number, usesMatrix: boolean, matrixLimit: number, spectralLimit: number}}
   */
  load(params, descriptorJsons) {
    this.tree.clear();
    this.set.clear();
    const set = descriptorSet(this.wasm, params, descriptorJsons);
    this.set.set(set);
    return { size: set.length, usesMatrix: set.usesMatrix, matrixLimit: set.matrixLimit, spectralLimit: set.spectralLimit };
  }

  /**
   * Hierarchical k-means++; the tree is kept for cuts. `restarts`: 2-means++ trials at
   * every split, the cheapest kept (1: the paper's tree; the wasm side refuses more than 1000).
   * @param {number} seed @param {number} [restarts] @returns {TreeData}
   * @throws {RangeError} unless `restarts` is a whole number from 1 to 2^32 - 1
   */
  hkmeans(seed, restarts = 1) {
    checkRuns(restarts);
    this.tree.clear();
    this.tree.set(this.set.get('scans').hkmeans(seed, restarts));
    const tree = this.tree.get('tree');
    return { nodes: tree.nodes(), rootHeight: tree.rootHeight(), restarts };
  }

  /** The kept tree cut at a threshold. @param {number} threshold @returns {CutData} */
  cut(threshold) {
    return cutData(this.tree.get('tree').cut(threshold), threshold);
  }

  /** The kept tree cut into k categories. @param {number} k @returns {CutData} */
  cutK(k) {
    const cut = this.tree.get('tree').cutK(k);
    return cutData(cut, cut.threshold);
  }

  /**
   * The first cut of the kept tree: how many categories the rule chose from
   * the data (issue 14 item 3: the core's choose_k, `silhouette_gap` by
   * default; one category when the scans are alike under the descriptor), and why.
   * `dispersions`: every reference set's, computed by the workers for this
   * set and the tree's seed and restarts (matrix.js); the same choice, not computed here.
   * Dispersions the set refuses (too few, another set's, another seed's or restarts') count
   * as none: the set computes its own, as when the workers failed.
   * @param {Float64Array | null} [dispersions] @param {number} [seed] the tree seed they were drawn for
   * @param {number} [restarts] the trials per split they were drawn for
   * @returns {{k: number, why: string}}
   */
  suggestCategories(dispersions, seed = 0, restarts = 1) {
    const set = this.set.get('scans');
    const tree = this.tree.get('tree');
    let choice = null;
    try {
      if (dispersions) choice = set.chooseCategoriesWith(tree, dispersions, seed, restarts);
    } catch {
      // refused: chosen below from the set's own reference sets
    }
    choice ??= set.chooseCategories(tree);
    return { k: choice.k, why: choiceReason(choice) };
  }

  /** How many reference sets the choice of categories draws. @returns {number} */
  referenceSets() {
    return this.set.get('scans').referenceSets;
  }

  /**
   * Use a Delta matrix computed elsewhere (matrix.js, from the workers) for
   * the set; a bad one throws and the set computes its own when needed.
   * @param {Float32Array} matrix n x n, row-major
   */
  setMatrix(matrix) {
    this.set.get('scans').setDeltaMatrix(matrix);
  }

  /** Delta between two scans of the set. @param {number} i @param {number} j @returns {number} */
  delta(i, j) {
    return this.set.get('scans').delta(i, j);
  }

  /**
   * k-means; `restarts` runs, the one of lowest cost kept (1: the paper's single run;
   * the wasm side refuses more than its limit, 1000).
   * @param {number} k @param {Seeding} seeding @param {number} seed @param {number} [restarts]
   * @returns {Int32Array}
   * @throws {RangeError} unless `restarts` is a whole number from 1 to 2^32 - 1
   */
  kmeans(k, seeding, seed, restarts = 1) {
    checkRuns(restarts);
    return Int32Array.from(this.set.get('scans').kmeans(k, seeding, seed, restarts).labels);
  }

  /**
   * The set's Delta matrix, n x n row-major (computed here if no worker gave it):
   * what `Describer.spectral` takes in a worker (app.js; spectral clustering
   * grows with the cube of the scans, so it never runs on the page's thread).
   * @returns {Float32Array}
   */
  deltaMatrix() {
    return this.set.get('scans').deltaMatrix();
  }

  /** @param {number} eps @param {number} minPoints @returns {Int32Array} */
  dbscan(eps, minPoints) {
    return this.set.get('scans').dbscan(eps, minPoints);
  }

  /** The most central scan of each category, label -> scan index. @param {Int32Array} labels @returns {Map<number, number>} */
  medoids(labels) {
    const flat = this.set.get('scans').medoids(labels);
    const out = new Map();
    for (let k = 0; k < flat.length; k += 2) out.set(flat[k], flat[k + 1]);
    return out;
  }

  /** DBSCAN over the set's own epsilon grid x these min points. @param {number[]} minPoints @param {string[] | undefined} truth @returns {SweepPoint[]} */
  sweep(minPoints, truth) {
    const set = this.set.get('scans');
    return set.dbscanSweep(set.epsilonGrid(), Uint32Array.from(minPoints), truth);
  }

  /** A named model of these labels, as JSON. @param {Int32Array} labels @param {[number, string][]} names @returns {string} */
  modelJson(labels, names) {
    return scoped(this.set.get('scans').buildModel(labels, names), (m) => m.toJson());
  }

  /** Load a model; a malformed one throws and the loaded one stays. @param {string} json @returns {CategorySummary[]} */
  loadModel(json) {
    const model = this.wasm.Model.fromJson(json);
    this.model.set(model);
    return model.categories();
  }

  /** The loaded model's category for a descriptor. @param {string} descriptorJson @returns {Classification} */
  classifyJson(descriptorJson) {
    return this.model.get('model').classifyJson(descriptorJson);
  }

  /**
   * Why the loaded model cannot classify descriptors made with `params`
   * (the first parameter that differs), or null when it can.
   * @param {Params} params @returns {string | null}
   */
  paramsRefusal(params) {
    try {
      this.model.get('model').checkMadeWith(params);
      return null;
    } catch (e) {
      return /** @type {Error} */ (e).message;
    }
  }

  dispose() {
    this.tree.clear();
    this.set.clear();
    this.model.clear();
  }
}

/**
 * A set of these descriptors; a bad one throws, and nothing is left to free.
 * @param {Wasm} wasm @param {Params} params @param {string[]} descriptorJsons
 */
function descriptorSet(wasm, params, descriptorJsons) {
  const set = new wasm.DescriptorSet(params, undefined);
  try {
    for (const json of descriptorJsons) set.addJson(json);
  } catch (e) {
    set.free();
    throw e;
  }
  return set;
}

/** @param {import('./pkg/placecat.js').Cut} cut @param {number} threshold @returns {CutData} */
function cutData(cut, threshold) {
  return { labels: Int32Array.from(cut.labels), nodes: cut.nodes, threshold };
}

/** The describing side (each worker): reads and describes one scan at a time. */
/**
 * What the page keeps of a described scan (a file's, or a bag cloud's, which
 * adds its pose).
 * @param {import('./pkg/placecat.js').DescribedScan} scan @returns {ScanResult}
 */
export function scanResult(scan) {
  const preview = scan.preview();
  return { name: scan.name, format: scan.format, descriptorJson: scan.descriptorJson(), summary: scan.summary(), preview, site: siteSubsample(preview) };
}

export class Describer {
  /**
   * @param {Wasm} wasm @param {{tailIdleMs?: number}} [how] `tailIdleMs`: how long the set of a tail is kept
   *   after its last task (the next comes within a message's round trip, or once the page's tree is built)
   */
  constructor(wasm, { tailIdleMs = 5000 } = {}) {
    this.wasm = wasm;
    this.tailIdleMs = tailIdleMs;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this.tailTimer = undefined;
    /** @type {Slot<import('./pkg/placecat.js').Simulator>} */
    this.simulator = new Slot();
    this.simKey = '';
    /** @type {Slot<import('./pkg/placecat.js').Model>} */
    this.model = new Slot();
    this.modelJson = '';
    /** @type {Slot<import('./pkg/placecat.js').DescriptorSet>} the set of the last tail's tasks */
    this.set = new Slot();
    this.setKey = '';
  }

  /**
   * @param {Uint8Array} bytes @param {string} name @param {Params} params
   * @param {number} [previewPoints] @returns {ScanResult}
   */
  describe(bytes, name, params, previewPoints = 3000) {
    return scoped(this.wasm.describeScan(bytes, name, params, undefined, previewPoints), scanResult);
  }

  /**
   * The set of a run's tail (matrix.js): built from these descriptors for
   * the first of its tasks (`key`), kept for the next ones, so that each
   * worker reads the descriptors and prepares them once.
   * @param {string} key @param {Params} params @param {string[]} descriptorJsons
   */
  tailSet(key, params, descriptorJsons) {
    if (key !== this.setKey || !this.set.value) {
      this.set.clear();
      this.set.set(descriptorSet(this.wasm, params, descriptorJsons));
      this.setKey = key;
    }
    return this.set.get('set');
  }

  /**
   * Delta from each scan of `rows` to every later one, row after row, in a
   * set of these descriptors: this worker's share of the Delta matrix.
   * @param {string} key @param {Params} params @param {string[]} descriptorJsons @param {number[]} rows @returns {Float32Array}
   */
  deltaRows(key, params, descriptorJsons, rows) {
    return this.#keepTail(this.tailSet(key, params, descriptorJsons).deltaRows(Uint32Array.from(rows)));
  }

  /**
   * The reference sets `which` of the choice of categories for a tree of
   * `seed` and `restarts`, in a set of these descriptors: this worker's share of the choice.
   * @param {string} key @param {Params} params @param {string[]} descriptorJsons @param {number} seed @param {number[]} which
   * @param {number} [restarts]
   * @returns {Float64Array}
   */
  referenceDispersions(key, params, descriptorJsons, seed, which, restarts = 1) {
    checkRuns(restarts);
    return this.#keepTail(this.tailSet(key, params, descriptorJsons).referenceDispersions(seed, Uint32Array.from(which), restarts));
  }

  /**
   * Spectral clustering in a worker, so that the page stays live however long
   * it takes (it grows with the cube of the scans; the core takes at most 2000):
   * a set of these descriptors with this Delta matrix (the page's, so that it is
   * not computed twice), clustered into `k`; with `kmeansSeeded`, k-means
   * started from spectral clustering's groups (`spectral` seeding) instead.
   * The core's errors are thrown as they are.
   * @param {Params} params @param {string[]} descriptorJsons @param {Float32Array} matrix n x n, row-major
   * @param {number} k @param {number} seed @param {boolean} [kmeansSeeded] @returns {Int32Array}
   */
  spectral(params, descriptorJsons, matrix, k, seed, kmeansSeeded = false) {
    return scoped(descriptorSet(this.wasm, params, descriptorJsons), (set) => {
      set.setDeltaMatrix(matrix);
      const result = kmeansSeeded ? set.kmeans(k, 'spectral', seed, 1) : set.spectral(k, seed);
      return Int32Array.from(result.labels);
    });
  }

  /**
   * A task comes (worker.js): one that is not a tail's ends the tail, so
   * its set (the descriptors of every scan) is not held beside a new run.
   * @param {string} type the task's
   */
  taskArrives(type) {
    if (type !== 'deltaRows' && type !== 'references') this.endTail();
  }

  /** Free the set of the tail, if any. */
  endTail() {
    clearTimeout(this.tailTimer);
    this.set.clear();
    this.setKey = '';
  }

  /**
   * After a tail's task: the tail has ended when no other of its tasks
   * comes within tailIdleMs. @template R @param {R} result @returns {R}
   */
  #keepTail(result) {
    clearTimeout(this.tailTimer);
    this.tailTimer = setTimeout(() => this.endTail(), this.tailIdleMs);
    return result;
  }

  /** The share of a scan's points beyond 10 m (all its points, not the preview). @param {Uint8Array} bytes @param {string} name */
  farShare(bytes, name) {
    return rangeShare(scoped(this.wasm.readScan(bytes, name), (scan) => scan.positions())).far;
  }

  /**
   * The first scan of a data set: its share of far points decides the
   * preset, and it is described with that preset's parameters (`byPreset`).
   * The file's bytes are read once; only the parse is done twice (positions,
   * then the descriptor), so nothing is read again once the preset is known.
   * @param {Uint8Array} bytes @param {string} name @param {Record<import('./suggest.js').SuggestedPreset, Params>} byPreset
   * @param {number} [previewPoints] @returns {ScanResult}
   */
  describeSuggesting(bytes, name, byPreset, previewPoints = 3000) {
    const far = this.farShare(bytes, name);
    const preset = suggestPreset(far);
    return { ...this.describe(bytes, name, byPreset[preset], previewPoints), far, preset };
  }

  /**
   * Scan `index` of a simulated data set, described, with its label and pose.
   * With `probe`, also its share of far points (the demo's preset suggestion).
   * @param {{scene: 'indoor' | 'warehouse' | 'outdoor', seed: number, scans: number, index: number, probe?: boolean}} sim
   * @param {Params} params @param {number} [previewPoints] @returns {ScanResult}
   */
  simulate({ scene, seed, scans, index, probe }, params, previewPoints = 3000) {
    const key = `${scene}/${seed}/${scans}`;
    if (key !== this.simKey || !this.simulator.value) {
      this.simulator.set(new this.wasm.Simulator(scene, seed, scans));
      this.simKey = key;
    }
    const s = this.simulator.get('simulator').scan(index);
    const far = probe ? { far: this.farShare(s.bytes, s.name) } : {};
    return { ...this.describe(s.bytes, s.name, params, previewPoints), label: s.label, pose: s.pose, ...far };
  }

  /**
   * Describe a scan with a model's parameters and classify it.
   * @param {Uint8Array} bytes @param {string} name @param {string} modelJson
   * @returns {Classification}
   */
  classify(bytes, name, modelJson) {
    if (modelJson !== this.modelJson || !this.model.value) {
      this.model.set(this.wasm.Model.fromJson(modelJson));
      this.modelJson = modelJson;
    }
    const model = this.model.get('model');
    return scoped(this.wasm.describeScan(bytes, name, model.params(), undefined, 0), (scan) => model.classify(scan));
  }

  dispose() {
    this.simulator.clear();
    this.model.clear();
    this.endTail();
  }
}
