// First contact (issue 14): the outdoor demo (the rule's number of
// categories, accuracy against its truth, a site on the map), ten scans of
// one place as one category, the warehouse demo, the preset suggested from
// the data, the dendrogram's height axis, 1 and 2 scans, and poses that do
// not outlive their data set (issue 16).
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

/**
 * Pixels of the map in the site's grey (rgb 70, 78, 92 at low alpha): the
 * scans' points, not the path; and the box around them (canvas pixels).
 */
const siteOnMap = () => h.page.evaluate(() => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('map'));
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let pixels = 0, x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < d.length; i += 4) {
    if (!(d[i + 3] > 0 && Math.abs(d[i] - 70) <= 12 && Math.abs(d[i + 1] - 78) <= 12 && Math.abs(d[i + 2] - 92) <= 12)) continue;
    pixels++;
    const x = (i / 4) % c.width, y = Math.floor(i / 4 / c.width);
    [x0, x1, y0, y1] = [Math.min(x0, x), Math.max(x1, x), Math.min(y0, y), Math.max(y1, y)];
  }
  return { pixels, width: x1 - x0 + 1, height: y1 - y0 + 1 };
});

/** The page's evaluation against the demo's truth, as numbers. */
const evaluation = async () => {
  const t = await text('#accuracy');
  const m = t.match(/^Against ground truth: accuracy (\d+\.\d) %, ARI (-?\d\.\d{3})/);
  assert.ok(m, t);
  return { accuracy: Number(m[1]) / 100, ari: Number(m[2]) };
};

