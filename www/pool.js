// A pool of module workers, one per core, each with its own wasm instance.
// Tasks queue; each worker takes one at a time. A worker that dies (an
// uncaught error, out of memory) fails only its task and is replaced. A
// task may send partial replies before its result (a bag's clouds, bag.js).

/** @typedef {{id: number, task: any, resolve: (r: any) => void, reject: (e: Error) => void, onPartial?: (p: any) => void, posted?: number}} Job */
/** @typedef {{worker: Worker, job: Job | null}} WorkerSlot */
/**
 * When a task was posted, started, had its file's bytes, ended (in its
 * worker) and its result came back (wall-clock ms): the stage profile that
 * `npm run bench` prints.
 * @typedef {{worker: number, posted: number, start: number, read: number, end: number, received: number}} TaskClock
 */

export class WorkerPool {
  /** @param {URL} url the worker module @param {number} [size] */
  constructor(url, size = Math.max(1, navigator.hardwareConcurrency || 2)) {
    this.url = url;
    this.size = size;
    /** @type {Job[]} */
    this.queue = [];
    /** @type {WorkerSlot[]} */
    this.slots = [];
    this.nextId = 1;
    /** @type {TaskClock[]} the tasks that ended (a run empties it as it begins) */
    this.clocks = [];
    for (let i = 0; i < size; i++) this.slots.push(this.#spawn());
  }

  #spawn() {
    const worker = new Worker(this.url, { type: 'module' });
    /** @type {WorkerSlot} */
    const slot = { worker, job: null };
    worker.onmessage = (e) => {
      const job = slot.job;
      if (!job || e.data.id !== job.id) return;
      if ('partial' in e.data) return job.onPartial?.(e.data.partial);
      slot.job = null;
      if (e.data.clock) this.clocks.push({ worker: this.slots.indexOf(slot), posted: job.posted ?? 0, ...e.data.clock, received: performance.timeOrigin + performance.now() });
      if (e.data.ok) job.resolve(e.data.result);
      else job.reject(new Error(e.data.error));
      this.#pump();
    };
    /** @param {Event & {message?: string}} [e] */
    const die = (e) => {
      e?.preventDefault?.();
      const job = slot.job;
      slot.job = null;
      worker.terminate();
      const i = this.slots.indexOf(slot);
      if (i >= 0) this.slots[i] = this.#spawn();
      job?.reject(new Error(`the worker failed: ${e?.message || 'crashed or ran out of memory'}`));
      this.#pump();
    };
    worker.onerror = die;
    worker.onmessageerror = die;
    return slot;
  }

  #pump() {
    for (const slot of this.slots) {
      if (slot.job || this.queue.length === 0) continue;
      const job = /** @type {Job} */ (this.queue.shift());
      slot.job = job;
      job.posted = performance.timeOrigin + performance.now();
      slot.worker.postMessage({ id: job.id, task: job.task });
    }
  }

  /**
   * Run a task on the next free worker; `onPartial` gets its partial replies.
   * @param {any} task @param {(p: any) => void} [onPartial] @returns {Promise<any>}
   */
  run(task, onPartial) {
    return new Promise((resolve, reject) => {
      this.queue.push({ id: this.nextId++, task, resolve, reject, onPartial });
      this.#pump();
    });
  }

  /**
   * Run every task; results in task order (a hole where a task failed or
   * was cancelled), `done` counts those that finished or failed. Each
   * callback is called as its task settles; a cancelled task calls none.
   * @param {any[]} tasks
   * @param {{onResult: (i: number, r: any) => void, onError: (i: number, e: Error) => void, onSettled: (done: number) => void,
   *   onPartial?: (i: number, p: any) => void}} on
   */
  async runAll(tasks, { onResult, onError, onSettled, onPartial }) {
    const results = new Array(tasks.length);
    let done = 0;
    await Promise.all(tasks.map((task, i) => this.run(task, onPartial && ((p) => onPartial(i, p))).then(
      (r) => {
        results[i] = r;
        done++;
        onResult(i, r);
      },
      (e) => {
        if (e.message === 'cancelled') return;
        done++;
        onError(i, e);
      },
    ).finally(() => onSettled(done))));
    return { results, done };
  }

  /** Drop queued tasks and stop running ones (their promises reject). */
  cancel() {
    const cancelled = new Error('cancelled');
    for (const job of this.queue.splice(0)) job.reject(cancelled);
    this.slots = this.slots.map((slot) => {
      if (!slot.job) return slot;
      slot.worker.terminate();
      slot.job.reject(cancelled);
      return this.#spawn();
    });
  }
}
