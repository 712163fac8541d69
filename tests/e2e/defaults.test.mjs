// First contact (issue 14): the preset suggested from the data, the
// dendrogram's height axis, 1 and 2 scans, the map of the outdoor demo's
// site, and poses that do not outlive their data set (issue 16).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { start, inkedPixels, afterRun, ARTIFACTS, REAL, ROOT } from './harness.mjs';

let h;
before(async () => { h = await start(); });
after(async () => { await h?.close(); });

const text = (sel) => h.page.textContent(sel);
const categories = () => h.page.$eval('#cluster-status', (e) => Number(e.dataset.categories));
const load = (files) => afterRun(h.page, () => h.page.setInputFiles('#files', files.map((f) => (f.startsWith('/') ? f : join(REAL, f)))));

/** Pixels of the map in the site's grey (rgb 70, 78, 92 at low alpha): the scans' points, not the path. */
const sitePixels = () => h.page.evaluate(() => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('map'));
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && Math.abs(d[i] - 70) <= 12 && Math.abs(d[i + 1] - 78) <= 12 && Math.abs(d[i + 2] - 92) <= 12) n++;
  return n;
});

test('the outdoor demo: outdoor suggested, a site under the trajectory, a readable dendrogram whose axis switches', async () => {
  await afterRun(h.page, () => h.page.click('#demo-outdoor'), 300000);
  assert.match(await text('#preset-note'), /^outdoor suggested: \d+ % of the points of scan_00000\.ply lie beyond 15 m/);
  assert.equal(await h.page.inputValue('#preset'), 'outdoor');
  const site = await sitePixels();
  assert.ok(site > 5000, `${site} site pixels on the map`);
  assert.match(await text('#map-caption'), /^Trajectory map/);
  assert.match(await text('#cut-note'), /^\d+ categor(y|ies): /);
  await h.page.screenshot({ path: join(ARTIFACTS, 'demo-outdoor.png') });
  // The README's picture of the page: PLACECAT_README_SHOT=1 refreshes it
  // (e.g. after the demo scene changes); the test never writes docs/ otherwise.
  if (process.env.PLACECAT_README_SHOT === '1') await h.page.screenshot({ path: join(ROOT, 'docs', 'page-outdoor-demo.jpg'), type: 'jpeg', quality: 80 });
  // Each scale draws another axis; dragging the line still cuts in each.
  const ticks = () => h.page.$eval('#dendrogram', (c) => c.dataset.ticks);
  const seen = new Set();
  for (const scale of ['linear', 'sqrt', 'log']) {
    await h.page.selectOption('#scale', scale);
    const box = await h.page.locator('#dendrogram').boundingBox(); // the notes above may wrap anew
    seen.add(await ticks());
    await h.page.mouse.click(box.x + box.width / 2, box.y + 3); // above the plot: the top, one category
    assert.equal(await categories(), 1, scale);
    await h.page.mouse.click(box.x + box.width / 2, box.y + box.height * 0.79); // just above the leaves: many
    assert.ok((await categories()) > 3, `${scale}: a low cut gives many categories`);
  }
  assert.equal(seen.size, 3, `three axes: ${[...seen].join(' | ')}`);
  await h.page.screenshot({ path: join(ARTIFACTS, 'demo-outdoor-log.png') });
});

test('one scan is one category, said so; nothing breaks', async () => {
  await load(['kitti00/000094.bin']);
  assert.equal(await categories(), 1);
  assert.match(await text('#cluster-status'), /^One scan is one category/);
  // 26.1 % of its 121618 points lie beyond 15 m (measured outside the page).
  assert.match(await text('#preset-note'), /^outdoor suggested: 26 % of the points of 000094\.bin lie beyond 15 m/);
  assert.equal(await h.page.inputValue('#preset'), 'outdoor');
  assert.ok((await inkedPixels(h.page, 'map')) > 0);
  await h.page.screenshot({ path: join(ARTIFACTS, 'one-scan.png') });
});

test('two scans of one room: indoor suggested, their Delta shown, one or two categories', async () => {
  await load(['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd']);
  assert.match(await text('#preset-note'), /^indoor suggested: 0 % of the points of room_scan1\.pcd lie beyond 15 m \(under 14 %/);
  assert.equal(await h.page.inputValue('#preset'), 'indoor');
  assert.match(await text('#cluster-status'), /^Two scans, Delta \d\.\d{3} between them/);
  assert.ok([1, 2].includes(await categories()));
  await h.page.screenshot({ path: join(ARTIFACTS, 'two-scans.png') });
  // The user's preset wins, and the page says it differs from the suggestion.
  await afterRun(h.page, () => h.page.selectOption('#preset', 'outdoor'));
  assert.match(await text('#preset-note'), /^indoor suggested: .*; described with outdoor \(as chosen\)$/);
});

test('an enclosed space is indoor, KITTI outdoor; poses go with their data set', async () => {
  await load(['ouster_os0_sequence/scan_000.bin', 'ouster_os0_sequence/scan_001.bin', 'ouster_os0_sequence/scan_002.bin']);
  assert.match(await text('#preset-note'), /^indoor suggested: 10 % /);
  const kitti = ['000094.bin', '000095.bin', '000198.bin', '000199.bin', 'poses.txt'].map((f) => `kitti00/${f}`);
  await load(kitti);
  assert.match(await text('#preset-note'), /^outdoor suggested/);
  assert.match(await text('#map-caption'), /^Trajectory map/);
  assert.ok((await sitePixels()) > 500, 'KITTI scans drawn by their poses');
  // The same poses as TUM rows (t x y z qx qy qz qw, a rotation about z by
  // the KITTI rows' yaw) draw the same map.
  const mapImage = () => h.page.$eval('#map', (c) => c.toDataURL());
  const kittiMap = await mapImage();
  const tum = readFileSync(join(REAL, 'kitti00/poses.txt'), 'utf8').trim().split('\n').map((line, i) => {
    const v = line.trim().split(/\s+/).map(Number);
    const yaw = Math.atan2(v[4], v[0]);
    return [i, v[3], v[7], v[11], 0, 0, Math.sin(yaw / 2), Math.cos(yaw / 2)].join(' ');
  });
  const tumFile = join(mkdtempSync(join(tmpdir(), 'placecat-e2e-')), 'poses_tum.txt');
  writeFileSync(tumFile, tum.join('\n') + '\n');
  await load(kitti.slice(0, 4).concat([tumFile]));
  assert.equal(await mapImage(), kittiMap, 'TUM poses draw the map KITTI poses drew');
  // A new data set without a poses file: the old poses are not its trajectory.
  await load(['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd']);
  assert.match(await text('#map-caption'), /^Categories along the scan sequence/);
  // A preset the user picked beyond indoor / outdoor stands for the next data set.
  await afterRun(h.page, () => h.page.selectOption('#preset', 'indoor_bands'));
  await load(['kitti00/000094.bin', 'kitti00/000095.bin']);
  assert.equal(await h.page.inputValue('#preset'), 'indoor_bands');
  assert.equal(await text('#preset-note'), '');
  assert.deepEqual(h.problems, []);
});
