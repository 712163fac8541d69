// bench/wasm-floor.mjs's `time` mode in headless Chromium (its V8 is newer
// than Node's): fastest of N / 5 runs of five calls of each stage, per wasm
// build given, the builds alternated ROUNDS times (docs/wasm-floor.md).
//   node bench/wasm-floor-chromium.mjs FILE N ROUNDS WASM...
import { readFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { formatOf } from './wasm-floor-lib.mjs';

const [file, nArg, roundsArg, ...wasms] = process.argv.slice(2);
formatOf(file); // a clear error before Chromium starts
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking'],
});
const page = await browser.newPage();
const b64 = (p) => readFileSync(p).toString('base64');
const fileB64 = b64(file);
const libUrl = `data:text/javascript;base64,${b64(new URL('./wasm-floor-lib.mjs', import.meta.url))}`;
for (let round = 0; round < Number(roundsArg); round++) {
  for (const wasm of wasms) {
    const result = await page.evaluate(async ([libUrl, wasmB64, fileB64, file, n]) => {
      const { fastest, importStubs, load } = await import(libUrl);
      const bytesOf = (s) => Uint8Array.from(atob(s), (c) => c.charCodeAt(0));
      const module = await WebAssembly.compile(bytesOf(wasmB64));
      const x = (await WebAssembly.instantiate(module, importStubs(module))).exports;
      const { points, stages } = load(x, bytesOf(fileB64), file);
      // Warm-up: Chromium tiers wasm up from Liftoff to TurboFan in the background.
      for (const f of Object.values(stages)) f(3);
      await new Promise((r) => setTimeout(r, 500));
      // Five calls in one timing: the page's clock is coarsened (to 0.1 ms).
      return { points, seconds: fastest(stages, n, 5) };
    }, [libUrl, b64(wasm), fileB64, file, Number(nArg)]);
    console.log(JSON.stringify({ round, wasm, ...result }));
  }
}
await browser.close();
