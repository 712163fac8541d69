// The tail of a finished run in the workers: the Delta matrix, and the
// reference sets of the choice of categories (the gap statistic's, the
// costly part of the choice, which needs no tree). Each worker takes every
// size-th row of the matrix (rows shrink down the matrix, so interleaved
// shares are even) and every size-th reference set; the page mirrors the
// rows into the n x n matrix and builds the tree while the workers draw
// and cluster the reference sets, then chooses with them (engine.js). On
// the main thread the matrix took 0.8 s of 1,000 scans and the choice
// 0.4 s while the workers stood idle. A worker keeps the set it built for
// the first task of a tail (`key`), so it reads the descriptors once.

/** Tails started by this page: the tasks of one share a key. */
let tails = 0;

/** A key for the tasks of a new tail. */
export const tailKey = () => `tail ${++tails}`;

/**
 * Every size-th number of 0..n, from each worker's own on.
 * @param {number} n @param {number} size @returns {number[][]}
 */
function interleaved(n, size) {
  return Array.from({ length: size }, (_, k) => {
    const share = [];
    for (let i = k; i < n; i += size) share.push(i);
    return share;
  });
}

/**
 * @param {import('./pool.js').WorkerPool} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @param {string} [key] the tail's (tailKey)
 * @returns {Promise<Float32Array>} n x n, row-major
 */
export async function matrixInWorkers(pool, params, descriptorJsons, key = tailKey()) {
  const n = descriptorJsons.length;
  const shares = interleaved(n, pool.size);
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
 * in order, for a tree of `seed`: what Engine.suggestCategories takes.
 * @param {import('./pool.js').WorkerPool} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @param {{seed: number, sets: number}} choice the tree's seed and how many reference
 *   sets the choice draws (Engine.referenceSets) @param {string} [key] the tail's (tailKey)
 * @returns {Promise<Float64Array>}
 */
export async function referencesInWorkers(pool, params, descriptorJsons, { seed, sets }, key = tailKey()) {
  const shares = interleaved(sets, pool.size).filter((which) => which.length);
  const values = await Promise.all(shares.map((which) => pool.run({ type: 'references', key, params, descriptorJsons, seed, which })));
  const perSet = values[0].length / shares[0].length;
  const all = new Float64Array(sets * perSet);
  shares.forEach((which, k) => which.forEach((b, at) => all.set(values[k].subarray(at * perSet, (at + 1) * perSet), b * perSet)));
  return all;
}
