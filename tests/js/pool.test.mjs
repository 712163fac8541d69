// The worker pool's scheduling with stand-in workers: tasks held two at a
// time, bags alone, and a worker's death blamed on the task that caused it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { WorkerPool } from '../../www/pool.js';
import { Batch } from '../../www/batch.js';

/** Records what it is sent; the test answers for it. */
class FakeWorker {
  /** @type {FakeWorker[]} */
  static all = [];
  constructor() {
    /** @type {{id: number, task: any}[]} */
    this.posted = [];
    this.terminated = false;
    /** @type {(e: any) => void} */
    this.onmessage = () => {};
    /** @type {(e: any) => void} */
    this.onerror = () => {};
    FakeWorker.all.push(this);
  }
  postMessage(m) { this.posted.push(m); }
  terminate() { this.terminated = true; }
  /** Answer the oldest task not answered yet. */
  answer(ok = true) {
    const m = this.posted.find((p) => !p.answered);
    m.answered = true;
    this.onmessage({ data: ok ? { id: m.id, ok: true, result: m.task.name } : { id: m.id, ok: false, error: `${m.task.name}: bad` } });
  }
  die() { this.onerror({ message: 'out of memory', preventDefault() {} }); }
  held() { return this.posted.filter((p) => !p.answered).map((p) => p.task.name); }
}
globalThis.Worker = /** @type {any} */ (FakeWorker);

const pool = (depth) => {
  FakeWorker.all = [];
  return new WorkerPool(/** @type {any} */ ('w.js'), 2, { depth, alone: (t) => t.type === 'bag' });
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
  assert.equal(p.clocks.length, 0, 'stand-in workers send no clocks');
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
