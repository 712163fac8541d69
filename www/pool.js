// A pool of module workers, one per core, each with its own wasm instance.
// Tasks queue; a worker holds up to `depth` of them (and up to `maxBytes` of
// their files) and runs them in order; the page reads a task's file and
// moves the bytes to the worker (`prepare`) while the worker describes the
// one before, so it never waits for the main thread to hand it the next. A
// task that must run `alone` (a bag: long, with partial replies) gets a
// worker to itself.
// A worker that dies (an uncaught error, out of memory) is replaced; a task
// it held alone fails, tasks it held together run again, each alone, so
// that the one that kills a worker is the one that fails. A task may send
// partial replies before its result (a bag's clouds, bag.js). One task can
// be stopped alone (`stop`: a spectral clustering a newer one supersedes).

/** @typedef {{id: number, task: any, resolve: (r: any) => void, reject: (e: Error) => void, onPartial?: (p: any) => void, posted?: number, sent?: boolean, alone: boolean}} Job `sent`: posted to its worker */
/** @typedef {{worker: Worker, jobs: Job[]}} WorkerSlot `jobs`: posted to the worker, not answered yet, oldest first */
/**
 * When a task was posted, came to its worker, started, had its file's
 * bytes, ended and its result came back (wall-clock ms): the stage profile
 * that `npm run bench` prints; `type` is the task's.
 * @typedef {{type: string, worker: number, posted: number, arrived: number, start: number, read: number, end: number, received: number}} TaskClock
 */

export class WorkerPool {
  /** Each task's job, by the promise `run` returned (for `stop`). @type {WeakMap<Promise<any>, Job>} */
  #jobs = new WeakMap();

  /**
   * @param {URL} url the worker module @param {number} [size]
   * @param {{depth?: number, alone?: (task: any) => boolean, prepare?: (task: any) => Promise<{task: any, transfer: Transferable[]}> | null,
   *   transfer?: (task: any) => Transferable[], bytes?: (task: any) => number, maxBytes?: number}} [how]
   *   `depth`: tasks a worker holds at once; `alone`: the tasks that get a worker to themselves; `prepare`: work on the
   *   main thread before a task is posted (none: null), e.g. reading its file, whose failure is the task's;
   *   `bytes`: what a task holds in memory (its file), `maxBytes`: a worker takes another task only while the tasks
   *   it holds stay within this many bytes (it always takes one); `transfer`: what a task that needs no
   *   preparation moves to its worker rather than copies (e.g. a large typed array's buffer)
   */
  constructor(url, size = Math.max(1, navigator.hardwareConcurrency || 2), { depth = 1, alone = () => false, prepare = () => null, transfer = () => [], bytes = () => 0, maxBytes = Infinity } = {}) {
    this.url = url;
    this.size = size;
    this.depth = depth;
    this.bytes = bytes;
    this.maxBytes = maxBytes;
    this.alone = alone;
    this.prepare = prepare;
    this.transfer = transfer;
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
    const slot = { worker, jobs: [] };
    worker.onmessage = (e) => {
      const job = slot.jobs.find((j) => j.id === e.data.id);
      if (!job) return;
      if ('partial' in e.data) return job.onPartial?.(e.data.partial);
      slot.jobs.splice(slot.jobs.indexOf(job), 1);
      if (e.data.clock) this.clocks.push({ type: job.task?.type, worker: this.slots.indexOf(slot), posted: job.posted ?? 0, ...e.data.clock, received: performance.timeOrigin + performance.now() });
      if (e.data.ok) job.resolve(e.data.result);
      else job.reject(new Error(e.data.error));
      this.#pump();
    };
    /** @param {Event & {message?: string}} [e] */
    const die = (e) => {
      e?.preventDefault?.();
      const jobs = slot.jobs.splice(0);
      worker.terminate();
      const i = this.slots.indexOf(slot);
      if (i >= 0) this.slots[i] = this.#spawn();
      if (jobs.length === 1) jobs[0].reject(new Error(`the worker failed: ${e?.message || 'crashed or ran out of memory'}`));
      else {
        // The jobs themselves (not copies), so that `stop` still finds them.
        for (const j of jobs) Object.assign(j, { alone: true, sent: false });
        this.queue.unshift(...jobs);
      }
      this.#pump();
    };
    worker.onerror = die;
    worker.onmessageerror = die;
    return slot;
  }

