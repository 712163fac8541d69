// The regression corpus of damaged scans (tests/data/bad) through the page's
// file input, in one batch with good scans: each damaged file is listed as
// an error with exactly the message in expected.tsv (the one the native and
// wasm tests check), and the good ones are described and clustered.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { start, afterRun, ARTIFACTS, ROOT, REAL } from './harness.mjs';

const BAD = join(ROOT, 'tests/data/bad');
// file<TAB>strict<TAB>lenient; the page reads strictly.
const rows = readFileSync(join(BAD, 'expected.tsv'), 'utf8')
  .split('\n')
  .filter((l) => l && !l.startsWith('#'))
  .map((l) => l.split('\t'));
const damaged = rows.filter(([, strict]) => !/^\d+ points$/.test(strict));
const readable = rows.filter(([, strict]) => /^\d+ points$/.test(strict));
const real = ['ouster_os0_sequence/scan_000.bin', 'ouster_os0_sequence/scan_005.bin', 'pcl_room/room_scan1.pcd', 'velodyne_pair/251370668.pcd'];

let h;
before(async () => { h = await start(); });
after(async () => { await h?.close(); });

test('damaged files are listed as errors naming the file, the rest of the batch is described', async () => {
  assert.ok(damaged.length >= 10, `${damaged.length} damaged files in the table`);
  const files = [...rows.map(([f]) => join(BAD, f)), ...real.map((f) => join(REAL, f))];
  await afterRun(h.page, () => h.page.setInputFiles('#files', files));
  const errors = await h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent));
  for (const [file, strict] of damaged) {
    assert.ok(errors.includes(strict), `${file}: want the error\n  ${strict}\namong\n  ${errors.join('\n  ')}`);
  }
  // The corpus's readable files (padding, CRLF) are not refused by the
  // reader; they are too small for a descriptor, and the page says so.
  for (const [file] of readable) {
    const mine = errors.filter((e) => e.startsWith(`${file}:`));
    assert.ok(mine.every((e) => /no descriptor/.test(e)), `${file} refused: ${mine}`);
  }
  assert.equal(errors.filter((e) => damaged.some(([f]) => e.startsWith(`${f}:`))).length, damaged.length, 'one error per damaged file');
  // Every real scan is described and clustered despite the bad ones.
  const total = rows.length + real.length;
  assert.match(await h.page.textContent('#progress-text'), new RegExp(`^${total} / ${total} scans`));
  const described = total - errors.length;
  assert.ok(described >= real.length, `${described} described`);
  assert.match(await h.page.textContent('#cluster-status'), new RegExp(`from ${described} scans`));
  await h.page.screenshot({ path: join(ARTIFACTS, 'bad-files.png') });
  assert.deepEqual(h.problems, []);
});

test('LAS, LAZ and E57 through the file input: read as the CLI reads them; a georeferenced LAS and damaged ones refused naming the file', async () => {
  // tests/data/survey: written by laspy and pye57 (make_survey.py), the CLI's fixtures.
  const SURVEY = join(ROOT, 'tests/data/survey');
  const good = ['las12_fmt1.las', 'laz12_fmt1.laz', 'laz14_fmt6.laz'];
  const refused = {
    'geo14_fmt6.las': /^geo14_fmt6\.las: LAS\/LAZ: no sensor position: the points span x 512337\.678\.\.512353\.678/,
    'truncated.las': /^truncated\.las: LAS\/LAZ: the header declares 700 points of 34 bytes from byte 227, but the file has 23027 bytes \(truncated\?\)$/,
    'corrupt_chunk.laz': /^corrupt_chunk\.laz: LAS\/LAZ: LAZ data damaged or cut short in points 0\.\.3000 of 3000/,
    'truncated.e57': /^truncated\.e57: E57: .*truncated/,
    // A survey of one station, 300 points in one plane: read, but too few
    // for a descriptor (the CLI says the same, naming the station).
    'single.e57': /^single\.e57:Scan 0: no descriptor: no classified voxel/,
  };
  const files = [...good, ...Object.keys(refused)].map((f) => join(SURVEY, f));
  const real = ['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd'].map((f) => join(REAL, f));
  await afterRun(h.page, () => h.page.setInputFiles('#files', [...files, ...real]));
  const errors = await h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent ?? ''));
  for (const [file, want] of Object.entries(refused)) {
    assert.ok(errors.some((e) => want.test(e)), `${file}: want ${want} among\n  ${errors.join('\n  ')}`);
  }
  assert.equal(errors.length, Object.keys(refused).length, errors.join('\n'));
  const described = good.length + real.length;
  assert.match(await h.page.textContent('#cluster-status'), new RegExp(`from ${described} scans`));
  assert.deepEqual(h.problems, []);
});

test('an E57 survey is one input of many scans: every station described with its pose, drawn as a site', async () => {
  const survey = join(ROOT, 'tests/data/survey/survey.e57');
  await afterRun(h.page, () => h.page.setInputFiles('#files', [survey]));
  assert.deepEqual(await h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent)), []);
  assert.match(await h.page.textContent('#progress-text'), /^4 \/ 4 scans/);
  assert.match(await h.page.textContent('#cluster-status'), /from 4 scans/);
  assert.equal(await h.page.textContent('#bag-note'), 'survey.e57: 4 of 4 scans described');
  // The stations' poses (pye57 wrote them; tests/it/survey.rs reads the same) make the map.
  assert.match(await h.page.textContent('#map-caption'), /Trajectory map/);
  // Each station by the name the CLI gives it (FILE:station, a repeated name with its index).
  const [download] = await Promise.all([h.page.waitForEvent('download'), h.page.click('#export-csv')]);
  const files = readFileSync(await download.path(), 'utf8').trim().split('\n').slice(1).map((r) => r.split(',')[0]);
  assert.deepEqual(files, ['survey.e57:hall', 'survey.e57:office', 'survey.e57:hall (scan 2)', 'survey.e57:store']);
  // Parked first: a scroll slides the legend under a resting pointer, and its row is highlighted.
  await h.page.mouse.move(1, 1);
  await h.page.locator('#map').scrollIntoViewIfNeeded();
  await h.page.screenshot({ path: join(ARTIFACTS, 'e57-survey.png') });
  assert.deepEqual(h.problems, []);
});
