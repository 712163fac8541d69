// What trial splits cost in wasm (issues 14 and 18, fifth round; not part of
// npm test): the hierarchical k-means++ tree and the gap statistic's 10
// reference trees, with one 2-means++ run a split (the paper's) and with the
// cheapest of 10, on the first N of the 1,000 simulated outdoor scans that
// `npm run bench` uses. The page's TRIAL_SPLITS_UP_TO (www/state.js) rests
// on these figures.
//
//   node bench/tree_trials.mjs [N]   (default 1000; needs pkg/ and
//   test-artifacts/bench-1000 from `placecat simulate --scene outdoor --seed 1 --scans 1000`)
import { readFileSync, readdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describeScan, DescriptorSet } from '../pkg/node/placecat.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const dir = join(root, 'test-artifacts', 'bench-1000');
const n = Number(process.argv[2] ?? 1000);
const files = readdirSync(dir).filter((f) => f.endsWith('.ply')).sort().slice(0, n);
const set = new DescriptorSet(undefined, 'outdoor');
for (const f of files) set.add(describeScan(readFileSync(join(dir, f)), f, undefined, 'outdoor'));
set.deltaMatrix(); // held by the set, as the page's is, before the tree
const all = Uint32Array.from({ length: set.referenceSets }, (_, b) => b);
const ms = (f) => {
  const t = performance.now();
  const out = f();
  return [performance.now() - t, out];
};
// Each setting twice, alternated; the second round is the one reported.
for (const round of [1, 2]) {
  for (const restarts of [1, 10]) {
    const [tree, t] = ms(() => set.hkmeans(0, restarts));
    const [references, d] = ms(() => set.referenceDispersions(0, all, restarts));
    const k = set.chooseCategoriesWith(t, d, 0, restarts).k;
    t.free();
    if (round === 2) console.log(`${files.length} scans, ${restarts} 2-means++ run(s) a split: tree ${tree.toFixed(0)} ms, reference trees ${references.toFixed(0)} ms, K chosen ${k}`);
  }
}
set.free();
