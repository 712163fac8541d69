// The bench's worker (bench/page.js): describing alone, without the page:
// one scan's bytes described over and over, for the wasm's points per
// second with every core busy.
import init, * as placecat from '../www/pkg/placecat.js';

const ready = init();

self.onmessage = async (e) => {
  await ready;
  const { bytes, name, times } = e.data;
  let points = 0;
  const t0 = performance.now();
  for (let r = 0; r < times; r++) {
    const d = placecat.describeScan(bytes, name, undefined, 'outdoor', 0);
    points += d.summary().points + d.summary().dropped;
    d.free();
  }
  self.postMessage({ seconds: (performance.now() - t0) / 1000, points });
};
