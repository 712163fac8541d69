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
 * in order, for a tree of `seed` and `restarts`: what Engine.suggestCategories takes. One
 * task a set, each held alone (oneAtATime), so that a worker slowed by the
 * page's tree (or by anything else on the machine) takes fewer of them.
 * @param {Pick<import('./pool.js').WorkerPool, 'size' | 'run'>} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @param {{seed: number, restarts: number, sets: number}} choice the tree's seed and
 *   trials a split, and how many reference sets the choice draws (Engine.referenceSets) @param {string} [key] the tail's (tailKey)
 * @returns {Promise<Float64Array>}
 */
export async function referencesInWorkers(pool, params, descriptorJsons, { seed, restarts, sets }, key = tailKey()) {
  const values = await Promise.all(Array.from({ length: sets }, (_, b) => pool.run({ type: 'references', key, params, descriptorJsons, seed, restarts, which: [b] })));
  const all = new Float64Array(values.reduce((n, v) => n + v.length, 0));
  values.reduce((at, v) => (all.set(v, at), at + v.length), 0);
  return all;
}
