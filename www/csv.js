// The page's one CSV module (RFC 4180): the categories export and import
// and labels.csv. Rows end in "\n" as the CLI writes them; reading takes
// CRLF, LF or CR, a byte-order mark, and quoted cells holding commas,
// doubled quotes and line breaks.

/** A cell as written: quoted when it holds a comma, a quote, a line break,
 * or space at either end (which readers that trim would lose). */
export function quote(cell) {
  return /[",\r\n]|^\s|\s$/.test(cell) ? `"${cell.replace(/"/g, '""')}"` : cell;
}

/**
 * Rows of cells as CSV text, one "\n" after every row.
 * @param {string[][]} rows
 */
export function formatCsv(rows) {
  return rows.map((r) => r.map(quote).join(',') + '\n').join('');
}

/**
 * The rows of a CSV text, each an array of cells. A blank line is a row of
 * one empty cell; a final line break does not start a row.
 * @param {string} text
 * @returns {string[][]}
 */
export function parseCsv(text) {
  const rows = [];
  let row = [''];
  let line = 1;
  let quoted = false; // inside a quoted cell
  let closed = false; // just after a quoted cell's closing quote
  let opened = 0; // the line of the last opening quote
  const s = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
  for (let i = 0; i < s.length; i++) {
    const c = s[i];
    if (quoted) {
      if (c !== '"') {
        if (c === '\n' || (c === '\r' && s[i + 1] !== '\n')) line++;
        row[row.length - 1] += c;
      } else if (s[i + 1] === '"') {
        row[row.length - 1] += '"';
        i++;
      } else {
        quoted = false;
        closed = true;
      }
    } else if (c === ',') {
      row.push('');
      closed = false;
    } else if (c === '\n' || c === '\r') {
      if (c === '\r' && s[i + 1] === '\n') i++;
      rows.push(row);
      row = [''];
      closed = false;
      line++;
    } else if (closed) {
      throw new Error(`line ${line}: text after a quoted cell's closing quote`);
    } else if (c === '"' && row[row.length - 1] === '') {
      quoted = true;
      opened = line;
    } else {
      row[row.length - 1] += c; // a quote inside an unquoted cell is kept as is
    }
  }
  if (quoted) throw new Error(`line ${opened}: a quote opened here is not closed`);
  if (row.length > 1 || row[0] !== '' || closed) rows.push(row);
  return rows;
}

/**
 * `file,value` rows (labels.csv, a categories export): [file, value] pairs
 * with both cells trimmed, skipping blank rows and a first row whose first
 * cell is `file` (the header).
 * @param {string} text
 * @returns {[string, string][]}
 */
export function fileRows(text) {
  /** @type {[string, string][]} */
  const out = [];
  for (const [i, row] of parseCsv(text).entries()) {
    const cells = row.map((c) => c.trim());
    if (cells.every((c) => c === '') || (i === 0 && cells[0].toLowerCase() === 'file')) continue;
    if (cells.length !== 2 || cells[0] === '') throw new Error(`row ${i + 1}: expected two cells, file,name (quote a name that holds a comma)`);
    out.push([cells[0], cells[1]]);
  }
  return out;
}
