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
