// Shared e2e set-up: serve www/ on a free loopback port, start Debian's
// chromium through playwright-core, record console errors and requests.
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { serve } from '../../scripts/serve.mjs';

export const ROOT = resolve(new URL('../..', import.meta.url).pathname);
export const REAL = resolve(ROOT, 'tests/data/real');
export const ARTIFACTS = join(ROOT, 'test-artifacts');
mkdirSync(ARTIFACTS, { recursive: true });

export async function start() {
  const server = await serve(join(ROOT, 'www'), 0);
  const url = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const context = await browser.newContext({ acceptDownloads: true, viewport: { width: 1400, height: 1000 } });
  await context.addInitScript(dieOnFile);
  await context.addInitScript(holdDeltaRows);
  const page = await context.newPage();
  const problems = [];
  const requests = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  context.on('request', (r) => requests.push(r.url()));
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60000 });
  return {
    url, page, context, problems, requests,
    async close() {
      await browser.close();
      server.close();
    },
  };
}

/**
 * Fault injection from outside the page (it ships no test hook): wraps
 * Worker.prototype.postMessage so that the task for the file named in
 * globalThis.crashOnFile is never answered and its worker dies as one that
 * runs out of memory does, terminated with an error event on the Worker.
 * Runs in the page before its scripts (context.addInitScript).
 */
function dieOnFile() {
  const post = Worker.prototype.postMessage;
  /** @this {Worker} */
  Worker.prototype.postMessage = function (message, ...rest) {
    const name = message?.task?.name;
    if (!name || name !== globalThis.crashOnFile) return post.call(this, message, ...rest);
    setTimeout(() => {
      this.terminate();
      this.dispatchEvent(new ErrorEvent('error', { message: 'worker crashed on purpose', cancelable: true }));
    });
  };
}

/**
 * Fault injection as above: while globalThis.holdDeltaRowsMs is set, a
 * worker handed a Delta-matrix task (deltaRows) gets it that many ms late
 * and everything posted to it after that, after it: a slow matrix step
 * that keeps its worker busy. globalThis.deltaRowsHeld counts the tasks held.
 * globalThis.holdTaskType holds tasks of another type instead (e.g.
 * 'references': the choice's reference sets, after the matrix).
 */
function holdDeltaRows() {
  const post = Worker.prototype.postMessage;
  /** @type {WeakMap<Worker, Promise<void>>} */
  const behind = new WeakMap();
  /** @this {Worker} */
  Worker.prototype.postMessage = function (message, ...rest) {
    const ms = globalThis.holdDeltaRowsMs;
    const matrix = message?.task?.type === (globalThis.holdTaskType || 'deltaRows');
    if (!ms || (!matrix && !behind.has(this))) return post.call(this, message, ...rest);
    if (matrix) globalThis.deltaRowsHeld = (globalThis.deltaRowsHeld || 0) + 1;
    const wait = matrix ? new Promise((ok) => setTimeout(ok, ms)) : Promise.resolve();
    behind.set(this, (behind.get(this) ?? Promise.resolve()).then(() => wait).then(() => post.call(this, message, ...rest)));
  };
}

/** Make the worker that gets `name` die (null: none). */
export function crashOn(page, name) {
  return page.evaluate((n) => { globalThis.crashOnFile = n; }, name);
}

/** Count canvas pixels that are not transparent or white. */
export function inkedPixels(page, id) {
  return page.evaluate((id) => {
    const c = document.getElementById(id);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && !(d[i] > 245 && d[i + 1] > 245 && d[i + 2] > 245)) n++;
    return n;
  }, id);
}

/**
 * Do `action` (a change that clusters the set again) and wait until the
 * clustering it asked for, the latest, settled (app.js: `body[data-asked]`
 * counts the clusterings asked for, `data-clustered` is the latest once it
 * settled): a spectral clustering comes back from a worker.
 * @param {import('playwright-core').Page} page @param {() => Promise<unknown>} action
 * @returns {Promise<number>} the clusterings asked for so far
 */
export async function afterClustering(page, action, timeout = 60000) {
  const asked = () => page.evaluate(() => Number(document.body.dataset.asked || 0));
  const before = await asked();
  await action();
  const now = await asked();
  if (now <= before) throw new Error('the action asked for no clustering');
  await page.waitForFunction((n) => Number(document.body.dataset.clustered || 0) >= n, now, { timeout });
  return now;
}

/** Do `action`, then wait until the page has finished one more run. */
export async function afterRun(page, action, timeout = 120000) {
  const runs = await page.evaluate(() => Number(document.body.dataset.runs || 0));
  await action();
  await page.waitForFunction((n) => Number(document.body.dataset.runs || 0) > n, runs, { timeout });
}
