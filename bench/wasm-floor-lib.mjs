// What bench/wasm-floor.mjs (Node) and bench/wasm-floor-chromium.mjs (in a
// page, imported there from a data: URL) share: instantiating the wasm build
// of examples/wasm_floor.rs, loading a file into it, and the fastest-call
// loop. No imports, so that it runs in both.

/// The file formats `floor_load` takes, by number.
export const FORMATS = ['ply', 'bin', 'pcd'];

/// The format number of `file`, or an error naming it (`floor_load` would
/// trap on an unknown number).
export function formatOf(file) {
  const format = FORMATS.indexOf(file.split('.').pop());
  if (format < 0) throw new Error(`${file}: not a .ply, .bin or .pcd file`);
  return format;
}

/// The library's wasm-bindgen imports, each a function that throws: the
/// example's exports never call them.
export function importStubs(module) {
  const imports = {};
  for (const { module: m, name } of WebAssembly.Module.imports(module)) {
    imports[m] ??= {};
    imports[m][name] = () => { throw new Error(`${m}.${name} called`); };
  }
  return imports;
}

/// Copies `bytes` (a file named `file`) into the instance's memory and
/// prepares every stage's input; returns the file's points and the stages.
export function load(x, bytes, file) {
  const format = formatOf(file);
  const ptr = x.floor_alloc(bytes.length);
  new Uint8Array(x.memory.buffer, ptr, bytes.length).set(bytes);
  const points = x.floor_load(ptr, bytes.length, format);
  const stages = { read: x.floor_read, grid: x.floor_grid, classify: x.floor_classify, align: x.floor_align, hist: x.floor_hist, describe: x.floor_describe, total: x.floor_total };
  return { points, stages };
}

/// Fastest call of each stage, in seconds, over about `n` calls: the stages
/// take turns, five calls at a time (as the native example's `time` mode),
/// timed one by one (`batch` 1) or five in one timing (`batch` 5, for a
/// page's coarsened clock).
export function fastest(stages, n, batch) {
  const best = Object.fromEntries(Object.keys(stages).map((k) => [k, Infinity]));
  for (let r = 0; r < Math.ceil(n / 5); r++) {
    for (const [k, f] of Object.entries(stages)) {
      for (let i = 0; i < 5 / batch; i++) {
        const t = performance.now();
        f(batch);
        best[k] = Math.min(best[k], (performance.now() - t) / 1000 / batch);
      }
    }
  }
  return best;
}
