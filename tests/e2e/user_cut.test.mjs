// The user's number of categories is never replaced by the automatic
// first cut: neither one typed while the page waits for the workers'
// reference sets (the tree built, its first cut not yet chosen), nor one
// typed before the tree exists (while the workers compute the matrix).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, afterRun } from './harness.mjs';

let h;
before(async () => { h = await start(); });
after(async () => { await h?.close(); });

const HOLD = 8000; // the held tasks' delay: long beside typing a number
const categories = () => h.page.$eval('#cluster-status', (e) => Number(e.dataset.categories));

/**
 * Run the outdoor demo (300 scans: the workers compute the Delta matrix and
 * the choice's 10 reference sets) with the tasks of `type` held HOLD ms;
 * once `ready` holds in the page, type `k` categories; wait for the run's end.
 * @param {string} type @param {() => boolean} ready run in the page @param {number} k
 */
async function typeWhileHeld(type, ready, k) {
  try {
    await h.page.evaluate(([t, ms]) => { globalThis.holdTaskType = t; globalThis.holdDeltaRowsMs = ms; globalThis.deltaRowsHeld = 0; }, [type, HOLD]);
    await afterRun(h.page, async () => {
      await h.page.click('#demo-outdoor');
      await h.page.waitForFunction(ready, null, { timeout: 240000 });
      await h.page.fill('#categories', String(k));
      await h.page.press('#categories', 'Enter');
    }, 300000);
  } finally {
    await h.page.evaluate(() => { globalThis.holdDeltaRowsMs = 0; globalThis.holdTaskType = undefined; });
  }
}

test('K typed while the reference sets are held (the tree built): the page keeps it, not the rule\'s 3', async () => {
  await typeWhileHeld('references', () => globalThis.deltaRowsHeld > 0 && performance.getEntriesByName('placecat:tree').length > 0, 5);
  assert.equal(await categories(), 5);
  assert.match(await h.page.textContent('#cut-note'), /^5 categories: your cut$/);
  assert.match(await h.page.textContent('#cluster-status'), /^5 categories from 300 scans; tree: the cheapest of 10 2-means\+\+ trials a split$/);
});

test('K typed before the tree exists (the matrix held): the page cuts the new tree into it', async () => {
  await typeWhileHeld('deltaRows', () => globalThis.deltaRowsHeld > 0 && performance.getEntriesByName('placecat:tree').length === 0, 6);
  assert.equal(await categories(), 6);
  assert.match(await h.page.textContent('#cut-note'), /^6 categories: your cut$/);
});

test('no console errors', () => {
  assert.deepEqual(h.problems, []);
});
