// `npm run bench` (not part of npm test): the wasm build beside its peers,
// in Node and in Chromium, the wasm vs the native build, and the page's
// worker pool on 1,000 simulated scans. Writes docs/benchmarks-web.{md,json}.
import { build } from 'esbuild';
import { chromium } from 'playwright-core';
import { createRequire } from 'node:module';
import { execFileSync, execSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, writeFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { serve } from '../scripts/serve.mjs';
import { makePly, compare } from './parsers.mjs';
import { stageBreakdown } from './stages.mjs';

const ROOT = resolve(new URL('..', import.meta.url).pathname);
const PARENT = resolve(ROOT, '..');
const ART = join(ROOT, 'test-artifacts');
mkdirSync(ART, { recursive: true });
const N = Number(process.env.BENCH_POINTS || 1_000_000);
const POOL_SCANS = Number(process.env.BENCH_SCANS || 1000);
const results = { date: new Date().toISOString(), machine: `${execSync('nproc').toString().trim()} cores`, points: N };
const fmt = (x) => (x / 1e6).toFixed(2);

// 1. Node: the three parsers on the same bytes.
const placecatNode = createRequire(import.meta.url)('../pkg/node/placecat.js');
const bin = makePly(N, true), ascii = makePly(N, false);
results.node = { binary: await compare(placecatNode, bin, N), ascii: await compare(placecatNode, ascii, N) };
console.log('node', results.node);

// 2. Chromium: the same, plus read+describe of real and simulated files.
await build({ entryPoints: [join(ROOT, 'bench/parsers.mjs')], bundle: true, format: 'esm', outfile: join(ROOT, 'bench/parsers.bundle.js'), logLevel: 'error' });
const simFile = join(ART, 'bench-sim-100k.ply');
const cli = join(ROOT, 'target/release/placecat');
execSync('cargo build --release --quiet --example time_describe', { cwd: ROOT, stdio: 'inherit' });
if (!existsSync(join(ART, 'bench-1000', 'scan_00000.ply')) || readdirSync(join(ART, 'bench-1000')).length < POOL_SCANS) {
  console.log(`simulating ${POOL_SCANS} outdoor scans for the pool benchmark`);
  execFileSync(cli, ['simulate', '--scene', 'outdoor', '--seed', '1', '--scans', String(POOL_SCANS), '-o', join(ART, 'bench-1000')], { stdio: 'inherit' });
}
execSync(`cp ${join(ART, 'bench-1000', `scan_${String(Math.floor(POOL_SCANS / 2)).padStart(5, '0')}.ply`)} ${simFile}`);
const realFile = join(ROOT, 'tests/data/real/kitti00/000094.bin');
const server = await serve(PARENT, 0);
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--enable-precise-memory-info'],
});
const page = await browser.newPage();
// The checkout's own folder name (main, or a worktree's).
const checkout = basename(ROOT);
await page.goto(`${base}/${checkout}/bench/page.html`);
await page.waitForFunction(() => document.getElementById('status').textContent === 'ready');
results.chromium = {
  binary: await page.evaluate((n) => window.benchParse(n, true), N),
  ascii: await page.evaluate((n) => window.benchParse(n, false), N),
};
console.log('chromium', results.chromium);
const rel = (p) => `${base}/${p.slice(PARENT.length + 1)}`;
const wasm = {
  kitti_000094: await page.evaluate(([u, n]) => window.benchDescribe(u, n), [rel(realFile), '000094.bin']),
  sim_100k_ply: await page.evaluate(([u, n]) => window.benchDescribe(u, n), [rel(simFile), 'sim.ply']),
};
const native = JSON.parse(execFileSync(join(ROOT, 'target/release/examples/time_describe'), [realFile, simFile]).toString());
results.describe = {
  kitti_000094: { wasm: wasm.kitti_000094, native: native[realFile] },
  sim_100k_ply: { wasm: wasm.sim_100k_ply, native: native[simFile] },
};
console.log('describe', results.describe);
await page.close();