test('the outdoor demo, no click but its button: a site of 300 scans, the categories the rule chose, accuracy against its truth', async (t) => {
  await afterRun(h.page, () => h.page.click('#demo-outdoor'), 300000);
  assert.match(await text('#progress-text'), /^300 \/ 300 scans/);
  assert.match(await text('#preset-note'), /^outdoor_hellinger suggested: \d+ % of the points of scan_00000\.ply lie beyond 15 m/);
  assert.equal(await h.page.inputValue('#preset'), 'outdoor_hellinger');
  // The automatic cut (issue 14: the three kinds, or plain vs forest): the
  // rule (silhouette_gap) chooses 3 on the demo (simulator seed 1,
  // hierarchical k-means++ seed 0), and the page says it was the rule's.
  assert.equal(await categories(), 3);
  assert.match(await text('#cut-note'), /^3 categories: the gap statistic's choice \(best mean silhouette 0\.\d\d\)$/);
  assert.match(await text('#cluster-status'), /^3 categories from 300 scans; tree: the cheapest of 10 2-means\+\+ trials a split$/);
  assert.equal(await h.page.$$eval('#legend li', (li) => li.length), 3);
  // The choice's 10 reference sets were computed by the two workers
  // (matrix.js), one task a set, after each worker's rows of the matrix.
  const tail = await h.page.evaluate(() => /** @type {any} */ (performance.getEntriesByName('placecat:pool')[0]).detail
    .filter((c) => c.type === 'deltaRows' || c.type === 'references').map((c) => `${c.type} ${c.worker}`));
  assert.deepEqual(tail.filter((c) => c.startsWith('deltaRows')).sort(), ['deltaRows 0', 'deltaRows 1']);
  assert.equal(tail.filter((c) => c.startsWith('references')).length, 10);
  assert.ok(tail.includes('references 0') && tail.includes('references 1'), tail.join(', '));
  // Accuracy at these three categories. Issue 14 asks for at least 97 %.
  // The page describes the demo with outdoor_hellinger (the paper's outdoor
  // parameters, Hellinger distance: the sixth round, docs/hellinger.md) and
  // its tree takes the cheapest of 10 2-means++ trials a split for sets of
  // up to 500 scans (the fifth round): 98.3 %, ARI 0.952, 295 of 300 scans
  // (the CLI's figure for what the page does: `placecat describe --preset
  // outdoor_hellinger` on `simulate --scene outdoor --seed 1`, then
  // `placecat cluster --method hkmeans --categories auto --seed 0
  // --restarts 10`). With the paper's `outdoor` it was 97.0 %, ARI 0.915.
  // Seed 1 is a development seed: this is a demonstration; the test seeds'
  // figures are in docs/hellinger.md. The errors are scans near a change of
  // place (docs/experiments.md section 4).
  const ev = await evaluation();
  t.diagnostic(`outdoor demo at 3 categories: accuracy ${ev.accuracy}, ARI ${ev.ari}; ${await text('#progress-text')}`);
  assert.equal(Math.round(ev.accuracy * 1000), 983, `accuracy ${ev.accuracy} at 3 categories`);
  assert.ok(ev.ari >= 0.95, `ARI ${ev.ari}`);
  // The paper's tree, one 2-means++ run a split, picked under "Splits":
  // 98.0 %, ARI 0.943 (tree seed 0, 294 of 300), then back.
  const splits = async (value, shown) => {
    await h.page.selectOption('#hk-splits', value);
    await h.page.waitForFunction((s) => document.querySelector('#cluster-status')?.textContent?.endsWith(s), shown);
  };
  try {
    await splits('1', "tree: one 2-means++ run a split (the paper's)");
    const paper = await evaluation();
    assert.deepEqual([Math.round(paper.accuracy * 1000), await categories()], [980, 3]);
    assert.ok(paper.ari >= 0.94 && paper.ari < ev.ari, `ARI ${paper.ari}`);
  } finally {
    await splits('auto', 'tree: the cheapest of 10 2-means++ trials a split');
  }
  assert.deepEqual(await evaluation(), ev, 'back to the page\'s default');
  // The map is a site, not a line: the scans' points spread both ways (the
  // old strip's would be about 60 m across 350 m: a ratio near 0.17).
  const site = await siteOnMap();
  assert.ok(site.pixels > 5000, `${site.pixels} site pixels on the map`);
  assert.ok(Math.min(site.width, site.height) / Math.max(site.width, site.height) > 0.4, `site ${site.width} x ${site.height} px`);
  assert.match(await text('#map-caption'), /^Trajectory map/);
  await h.page.screenshot({ path: join(ARTIFACTS, 'demo-outdoor.png') });
  // The README's picture of the page: PLACECAT_README_SHOT=1 refreshes it
  // (e.g. after the demo scene changes); the test never writes docs/
  // otherwise. The whole page: the accuracy and the legend of the
  // categories lie below the first screen.
  if (process.env.PLACECAT_README_SHOT === '1') await h.page.screenshot({ path: join(ROOT, 'docs', 'page-outdoor-demo.jpg'), type: 'jpeg', quality: 80, fullPage: true });
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
  // Another preset describes the demo again, and the note says the user
  // chose it. outdoor_near (the seventh round) on seed 1: the rule cuts 4
  // categories (docs/near-ranges-dev.json: 4 on every tree of seed 1, 98.7 %
  // named by majority), why the page keeps outdoor_hellinger for its demo.
  await afterRun(h.page, () => h.page.selectOption('#preset', 'outdoor_near'));
  assert.match(await text('#preset-note'), /^outdoor_hellinger suggested: .*; described with outdoor_near \(as chosen\)$/);
  assert.equal(await categories(), 4);
  assert.equal(Math.round((await evaluation()).accuracy * 1000), 987);
  await afterRun(h.page, () => h.page.selectOption('#preset', 'outdoor_hellinger'));
  assert.match(await text('#preset-note'), /^outdoor_hellinger suggested: .*\.$/);
  assert.deepEqual(await evaluation(), ev, 'the demo as it opened');
});

test('ten scans of one place are one category, not five', async () => {
  const ouster = Array.from({ length: 10 }, (_, i) => `ouster_os0_sequence/scan_00${i}.bin`);
  await load(ouster);
  assert.match(await text('#progress-text'), /^10 \/ 10 scans/);
  assert.equal(await categories(), 1);
  assert.match(await text('#cluster-status'), /^1 category from 10 scans; tree: the cheapest of 10 2-means\+\+ trials a split$/);
  // The rule's reason: no K from 2 on reaches a mean silhouette of 0.5.
  assert.match(await text('#cut-note'), /^1 category: the scans are alike under this descriptor, no grouping stands out \(best mean silhouette 0\.[0-4]\d, under 0\.5\)$/);
  await h.page.screenshot({ path: join(ARTIFACTS, 'one-place.png') });
});

test('the warehouse demo: 300 scans of an AGV route, described with the indoor preset, drawn as a site', async () => {
  await afterRun(h.page, () => h.page.click('#demo-warehouse'), 300000);
  assert.match(await text('#progress-text'), /^300 \/ 300 scans/);
  // The demo keeps the paper's indoor preset, as the paper's ArlaWarehouse
  // (the `warehouse` preset of docs/parts.md is the user's choice). Issue
  // 14's third round tried the demo under `warehouse` on development seeds
  // 1-10: the rule then finds 3 or 2 categories for 24 of 100 tree seeds
  // and mostly 4-6 (the large hall's main aisle and rack aisles apart;
  // seed 1, tree seed 0: 4, accuracy 98.0 % by majority names, ARI 0.46),
  // so the demo stays on indoor (docs/experiments.md section 4).
  assert.equal(await h.page.inputValue('#preset'), 'indoor');
  assert.match(await text('#preset-note'), /^indoor suggested: \d+ % of the points of scan_00000\.ply lie beyond 15 m \(under 14 %/);
  assert.match(await text('#map-caption'), /^Trajectory map/);
  assert.ok((await siteOnMap()).pixels > 5000, 'the halls drawn');
  // Measured: the rule finds no grouping here (best mean silhouette 0.35 on
  // seed 1; the true kinds' own mean silhouette is 0.27, and the large
  // hall's scans differ among themselves along the route nearly as much as
  // from the small hall's: examples/site_errors.rs warehouse); issue 18
  // found the same on independent warehouse data. At 3 categories the tree
  // reaches 50.7 % (docs/experiments.md section 4: 59-72 % with k-means
  // on the test seeds). A change in either shows here.
  assert.equal(await categories(), 1);
  assert.match(await text('#cut-note'), /^1 category: the scans are alike under this descriptor/);
  // The page says why three kinds are one category: the descriptor, not the rule.
  assert.match(await text('#accuracy'), /\. 3 true kinds, 1 category: under this descriptor these scans do not fall into clear groups, so no cut stands out; type 3 categories to see the best split$/);
  await h.page.screenshot({ path: join(ARTIFACTS, 'demo-warehouse.png') });
});

test('one scan is one category, said so; nothing breaks', async () => {
  await load(['kitti00/000094.bin']);
  assert.equal(await categories(), 1);
  assert.match(await text('#cluster-status'), /^One scan is one category/);
  // 26.1 % of its 121618 points lie beyond 15 m (measured outside the page).
  assert.match(await text('#preset-note'), /^outdoor_hellinger suggested: 26 % of the points of 000094\.bin lie beyond 15 m/);
  assert.equal(await h.page.inputValue('#preset'), 'outdoor_hellinger');
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
  assert.match(await text('#preset-note'), /^outdoor_hellinger suggested/);
  assert.match(await text('#map-caption'), /^Trajectory map/);
  assert.ok((await siteOnMap()).pixels > 500, 'KITTI scans drawn by their poses');
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
