// Work that need not be done per event: items are collected and handled
// together, at most once every `ms`. The page shows a run's progress and
// saves its results this way: per scan, 1,000 scans made ~1,000 frames
// (style, layout, paint, commit) and 1,000 IndexedDB transactions on the
// main thread, which shares the machine's cores with the workers.

/** @template T */
export class Batch {
  /** @param {number} ms @param {(items: T[]) => void} handle */
  constructor(ms, handle) {
    this.ms = ms;
    this.handle = handle;
    /** @type {T[]} */
    this.items = [];
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this.timer = undefined;
  }

  /** Add items (none: only ask for a call of `handle` at the next tick). @param {T[]} items */
  add(...items) {
    this.items.push(...items);
    this.timer ??= setTimeout(() => this.flush(), this.ms);
  }

  /** Handle what was collected now (the end of a run). */
  flush() {
    clearTimeout(this.timer);
    this.timer = undefined;
    this.handle(this.items.splice(0));
  }
}
