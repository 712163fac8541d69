// The tail of a finished run in the workers: the Delta matrix, and the
// reference sets of the choice of categories (the gap statistic's, its
// costly part, which needs no tree). Each worker takes every size-th row
// of the matrix (rows shrink down the matrix, so interleaved shares are
// even), then reference sets one at a time, as it comes free. The page
// mirrors the rows into the n x n matrix and builds the tree while the
// workers draw and cluster the reference sets, then chooses with them
// (engine.js). On the main thread the matrix took 0.8 s of 1,000 scans and
// the choice 0.4 s, while the workers stood idle. A worker keeps the set
// it built for the first task of a tail (`key`): it reads the descriptors once.

/**
 * The tasks a worker holds one at a time (the pool's `alone`): a reference
 * set. The pool hands a worker several tasks at once (app.js: four), so a
 * worker would take its rows and the next three sets together and keep
 * them however slow it turns out; held one at a time, a set goes to
 * whichever worker comes free (a set takes tens of ms, a message's round
 * trip well under one).
 * @param {{type?: string}} task
 */
export const oneAtATime = (task) => task.type === 'references';

/** Tails started by this page: the tasks of one share a key. */
let tails = 0;

/** A key for the tasks of a new tail. */
export const tailKey = () => `tail ${++tails}`;

/**
 * @param {Pick<import('./pool.js').WorkerPool, 'size' | 'run'>} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @param {string} [key] the tail's (tailKey)
 * @returns {Promise<Float32Array>} n x n, row-major
 */
export async function matrixInWorkers(pool, params, descriptorJsons, key = tailKey()) {
  const n = descriptorJsons.length;
  const shares = Array.from({ length: pool.size }, (_, k) => {
    const rows = [];
    for (let i = k; i < n; i += pool.size) rows.push(i);
    return rows;
  });
  const values = await Promise.all(shares.map((rows) => pool.run({ type: 'deltaRows', key, params, descriptorJsons, rows })));
  const m = new Float32Array(n * n);
  shares.forEach((rows, k) => {
    let at = 0;
    for (const i of rows) {
      for (let j = i + 1; j < n; j++) {
        const v = values[k][at++];
        m[i * n + j] = v;
        m[j * n + i] = v;
      }
    }
  });
  return m;
}

/**
 * Every reference set's dispersions (DescriptorSet.referenceDispersions),
 * in order, for a tree of `seed`: what Engine.suggestCategories takes. One
 * task a set, each held alone (oneAtATime), so that a worker slowed by the
 * page's tree (or by anything else on the machine) takes fewer of them.
 * @param {Pick<import('./pool.js').WorkerPool, 'size' | 'run'>} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @param {{seed: number, sets: number}} choice the tree's seed and how many reference
 *   sets the choice draws (Engine.referenceSets) @param {string} [key] the tail's (tailKey)
 * @returns {Promise<Float64Array>}
 */
export async function referencesInWorkers(pool, params, descriptorJsons, { seed, sets }, key = tailKey()) {
  const values = await Promise.all(Array.from({ length: sets }, (_, b) => pool.run({ type: 'references', key, params, descriptorJsons, seed, which: [b] })));
  const all = new Float64Array(values.reduce((n, v) => n + v.length, 0));
  values.reduce((at, v) => (all.set(v, at), at + v.length), 0);
  return all;
}

/** @typedef {import('./pool.js').Filler} Filler */
/** @typedef {{json: string, place: number}} Arrival a descriptor, with its place in the run's set (the order of its inputs) */

/**
 * The Delta matrix of a run's scans, computed while they are described:
 * the workers' waits for their next file (0.8 s each of a 1,000-scan run)
 * go to blocks of it, so that after the last scan only the last rows are
 * left (before, all of it: 0.47 s of the 1,000-scan run's wall time).
 * Scans come out of order; each gets a row in the order it came (arrival
 * r: its Delta to every earlier arrival), and the matrix is put in the
 * order of the set (the places) once, at the end. Each worker keeps the
 * run's descriptors it was sent (Describer.arrivalRows), so each is sent
 * to each worker once.
 *
 * During the run each worker holds a block (type `deltaBlock`, the pool's
 * filler) of up to `pairsPerTask` Deltas (~30 ms: the page hears of its
 * end 20-30 ms late), which it computes only while it has no scan to
 * describe, in chunks of 2 ms (idle.js); the newest `pool.size` arrivals wait for the end,
 * so that the rows left are shared by every worker (`rest`, type
 * `deltaRows`, like the tail's of matrixInWorkers). A failed block (a
 * worker died, the run was cancelled) fails the matrix: the page then
 * computes it as before.
 */
export class GrowingMatrix {
  /**
   * @param {Pick<import('./pool.js').WorkerPool, 'size' | 'run' | 'fill' | 'filler'>} pool @param {import('./engine.js').Params} params
   * @param {{key?: string, pairsPerTask?: number, limit?: number}} [how] `limit`: the most scans a Delta matrix is kept for
   *   (more fail the matrix: the set would not take it)
   */
  constructor(pool, params, { key = tailKey(), pairsPerTask = 15000, limit = Infinity } = {}) {
    this.pool = pool;
    this.params = params;
    this.key = key;
    this.pairsPerTask = pairsPerTask;
    this.limit = limit;
    /** @type {Arrival[]} */
    this.arrivals = [];
    /** @type {Float32Array[]} row r: the Delta from arrival r to each earlier one, in order */
    this.rows = [];
    /** Arrivals whose rows are handed to a worker (or done). */
    this.handed = 0;
    /** @type {WeakMap<Worker, number>} how many arrivals each worker was sent */
    this.sent = new WeakMap();
    /** @type {Set<Promise<void>>} the tasks given out, until they are stored (they never reject) */
    this.inFlight = new Set();
    /** @type {Error | null} the first failure; the matrix is then given up */
    this.failure = null;
    /** @type {Filler} */
    this.filler = (worker) => this.#block(worker);
    pool.filler = this.filler;
  }

