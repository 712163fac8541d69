// A run over a data set (describe.js) with a stand-in for the worker pool:
// the first scan that reads decides the preset and the rest follow with it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { describeInputs } from '../../www/describe.js';
import { WorkerPool } from '../../www/pool.js';

const byPreset = /** @type {any} */ ({ indoor: { preset: 'indoor' }, outdoor_hellinger: { preset: 'outdoor_hellinger' } });
const inputs = ['bad.ply', 'a.bin', 'b.bin', 'c.bin'].map((name) => ({ name, file: /** @type {any} */ ({}) }));

/** A bag of 5 clouds, the 2nd unreadable, 3 kept: partial replies as bagreader.js sends them. */
function bagRun(task, onPartial) {
  onPartial({ scan: { name: `${task.name}:/points:000000` }, met: 1, total: 5 });
  onPartial({ error: `${task.name}: topic /points: cloud 1: truncated`, met: 2, total: 5 });
  onPartial({ scan: { name: `${task.name}:/points:000002` }, met: 3, total: 5 });
  onPartial({ scan: { name: `${task.name}:/points:000004` }, met: 5, total: 5 });
  return { recording: true, topic: '/points', kept: 3, failed: 1, total: 5, ...(task.byPreset ? { far: 0.02, preset: 'indoor' } : {}) };
}

/** A pool whose workers fail on bad.ply and measure 30 % far points on the others. */
function fakePool(fail = (name) => name === 'bad.ply' ? new Error('bad.ply: truncated') : null) {
  const tasks = [];
  const pool = {
    tasks,
    async run(task, onPartial) {
      tasks.push(task);
      const e = fail(task.name);
      if (e) throw e;
      if (task.type === 'bag') return bagRun(task, onPartial);
      return task.byPreset ? { name: task.name, far: 0.3, preset: 'outdoor_hellinger', params: task.byPreset.outdoor_hellinger } : { name: task.name, params: task.params };
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
    onProgress: (n, total) => seen.settled.push([n, total]),
  });
  assert.deepEqual(seen.errors, [[0, 'bad.ply: truncated']]);
  assert.deepEqual(seen.presets, [['outdoor_hellinger', 'outdoor_hellinger']]);
  assert.deepEqual(pool.tasks.map((t) => [t.name, Boolean(t.byPreset), t.params.preset]), [
    ['bad.ply', true, 'indoor'], ['a.bin', true, 'indoor'], ['b.bin', false, 'outdoor_hellinger'], ['c.bin', false, 'outdoor_hellinger'],
  ]);
  assert.deepEqual(Array.from(out.results, (r) => r?.name), [undefined, 'a.bin', 'b.bin', 'c.bin']);
  assert.equal(out.done, 4);
  assert.deepEqual(out.suggestion, { preset: 'outdoor_hellinger', far: 0.3, from: 'a.bin' });
  assert.deepEqual(seen.settled.slice(0, 2), [[1, 4], [2, 4]]);
  assert.deepEqual(seen.settled.at(-1), [4, 4]);
});

test('cancelled while the first scan decides: nothing more is started', async () => {
  const pool = fakePool(() => new Error('cancelled'));
  const out = await describeInputs(/** @type {any} */ (pool), inputs, { params: /** @type {any} */ ({}), byPreset }, {
    onPreset: () => assert.fail('no preset'), onResult: () => assert.fail('no result'), onError: () => assert.fail('a cancel is no error'), onProgress: () => {},
  });
  assert.equal(pool.tasks.length, 1);
  assert.deepEqual([out.done, out.suggestion], [0, null]);
});

test('without a choice to make (the demo, a preset the user chose) every task goes at once, the first one measured', async () => {
  const pool = fakePool(() => null);
  const out = await describeInputs(/** @type {any} */ (pool), inputs.slice(1), { params: /** @type {any} */ ({ preset: 'indoor' }), byPreset: null }, {
    onPreset: () => assert.fail('no preset'), onResult: () => {}, onError: () => {}, onProgress: () => {},
  });
  assert.deepEqual(pool.tasks.map((t) => [t.probe, t.params.preset]), [[true, 'indoor'], [false, 'indoor'], [false, 'indoor']]);
  assert.equal(out.done, 3);
  assert.equal(out.suggestion, null, 'the stand-in measures nothing without byPreset');
});

test('a bag is one input of many scans: each cloud a result as it comes, its errors said, progress in clouds read', async () => {
  const pool = fakePool();
  const mixed = [{ name: 'walk.bag', file: {}, bag: { every: 1, hasPoses: true, thinning: '' } }, ...inputs.slice(1, 3)];
  const seen = { results: [], errors: [], progress: [] };
  const out = await describeInputs(/** @type {any} */ (pool), /** @type {any} */ (mixed), { params: /** @type {any} */ ({ preset: 'indoor' }), byPreset }, {
    onPreset: () => {},
    onResult: (i, r, j) => seen.results.push([i, j, r.name]),
    onError: (i, e) => seen.errors.push([i, e.message]),
    onProgress: (n, total) => seen.progress.push([n, total]),
  });
  assert.equal(pool.tasks[0].type, 'bag');
  assert.equal(pool.tasks[0].every, 1);
  assert.deepEqual(seen.results.slice(0, 3), [[0, 0, 'walk.bag:/points:000000'], [0, 1, 'walk.bag:/points:000002'], [0, 2, 'walk.bag:/points:000004']]);
  assert.deepEqual(seen.errors, [[0, 'walk.bag: topic /points: cloud 1: truncated']]);
  assert.deepEqual(Array.from(out.bags, (b) => b && [b.topic, b.kept, b.failed, b.total]), [['/points', 3, 1, 5], undefined, undefined]);
  // The bag decided the preset (indoor), so the files follow with it.
  assert.deepEqual(pool.tasks.slice(1).map((t) => t.params.preset), ['indoor', 'indoor']);
  assert.deepEqual(seen.progress.slice(0, 4), [[1, 7], [2, 7], [3, 7], [5, 7]]);
  assert.deepEqual([out.done, out.total], [7, 7]);
  assert.deepEqual(out.results.map((r) => (Array.isArray(r) ? r.map((x) => x.name) : r.name)),
    [['walk.bag:/points:000000', 'walk.bag:/points:000002', 'walk.bag:/points:000004'], 'a.bin', 'b.bin']);
  assert.deepEqual(out.suggestion, { preset: 'indoor', far: 0.02, from: 'walk.bag' });
});
