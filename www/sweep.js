// The DBSCAN sweep table (paper Fig. 3): rows epsilon, columns min points.
// Each cell shows the clusters and inliers DBSCAN gives there; with ground
// truth also S = ARI x inliers / all, shaded, the best cell marked. A click
// on a cell hands its (epsilon, min points) to `onPick`.

/** Fill `table` from `points` ([{epsilon, min_points, clusters, inlier_ratio, ari, score}]). */
export function renderSweep(table, points, onPick) {
  const eps = [...new Set(points.map((p) => p.epsilon))];
  const cs = [...new Set(points.map((p) => p.min_points))];
  const scored = points.filter((p) => p.score !== null && p.score !== undefined);
  const best = scored.reduce((b, p) => (b === null || p.score > b.score ? p : b), null);
  const head = document.createElement('tr');
  head.append(cell('th', 'ε \\ c'), ...cs.map((c) => cell('th', String(c))));
  const rows = eps.map((e) => {
    const tr = document.createElement('tr');
    tr.append(cell('th', f32String(e)));
    for (const c of cs) {
      const p = points.find((q) => q.epsilon === e && q.min_points === c);
      const td = cell('td', `${p.clusters} · ${Math.round(100 * p.inlier_ratio)}%`);
      td.title = `epsilon ${f32String(p.epsilon)}, min points ${p.min_points}: ${p.clusters} clusters, ${(100 * p.inlier_ratio).toFixed(1)} % of scans in one`
        + (p.score == null ? '' : `, ARI ${p.ari.toFixed(3)}, S ${p.score.toFixed(3)}`);
      td.dataset.eps = f32String(p.epsilon);
      td.dataset.minPoints = String(p.min_points);
      if (p.score != null) {
        td.dataset.score = p.score.toFixed(4);
        // Shade by S: white at 0, the accent's light tint at 1.
        td.style.background = `rgba(47, 111, 219, ${(0.35 * Math.max(0, p.score)).toFixed(3)})`;
      }
      if (p === best) td.classList.add('best');
      td.tabIndex = 0;
      const pick = () => {
        for (const x of table.querySelectorAll('td.picked')) x.classList.remove('picked');
        td.classList.add('picked');
        onPick(f32String(p.epsilon), p.min_points);
      };
      td.addEventListener('click', pick);
      td.addEventListener('keydown', (ev) => (ev.key === 'Enter' || ev.key === ' ') && (ev.preventDefault(), pick()));
      tr.append(td);
    }
    return tr;
  });
  table.replaceChildren(head, ...rows);
  return best;
}

/**
 * The shortest decimal that is the same float32 as `x` (wasm hands float32
 * epsilons over as float64: 0.211 arrives as 0.210999995470047).
 */
export function f32String(x) {
  for (let p = 1; p < 9; p++) {
    const s = x.toPrecision(p);
    if (Math.fround(Number(s)) === Math.fround(x)) return String(Number(s));
  }
  return String(x);
}

function cell(tag, text) {
  const el = document.createElement(tag);
  el.textContent = text;
  return el;
}
