// bench/wasm-floor.mjs's `time` mode in headless Chromium (its V8 is newer
// than Node's): fastest of N / 5 runs of five calls of each stage, per wasm
// build given, the builds alternated ROUNDS times (docs/wasm-floor.md).
//   node bench/wasm-floor-chromium.mjs FILE N ROUNDS WASM...
import { readFileSync } from 'node:fs';
import { chromium } from 'playwright-core';

const [file, nArg, roundsArg, ...wasms] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking'],
});
const page = await browser.newPage();
const format = ['ply', 'bin', 'pcd'].indexOf(file.split('.').pop());
const b64 = (p) => readFileSync(p).toString('base64');
const fileB64 = b64(file);
for (let round = 0; round < Number(roundsArg); round++) {
  for (const wasm of wasms) {
    const result = await page.evaluate(async ([wasmB64, fileB64, format, n]) => {
      const bytesOf = (s) => Uint8Array.from(atob(s), (c) => c.charCodeAt(0));
      const module = await WebAssembly.compile(bytesOf(wasmB64));
      const imports = {};
      for (const { module: m, name } of WebAssembly.Module.imports(module)) {
        imports[m] ??= {};
        imports[m][name] = () => { throw new Error(`${m}.${name} called`); };
      }
      const x = (await WebAssembly.instantiate(module, imports)).exports;
      const bytes = bytesOf(fileB64);
      const ptr = x.floor_alloc(bytes.length);
      new Uint8Array(x.memory.buffer, ptr, bytes.length).set(bytes);
      const points = x.floor_load(ptr, bytes.length, format);
      const stages = { read: x.floor_read, grid: x.floor_grid, classify: x.floor_classify, align: x.floor_align, hist: x.floor_hist, describe: x.floor_describe, total: x.floor_total };
      // Warm-up: Chromium tiers wasm up from Liftoff to TurboFan in the background.
      for (const f of Object.values(stages)) f(3);
      await new Promise((r) => setTimeout(r, 500));
      const best = Object.fromEntries(Object.keys(stages).map((k) => [k, Infinity]));
      for (let r = 0; r < Math.ceil(n / 5); r++) {
        for (const [k, f] of Object.entries(stages)) {
          // Five calls in one: the page's clock is coarsened (to 0.1 ms).
          const t = performance.now();
          f(5);
          best[k] = Math.min(best[k], (performance.now() - t) / 5000);
        }
      }
      return { points, seconds: best };
    }, [b64(wasm), fileB64, format, Number(nArg)]);
    console.log(JSON.stringify({ round, wasm, ...result }));
  }
}
await browser.close();
