// The wasm build of examples/wasm_floor.rs in Node: the same stages, the
// same calls as the native example (docs/wasm-floor.md).
//   node bench/wasm-floor.mjs WASM FILE STAGE N   runs one stage N times
//   node bench/wasm-floor.mjs WASM FILE time N    fastest of N calls of each stage, 5 in a row
//   node bench/wasm-floor.mjs WASM FILE digest 0  digest of the grid's and descriptor's bits
// Run with `--no-liftoff` so that every function is V8's optimised code
// (TurboFan) from the first call, as the page's code is after warm-up.
import { readFileSync } from 'node:fs';
import { fastest, importStubs, load } from './wasm-floor-lib.mjs';

const [wasmPath, file, stage, nArg] = process.argv.slice(2);
const module = new WebAssembly.Module(readFileSync(wasmPath));
const { exports: x } = new WebAssembly.Instance(module, importStubs(module));
const { points, stages } = load(x, readFileSync(file), file);
const n = Number(nArg);
if (stage === 'digest') {
  console.log(BigInt.asUintN(64, x.floor_digest()).toString(16).padStart(16, '0'));
} else if (stage === 'time') {
  console.log(JSON.stringify({ points, seconds: fastest(stages, n, 1) }));
} else if (stages[stage]) {
  console.log(stages[stage](n));
} else {
  throw new Error(`unknown stage ${stage} (one of ${Object.keys(stages).join(', ')}, time, digest)`);
}
