// The Chromium side of the bench: exposes the comparisons to the driver.
import init, * as placecat from '../www/pkg/placecat.js';
import { makePly, compare } from './parsers.bundle.js';

await init();
window.benchParse = async (n, binary) => compare(placecat, makePly(n, binary), n);
window.benchDescribe = async (url, name, runs = 5) => {
  const bytes = new Uint8Array(await (await fetch(url)).arrayBuffer());
  const times = [];
  let points = 0;
  for (let r = 0; r < runs + 1; r++) {
    const t0 = performance.now();
    const d = placecat.describeScan(bytes, name, undefined, 'outdoor', 0);
    const dt = performance.now() - t0;
    points = d.summary().points + d.summary().dropped;
    d.free();
    if (r > 0) times.push(dt);
  }
  times.sort((a, b) => a - b);
  return { points, seconds: times[Math.floor(times.length / 2)] / 1000 };
};
document.getElementById('status').textContent = 'ready';
