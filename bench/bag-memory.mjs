// The page's memory while a big ROS bag streams through it (issue 16: a bag
// of gigabytes is read in slices, never whole). Not part of npm test: the
// bag is made first, outside the repository (rooms that every cloud can
// be described by, 0.1 m apart, with odometry), e.g. 1 GB:
//
//   python3 -m venv /tmp/venv-bags && /tmp/venv-bags/bin/pip install rosbags numpy
//   /tmp/venv-bags/bin/python tests/data/bags/make_big_bag.py /tmp/big.bag 740 120000 --rooms
//   bash scripts/build-www.sh && node bench/bag-memory.mjs /tmp/big.bag [/tmp/small.bag ...]
//
// Each bag is dropped into the page (headless Chromium, a fresh browser per
// bag) through its file input; the resident memory (VmRSS in /proc) of every
// Chromium process is sampled every 50 ms until the run ends. The page's
// workers are threads of its renderer process, so the renderer's RSS holds
// the page, both workers and their wasm memories. Printed per bag: file
// size, clouds read and kept, seconds, the renderer's RSS before the drop
// and at its peak, and the peak of all Chromium processes together; also
// written to test-artifacts/bag-memory.json. BAG_THIN=every|metres|auto and
// BAG_STEP choose the page's thinning (default: its own, one cloud a metre).
import { chromium } from 'playwright-core';
import { readFileSync, readdirSync, statSync, writeFileSync, mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { serve } from '../scripts/serve.mjs';

const ROOT = resolve(new URL('..', import.meta.url).pathname);
const MB = 2 ** 20;

/** Every process under `pid` (itself included). @param {number} pid */
function tree(pid) {
  const parent = new Map();
  for (const d of readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const stat = readFileSync(`/proc/${d}/stat`, 'utf8');
      parent.set(Number(d), Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]));
    } catch { /* gone */ }
  }
  const out = [pid];
  for (let i = 0; i < out.length; i++) for (const [p, pp] of parent) if (pp === out[i]) out.push(p);
  return out;
}

/** Resident bytes of a process, and whether it is a renderer. @param {number} pid */
function rss(pid) {
  try {
    const kb = /VmRSS:\s+(\d+)/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
    const renderer = readFileSync(`/proc/${pid}/cmdline`, 'utf8').includes('--type=renderer');
    return { bytes: kb ? Number(kb[1]) * 1024 : 0, renderer };
  } catch {
    return { bytes: 0, renderer: false };
  }
}

/** Sum and renderer RSS over the browser's processes now: all processes under this one (playwright launched them). */
function sample() {
  let all = 0, renderer = 0;
  for (const p of tree(process.pid).slice(1)) {
    const r = rss(p);
    all += r.bytes;
    if (r.renderer) renderer = Math.max(renderer, r.bytes);
  }
  return { all, renderer };
}

/** @param {string} bag */
async function measure(bag) {
  const server = await serve(join(ROOT, 'www'), 0);
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = await browser.newPage();
    await page.goto(`http://127.0.0.1:${/** @type {any} */ (server.address()).port}/`);
    await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60000 });
    if (process.env.BAG_THIN) await page.selectOption('#bag-thin', process.env.BAG_THIN);
    if (process.env.BAG_STEP) await page.fill('#bag-step', process.env.BAG_STEP);
    await new Promise((r) => setTimeout(r, 1000));
    const before = sample();
    const peak = { ...before };
    /** @type {number[]} renderer RSS over the run, every 50 ms */
    const series = [];
    const timer = setInterval(() => {
      const s = sample();
      series.push(s.renderer);
      peak.all = Math.max(peak.all, s.all);
      peak.renderer = Math.max(peak.renderer, s.renderer);
    }, 50);
    const t0 = performance.now();
    await page.setInputFiles('#files', bag);
    await page.waitForFunction(() => Number(document.body.dataset.runs || 0) >= 1, null, { timeout: 3_600_000, polling: 500 });
    const secs = (performance.now() - t0) / 1000;
    clearInterval(timer);
    const progress = await page.textContent('#progress-text');
    const note = await page.textContent('#bag-note');
    const errors = await page.$$eval('#errors li', (li) => li.map((x) => x.textContent));
    const status = await page.textContent('#cluster-status');
    return {
      bag, bytes: statSync(bag).size, secs: Math.round(secs * 10) / 10, progress, note, status, errors: errors.slice(0, 5), errorCount: errors.length,
      // The renderer's peak in each tenth of the run: flat when memory is bounded, rising with the bytes read when not.
      rendererByTenthMB: Array.from({ length: 10 }, (_, k) => Math.round(Math.max(0, ...series.slice(Math.floor((k * series.length) / 10), Math.floor(((k + 1) * series.length) / 10))) / MB)),
      rendererBeforeMB: Math.round(before.renderer / MB), rendererPeakMB: Math.round(peak.renderer / MB),
      allBeforeMB: Math.round(before.all / MB), allPeakMB: Math.round(peak.all / MB),
    };
  } finally {
    await browser.close();
    server.close();
  }
}

const bags = process.argv.slice(2);
if (bags.length === 0) {
  console.error('usage: node bench/bag-memory.mjs BAG [BAG ...]');
  process.exit(2);
}
const results = [];
for (const bag of bags) {
  const r = await measure(bag);
  console.log(`${bag}: ${(r.bytes / MB).toFixed(0)} MiB in ${r.secs} s; ${r.progress}\n  ${r.note}\n  ${r.status}; ${r.errorCount} errors`
    + `\n  renderer RSS ${r.rendererBeforeMB} MiB before, peak ${r.rendererPeakMB} MiB; all Chromium processes ${r.allBeforeMB} -> peak ${r.allPeakMB} MiB`
    + `\n  renderer peak per tenth of the run (MiB): ${r.rendererByTenthMB.join(' ')}`);
  if (r.errorCount) console.log(`  first errors: ${r.errors.join('\n    ')}`);
  results.push(r);
}
mkdirSync(join(ROOT, 'test-artifacts'), { recursive: true });
writeFileSync(join(ROOT, 'test-artifacts/bag-memory.json'), JSON.stringify({ date: new Date().toISOString(), thin: process.env.BAG_THIN ?? 'page default', results }, null, 1));
