// The package README's Vite app (page + worker) in headless Chromium, on
// Vite's dev server and on its production build (vite build + preview):
// four real scans picked in the page are described in the worker and
// clustered in the page into rooms and street. Usage: node run.mjs REPO_ROOT
import assert from 'node:assert/strict';
import { existsSync, readdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { build, createServer, preview } from 'vite';

const root = process.argv[2];
const app = process.cwd();
// The repository's playwright-core drives Debian's chromium (as tests/e2e).
const { chromium } = createRequire(join(root, 'package.json'))('playwright-core');
const real = join(root, 'tests/data/real');
const files = ['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd', 'velodyne_pair/251370668.pcd', 'velodyne_pair/251371071.pcd'].map((f) => join(real, f));

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});

/** Open the app at `url`, pick the four scans, return the labels shown. */
async function labelsAt(url, how) {
  const page = await browser.newPage();
  const problems = [];
  const workers = [];
  const wasm = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`failed: ${r.url()}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });
  page.on('worker', (w) => workers.push(w.url()));
  page.on('response', (r) => { if (r.url().endsWith('.wasm')) wasm.push(`${r.status()} ${r.url()}`); });
  const t0 = Date.now();
  await page.goto(url);
  await page.setInputFiles('input[type=file]', files);
  await page.waitForFunction(() => document.querySelector('output').textContent !== '', null, { timeout: 60000 }).catch(() => {});
  const text = await page.locator('output').textContent();
  await page.close();
  assert.deepEqual(problems, [], `${how}: errors in the page`);
  assert.equal(text, '0 0 1 1', `${how}: the rooms and the street apart`);
  assert.equal(workers.length, 1, `${how}: one worker (${workers})`);
  // The page and the worker each load the wasm, and it comes as wasm.
  assert.equal(wasm.length, 2, `${how}: wasm loads ${wasm}`);
  for (const w of wasm) assert.match(w, /^200 /, how);
  console.log(`${how}: labels ${text} in ${Date.now() - t0} ms; worker ${workers[0]}; wasm ${wasm[0]}`);
}

try {
  const dev = await createServer({ root: app, logLevel: 'warn', server: { host: '127.0.0.1', port: 0 } });
  await dev.listen();
  try {
    await labelsAt(dev.resolvedUrls.local[0], 'vite dev');
  } finally {
    await dev.close();
  }

  await build({ root: app, logLevel: 'warn' });
  const assets = readdirSync(join(app, 'dist/assets'));
  assert.ok(assets.some((a) => a.endsWith('.wasm')), `the build emits the wasm: ${assets}`);
  assert.ok(assets.some((a) => /^worker-.*\.js$/.test(a)), `the build emits the worker: ${assets}`);
  assert.ok(existsSync(join(app, 'dist/index.html')));
  const prod = await preview({ root: app, logLevel: 'warn', preview: { host: '127.0.0.1', port: 0 } });
  try {
    await labelsAt(prod.resolvedUrls.local[0], 'vite build + preview');
  } finally {
    await new Promise((resolve) => prod.httpServer.close(resolve));
  }
} finally {
  await browser.close();
}
