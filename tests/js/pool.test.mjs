// The worker pool's scheduling with stand-in workers: tasks held several at
// a time within a byte budget, bags alone, a worker's death blamed on the
// task that caused it, the main thread's preparation (reading a file)
// before a task is posted, and a run's tail shared between the workers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { WorkerPool } from '../../www/pool.js';
import { Batch } from '../../www/batch.js';

/** Records what it is sent; the test answers for it. */
class FakeWorker {
  /** @type {FakeWorker[]} */
  static all = [];
  constructor() {
    /** @type {{id: number, task: any, transfer?: any[]}[]} */
    this.posted = [];
    this.terminated = false;
    /** @type {(e: any) => void} */
    this.onmessage = () => {};
    /** @type {(e: any) => void} */
    this.onerror = () => {};
    FakeWorker.all.push(this);
  }
  postMessage(m, transfer) { this.posted.push({ ...m, transfer }); }
  terminate() { this.terminated = true; }
  /** Answer the oldest task not answered yet. */
  answer(ok = true) {
    const m = this.posted.find((p) => !p.answered);
    m.answered = true;
    const clock = { arrived: 1, start: 2, read: 3, end: 4 };
    this.onmessage({ data: ok ? { id: m.id, ok: true, result: m.task.name, clock } : { id: m.id, ok: false, error: `${m.task.name}: bad` } });
  }
  die() { this.onerror({ message: 'out of memory', preventDefault() {} }); }
  held() { return this.posted.filter((p) => !p.answered).map((p) => p.task.name); }
}
globalThis.Worker = /** @type {any} */ (FakeWorker);

const pool = (depth, how = {}) => {
  FakeWorker.all = [];
  return new WorkerPool(/** @type {any} */ ('w.js'), 2, { depth, alone: (t) => t.type === 'bag', ...how });
};
const settle = () => new Promise((ok) => setTimeout(ok, 0));

test('each worker holds two tasks: one each first, then a second each; an answer brings the next', async () => {
  const p = pool(2);
  const done = [];
  for (const name of ['a', 'b', 'c', 'd', 'e']) p.run({ type: 'describe', name }).then((r) => done.push(r));
  const [w0, w1] = FakeWorker.all;
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['b', 'd']]);
  w1.answer();
  await settle();
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['d', 'e']]);
  for (const w of [w0, w0, w1, w1]) w.answer();
  await settle();
  assert.deepEqual(done.sort(), ['a', 'b', 'c', 'd', 'e']);
  // Each answer's clock is kept with its task's type and worker, in the order the answers came.
  assert.deepEqual(p.clocks.map((c) => [c.type, c.worker, c.start]), [['describe', 1, 2], ['describe', 0, 2], ['describe', 0, 2], ['describe', 1, 2], ['describe', 1, 2]]);
});

test('a worker takes another task only while the files it holds stay within maxBytes, and always takes one', async () => {
  const p = pool(4, { bytes: (t) => t.size, maxBytes: 32 });
  for (const [name, size] of [['a', 10], ['b', 10], ['c', 10], ['d', 10], ['e', 40], ['f', 5]]) p.run({ type: 'describe', name, size });
  const [w0, w1] = FakeWorker.all;
  // 10 + 10 each; e (40) joins neither, and f waits behind it.
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['b', 'd']]);
  w0.answer();
  await settle();
  assert.deepEqual(w0.held(), ['c'], '10 + 40 is over 32');
  w0.answer();
  await settle();
  // Alone, e goes over the budget; f (5) then joins b and d (25), not e (45).
  assert.deepEqual([w0.held(), w1.held()], [['e'], ['b', 'd', 'f']]);
});

/** A promise settled from outside. */
const deferred = () => {
  let resolve, reject;
  const promise = new Promise((ok, fail) => { resolve = ok; reject = fail; });
  return { promise, resolve, reject };
};
/** What the page's prepare does: the file's bytes, moved to the worker. */
const readBytes = (t) => ({ task: { ...t, file: undefined, bytes: t.file.bytes }, transfer: [t.file.bytes] });

test('prepare: the bytes it reads are posted and transferred, not the file', async () => {
  const p = pool(2, { prepare: (t) => Promise.resolve(readBytes(t)) });
  const bytes = new ArrayBuffer(8);
  p.run({ type: 'describe', name: 'a', file: { bytes } });
  await settle();
  const [m] = FakeWorker.all[0].posted;
  assert.equal(m.task.bytes, bytes);
  assert.equal(m.task.file, undefined);
  assert.deepEqual(m.transfer, [bytes]);
});

