// The wasm build of examples/wasm_floor.rs in Node: the same stages, the
// same calls as the native example (docs/wasm-floor.md).
//   node bench/wasm-floor.mjs WASM FILE STAGE N   runs one stage N times
//   node bench/wasm-floor.mjs WASM FILE time N    fastest of N calls of each stage, 5 in a row
//   node bench/wasm-floor.mjs WASM FILE digest 0  digest of the grid's and descriptor's bits
// Run with `--no-liftoff` so that every function is V8's optimised code
// (TurboFan) from the first call, as the page's code is after warm-up.
import { readFileSync } from 'node:fs';

const [wasmPath, file, stage, nArg] = process.argv.slice(2);
const module = new WebAssembly.Module(readFileSync(wasmPath));
// The library's wasm-bindgen imports are never called by these exports.
const imports = {};
for (const { module: m, name } of WebAssembly.Module.imports(module)) {
  imports[m] ??= {};
  imports[m][name] = () => { throw new Error(`${m}.${name} called`); };
}
const { exports: x } = new WebAssembly.Instance(module, imports);
const bytes = readFileSync(file);
const ptr = x.floor_alloc(bytes.length);
new Uint8Array(x.memory.buffer, ptr, bytes.length).set(bytes);
const points = x.floor_load(ptr, bytes.length, ['ply', 'bin', 'pcd'].indexOf(file.split('.').pop()));
const n = Number(nArg);
const stages = { read: x.floor_read, grid: x.floor_grid, classify: x.floor_classify, align: x.floor_align, hist: x.floor_hist, describe: x.floor_describe, total: x.floor_total };
if (stage === 'digest') {
  console.log(BigInt.asUintN(64, x.floor_digest()).toString(16).padStart(16, '0'));
} else if (stage === 'time') {
  const best = Object.fromEntries(Object.keys(stages).map((k) => [k, Infinity]));
  // As the native example: the stages take turns, 5 calls at a time.
  for (let r = 0; r < Math.ceil(n / 5); r++) {
    for (const [k, f] of Object.entries(stages)) {
      for (let i = 0; i < 5; i++) {
        const t = performance.now();
        f(1);
        best[k] = Math.min(best[k], (performance.now() - t) / 1000);
      }
    }
  }
  console.log(JSON.stringify({ points, seconds: best }));
} else {
  console.log(stages[stage](n));
}
