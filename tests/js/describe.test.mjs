// A run over a data set (describe.js) with a stand-in for the worker pool:
// the first scan that reads decides the preset and the rest follow with it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { describeInputs } from '../../www/describe.js';
import { WorkerPool } from '../../www/pool.js';

const byPreset = /** @type {any} */ ({ indoor: { preset: 'indoor' }, outdoor: { preset: 'outdoor' } });
const inputs = ['bad.ply', 'a.bin', 'b.bin', 'c.bin'].map((name) => ({ name, file: /** @type {any} */ ({}) }));

/** A pool whose workers fail on bad.ply and measure 30 % far points on the others. */
function fakePool(fail = (name) => name === 'bad.ply' ? new Error('bad.ply: truncated') : null) {
  const tasks = [];
  const pool = {
    tasks,
    async run(task) {
      tasks.push(task);
      const e = fail(task.name);
      if (e) throw e;
      return task.byPreset ? { name: task.name, far: 0.3, preset: 'outdoor', params: task.byPreset.outdoor } : { name: task.name, params: task.params };
    },
    runAll: WorkerPool.prototype.runAll,
  };
  return pool;
}

test('the first scan that reads picks the preset; a failed first scan passes the choice on; the rest use the preset', async () => {
  const pool = fakePool();
  const seen = { presets: [], errors: [], settled: [], results: [] };
  const out = await describeInputs(/** @type {any} */ (pool), inputs, { params: /** @type {any} */ ({ preset: 'indoor' }), byPreset }, {
    onPreset: (p, params) => seen.presets.push([p, params.preset]),
    onResult: (i, r) => seen.results.push([i, r.name]),
    onError: (i, e) => seen.errors.push([i, e.message]),
    onSettled: (n) => seen.settled.push(n),
  });
  assert.deepEqual(seen.errors, [[0, 'bad.ply: truncated']]);
  assert.deepEqual(seen.presets, [['outdoor', 'outdoor']]);
  assert.deepEqual(pool.tasks.map((t) => [t.name, Boolean(t.byPreset), t.params.preset]), [
    ['bad.ply', true, 'indoor'], ['a.bin', true, 'indoor'], ['b.bin', false, 'outdoor'], ['c.bin', false, 'outdoor'],
  ]);
  assert.deepEqual(Array.from(out.results, (r) => r?.name), [undefined, 'a.bin', 'b.bin', 'c.bin']);
  assert.equal(out.done, 4);
  assert.deepEqual(out.suggestion, { preset: 'outdoor', far: 0.3, from: 'a.bin' });
  assert.deepEqual(seen.settled.slice(0, 2), [1, 2]);
  assert.equal(Math.max(...seen.settled), 4);
});

test('cancelled while the first scan decides: nothing more is started', async () => {
  const pool = fakePool(() => new Error('cancelled'));
  const out = await describeInputs(/** @type {any} */ (pool), inputs, { params: /** @type {any} */ ({}), byPreset }, {
    onPreset: () => assert.fail('no preset'), onResult: () => assert.fail('no result'), onError: () => assert.fail('a cancel is no error'), onSettled: () => {},
  });
  assert.equal(pool.tasks.length, 1);
  assert.deepEqual([out.done, out.suggestion], [0, null]);
});

test('without a choice to make (the demo, a preset the user chose) every task goes at once, the first one measured', async () => {
  const pool = fakePool(() => null);
  const out = await describeInputs(/** @type {any} */ (pool), inputs.slice(1), { params: /** @type {any} */ ({ preset: 'indoor' }), byPreset: null }, {
    onPreset: () => assert.fail('no preset'), onResult: () => {}, onError: () => {}, onSettled: () => {},
  });
  assert.deepEqual(pool.tasks.map((t) => [t.probe, t.params.preset]), [[true, 'indoor'], [false, 'indoor'], [false, 'indoor']]);
  assert.equal(out.done, 3);
  assert.equal(out.suggestion, null, 'the stand-in measures nothing without byPreset');
});