test('prepare: a read that fails fails its task alone, with its error, and the next task takes its place', async () => {
  const p = pool(2, { prepare: (t) => t.name === 'x' ? Promise.reject(new Error('x.ply: could not be read')) : Promise.resolve(readBytes(t)) });
  const errors = [];
  const results = [];
  const names = ['a', 'x', 'c', 'd', 'e'];
  const all = p.runAll(names.map((name) => ({ type: 'describe', name, file: { bytes: new ArrayBuffer(1) } })), {
    onResult: (i, r) => (results[i] = r), onError: (i, e) => errors.push(`${names[i]}: ${e.message}`), onSettled: () => {},
  });
  await settle();
  const [w0, w1] = FakeWorker.all;
  assert.deepEqual(errors, ['x: x.ply: could not be read']);
  // x was never posted; e came in its place.
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['d', 'e']]);
  for (const w of [w0, w0, w1, w1]) w.answer();
  assert.equal(await all, 5, 'every task finished or failed');
  assert.deepEqual([...results], ['a', undefined, 'c', 'd', 'e']);
  assert.equal(1 in results, false, 'no result where x failed');
});

test('prepare: a read that ends after cancel, or after its worker died, is not posted to that worker', async () => {
  const reads = [];
  const p = pool(2, { prepare: (t) => { const d = deferred(); reads.push({ name: t.name, ...d }); return d.promise; } });
  p.run({ type: 'describe', name: 'a', file: { bytes: new ArrayBuffer(1) } }).catch(() => {});
  p.cancel();
  reads[0].resolve(readBytes({ name: 'a', file: { bytes: new ArrayBuffer(1) } }));
  await settle();
  assert.deepEqual(FakeWorker.all.map((w) => w.posted.length), [0, 0, 0], 'the cancelled read reaches no worker');

  reads.length = 0;
  const q = pool(2, { prepare: (t) => { const d = deferred(); reads.push({ name: t.name, ...d }); return d.promise; } });
  for (const name of ['a', 'b', 'c', 'd']) q.run({ type: 'describe', name, file: { bytes: new ArrayBuffer(1) } }).catch(() => {});
  const [w0] = FakeWorker.all;
  assert.deepEqual(reads.map((r) => r.name), ['a', 'b', 'c', 'd']);
  // w0 was to get a and c; it dies before their reads end. a runs again alone on a new worker, read again.
  w0.die();
  await settle();
  for (const r of reads.slice(0, 4)) r.resolve(readBytes({ name: r.name, file: { bytes: new ArrayBuffer(1) } }));
  await settle();
  const w2 = FakeWorker.all[2];
  assert.equal(w0.posted.length, 0, 'nothing posted to the dead worker');
  assert.deepEqual(w2.posted.length, 0, 'the first reads are not posted to its successor');
  assert.deepEqual(reads.map((r) => r.name), ['a', 'b', 'c', 'd', 'a']);
  reads[4].resolve(readBytes({ name: 'a', file: { bytes: new ArrayBuffer(1) } }));
  await settle();
  assert.deepEqual(w2.posted.map((m) => m.task.name), ['a']);
});

test('a bag has a worker to itself, and nothing joins it', async () => {
  const p = pool(2);
  for (const [type, name] of [['describe', 'a'], ['bag', 'B'], ['describe', 'c'], ['describe', 'd']]) p.run({ type, name });
  const [w0, w1] = FakeWorker.all;
  // a and B one each; B's worker takes nothing more, a's takes c (and d waits: order is kept).
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['B']]);
  w0.answer();
  await settle();
  assert.deepEqual([w0.held(), w1.held()], [['c', 'd'], ['B']]);
});

test('a worker that dies holding two tasks: both run again alone, and only the one that kills a worker fails', async () => {
  const p = pool(2);
  const seen = [];
  for (const name of ['a', 'b', 'x', 'd']) p.run({ type: 'describe', name }).then((r) => seen.push(`ok ${r}`), (e) => seen.push(`failed ${name}: ${e.message}`));
  const [w0, w1] = FakeWorker.all;
  assert.deepEqual([w0.held(), w1.held()], [['a', 'x'], ['b', 'd']]);
  w0.die();
  await settle();
  assert.equal(w0.terminated, true);
  const w2 = FakeWorker.all[2];
  // a runs again alone on the new worker; x waits for a worker with nothing else.
  assert.deepEqual(w2.held(), ['a']);
  w2.answer();
  await settle();
  assert.deepEqual(w2.held(), ['x']);
  w2.die();
  await settle();
  assert.deepEqual(seen, ['ok a', 'failed x: the worker failed: out of memory']);
  // The new worker after it takes the rest.
  w1.answer();
  w1.answer();
  await settle();
  assert.deepEqual(seen.slice(2).sort(), ['ok b', 'ok d']);
});