// 3. The page's worker pool on POOL_SCANS files, with memory sampled.
const app = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
await app.goto(`${base}/${checkout}/www/index.html`);
await app.waitForFunction(() => document.body.dataset.ready === 'true');
const files = readdirSync(join(ART, 'bench-1000')).filter((f) => f.endsWith('.ply')).sort().slice(0, POOL_SCANS).map((f) => join(ART, 'bench-1000', f));
let peakHeap = 0, peakRss = 0;
const rss = () => {
  try {
    return Number(execSync("ps -C chromium -o rss= | awk '{s+=$1} END {print s}'").toString().trim()) * 1024;
  } catch { return 0; }
};
const baseRss = rss();
const sampler = setInterval(async () => {
  peakRss = Math.max(peakRss, rss());
  try { peakHeap = Math.max(peakHeap, await app.evaluate(() => performance.memory.usedJSHeapSize)); } catch {}
}, 250);
const t0 = Date.now();
await app.setInputFiles('#files', files);
await app.waitForFunction(() => Number(document.body.dataset.runs || 0) >= 1, null, { timeout: 30 * 60 * 1000 });
const seconds = (Date.now() - t0) / 1000;
clearInterval(sampler);
const status = await app.textContent('#cluster-status');
const { entries, timeOrigin } = await app.evaluate(() => ({
  timeOrigin: performance.timeOrigin,
  entries: performance.getEntries().filter((e) => e.name.startsWith('placecat:'))
    .map((e) => ({ name: e.name, startTime: e.startTime, duration: e.duration, detail: /** @type {any} */ (e).detail })),
}));
const breakdown = stageBreakdown(entries, timeOrigin);
results.pool = { scans: files.length, seconds, status, peakMainHeapBytes: peakHeap, peakChromiumRssBytes: peakRss, baselineRssBytes: baseRss,
  stages: breakdown.stages, workers: breakdown.workers };
await app.screenshot({ path: join(ART, 'bench-pool.png') });
console.log('pool', results.pool);
console.log(breakdown.text);
await browser.close();
server.close();

// 4. The table.
const pts = (ds) => ds.points / ds.seconds;
const lines = [
  '# Web benchmarks', '',
  `Measured ${results.date} on this machine (${results.machine}); regenerate with \`npm run bench\`. Million points per second, median of 5 runs; ${N.toLocaleString()}-point PLY (float x, y, z, intensity), identical bytes for every parser.`, '',
  '| where | format | placecat (wasm) | three.js PLYLoader | @loaders.gl/ply | placecat / three.js | placecat / loaders.gl |',
  '|---|---|---|---|---|---|---|',
];
for (const where of ['node', 'chromium']) for (const f of ['binary', 'ascii']) {
  const r = results[where][f];
  lines.push(`| ${where} | ${f} | ${fmt(r.placecat)} | ${fmt(r['three.js PLYLoader'])} | ${fmt(r['@loaders.gl/ply'])} | ${(r.placecat / r['three.js PLYLoader']).toFixed(1)}x | ${(r.placecat / r['@loaders.gl/ply']).toFixed(1)}x |`);
}
lines.push('', '## Read + describe, wasm in Chromium vs native (one core, outdoor preset)', '', '| file | points | native Mpts/s | wasm Mpts/s | wasm / native |', '|---|---|---|---|---|');
for (const [name, r] of Object.entries(results.describe)) {
  lines.push(`| ${name} | ${r.native.points} | ${fmt(pts(r.native))} | ${fmt(pts(r.wasm))} | ${(pts(r.wasm) / pts(r.native)).toFixed(2)} |`);
}
const p = results.pool;
lines.push('', '## The page: worker pool end to end', '',
  `${p.scans} simulated outdoor scans (~107k points each, binary PLY) given to the page's file input; time until described (both cores), Delta matrix, hierarchical tree and drawing are done: **${p.seconds.toFixed(1)} s** (${(p.scans / p.seconds).toFixed(1)} scans/s). ${p.status}.`, '',
  'Where the time goes (the page\'s own stage measures, www/stages.js, and the pool\'s task clocks; seconds of wall time):', '', breakdown.text, '',
  `Peak main-thread JS heap ${(p.peakMainHeapBytes / 2 ** 20).toFixed(0)} MiB; peak resident memory of all Chromium processes ${(p.peakChromiumRssBytes / 2 ** 20).toFixed(0)} MiB (${(p.baselineRssBytes / 2 ** 20).toFixed(0)} MiB before loading).`);
writeFileSync(join(ROOT, 'docs/benchmarks-web.md'), lines.join('\n') + '\n');
writeFileSync(join(ROOT, 'docs/benchmarks-web.json'), JSON.stringify(results, null, 2) + '\n');
console.log(lines.join('\n'));