  /** A scan was described: its descriptor, and its place in the run's set. @param {number} place @param {string} json */
  add(place, json) {
    if (this.failure) return;
    if (this.arrivals.length >= this.limit) return this.#fail(new Error(`more than ${this.limit} scans: no Delta matrix is kept`));
    this.arrivals.push({ json, place });
    this.pool.fill();
  }

  /** No more blocks (the run ended or was superseded): the rows left wait for `rest`. */
  stop() {
    if (this.pool.filler === this.filler) this.pool.filler = null;
  }

  /** Whether the run was cancelled while blocks were computed (Cancel or a new run). */
  get cancelled() {
    return this.failure?.message === 'cancelled';
  }

  /**
   * Wait for the blocks in the workers; then whether the rows computed
   * can make the matrix of a set of `n` scans with `params` (no failure,
   * every scan came).
   * @param {import('./engine.js').Params} params @param {number} n @returns {Promise<boolean>}
   */
  async settled(params, n) {
    this.stop();
    while (this.inFlight.size) await Promise.all(this.inFlight);
    return !this.failure && params === this.params && this.arrivals.length === n;
  }

  /**
   * The rows left, as one task per worker (interleaved rows: each worker
   * gets a like share), queued with `run` (the pool's, or one that counts
   * them); resolves to the matrix, n x n in the order of the places.
   * @param {(task: any) => Promise<any>} run @returns {Promise<Float32Array>}
   */
  async rest(run) {
    const n = this.arrivals.length, size = this.pool.size;
    for (let k = 0; k < size; k++) {
      const rows = [];
      for (let r = this.handed + k; r < n; r += size) rows.push(r);
      if (rows.length) this.#track(run({ type: 'deltaRows', growing: this, rows }), rows);
    }
    this.handed = n;
    while (this.inFlight.size) await Promise.all(this.inFlight);
    if (this.failure) throw this.failure;
    return this.#assemble();
  }

  /**
   * The task of `rows` for `worker` (the pool's prepare, for the tasks of
   * `rest`): the descriptors it has not been sent yet come with it.
   * @param {{rows: number[]}} task @param {Worker} worker
   */
  prepare(task, worker) {
    return Promise.resolve({ task: this.#task('deltaRows', worker, task.rows), transfer: [] });
  }

  /** @param {string} type @param {Worker} worker @param {number[]} rows */
  #task(type, worker, rows) {
    const have = this.sent.get(worker) ?? 0;
    const needs = Math.max(...rows) + 1;
    this.sent.set(worker, Math.max(have, needs));
    return { type, key: this.key, params: this.params, have, adds: this.arrivals.slice(have, needs), rows };
  }

  /** A block for a worker to hold: the next rows but the newest pool.size, up to pairsPerTask Deltas. @param {Worker} worker */
  #block(worker) {
    const upto = this.arrivals.length - this.pool.size;
    if (this.failure || this.handed >= upto) return null;
    const rows = [this.handed];
    for (let r = this.handed + 1, pairs = this.handed; r < upto && pairs + r <= this.pairsPerTask; pairs += r++) rows.push(r);
    this.handed += rows.length;
    /** @type {{resolve: (r: any) => void, reject: (e: Error) => void}} */
    const settle = { resolve: () => {}, reject: () => {} };
    this.#track(new Promise((resolve, reject) => Object.assign(settle, { resolve, reject })), rows);
    return { task: this.#task('deltaBlock', worker, rows), ...settle };
  }

  /** @param {Promise<Float32Array>} result @param {number[]} rows */
  #track(result, rows) {
    const stored = result.then((values) => this.#store(rows, values), (e) => this.#fail(e));
    this.inFlight.add(stored);
    stored.then(() => this.inFlight.delete(stored));
  }

  /** @param {number[]} rows @param {Float32Array} values */
  #store(rows, values) {
    let at = 0;
    for (const r of rows) {
      this.rows[r] = values.subarray(at, at + r);
      at += r;
    }
    if (at !== values.length) this.#fail(new Error(`${values.length} Deltas for rows of ${at} pairs`));
  }

  /** @param {Error} e */
  #fail(e) {
    this.failure ??= e;
    this.stop();
  }

  /** The rows, in the order of the places, mirrored: n x n, row-major. */
  #assemble() {
    const n = this.arrivals.length;
    const byPlace = this.arrivals.map((_, r) => r).sort((a, b) => this.arrivals[a].place - this.arrivals[b].place);
    const at = new Int32Array(n);
    byPlace.forEach((r, i) => (at[r] = i));
    const m = new Float32Array(n * n);
    for (let r = 1; r < n; r++) {
      const row = this.rows[r], i = at[r];
      for (let q = 0; q < r; q++) {
        const j = at[q], v = row[q];
        m[i * n + j] = v;
        m[j * n + i] = v;
      }
    }
    return m;
  }
}