test('cancel rejects the queued and the held tasks and replaces the busy workers', async () => {
  const p = pool(2);
  const seen = [];
  for (const name of ['a', 'b', 'c', 'd', 'e']) p.run({ type: 'describe', name }).catch((e) => seen.push(`${name} ${e.message}`));
  p.cancel();
  await settle();
  assert.deepEqual(seen.sort(), ['a cancelled', 'b cancelled', 'c cancelled', 'd cancelled', 'e cancelled']);
  assert.deepEqual(FakeWorker.all.map((w) => w.terminated), [true, true, false, false]);
});

test('stop: a queued task is dropped; a running one loses its worker, whose other tasks run again; a settled one is left', async () => {
  const q = pool(2);
  const seen = [];
  /** @type {Record<string, Promise<any>>} what `run` returned, which `stop` takes */
  const promises = {};
  for (const name of ['a', 'b', 'c', 'd', 'e']) {
    promises[name] = q.run({ type: 'describe', name });
    promises[name].then((r) => seen.push(`ok ${r}`), (e) => seen.push(`${name} ${e.message}`));
  }
  const [w0, w1] = FakeWorker.all;
  assert.deepEqual([w0.held(), w1.held()], [['a', 'c'], ['b', 'd']]);
  q.stop(promises.e); // queued
  await settle();
  assert.deepEqual(seen, ['e cancelled']);
  q.stop(promises.c); // held by w0 with a
  await settle();
  assert.deepEqual(seen, ['e cancelled', 'c cancelled']);
  assert.equal(w0.terminated, true);
  assert.equal(w1.terminated, false);
  const w2 = FakeWorker.all[2];
  assert.deepEqual(w2.held(), ['a'], 'a runs again on the new worker');
  w2.answer();
  w1.answer();
  await settle();
  q.stop(promises.a); // settled: nothing happens
  assert.equal(w2.terminated, false);
  w1.answer();
  await settle();
  assert.deepEqual(seen, ['e cancelled', 'c cancelled', 'ok a', 'ok b', 'ok d']);
});

test('transfer: what a task moves to its worker is posted as transferred', () => {
  const matrix = new Float32Array(4);
  const q = pool(1, { transfer: (t) => (t.matrix ? [t.matrix.buffer] : []) });
  q.run({ type: 'spectral', name: 'm', matrix });
  q.run({ type: 'describe', name: 'd' });
  const [w0] = FakeWorker.all;
  assert.deepEqual(w0.posted.map((p) => p.transfer), [[matrix.buffer]], 'the second waits for the first');
});

test('stop finds a task a dead worker left to run again, and one whose preparation is pending (no worker replaced)', async () => {
  const q = pool(2);
  const seen = [];
  const a = q.run({ type: 'describe', name: 'a' });
  q.run({ type: 'describe', name: 'b' });
  const c = q.run({ type: 'describe', name: 'c' });
  for (const [name, p] of [['a', a], ['c', c]]) p.catch((e) => seen.push(`${name} ${e.message}`));
  const [w0] = FakeWorker.all;
  assert.deepEqual(w0.held(), ['a', 'c']);
  w0.die(); // a and c queued again, each alone
  await settle();
  q.stop(c);
  await settle();
  assert.deepEqual(seen, ['c cancelled']);
  // Preparation pending: the job is the worker's, but was never posted.
  let release = () => {};
  const r = pool(1, { prepare: (t) => t.name === 'slow' ? new Promise((ok) => { release = () => ok({ task: t, transfer: [] }); }) : null });
  const slow = r.run({ type: 'describe', name: 'slow' });
  slow.catch((e) => seen.push(`slow ${e.message}`));
  const [v0] = FakeWorker.all;
  r.stop(slow);
  release();
  await settle();
  assert.deepEqual(seen, ['c cancelled', 'slow cancelled']);
  assert.equal(v0.terminated, false, 'the worker that never got it stays');
  assert.deepEqual(v0.posted, [], 'nor is it posted once prepared');
});

