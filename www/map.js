// The trajectory map (paper Fig. 1a): poses as a path coloured by category
// over a faint top-down map of the scans' points placed by their poses.
// Without poses: a strip of categories along the scan sequence (Fig. 4, 6).
// The site is drawn from each scan's `site` subsample (a few hundred x, y
// points, suggest.js), so the map's memory stays a few kilobytes per scan.
import { colour, drawPlaceholder } from './colours.js';

/** @typedef {{name: string, pose?: import('./engine.js').Pose, site?: Float32Array}} MapScan */
/** `drawSite`: the poses carry headings (not CSV poses, which have none), so scans can be placed.
 * @typedef {{scans: MapScan[], labels: Int32Array, usePoses: boolean, drawSite: boolean}} MapData */

export class TrajectoryMap {
  /** @param {HTMLCanvasElement} canvas @param {{onSelect: (i: number) => void}} on */
  constructor(canvas, { onSelect }) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    this.onSelect = onSelect;
    /** @type {MapData | null} */
    this.data = null;
    this.view = { s: 1, ox: 0, oy: 0 };
    this.selected = -1;
    this.highlight = -1;
    /** @type {{start: number[], view: {s: number, ox: number, oy: number}, moved: boolean} | null} */
    let drag = null;
    /** @param {PointerEvent | WheelEvent} e */
    const pos = (e) => {
      const r = canvas.getBoundingClientRect();
      return [((e.clientX - r.left) / r.width) * canvas.width, ((e.clientY - r.top) / r.height) * canvas.height];
    };
    canvas.addEventListener('pointerdown', (e) => {
      drag = { start: pos(e), view: { ...this.view }, moved: false };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const [x, y] = pos(e);
      const dx = x - drag.start[0], dy = y - drag.start[1];
      if (Math.hypot(dx, dy) > 3) drag.moved = true;
      if (drag.moved) {
        this.view.ox = drag.view.ox + dx;
        this.view.oy = drag.view.oy + dy;
        this.draw();
      }
    });
    canvas.addEventListener('pointerup', (e) => {
      if (drag && !drag.moved) this.#click(pos(e));
      drag = null;
    });
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const [x, y] = pos(e);
      const f = Math.exp(-e.deltaY * 0.0015);
      this.view.ox = x - (x - this.view.ox) * f;
      this.view.oy = y - (y - this.view.oy) * f;
      this.view.s *= f;
      this.draw();
    }, { passive: false });
  }

  /** Scans (a pose each when usePoses) and each one's category index. @param {MapData} data */
  set({ scans, labels, usePoses, drawSite }) {
    this.data = { scans, labels, usePoses, drawSite };
    this.selected = -1;
    this.#fit();
    this.draw();
  }

  /** @param {number} c */
  setHighlight(c) {
    this.highlight = c;
    this.draw();
  }

  /** @param {number} i */
  select(i) {
    this.selected = i;
    this.draw();
  }

  #fit() {
    const { width: w, height: h } = this.canvas;
    const pts = this.#positions();
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of pts) {
      x0 = Math.min(x0, x); x1 = Math.max(x1, x);
      y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
    const pad = this.#d.usePoses ? 15 : 0;
    x0 -= pad; x1 += pad; y0 -= pad; y1 += pad;
    const s = Math.min((w - 40) / Math.max(x1 - x0, 1e-6), (h - 40) / Math.max(y1 - y0, 1e-6));
    this.view = { s, ox: w / 2 - ((x0 + x1) / 2) * s, oy: h / 2 + ((y0 + y1) / 2) * s };
  }

  /** Only called while there is data. */
  get #d() {
    return /** @type {MapData} */ (this.data);
  }

  /** World (or strip) position of each scan. @returns {[number, number][]} */
  #positions() {
    const { scans, usePoses, labels } = this.#d;
    if (usePoses) return scans.map((s) => { const p = /** @type {import('./engine.js').Pose} */ (s.pose).position; return [p[0], p[1]]; });
    // Strip: x = sequence index, y = category row.
    return scans.map((_, i) => [i, -Math.max(-1, labels?.[i] ?? 0) * 3]);
  }

  #screen([x, y]) {
    return [this.view.ox + x * this.view.s, this.view.oy - y * this.view.s];
  }

  #click(p) {
    if (!this.data) return;
    let best = -1, bd = 12;
    this.#positions().forEach((q, i) => {
      const [x, y] = this.#screen(q);
      const d = Math.hypot(x - p[0], y - p[1]);
      if (d < bd) { bd = d; best = i; }
    });
    this.selected = best;
    this.draw();
    this.onSelect(best);
  }

  draw() {
    const { ctx, canvas } = this;
    if (!this.data) return drawPlaceholder(canvas, 'The trajectory map (with a poses file) or the category strip appears here.');
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const { scans, labels, usePoses, drawSite } = this.data;
    const pos = this.#positions();
    if (usePoses) {
      // The site, faint grey under the path: each scan's subsample turned
      // by its heading and moved to its position (top-down, z dropped).
      ctx.fillStyle = 'rgba(70, 78, 92, 0.22)';
      for (const { site: p, pose } of drawSite ? scans : []) {
        if (!p || !pose) continue;
        const c = Math.cos(pose.yaw), sn = Math.sin(pose.yaw);
        for (let i = 0; i + 1 < p.length; i += 2) {
          const [x, y] = this.#screen([pose.position[0] + c * p[i] - sn * p[i + 1], pose.position[1] + sn * p[i] + c * p[i + 1]]);
          if (x >= 0 && y >= 0 && x < canvas.width && y < canvas.height) ctx.fillRect(x, y, 1.5, 1.5);
        }
      }
      // The path, coloured by category.
      ctx.lineWidth = 3;
      for (let i = 1; i < pos.length; i++) {
        const [ax, ay] = this.#screen(pos[i - 1]);
        const [bx, by] = this.#screen(pos[i]);
        ctx.strokeStyle = this.#colourOf(labels?.[i] ?? -1);
        ctx.beginPath();
        ctx.moveTo(ax, ay);
        ctx.lineTo(bx, by);
        ctx.stroke();
      }
    }
    pos.forEach((q, i) => {
      const [x, y] = this.#screen(q);
      const l = labels?.[i] ?? -1;
      ctx.fillStyle = this.#colourOf(l);
      if (usePoses) {
        ctx.beginPath();
        ctx.arc(x, y, 3.5, 0, 2 * Math.PI);
        ctx.fill();
      } else {
        const w = Math.max(2, this.view.s * 0.9);
        ctx.fillRect(x - w / 2, y - 8, w, 16);
      }
      if (i === this.selected) {
        ctx.strokeStyle = '#111';
        ctx.lineWidth = 2;
        ctx.strokeRect(x - 7, y - 11, 14, 22);
      }
    });
    if (!usePoses) {
      ctx.fillStyle = '#5b6575';
      ctx.font = '11px system-ui';
      ctx.fillText('scan sequence →', 8, canvas.height - 8);
    }
  }

  #colourOf(l) {
    if (this.highlight >= 0 && l !== this.highlight) return '#d5d9df';
    return l < 0 ? '#c0392b' : colour(l);
  }
}