  /** Hand queued tasks to the workers: one to each idle worker first, then up to `depth` (and `maxBytes`) each. */
  #pump() {
    for (let held = 0; held < this.depth; held++) {
      for (const slot of this.slots) {
        const next = this.queue[0];
        if (!next) return;
        if (slot.jobs.length !== held || (held > 0 && (next.alone || slot.jobs.some((j) => j.alone) || !this.#fits(slot, next)))) continue;
        this.queue.shift();
        slot.jobs.push(next);
        this.#post(slot, next);
      }
    }
  }

  /** Whether `job` joins what `slot` holds within `maxBytes`. @param {WorkerSlot} slot @param {Job} job */
  #fits(slot, job) {
    return slot.jobs.reduce((sum, j) => sum + this.bytes(j.task), this.bytes(job.task)) <= this.maxBytes;
  }

  /** Post a job, once `prepare` (if it has work for the task) is done; a job dropped meanwhile is not posted. @param {WorkerSlot} slot @param {Job} job */
  #post(slot, job) {
    job.posted = performance.timeOrigin + performance.now();
    const prepared = this.prepare(job.task);
    if (!prepared) return this.#send(slot, job, job.task, this.transfer(job.task));
    prepared.then(({ task, transfer }) => {
      if (slot.jobs.includes(job)) this.#send(slot, job, task, transfer);
    }, (e) => {
      const i = slot.jobs.indexOf(job);
      if (i < 0) return;
      slot.jobs.splice(i, 1);
      job.reject(e);
      this.#pump();
    });
  }

  /**
   * Post a job to its worker; one that cannot be posted (a value that does not
   * clone, a buffer moved already) fails alone, and its place goes to the next.
   * @param {WorkerSlot} slot @param {Job} job @param {any} task @param {Transferable[]} transfer
   */
  #send(slot, job, task, transfer) {
    try {
      slot.worker.postMessage({ id: job.id, task }, transfer);
      job.sent = true;
    } catch (e) {
      const i = slot.jobs.indexOf(job);
      if (i >= 0) slot.jobs.splice(i, 1);
      job.reject(/** @type {Error} */ (e));
      queueMicrotask(() => this.#pump()); // not inside the pump that may be posting it
    }
  }

  /**
   * Run a task on the next free worker; `onPartial` gets its partial replies.
   * @param {any} task @param {(p: any) => void} [onPartial] @returns {Promise<any>}
   */
  run(task, onPartial) {
    /** @type {Job | undefined} */
    let job;
    const promise = new Promise((resolve, reject) => {
      job = { id: this.nextId++, task, resolve, reject, onPartial, alone: this.alone(task) };
      this.queue.push(job);
    });
    this.#jobs.set(promise, /** @type {Job} */ (job));
    this.#pump();
    return promise;
  }

  /**
   * Stop one task (its promise rejects with 'cancelled'): dropped if queued
   * or not posted yet; if a worker holds it, that worker is replaced and the other tasks it held
   * are queued again, first. A task that has settled is left as it is.
   * @param {Promise<any>} promise what `run` returned
   */
  stop(promise) {
    const job = this.#jobs.get(promise);
    if (!job) return;
    const cancelled = new Error('cancelled');
    const queued = this.queue.indexOf(job);
    if (queued >= 0) {
      this.queue.splice(queued, 1);
      return job.reject(cancelled);
    }
    const i = this.slots.findIndex((slot) => slot.jobs.includes(job));
    if (i < 0) return;
    const slot = this.slots[i];
    if (!job.sent) {
      // Its file or matrix is still being prepared: the worker never got it.
      slot.jobs.splice(slot.jobs.indexOf(job), 1);
      job.reject(cancelled);
      return this.#pump();
    }
    slot.worker.terminate();
    const others = slot.jobs.splice(0).filter((j) => j !== job);
    this.slots[i] = this.#spawn();
    this.queue.unshift(...others);
    job.reject(cancelled);
    this.#pump();
  }

  /**
   * Run every task; each callback is called as its task settles (a
   * cancelled task calls none), `onSettled` with how many finished or
   * failed so far. Resolves to that count once every task settled.
   * @param {any[]} tasks
   * @param {{onResult: (i: number, r: any) => void, onError: (i: number, e: Error) => void, onSettled: (done: number) => void,
   *   onPartial?: (i: number, p: any) => void}} on
   * @returns {Promise<number>}
   */
  async runAll(tasks, { onResult, onError, onSettled, onPartial }) {
    let done = 0;
    await Promise.all(tasks.map((task, i) => this.run(task, onPartial && ((p) => onPartial(i, p))).then(
      (r) => {
        done++;
        onResult(i, r);
      },
      (e) => {
        if (e.message === 'cancelled') return;
        done++;
        onError(i, e);
      },
    ).finally(() => onSettled(done))));
    return done;
  }

  /** Drop queued tasks and stop running ones (their promises reject). */
  cancel() {
    const cancelled = new Error('cancelled');
    for (const job of this.queue.splice(0)) job.reject(cancelled);
    this.slots = this.slots.map((slot) => {
      if (!slot.jobs.length) return slot;
      slot.worker.terminate();
      for (const job of slot.jobs.splice(0)) job.reject(cancelled);
      return this.#spawn();
    });
  }
}
