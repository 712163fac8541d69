// How long each stage of a run takes on the page's main thread, as user
// timing measures (`placecat:<stage>`), which `npm run bench` reads to
// print the stage breakdown; they cost a few microseconds each.

/**
 * Run `fn` and measure it as stage `name`.
 * @template R @param {string} name @param {() => R} fn @returns {R}
 */
export function stage(name, fn) {
  const start = performance.now();
  try {
    return fn();
  } finally {
    performance.measure(`placecat:${name}`, { start, end: performance.now() });
  }
}

/** Measure stage `name` from `start` (a performance.now()) to now. @param {string} name @param {number} start */
export function stageSince(name, start) {
  performance.measure(`placecat:${name}`, { start, end: performance.now() });
}

/**
 * Forget the marks and measures of earlier runs (each run's are read after
 * it; a page used for hours would otherwise pile them up), but those named
 * in `keep`. @param {string[]} [keep] e.g. the mark of the files just given
 */
export function clearStages(keep = []) {
  for (const e of performance.getEntries()) {
    if (!e.name.startsWith('placecat:') || keep.includes(e.name)) continue;
    if (e.entryType === 'mark') performance.clearMarks(e.name);
    else if (e.entryType === 'measure') performance.clearMeasures(e.name);
  }
}
