// What the page shows, from the state: the dendrogram, the map, the legend
// and the status lines. It reads the state and writes the DOM; it changes
// no state (user actions go back to app.js through the callbacks).
import { Dendrogram } from './dendrogram.js';
import { TrajectoryMap } from './map.js';
import { Legend } from './legend.js';
import { shareColours } from './colours.js';
import { renderSweep, f32String } from './sweep.js';
import { DEMO_PRESET, categoryIndex, colourSlots, dendrogramOf, displayName, errorText, nameOf, posesOf } from './state.js';
import { suggestionText } from './suggest.js';

/** @typedef {import('./state.js').State} State */
/** @typedef {import('./state.js').Method} Method */

/** @param {string} id */
export const $ = (id) => /** @type {HTMLInputElement} */ (document.getElementById(id));
/** @param {string} id */
const canvas = (id) => /** @type {HTMLCanvasElement} */ (document.getElementById(id));

export class View {
  /**
   * @param {{onThreshold: (t: number) => void, onName: (i: number, name: string) => void,
   *   onSweepPick: () => void, onScale: (scale: import('./scale.js').Scale) => void}} on
   */
  constructor(on) {
    $('scale').addEventListener('change', () => on.onScale(/** @type {import('./scale.js').Scale} */ ($('scale').value)));
    this.on = on;
    /** @type {State | null} the state last rendered */
    this.s = null;
    /** @type {number[] | null} category index of each dendrogram category */
    this.catIndex = null;
    /** @type {number | undefined} */
    this.hovered = undefined;
    this.t0 = performance.now(); // when the run began
    this.dendrogram = new Dendrogram(canvas('dendrogram'), { onThreshold: on.onThreshold, onHover: (c, e) => this.#hover(c, e) });
    this.map = new TrajectoryMap(canvas('map'), { onSelect: (i) => this.#select(i) });
    this.legend = new Legend(/** @type {any} */ ($('legend')), { onName: on.onName, onHighlight: (i) => this.highlight(i) });
    this.dendrogram.draw();
    this.map.draw();
  }

  /**
   * Everything that depends on the clustering. `preset`: the one selected;
   * `delta`: Delta between the scans when there are two.
   * @param {State} s @param {string} preset @param {number} [delta]
   */
  render(s, preset, delta) {
    this.s = s;
    // Every clustering numbers its categories afresh, so a highlight of the
    // last one is forgotten (the map and dendrogram redraw below): a legend
    // row replaced under the pointer fires no mouseleave, and a pointer at
    // rest on the dendrogram would keep greying the scans of a category
    // that is now another. The next pointer move highlights again.
    this.hovered = undefined;
    $('tooltip').hidden = true;
    this.map.highlight = this.dendrogram.highlight = -1;
    const n = s.scans.length;
    const sg = s.suggestion;
    // A demo opens on its own preset; any other the user chose.
    const why = s.demo && DEMO_PRESET[s.demo] === preset ? "the demo's" : 'as chosen';
    $('preset-note').textContent = sg ? suggestionText(sg) + (sg.preset !== preset ? `; described with ${preset} (${why})` : '.') : '';
    $('threshold').value = s.lastCut ? s.lastCut.threshold.toFixed(4) : '';
    $('classify').disabled = !s.modelJson;
    if (!s.labels || s.labels.length !== n) {
      this.dendrogram.data = null;
      this.dendrogram.draw();
      return;
    }
    if (s.cut) $('categories').value = String(s.cut.nodes.length);
    shareColours(colourSlots(s));
    this.legend.set(s.categories.map((c, i) => ({ name: nameOf(s, c), size: c.members.length, preview: s.scans[c.medoid].preview })));
    const d = dendrogramOf(s);
    this.catIndex = d?.catIndex ?? null;
    $('scale').value = d?.scale ?? 'linear';
    const named = { linear: 'linear', sqrt: 'square root', log: 'log' };
    $('scale-note').textContent = d && d.auto.merges >= 3 ? `default ${named[d.auto.scale]}: the root is ${d.auto.ratio.toFixed(0)} × the median merge height` : '';
    $('cut-note').textContent = this.#cutNote(s);
    if (d) this.dendrogram.set(d);
    else {
      this.dendrogram.data = null;
      this.dendrogram.draw();
    }
    const { poses, usePoses, drawSite, note } = posesOf(s);
    if (note) $('info').textContent = note;
    $('map-caption').textContent = usePoses
      ? 'Trajectory map: drag to pan, wheel to zoom, click a scan'
      : 'Categories along the scan sequence (no poses file): click a scan';
    this.map.set({ scans: s.scans.map((r, i) => ({ ...r, pose: poses[i] })), labels: categoryIndex(s), usePoses, drawSite });
    const noise = s.labels.filter((l) => l < 0).length;
    const path = s.set && !s.set.usesMatrix ? ` (centre-based path: more than ${s.set.matrixLimit} scans, no Delta matrix)` : '';
    const few = n === 1 ? 'One scan is one category: load more scans to compare places. '
      : n === 2 && delta !== undefined ? `Two scans, Delta ${delta.toFixed(3)} between them: one category if they show one kind of place, two if not. ` : '';
    // Which tree the categories come from (none after k-means or DBSCAN).
    const splits = !s.tree ? ''
      : s.tree.restarts === 1 ? '; tree: one 2-means++ run a split (the paper\'s)' : `; tree: the cheapest of ${s.tree.restarts} 2-means++ trials a split`;
    this.status(`${few}${s.categories.length} ${s.categories.length === 1 ? 'category' : 'categories'}${noise ? `, ${noise} noise` : ''} from ${n} ${n === 1 ? 'scan' : 'scans'}${path}${splits}`);
    $('cluster-status').dataset.categories = String(s.categories.length);
  }

  /** Why the tree is cut where it is: the first cut's rule, or the user's cut. @param {State} s */
  #cutNote(s) {
    if (!s.cut) return '';
    const k = s.cut.nodes.length;
    const first = s.firstCut && !s.cutBy && s.firstCut.k === k;
    return `${k} ${k === 1 ? 'category' : 'categories'}: ${first ? s.firstCut?.why : 'your cut'}`;
  }

  /** A new run: no errors, sweep, accuracy or note from the last. @param {State} s */
  reset(s) {
    this.highlight(-1); // a category picked in the last data set
    this.#hover(-1); // and the tooltip over its dendrogram
    this.errors(s);
    this.sweep('');
    this.accuracy('');
    $('info').textContent = '';
  }

  /** A name changed: new colours in the legend (in place), map and dendrogram. @param {State} s */
  recolour(s) {
    this.s = s;
    shareColours(colourSlots(s));
    this.legend.recolour();
    this.map.draw();
    this.dendrogram.draw();
  }

  /** @param {string} text */
  status(text) {
    $('cluster-status').textContent = text;
  }

  /** Accuracy against ground truth, or why there is none. @param {import('./engine.js').Evaluation | string} ev */
  accuracy(ev) {
    $('accuracy').textContent = typeof ev === 'string'
      ? ev
      : `Against ground truth: accuracy ${(100 * ev.accuracy).toFixed(1)} %, ARI ${ev.ari.toFixed(3)}${ev.inliers < ev.total ? `, S ${(ev.score ?? 0).toFixed(3)}` : ''}${oneForMany(ev)}`;
  }

  /** @param {State} s */
  errors(s) {
    $('errors').replaceChildren(...s.errors.map((e) => Object.assign(document.createElement('li'), { textContent: errorText(e) })));
    $('errors-box').hidden = s.errors.length === 0;
    $('errors-summary').textContent = `${s.errors.length} skipped (files, or clouds of a bag)`;
  }

  /** Progress of a run (its clock starts at 0 done). @param {number} done @param {number} total @param {'running' | 'done' | 'cancelled'} phase @param {string} [unit] what is counted */
  progress(done, total, phase, unit = 'scans') {
    if (done === 0 && phase === 'running') this.t0 = performance.now();
    const secs = (performance.now() - this.t0) / 1000;
    const rate = done / Math.max(secs, 1e-3);
    const left = rate > 0 ? (total - done) / rate : 0;
    $('progress').hidden = false;
    $('progress').dataset.state = phase === 'running' ? 'running' : 'done';
    /** @type {HTMLProgressElement} */ (/** @type {unknown} */ ($('progress-bar'))).value = phase === 'running' ? done / total : 1;
    const end = { running: '', done: ' (done)', cancelled: ' (cancelled)' }[phase];
    $('progress-text').textContent = `${done} / ${total} ${unit}, ${rate.toFixed(1)} ${unit}/s, ${left.toFixed(0)} s left${end}`;
  }

  /** The sweep table, or a message. @param {import('./engine.js').SweepPoint[] | string} points */
  sweep(points) {
    if (typeof points === 'string') {
      $('sweep-table').replaceChildren();
      $('sweep-status').textContent = points;
      return;
    }
    const best = renderSweep($('sweep-table'), points, (eps, minPoints) => {
      $('eps').value = eps;
      $('minpts').value = String(minPoints);
      this.on.onSweepPick();
    });
    $('sweep-status').textContent = best
      ? `Cells: clusters · inliers, shaded by S; best S ${(best.score ?? 0).toFixed(3)} at epsilon ${f32String(best.epsilon)}, min points ${best.min_points} (outlined). Click a cell to use it.`
      : 'Cells: clusters · share of scans in one. Click a cell to use it (with labels.csv, cells are shaded by S).';
  }

  /** The clustering method and its settings, as the form has them. @returns {Method} */
  method() {
    return {
      method: /** @type {Method['method']} */ ($('method').value),
      hkSeed: Number($('hk-seed').value),
      hkSplits: $('hk-splits').value === 'auto' ? 'auto' : Number($('hk-splits').value),
      k: Number($('k').value),
      seeding: /** @type {Method['seeding']} */ ($('seeding').value),
      // "k-means++, best of 10" is plusplus seeding with 10 restarts.
      restarts: Number(/** @type {HTMLSelectElement} */ (document.getElementById('seeding')).selectedOptions[0]?.dataset.restarts ?? 1),
      kmSeed: Number($('km-seed').value),
      spK: Number($('sp-k').value),
      spSeed: Number($('sp-seed').value),
      eps: Number($('eps').value),
      minPoints: Number($('minpts').value),
    };
  }

  showMethod() {
    for (const div of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('[data-for]'))) div.hidden = div.dataset.for !== $('method').value;
  }

  /**
   * Each file's classification, in order, as it arrives.
   * @param {{name: string, result: Promise<import('./engine.js').Classification>}[]} items
   */
  async classified(items) {
    const ul = $('classified');
    ul.replaceChildren();
    for (const { name, result } of items) {
      const li = ul.appendChild(document.createElement('li'));
      try {
        const r = await result;
        li.textContent = `${name} → ${r.name} (Delta ${r.distance.toFixed(3)}${r.relative > 1 ? ', farther than any member' : ''})`;
      } catch (e) {
        li.textContent = e.message;
      }
    }
  }

  /** @param {number} i category index, -1 for none */
  highlight(i) {
    this.dendrogram.setHighlight(i);
    this.map.setHighlight(i);
    this.legend.highlight(i);
  }

  /** @param {number} c dendrogram category under the pointer, -1 for none @param {PointerEvent} [e] */
  #hover(c, e) {
    const tip = $('tooltip');
    const s = this.s;
    if (c < 0 || !this.catIndex || !s || !e) {
      tip.hidden = true;
      if (this.hovered !== undefined) this.map.setHighlight(-1);
      this.hovered = undefined;
      return;
    }
    const i = this.catIndex[c];
    if (this.hovered !== i) this.map.setHighlight((this.hovered = i)); // the map shows the category under the pointer
    tip.textContent = `${displayName(s, i)}: ${s.categories[i].members.length} scans`;
    tip.style.left = `${e.clientX + 12}px`;
    tip.style.top = `${e.clientY + 12}px`;
    tip.hidden = false;
  }

  /** @param {number} i the scan clicked on the map, -1 for none */
  #select(i) {
    const s = this.s;
    if (i < 0 || !s) return ($('info').textContent = '');
    const ci = categoryIndex(s)[i];
    const unreliable = s.scans[i].summary.unreliable ? ' (few voxels: unreliable)' : '';
    $('info').textContent = `${s.scans[i].name}: ${ci >= 0 ? displayName(s, ci) : 'noise'}${unreliable}`;
    this.highlight(ci);
  }
}

/** Save text as a file. @param {string} name @param {string} text @param {string} type */
export function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = Object.assign(document.createElement('a'), { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/**
 * Why a data set with several true kinds is shown as one category: the
 * descriptor, not the rule (the warehouse demo: its halls' scans differ more
 * along the route than hall from hall; issue 18 found the same on
 * independent warehouse data).
 * @param {import('./engine.js').Evaluation} ev
 */
function oneForMany(ev) {
  const kinds = ev.confusion.rows.length;
  if (ev.confusion.cluster_class.length !== 1 || kinds < 2) return '';
  return `. ${kinds} true kinds, 1 category: under this descriptor these scans do not fall into clear groups, so no cut stands out; type ${kinds} categories to see the best split`;
}
