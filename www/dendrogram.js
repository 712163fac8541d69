// The dendrogram (paper Fig. 1b, 2): node heights are diameters; a red
// threshold line the user drags; categories coloured at the cut, with a
// thumbnail of each category's most central scan beneath its leaves. The
// height axis is linear, square root or log (scale.js); the threshold line
// is placed and dragged through the same map, so dragging works in each.
import { colour, drawThumbnail, drawPlaceholder } from './colours.js';
import { axis, logFloor, heightLabel } from './scale.js';

const M = { left: 46, right: 12, top: 14, bottom: 64 };

/** @typedef {import('./engine.js').TreeNode} TreeNode */
/**
 * What is drawn: the tree's nodes with their x, each node's category at the
 * cut (-1 above it), each category's leaf span, and the threshold.
 * @typedef {{nodes: TreeNode[], x: Float64Array, cat: Int32Array, spans: [number, number][], step: number,
 *   rootHeight: number, threshold: number, top: number, central: Float32Array[], cutNodes: number[],
 *   axis: {at: (h: number) => number, height: (v: number) => number}}} Drawn
 */

export class Dendrogram {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{onThreshold: (t: number) => void, onHover: (c: number, e?: PointerEvent) => void}} on
   */
  constructor(canvas, { onThreshold, onHover }) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    this.onThreshold = onThreshold;
    this.onHover = onHover;
    /** @type {Drawn | null} */
    this.data = null;
    this.highlight = -1;
    let dragging = false;
    /** @param {PointerEvent} e */
    const heightAt = (e) => {
      const r = canvas.getBoundingClientRect();
      const y = ((e.clientY - r.top) / r.height) * canvas.height;
      return this.#heightOf(y);
    };
    canvas.addEventListener('pointerdown', (e) => {
      if (!this.data) return;
      dragging = true;
      canvas.setPointerCapture(e.pointerId);
      this.onThreshold(heightAt(e));
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!this.data) return;
      if (dragging) this.onThreshold(heightAt(e));
      this.onHover(this.#categoryAt(e), e);
    });
    canvas.addEventListener('pointerup', () => (dragging = false));
    canvas.addEventListener('pointerleave', () => this.onHover(-1));
    canvas.addEventListener('keydown', (e) => {
      if (!this.data || !['ArrowUp', 'ArrowDown'].includes(e.key)) return;
      e.preventDefault();
      // A 50th of the axis, in its scale.
      const { at, height } = this.data.axis;
      const v = at(this.data.threshold) + (e.key === 'ArrowUp' ? 0.02 : -0.02);
      this.onThreshold(Math.max(0, height(Math.min(1, Math.max(0, v)))));
    });
  }

  get plotHeight() {
    return this.canvas.height - M.top - M.bottom;
  }
  /** Only called while there is data. */
  get #d() {
    return /** @type {Drawn} */ (this.data);
  }
  /** @param {number} h */
  #y(h) {
    return M.top + (1 - this.#d.axis.at(h)) * this.plotHeight;
  }
  /** @param {number} y */
  #heightOf(y) {
    const v = Math.min(1, Math.max(0, 1 - (y - M.top) / this.plotHeight));
    return Math.min(this.#d.top, Math.max(0, this.#d.axis.height(v)));
  }
  /** @param {PointerEvent} e */
  #categoryAt(e) {
    const r = this.canvas.getBoundingClientRect();
    const x = ((e.clientX - r.left) / r.width) * this.canvas.width;
    const { spans, step } = this.#d;
    return spans.findIndex(([a, b]) => x >= a - step / 2 && x <= b + step / 2);
  }

  /**
   * nodes: the tree's nodes; cutNodes: the tree node of each category;
   * central: per category, the preview points of its most central scan.
   * scale: the height axis.
   * @param {{nodes: TreeNode[], rootHeight: number, threshold: number, cutNodes: number[], central: Float32Array[],
   *   scale: import('./scale.js').Scale}} tree
   */
  set({ nodes, rootHeight, threshold, cutNodes, central, scale }) {
    /** @type {number[]} */
    const leaves = [];
    const stack = [0];
    while (stack.length) {
      const id = /** @type {number} */ (stack.pop());
      if (nodes[id].children.length === 0) leaves.push(id);
      else for (let i = nodes[id].children.length - 1; i >= 0; i--) stack.push(nodes[id].children[i]);
    }
    const width = this.canvas.width - M.left - M.right;
    const step = width / Math.max(1, leaves.length);
    const x = new Float64Array(nodes.length);
    leaves.forEach((id, i) => (x[id] = M.left + (i + 0.5) * step));
    // Internal nodes: the middle of their children (post-order).
    /** @type {number[]} */
    const order = [];
    /** @type {[number, boolean][]} */
    const st = [[0, false]];
    while (st.length) {
      const [id, done] = /** @type {[number, boolean]} */ (st.pop());
      if (done || nodes[id].children.length === 0) order.push(id);
      else {
        st.push([id, true]);
        for (const c of nodes[id].children) st.push([c, false]);
      }
    }
    for (const id of order) {
      const ch = nodes[id].children;
      if (ch.length) x[id] = ch.reduce((s, c) => s + x[c], 0) / ch.length;
    }
    // Category of each node at the cut (-1 above the cut).
    const cat = new Int32Array(nodes.length).fill(-1);
    /** @type {[number, number][]} */
    const spans = [];
    cutNodes.forEach((root, c) => {
      const s = [root];
      let lo = Infinity, hi = -Infinity;
      while (s.length) {
        const id = /** @type {number} */ (s.pop());
        cat[id] = c;
        if (nodes[id].children.length === 0) {
          lo = Math.min(lo, x[id]);
          hi = Math.max(hi, x[id]);
        }
        s.push(...nodes[id].children);
      }
      spans.push([lo, hi]);
    });
    const top = Math.max(rootHeight * 1.05, 1e-6);
    this.data = { nodes, x, cat, spans, step, rootHeight, threshold, top, central, cutNodes, axis: axis(scale, top, logFloor(nodes, top)) };
    this.draw();
  }

  /** @param {number} c */
  setHighlight(c) {
    this.highlight = c;
    this.draw();
  }

  draw() {
    const { ctx, canvas } = this;
    if (!this.data) return drawPlaceholder(canvas, 'Load scans or try the demo; the dendrogram of hierarchical k-means++ appears here.');
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const { nodes, x, cat, spans, threshold, top, central } = this.data;
    // Axis.
    ctx.strokeStyle = '#c5ccd6';
    ctx.fillStyle = '#5b6575';
    ctx.font = '11px system-ui';
    ctx.beginPath();
    ctx.moveTo(M.left - 6, M.top);
    ctx.lineTo(M.left - 6, M.top + this.plotHeight);
    ctx.stroke();
    // Ticks evenly spaced along the axis, labelled with their heights.
    const ticks = [];
    // (A lone scan has no merges: its axis is only 0.)
    for (let i = 0; i <= (this.data.rootHeight > 0 ? 5 : 0); i++) {
      const h = i === 5 ? top : this.data.axis.height(i / 5);
      ticks.push(heightLabel(h));
      ctx.fillText(ticks[i], 2, this.#y(h) + 4);
    }
    canvas.dataset.ticks = ticks.join(' '); // what the axis says, readable outside the canvas
    // Links.
    ctx.lineWidth = 1.2;
    nodes.forEach((n, id) => {
      if (!n.children.length) return;
      const y = this.#y(n.height);
      for (const c of n.children) {
        ctx.strokeStyle = cat[c] >= 0 ? colour(cat[c]) : '#6b7280';
        if (cat[c] >= 0 && this.highlight >= 0 && cat[c] !== this.highlight) ctx.strokeStyle = '#d5d9df';
        ctx.beginPath();
        ctx.moveTo(x[c], this.#y(nodes[c].height));
        ctx.lineTo(x[c], y);
        ctx.lineTo(x[id], y);
        ctx.stroke();
      }
    });
    // Leaves: a tick per leaf in its category colour.
    nodes.forEach((n, id) => {
      if (n.children.length) return;
      ctx.fillStyle = colour(cat[id]);
      ctx.fillRect(x[id] - 1, M.top + this.plotHeight, 2, 6);
    });
    // Threshold line with a handle.
    const ty = this.#y(threshold);
    ctx.strokeStyle = '#e0302b';
    ctx.lineWidth = 2;
    ctx.setLineDash([6, 4]);
    ctx.beginPath();
    ctx.moveTo(M.left - 6, ty);
    ctx.lineTo(this.canvas.width - M.right, ty);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = '#e0302b';
    ctx.fillRect(this.canvas.width - M.right - 10, ty - 5, 10, 10);
    ctx.fillText(`t = ${threshold.toFixed(3)}  (${spans.length} ${spans.length === 1 ? 'category' : 'categories'})`, M.left, Math.max(12, ty - 6));
    // Thumbnails of each category's most central scan, if there is room.
    const room = Math.min(48, ...spans.map(([a, b], i) => (i + 1 < spans.length ? spans[i + 1][0] - a : 1e9)));
    if (room >= 20 && central) {
      const size = Math.floor(Math.min(48, room - 2));
      const tmp = document.createElement('canvas');
      tmp.width = tmp.height = size;
      spans.forEach(([a, b], c) => {
        drawThumbnail(tmp, central[c], colour(c));
        const cx = (a + b) / 2 - size / 2;
        const cy = this.canvas.height - M.bottom + 10;
        ctx.strokeStyle = colour(c);
        ctx.lineWidth = c === this.highlight ? 3 : 1;
        ctx.strokeRect(cx - 0.5, cy - 0.5, size + 1, size + 1);
        ctx.drawImage(tmp, cx, cy);
      });
    }
  }
}
