// The legend: per category a colour swatch, a thumbnail of its most central
// scan, its name (editable) and its size. A pure renderer of plain data;
// typing a name calls `onName`, pointing at a row calls `onHighlight`.
import { colour, drawThumbnail } from './colours.js';

/** @typedef {{name: string, size: number, preview: Float32Array}} LegendRow */

export class Legend {
  /**
   * @param {HTMLOListElement} ol
   * @param {{onName: (i: number, name: string) => void, onHighlight: (i: number) => void}} on
   */
  constructor(ol, { onName, onHighlight }) {
    this.ol = ol;
    this.onName = onName;
    this.onHighlight = onHighlight;
    /** @type {LegendRow[]} */
    this.rows = [];
  }

  /** Rebuild the list. @param {LegendRow[]} rows */
  set(rows) {
    this.rows = rows;
    this.ol.replaceChildren(...rows.map((row, i) => {
      const li = document.createElement('li');
      li.dataset.category = String(i);
      const sw = document.createElement('span');
      sw.className = 'swatch';
      const thumb = document.createElement('canvas');
      thumb.width = thumb.height = 96;
      const input = document.createElement('input');
      input.type = 'text';
      input.value = row.name;
      input.placeholder = `category ${i + 1}`;
      input.setAttribute('aria-label', `Name of category ${i + 1}`);
      input.addEventListener('input', () => this.onName(i, input.value));
      const size = document.createElement('span');
      size.className = 'size';
      size.textContent = `${row.size} scans`;
      li.append(sw, thumb, input, size);
      li.addEventListener('mouseenter', () => this.onHighlight(i));
      li.addEventListener('mouseleave', () => this.onHighlight(-1));
      return li;
    }));
    this.recolour();
  }

  /** Colours changed (a name was typed): repaint in place, keeping the focus. */
  recolour() {
    for (const li of /** @type {HTMLCollectionOf<HTMLLIElement>} */ (this.ol.children)) {
      const i = Number(li.dataset.category);
      /** @type {HTMLElement} */ (li.querySelector('.swatch')).style.background = colour(i);
      drawThumbnail(/** @type {HTMLCanvasElement} */ (li.querySelector('canvas')), this.rows[i].preview, colour(i));
    }
  }

  /** @param {number} i the category to mark, -1 for none */
  highlight(i) {
    for (const li of /** @type {HTMLCollectionOf<HTMLLIElement>} */ (this.ol.children)) li.classList.toggle('hl', Number(li.dataset.category) === i);
  }
}
