// Work a worker does only while it has no task to run (worker.js): the
// blocks of a run's Delta matrix (matrix.js, GrowingMatrix), computed in
// the waits for the next file. The page cannot time them: it hears of a
// worker's result 20-30 ms late in a 1,000-scan run (its main thread
// busy), by when the next file has mostly been posted, so blocks offered
// when it saw a worker idle ran 5 times a worker in the whole run, while
// the worker waited ~50 times for 5-20 ms. So a worker holds a block and
// computes it in chunks of about `chunkPairs` Deltas (2 ms), only while no
// task of its own is queued; between two chunks the messages that came
// are handled first, so a file that comes waits at most one chunk.

/** @typedef {{rows: number[], key: string, params: any}} Block */
/** @typedef {{arrived: number, start: number, read: number, end: number, chunks: [number, number][]}} IdleClock `chunks`: when each chunk ran */

export class IdleWork {
  /**
   * @param {(rows: number[], block: Block) => Float32Array} compute the Deltas of these rows of a block
   * @param {(message: any, transfer?: Transferable[]) => void} post the worker's reply
   * @param {{chunkPairs?: number, now?: () => number}} [how]
   */
  constructor(compute, post, { chunkPairs = 1000, now = () => performance.timeOrigin + performance.now() } = {}) {
    this.compute = compute;
    this.post = post;
    this.chunkPairs = chunkPairs;
    this.now = now;
    /** Tasks of the worker's own queue not finished yet: while any is, no chunk runs. */
    this.tasks = 0;
    /** @type {{id: number, block: Block, next: number, parts: Float32Array[], clock: IdleClock}[]} */
    this.blocks = [];
    this.pinged = false;
    // A message to itself: a timer would be clamped to 4 ms once nested.
    this.channel = new MessageChannel();
    this.channel.port1.onmessage = () => {
      this.pinged = false;
      this.#chunk();
    };
  }

  /** A block to compute while idle. @param {number} id @param {Block} block */
  add(id, block) {
    this.blocks.push({ id, block, next: 0, parts: [], clock: { arrived: this.now(), start: 0, read: 0, end: 0, chunks: [] } });
    this.#wake();
  }

  /** A task of the worker's own queue came. */
  taskCame() {
    this.tasks++;
  }

  /** A task of the worker's own queue ended. */
  taskEnded() {
    this.tasks--;
    this.#wake();
  }

  #wake() {
    if (this.pinged || this.tasks > 0 || !this.blocks.length) return;
    this.pinged = true;
    this.channel.port2.postMessage(0);
  }

  /** The next chunk of the oldest block, if no task is queued. */
  #chunk() {
    const job = this.blocks[0];
    if (this.tasks > 0 || !job) return;
    const start = this.now();
    job.clock.start ||= start;
    const rows = [];
    for (let pairs = 0; job.next < job.block.rows.length && (rows.length === 0 || pairs + job.block.rows[job.next] <= this.chunkPairs);) {
      pairs += job.block.rows[job.next];
      rows.push(job.block.rows[job.next++]);
    }
    try {
      job.parts.push(this.compute(rows, job.block));
    } catch (err) {
      this.blocks.shift();
      this.post({ id: job.id, ok: false, error: String(/** @type {any} */ (err)?.message ?? err) });
      return this.#wake();
    }
    job.clock.chunks.push([start, this.now()]);
    if (job.next === job.block.rows.length) {
      this.blocks.shift();
      const result = new Float32Array(job.parts.reduce((n, p) => n + p.length, 0));
      job.parts.reduce((at, p) => (result.set(p, at), at + p.length), 0);
      job.clock.end = this.now();
      this.post({ id: job.id, ok: true, result, clock: job.clock }, [result.buffer]);
    }
    this.#wake();
  }

  close() {
    this.channel.port1.close();
  }
}
