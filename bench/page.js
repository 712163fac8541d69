// The Chromium side of the bench: exposes the comparisons to the driver.
import init, * as placecat from '../www/pkg/placecat.js';
import { makePly, compare } from './parsers.bundle.js';

await init();
window.benchParse = async (n, binary) => compare(placecat, makePly(n, binary), n);
// Read + describe on one core, from memory: batches of 10 (performance.now()
// is coarse here), the median and the fastest batch of `batches`.
window.benchDescribe = async (url, name, batches = 10) => {
  const bytes = new Uint8Array(await (await fetch(url)).arrayBuffer());
  const times = [];
  let points = 0;
  for (let r = 0; r < batches + 1; r++) {
    const t0 = performance.now();
    for (let k = 0; k < 10; k++) {
      const d = placecat.describeScan(bytes, name, undefined, 'outdoor', 0);
      points = d.summary().points + d.summary().dropped;
      d.free();
    }
    const dt = (performance.now() - t0) / 10;
    if (r > 0) times.push(dt);
  }
  times.sort((a, b) => a - b);
  return { points, seconds: times[Math.floor(times.length / 2)] / 1000, fastest: times[0] / 1000 };
};

const chosen = () => [.../** @type {HTMLInputElement} */ (document.getElementById('files')).files];

/**
 * The page's reading alone: every file given to #files read on the main
 * thread as the page reads them (File.arrayBuffer, `inFlight` at once).
 */
window.benchRead = async (inFlight = 8) => {
  const files = chosen();
  let next = 0, bytes = 0;
  const t0 = performance.now();
  const lane = async () => {
    while (next < files.length) {
      const buf = await files[next++].arrayBuffer();
      bytes += buf.byteLength;
    }
  };
  await Promise.all(Array.from({ length: inFlight }, lane));
  return { seconds: (performance.now() - t0) / 1000, bytes, files: files.length };
};

/**
 * The page's describing alone: the first file's bytes described in
 * `workers` workers, as many times in all as there are files (outdoor
 * preset, no preview), after one warm-up each.
 */
window.benchDescribeAlone = async (workers = 2) => {
  const files = chosen();
  const bytes = new Uint8Array(await files[0].arrayBuffer());
  const pool = Array.from({ length: workers }, () => new Worker(new URL('./worker.js', import.meta.url), { type: 'module' }));
  const one = (w, times) => new Promise((ok) => { w.onmessage = (e) => ok(e.data); w.postMessage({ bytes, name: files[0].name, times }); });
  await Promise.all(pool.map((w) => one(w, 1)));
  const t0 = performance.now();
  const out = await Promise.all(pool.map((w) => one(w, Math.ceil(files.length / workers))));
  const seconds = (performance.now() - t0) / 1000;
  for (const w of pool) w.terminate();
  return { seconds, points: out.reduce((s, o) => s + o.points, 0), busy: out.reduce((s, o) => s + o.seconds, 0) };
};
document.getElementById('status').textContent = 'ready';