test('a task that cannot be posted fails alone and the next takes its place', async () => {
  const q = pool(1);
  const [w0] = FakeWorker.all;
  const post = w0.postMessage.bind(w0);
  w0.postMessage = (m, transfer) => {
    if (m.task.name === 'bad') throw new Error('could not be cloned');
    post(m, transfer);
  };
  const seen = [];
  q.run({ type: 'describe', name: 'bad' }).catch((e) => seen.push(`bad ${e.message}`));
  q.run({ type: 'describe', name: 'next' }).then((r) => seen.push(`ok ${r}`));
  await settle();
  assert.deepEqual(w0.held(), ['next']);
  w0.answer();
  await settle();
  assert.deepEqual(seen, ['bad could not be cloned', 'ok next']);
});

test('a batch hands its items over together, once per tick, and at once on flush', async () => {
  const calls = [];
  const b = new Batch(20, (items) => calls.push(items));
  b.add(1);
  b.add(2, 3);
  b.add();
  assert.deepEqual(calls, []);
  await new Promise((ok) => setTimeout(ok, 40));
  assert.deepEqual(calls, [[1, 2, 3]]);
  b.add(4);
  b.flush();
  assert.deepEqual(calls, [[1, 2, 3], [4]]);
  await new Promise((ok) => setTimeout(ok, 40));
  assert.equal(calls.length, 2, 'flush cancels the pending tick');
});

test('a run\'s tail (matrix.js): each worker gets its rows of the matrix first, then reference sets one at a time; one slowed down takes fewer', async () => {
  const { matrixInWorkers, referencesInWorkers, tailKey, oneAtATime } = await import('../../www/matrix.js');
  // As the page's pool: eight tasks a worker, a reference set held alone.
  const p = pool(8, { alone: oneAtATime });
  const jsons = ['a', 'b', 'c', 'd', 'e'];
  const key = tailKey();
  const matrix = matrixInWorkers(p, /** @type {any} */ ({}), jsons, key);
  const dispersions = referencesInWorkers(p, /** @type {any} */ ({}), jsons, { seed: 0, restarts: 1, sets: 10 }, key);
  const [w0, w1] = FakeWorker.all;
  const held = (w) => w.posted.filter((m) => !m.answered).map((m) => m.task.type === 'references' ? m.task.which[0] : `rows ${m.task.rows}`);
  // Answer a worker's oldest task as worker.js would: the share's Delta values, or set b's two values [b, b + 0.5].
  const answer = async (w) => {
    const m = w.posted.find((q) => !q.answered);
    m.answered = true;
    const { task } = m;
    const result = task.type === 'references' ? Float64Array.of(task.which[0], task.which[0] + 0.5)
      : Float32Array.from(task.rows.flatMap((i) => jsons.slice(i + 1).map((_, j) => 10 * i + i + 1 + j)));
    w.onmessage({ data: { id: m.id, ok: true, result, clock: { arrived: 0, start: 0, read: 0, end: 0 } } });
    await settle();
  };
  // The rows alone: no set is held behind them (with four a worker, each took three sets at once).
  assert.deepEqual([held(w0), held(w1)], [['rows 0,2,4'], ['rows 1,3']]);
  await answer(w0);
  await answer(w1);
  assert.deepEqual([held(w0), held(w1)], [[0], [1]]);
  assert.ok([...w0.posted, ...w1.posted].every((m) => m.task.key === key), 'one key: a worker builds its set once');
  // Worker 1 is slowed down (the page's tree, another process): a third as fast; each set goes to the worker that comes free.
  while (held(w0).length || held(w1).length) {
    for (let k = 0; k < 3 && held(w0).length; k++) await answer(w0);
    if (held(w1).length) await answer(w1);
  }
  // The values in order of the sets, the rows mirrored: (i, j) = 10 i + j.
  assert.deepEqual(await dispersions, Float64Array.from({ length: 20 }, (_, k) => Math.floor(k / 2) + (k % 2) / 2));
  const m = await matrix;
  assert.deepEqual([m[0 * 5 + 3], m[3 * 5 + 0], m[3 * 5 + 4], m[4 * 5 + 3], m[2 * 5 + 2]], [3, 3, 34, 34, 0]);
  const sets = (w) => p.clocks.filter((c) => c.type === 'references' && c.worker === w).length;
  assert.deepEqual([sets(0), sets(1)], [7, 3], 'the fast worker did 7 sets of 10, the slow one 3');
});
