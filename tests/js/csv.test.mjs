// The page's CSV module: RFC 4180 quoting and parsing, and what the CLI's
// reader (src/bin/placecat/cli: `file,category` lines, cells trimmed) needs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { quote, formatCsv, parseCsv, fileRows } from '../../www/csv.js';

const HOSTILE = ['lab, "wet"', 'first line\nsecond line', 'Küche – 2. Stock, 東京', '"', ',', 'a\r\nb', ' padded ', 'plain'];

test('quote leaves plain cells alone and quotes the rest, doubling quotes', () => {
  assert.equal(quote('plain'), 'plain');
  assert.equal(quote('Küche 東京'), 'Küche 東京');
  assert.equal(quote('lab, "wet"'), '"lab, ""wet"""');
  assert.equal(quote('a\nb'), '"a\nb"');
  assert.equal(quote('a\rb'), '"a\rb"');
  assert.equal(quote(' x'), '" x"');
  assert.equal(quote(''), '');
});

test('formatCsv writes the header the CLI skips and one \\n per row', () => {
  const text = formatCsv([['file', 'category'], ['a.ply', 'lab, "wet"'], ['b.ply', 'office']]);
  assert.equal(text, 'file,category\na.ply,"lab, ""wet"""\nb.ply,office\n');
});

test('parseCsv reads quoted commas, doubled quotes, line breaks in quotes, a BOM and CRLF', () => {
  assert.deepEqual(parseCsv('\ufefffile,category\r\na.ply,"lab, ""wet"""\r\n"b.ply","two\r\nlines"\r\n'), [
    ['file', 'category'],
    ['a.ply', 'lab, "wet"'],
    ['b.ply', 'two\r\nlines'],
  ]);
  assert.deepEqual(parseCsv('a,b\rc,d'), [['a', 'b'], ['c', 'd']]);
  assert.deepEqual(parseCsv('a,,\n\n'), [['a', '', ''], ['']]);
  assert.deepEqual(parseCsv('x,""'), [['x', '']]);
  assert.deepEqual(parseCsv(''), []);
  // A quote inside an unquoted cell is text (5" disk), as the CLI reads it.
  assert.deepEqual(parseCsv('a,5" disk'), [['a', '5" disk']]);
});

test('parseCsv refuses an open quote and text after a closing quote, naming the line', () => {
  assert.throws(() => parseCsv('file,category\na.ply,"open\nb.ply,x\n'), /line 2: a quote opened here is not closed/);
  assert.throws(() => parseCsv('a,b\n"x"y,z\n'), /line 2: text after a quoted cell's closing quote/);
});

test('every hostile cell survives formatCsv then parseCsv, and the bytes are stable', () => {
  const rows = [['file', 'category'], ...HOSTILE.map((name, i) => [`scan_${i}.ply`, name])];
  const text = formatCsv(rows);
  assert.deepEqual(parseCsv(text), rows);
  assert.equal(formatCsv(parseCsv(text)), text);
  // Non-ASCII text is kept as it is (the file is UTF-8).
  assert.ok(text.includes('Küche – 2. Stock, 東京'));
});

test('fileRows skips the header and blank rows, trims cells, and refuses a row of one or three cells', () => {
  assert.deepEqual(fileRows('File,Label\n\n a.ply , room \n"b,1.ply","x, y"\n'), [['a.ply', 'room'], ['b,1.ply', 'x, y']]);
  assert.deepEqual(fileRows('a.ply,room\n'), [['a.ply', 'room']]);
  assert.throws(() => fileRows('file,category\na.ply\n'), /row 2: expected two cells/);
  assert.throws(() => fileRows('a.ply,lab, "wet"\n'), /row 1: expected two cells/);
});
