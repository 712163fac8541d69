// The dendrogram's height axis: linear, square root or log, as pure maps
// between a height and a position in [0, 1] along the axis, and the default
// scale for a tree. Heights of mixed data span orders of magnitude (a root
// at 16 over merges at 0.05): a linear axis squashes every useful cut onto
// the zero line.

/** @typedef {'linear' | 'sqrt' | 'log'} Scale */

/**
 * The axis of a tree: `at(h)` is h's position (0 bottom, 1 top), `height(v)`
 * its inverse. The log axis is log(1 + h / h0) (0 stays at the bottom),
 * with h0 the lowest merge height above 0 (or top / 1e4) so that the lowest
 * merges are a step above the leaves.
 * @param {Scale} scale @param {number} top @param {number} h0 @returns {{at: (h: number) => number, height: (v: number) => number}}
 */
export function axis(scale, top, h0) {
  if (scale === 'sqrt') {
    const st = Math.sqrt(top);
    return { at: (h) => Math.sqrt(Math.max(0, h)) / st, height: (v) => (v * st) ** 2 };
  }
  if (scale === 'log') {
    const lt = Math.log1p(top / h0);
    return { at: (h) => Math.log1p(Math.max(0, h) / h0) / lt, height: (v) => h0 * Math.expm1(v * lt) };
  }
  return { at: (h) => h / top, height: (v) => v * top };
}

/** Heights of the merges (nodes with children), above 0. @param {{height: number, children: number[]}[]} nodes */
function mergeHeights(nodes) {
  return nodes.filter((n) => n.children.length > 0 && n.height > 0).map((n) => n.height).sort((a, b) => a - b);
}

/** h0 of the log axis: the lowest merge above 0, or top / 1e4. @param {{height: number, children: number[]}[]} nodes @param {number} top */
export function logFloor(nodes, top) {
  const h = mergeHeights(nodes);
  return Math.max(h[0] ?? 0, top * 1e-4, 1e-9);
}

/**
 * The default scale: from the ratio of the root height to the median merge
 * height. Under 10 the merges spread over a linear axis; up to 100 a square
 * root (which maps the ratio r to sqrt r) keeps the median a tenth of the
 * way up or more; beyond, log.
 * `merges`: how many merges the ratio is taken over (below 3 it says little).
 * @param {{height: number, children: number[]}[]} nodes @param {number} rootHeight @returns {{scale: Scale, ratio: number, merges: number}}
 */
export function defaultScale(nodes, rootHeight) {
  const h = mergeHeights(nodes);
  const median = h.length ? h[Math.floor((h.length - 1) / 2)] : rootHeight;
  const ratio = median > 0 ? rootHeight / median : 1;
  return { scale: ratio < 10 ? 'linear' : ratio < 100 ? 'sqrt' : 'log', ratio, merges: h.length };
}

/** A height as a short label (3 significant digits, no exponent for 0.001..9999). @param {number} h */
export function heightLabel(h) {
  if (h === 0) return '0';
  if (h >= 1000 || h < 0.001) return h.toExponential(1);
  return Number(h.toPrecision(3)).toString();
}
