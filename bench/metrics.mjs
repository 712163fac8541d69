// What the Hellinger distance costs in wasm against the paper's (issues 14
// and 18, sixth round; not part of npm test): the Delta matrix of the first
// N of the 1,000 simulated outdoor scans that `npm run bench` uses, in one
// thread, under `outdoor` (the paper's Eq. 2) and `outdoor_hellinger` (the
// page's outdoor suggestion; the same descriptors, roots taken once).
//
//   node bench/metrics.mjs [N]   (default 1000; needs pkg/ and
//   test-artifacts/bench-1000 from `placecat simulate --scene outdoor --seed 1 --scans 1000`)
import { readFileSync, readdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describeScan, DescriptorSet } from '../pkg/node/placecat.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const dir = join(root, 'test-artifacts', 'bench-1000');
const n = Number(process.argv[2] ?? 1000);
const files = readdirSync(dir).filter((f) => f.endsWith('.ply')).sort().slice(0, n);
const presets = ['outdoor', 'outdoor_hellinger'];
const json = files.map((f) => {
  const d = describeScan(readFileSync(join(dir, f)), f, undefined, 'outdoor');
  const j = d.descriptorJson();
  d.free();
  return j;
});
/** A fresh set of the same descriptors under `preset`'s distance. */
const setOf = (preset) => {
  const set = new DescriptorSet(undefined, preset);
  for (const j of json) set.addJson(j);
  return set;
};
// Three rounds, the presets alternated; the median of each is reported.
const times = { outdoor: [], outdoor_hellinger: [] };
for (let round = 0; round < 3; round++) {
  for (const preset of presets) {
    const set = setOf(preset);
    const t = performance.now();
    set.deltaMatrix();
    times[preset].push(performance.now() - t);
    set.free();
  }
}
const median = (v) => [...v].sort((a, b) => a - b)[1];
const [paper, hellinger] = presets.map((p) => median(times[p]));
console.log(`${files.length} scans, Delta matrix in one wasm thread: outdoor ${paper.toFixed(0)} ms, outdoor_hellinger ${hellinger.toFixed(0)} ms (${(hellinger / paper).toFixed(2)}x)`);
