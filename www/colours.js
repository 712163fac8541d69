// Category colours: a qualitative palette, then evenly spaced hues.
const PALETTE = ['#4e79a7', '#f28e2b', '#59a14f', '#e15759', '#b07aa1', '#76b7b2', '#edc948', '#9c755f', '#ff9da7', '#2f4b7c', '#a05195', '#665191'];
export const NOISE = '#9aa0a6';

// Categories the user gave one name are one kind of place: they share the
// colour of the first of them, so the map shows kinds, not cut pieces.
let shared = [];

/** slots[i]: the category whose colour category i takes (i itself if none). */
export function shareColours(slots) {
  shared = slots;
}

export function colour(i) {
  if (i < 0) return NOISE;
  const k = shared[i] ?? i;
  return k < PALETTE.length ? PALETTE[k] : `hsl(${(k * 137.5) % 360} 60% 45%)`;
}

/** Draw a top-down thumbnail of interleaved x,y,z points into a canvas. */
export function drawThumbnail(canvas, points, colourCss) {
  const ctx = canvas.getContext('2d');
  const { width: w, height: h } = canvas;
  ctx.clearRect(0, 0, w, h);
  if (!points || points.length < 3) return;
  // Half-width of the view: the 90th percentile of horizontal range.
  const r = [];
  for (let i = 0; i < points.length; i += 3) r.push(Math.hypot(points[i], points[i + 1]));
  r.sort((a, b) => a - b);
  const half = Math.max(1, r[Math.floor(r.length * 0.9)] || 1);
  const s = (Math.min(w, h) / 2 - 1) / half;
  ctx.fillStyle = colourCss;
  for (let i = 0; i < points.length; i += 3) {
    const x = w / 2 + points[i] * s;
    const y = h / 2 - points[i + 1] * s;
    if (x >= 0 && x < w && y >= 0 && y < h) ctx.fillRect(x, y, 1, 1);
  }
}

/** Clear a canvas and write a hint where the view will appear. */
export function drawPlaceholder(canvas, text) {
  const ctx = canvas.getContext('2d');
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = '#5b6575';
  ctx.font = '14px system-ui';
  ctx.fillText(text, 20, 40);
}
