// The Delta matrix of a finished run, computed by the workers: each takes
// every size-th row (rows shrink down the matrix, so interleaved shares are
// even) and the page mirrors the shares into the n x n matrix. On the main
// thread alone it was 0.8 s of 1,000 scans while the workers stood idle.

/**
 * @param {import('./pool.js').WorkerPool} pool @param {import('./engine.js').Params} params
 * @param {string[]} descriptorJsons @returns {Promise<Float32Array>} n x n, row-major
 */
export async function matrixInWorkers(pool, params, descriptorJsons) {
  const n = descriptorJsons.length;
  const shares = Array.from({ length: pool.size }, (_, k) => {
    const rows = [];
    for (let i = k; i < n; i += pool.size) rows.push(i);
    return rows;
  });
  const values = await Promise.all(shares.map((rows) => pool.run({ type: 'deltaRows', params, descriptorJsons, rows })));
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
