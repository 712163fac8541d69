// End-to-end tests of the page in Debian's chromium (playwright-core).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { formatCsv, parseCsv } from '../../www/csv.js';
import { start, inkedPixels, afterRun, afterClustering, crashOn, ARTIFACTS, REAL } from './harness.mjs';

const groups = readFileSync(join(REAL, 'groups.csv'), 'utf8').trim().split('\n').slice(1).map((l) => l.split(',')[0]);
const tmp = mkdtempSync(join(tmpdir(), 'placecat-e2e-'));
const bad = join(tmp, 'broken.ply');
writeFileSync(bad, 'ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty float y\nproperty float z\nend_header\n\x00\x00');
const realFiles = groups.map((f) => join(REAL, f));

let h;
before(async () => { h = await start(); });
after(async () => { await h?.close(); });

const categories = () => h.page.$eval('#cluster-status', (e) => Number(e.dataset.categories));

async function loadReal() {
  await afterRun(h.page, () => h.page.setInputFiles('#files', [...realFiles, bad]));
}

test('real scans through the file input: progress, dendrogram, map, a bad file skipped', async () => {
  await loadReal();
  const text = await h.page.textContent('#progress-text');
  assert.match(text, /^19 \/ 19 scans/);
  assert.match(await h.page.textContent('#cluster-status'), /from 18 scans/);
  const errors = await h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent));
  assert.equal(errors.length, 1);
  assert.match(errors[0], /broken\.ply.*truncated/);
  assert.ok((await inkedPixels(h.page, 'dendrogram')) > 2000, 'dendrogram drawn');
  assert.ok((await inkedPixels(h.page, 'map')) > 500, 'strip drawn');
  await h.page.screenshot({ path: join(ARTIFACTS, 'real-files.png') });
});

test('dragging the threshold changes the number of categories', async () => {
  const before = await categories();
  const box = await h.page.locator('#dendrogram').boundingBox();
  // Near the bottom of the plot: a low threshold, many categories.
  await h.page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.78);
  await h.page.mouse.down();
  await h.page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.8, { steps: 3 });
  await h.page.mouse.up();
  const low = await categories();
  assert.ok(low > before, `${low} categories after dragging down from ${before}`);
  // Near the top: one category.
  await h.page.mouse.move(box.x + box.width / 2, box.y + 6);
  await h.page.mouse.down();
  await h.page.mouse.up();
  assert.equal(await categories(), 1);
  // And the numeric fields: a threshold, or a number of categories (which
  // then sets the threshold field to the cut's).
  await h.page.fill('#threshold', '0.3');
  await h.page.press('#threshold', 'Enter');
  assert.ok((await categories()) > 1);
  for (const k of [3, 2, 7]) {
    await h.page.fill('#categories', String(k));
    await h.page.press('#categories', 'Enter');
    assert.equal(await categories(), k);
    assert.equal(await h.page.$$eval('#legend li', (li) => li.length), k);
  }
  // A new seed keeps the number of categories asked for and re-cuts the
  // new tree. The page's default tree (ten trial splits for these 18 scans)
  // is the same for seeds 3 and 0 here, so this runs on the paper's tree
  // (one run a split, under "Splits"): on these scans (described with
  // outdoor_hellinger, which the first, a KITTI scan, suggests) 7 categories
  // are the cut at 0.1701 with seed 3 and at 0.1937 with seed 0 (`placecat
  // cluster --method hkmeans --categories 7 --seed 3|0`); a page that kept
  // the last threshold instead of re-cutting would show the same threshold
  // twice. (Under the paper's outdoor preset: 0.2561 and 0.2452; under the
  // indoor preset: 0.2122 and 0.2218, checked by disabling the re-cut,
  // which failed here with 0.2218 twice.)
  const thresholds = [];
  try {
    await h.page.selectOption('#hk-splits', '1');
    assert.equal(await categories(), 7, 'the paper\'s tree, cut into the 7 asked for');
    for (const seed of ['3', '0']) {
      await h.page.fill('#hk-seed', seed);
      await h.page.dispatchEvent('#hk-seed', 'change');
      assert.equal(await categories(), 7, `seed ${seed}`);
      thresholds.push(Number(await h.page.inputValue('#threshold')));
    }
  } finally {
    await h.page.selectOption('#hk-splits', 'auto');
  }
  assert.notEqual(thresholds[0], thresholds[1], `thresholds of 7 categories, seeds 3 and 0: ${thresholds}`);
  await h.page.fill('#threshold', '0.3');
  await h.page.press('#threshold', 'Enter');
  await h.page.screenshot({ path: join(ARTIFACTS, 'threshold-dragged.png') });
});

test('a name survives a reload and appears in the exported CSV', async () => {
  const input = h.page.locator('#legend input').first();
  await input.fill('loading dock');
  const size = Number((await h.page.locator('#legend .size').first().textContent()).split(' ')[0]);
  await h.page.reload();
  await h.page.waitForFunction(() => document.body.dataset.ready === 'true');
  await loadReal();
  await h.page.fill('#threshold', '0.3');
  await h.page.press('#threshold', 'Enter');
  const names = await h.page.$$eval('#legend input', (xs) => xs.map((x) => x.value));
  assert.ok(names.includes('loading dock'), `names after reload: ${names}`);
  const [download] = await Promise.all([h.page.waitForEvent('download'), h.page.click('#export-csv')]);
  const csv = readFileSync(await download.path(), 'utf8').trim().split('\n');
  assert.equal(csv[0], 'file,category');
  assert.equal(csv.length, 19);
  const rows = csv.slice(1).map((r) => r.split(','));
  assert.deepEqual(rows.map((r) => r[0]).sort(), groups.map((g) => g.split('/')[1]).sort());
  assert.equal(rows.filter((r) => r[1] === 'loading dock').length, size);
});

test('categories given one name share a colour in the legend and on the map', async () => {
  assert.ok((await categories()) >= 3, 'several categories at threshold 0.3');
  const swatches = () => h.page.$$eval('#legend .swatch', (xs) => xs.map((x) => x.style.background));
  // Exact pixels of a CSS rgb() colour on the map canvas.
  const onMap = (css) => h.page.evaluate((css) => {
    const [r, g, b] = css.match(/\d+/g).map(Number);
    const c = document.getElementById('map');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] === r && d[i + 1] === g && d[i + 2] === b && d[i + 3] === 255) n++;
    return n;
  }, css);
  const before = await swatches();
  assert.notEqual(before[2], before[1]);
  assert.ok((await onMap(before[2])) > 0, 'the third category has its own colour on the map');
  const inputs = h.page.locator('#legend input');
  await inputs.nth(1).fill('same place');
  await inputs.nth(2).fill('same place');
  let now = await swatches();
  assert.equal(now[2], before[1]);
  assert.equal(now[0], before[0]);
  assert.equal(await onMap(before[2]), 0, 'its own colour is gone from the map');
  await h.page.screenshot({ path: join(ARTIFACTS, 'shared-colour.png') });
  // Another name gives the colour back; no names leave every colour as it was.
  await inputs.nth(2).fill('elsewhere');
  now = await swatches();
  assert.equal(now[2], before[2]);
  await inputs.nth(1).fill('');
  await inputs.nth(2).fill('');
  assert.deepEqual(await swatches(), before);
});

test('the model exports, a malformed one is rejected, a good one loads', async () => {
  const [download] = await Promise.all([h.page.waitForEvent('download'), h.page.click('#export-model')]);
  const model = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.equal(model.format, 'placecat-model/1');
  assert.ok(model.categories.some((c) => c.name === 'loading dock'));
  const before = await h.page.$$eval('#legend input', (xs) => xs.map((x) => x.value));
  const broken = join(tmp, 'broken-model.json');
  writeFileSync(broken, '{"format": "placecat-model/1", "categories": 3}');
  await h.page.setInputFiles('#import', broken);
  await h.page.waitForFunction(() => /Rejected/.test(document.getElementById('import-status').textContent));
  assert.deepEqual(await h.page.$$eval('#legend input', (xs) => xs.map((x) => x.value)), before);
  assert.equal(await h.page.$eval('#classify', (e) => e.disabled), true);
  const good = join(tmp, 'model.json');
  writeFileSync(good, JSON.stringify(model));
  await h.page.setInputFiles('#import', good);
  await h.page.waitForFunction(() => /Model loaded/.test(document.getElementById('import-status').textContent));
  await h.page.setInputFiles('#classify', [join(REAL, 'pcl_room/room_scan1.pcd')]);
  await h.page.waitForFunction(() => /room_scan1\.pcd →/.test(document.getElementById('classified').textContent));
});

test('the categories CSV survives its own import: export, import, export give the same bytes for hostile names', async () => {
  const exportCsv = async () => {
    const [download] = await Promise.all([h.page.waitForEvent('download'), h.page.click('#export-csv')]);
    return readFileSync(await download.path(), 'utf8');
  };
  const importCsv = async (name, text) => {
    const file = join(tmp, name);
    writeFileSync(file, text);
    await h.page.setInputFiles('#import', file);
    await h.page.waitForFunction((n) => document.getElementById('import-status').textContent === `Names imported from ${n}.`, name);
  };
  // Every category renamed to a hostile name: a comma and quotes, a line break, non-ASCII.
  const hostile = ['lab, "wet"', 'first line\nsecond line', 'Küche – 2. Stock, 東京'];
  const rows = parseCsv(await exportCsv());
  const kinds = [...new Set(rows.slice(1).map((r) => r[1]))];
  assert.ok(kinds.length >= 3, `${kinds.length} categories`);
  const renamed = rows.map((r, i) => (i === 0 ? r : [r[0], hostile[kinds.indexOf(r[1]) % 3] + (kinds.indexOf(r[1]) >= 3 ? ` ${kinds.indexOf(r[1])}` : '')]));
  await importCsv('hostile.csv', formatCsv(renamed));
  const first = await exportCsv();
  assert.deepEqual(parseCsv(first), renamed, 'each scan exported with its hostile name');
  assert.match(first, /^file,category\n.*,"lab, ""wet"""\n/s);
  const names = await h.page.$$eval('#legend input', (xs) => xs.map((x) => x.value));
  assert.ok(names.includes('lab, "wet"'), `legend: ${names}`);
  await importCsv('exported.csv', first);
  assert.equal(await exportCsv(), first);
});

test('KITTI scans with a poses file draw a trajectory map', async () => {
  const dir = join(REAL, 'kitti00');
  // The pointer rests where the last test clicked (Export CSV, under the
  // legend). Scrolling the map into view slid a legend row under it, Chrome
  // highlighted that row's category on hover, and the map greyed the rest:
  // once in CI the first category's colour was gone (seen again in a
  // screenshot of bad_files.test.mjs). Parked in the page's corner, over
  // nothing that highlights, and the map read before any scroll.
  await h.page.mouse.move(1, 1);
  await afterRun(h.page, () => h.page.setInputFiles('#files', ['000094.bin', '000095.bin', '000198.bin', '000199.bin', 'poses.txt'].map((f) => join(dir, f))));
  assert.match(await h.page.textContent('#map-caption'), /Trajectory map/);
  assert.ok((await inkedPixels(h.page, 'map')) > 2000);
  // Click the first scan on the map (leftmost-bottom of the fitted path): its name shows.
  const hit = await h.page.evaluate(() => {
    const c = document.getElementById('map');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    // A fully opaque category-coloured pixel (the scan markers).
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] === 255 && d[i] === 0x4e && d[i + 1] === 0x79) return [(i / 4) % c.width, Math.floor(i / 4 / c.width), c.width, c.height];
    return null;
  });
  const seen = async () => h.page.evaluate(() => {
    const c = /** @type {HTMLCanvasElement} */ (document.getElementById('map'));
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const opaque = new Set();
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] === 255) opaque.add(((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]).toString(16));
    return `opaque colours ${[...opaque].slice(0, 8)}; legend highlight ${document.querySelector('#legend li.hl')?.dataset.category ?? 'none'}; ${document.getElementById('cluster-status').textContent}`;
  });
  assert.ok(hit, `a scan marker in the first category colour (${hit ? '' : await seen()})`);
  // In view next (the scroll may move the page under the parked pointer; the
  // pixels are read): the tests before may leave the page scrolled past the map's top.
  await h.page.locator('#map').scrollIntoViewIfNeeded();
  const box = await h.page.locator('#map').boundingBox();
  await h.page.mouse.click(box.x + ((hit[0] + 2) / hit[2]) * box.width, box.y + ((hit[1] + 2) / hit[3]) * box.height);
  assert.match(await h.page.textContent('#info'), /0001?9[459]\.bin: /);
  await h.page.screenshot({ path: join(ARTIFACTS, 'kitti-map.png') });
});

test('the demo runs with no files and shows accuracy against its ground truth', async () => {
  await afterRun(h.page, () => h.page.click('#demo-indoor'));
  assert.match(await h.page.textContent('#cluster-status'), /from 40 scans/);
  assert.match(await h.page.textContent('#accuracy'), /accuracy \d+\.\d %/);
  await h.page.screenshot({ path: join(ARTIFACTS, 'demo-indoor.png') });
});

test('k-means on the demo: "k-means++, best of 10" keeps the cheapest of ten runs; spectral seeding runs in a worker', async () => {
  await h.page.selectOption('#method', 'kmeans'); // k 5, k-means++
  const seed = async (n) => {
    await h.page.fill('#km-seed', String(n));
    await h.page.dispatchEvent('#km-seed', 'change');
  };
  const accuracy = async () => (await h.page.textContent('#accuracy'))?.match(/accuracy (\S+) %/)?.[1];
  // Seed 1's single k-means++ run merges two kinds (measured on this demo,
  // as tests/js/engine.test.mjs measures the engine); the best of 10 does not.
  try {
    await seed(1);
    assert.equal(await accuracy(), '75.0');
    await h.page.selectOption('#seeding', { label: 'k-means++, best of 10' });
    assert.equal(await accuracy(), '100.0');
    await h.page.selectOption('#seeding', { index: 0 });
    assert.equal(await accuracy(), '75.0', 'back to one run');
    // k-means from spectral clustering's groups (seed 1, measured with the engine in Node):
    // one corridor scan with another kind, where seed 1's k-means++ run merged two kinds.
    await afterClustering(h.page, () => h.page.selectOption('#seeding', 'spectral'));
    assert.equal(await accuracy(), '97.5');
    await h.page.waitForFunction(() => document.body.dataset.spectral === '0'); // its worker task ended
  } finally {
    // The tests after this one expect the page's default method.
    await h.page.selectOption('#seeding', { index: 0 });
    await seed(0);
    await h.page.selectOption('#method', 'hkmeans');
  }
});

test('spectral clustering on the demo, in a worker: its own k and seed, the page evaluates it', async () => {
  await afterClustering(h.page, () => h.page.selectOption('#method', 'spectral')); // k 5
  /** @param {string} k */
  const spectralK = (k) => afterClustering(h.page, async () => {
    await h.page.fill('#sp-k', k);
    await h.page.dispatchEvent('#sp-k', 'change');
  });
  try {
    assert.ok(await h.page.isVisible('#sp-k') && !(await h.page.isVisible('#km-seed')));
    // Measured on this demo (as tests/js/engine.test.mjs measures the engine):
    // one corridor scan with another kind at k 5, none at k 8.
    assert.match(await h.page.textContent('#accuracy'), /accuracy 97\.5 %/);
    await spectralK('8');
    assert.match(await h.page.textContent('#accuracy'), /accuracy 100\.0 %/);
    await spectralK('41');
    assert.match(await h.page.textContent('#cluster-status'), /k = 41 is more than the 40 scans/);
    // Two asked for at once: the later one is shown, the earlier is stopped.
    const data = () => h.page.evaluate(() => ({ ...document.body.dataset }));
    const stopped = Number((await data()).stopped || 0);
    await afterClustering(h.page, () => h.page.evaluate(() => {
      const k = /** @type {HTMLInputElement} */ (document.getElementById('sp-k'));
      for (const v of ['8', '5']) {
        k.value = v;
        k.dispatchEvent(new Event('change'));
      }
    }));
    assert.match(await h.page.textContent('#accuracy'), /accuracy 97\.5 %/);
    assert.equal(await categories(), 5);
    assert.equal(Number((await data()).stopped), stopped + 1, 'the clustering into 8 was stopped');
    // Spectral clustering into 8, then at once k-means into 5 (its labels come
    // at once): k-means' stay, the spectral clustering does not come back over them.
    const asked = await afterClustering(h.page, () => h.page.evaluate(() => {
      // Not from a field that has the focus: hidden with k-means' fields shown, it would
      // send a change of its own (a third clustering, after the spectral one came).
      /** @type {HTMLElement | null} */ (document.activeElement)?.blur();
      const k = /** @type {HTMLInputElement} */ (document.getElementById('sp-k'));
      const method = /** @type {HTMLSelectElement} */ (document.getElementById('method'));
      k.value = '8';
      k.dispatchEvent(new Event('change'));
      method.value = 'kmeans';
      method.dispatchEvent(new Event('change'));
    }));
    await h.page.waitForFunction(() => document.body.dataset.spectral === '0'); // none in flight
    assert.equal(await categories(), 5);
    assert.equal(Number((await data()).asked), asked, 'no other clustering was asked for');
    assert.doesNotMatch(await h.page.textContent('#cluster-status'), /[Ss]pectral/);
    await afterClustering(h.page, () => h.page.selectOption('#method', 'spectral')); // k 8
    assert.match(await h.page.textContent('#accuracy'), /accuracy 100\.0 %/);
    await spectralK('5');
    // Cancel while the worker clusters (clicked in the same task as the change,
    // so before any worker could answer): the status says so, the last labels stay,
    // and the next change clusters again in the replaced workers.
    await afterClustering(h.page, () => h.page.evaluate(() => {
      const k = /** @type {HTMLInputElement} */ (document.getElementById('sp-k'));
      k.value = '8';
      k.dispatchEvent(new Event('change'));
      document.getElementById('cancel')?.click();
    }));
    assert.match(await h.page.textContent('#cluster-status'), /^Spectral clustering cancelled/);
    assert.equal(await categories(), 5);
    await spectralK('8');
    assert.match(await h.page.textContent('#accuracy'), /accuracy 100\.0 %/);
  } finally {
    // The tests after this one expect the page's default method (and spectral k 5);
    // set without clustering, so that a failure above is the one reported.
    await h.page.$eval('#sp-k', (e) => { /** @type {HTMLInputElement} */ (e).value = '5'; });
    await h.page.selectOption('#method', 'hkmeans');
  }
});

test('the DBSCAN sweep shades cells by S and a click clusters with that cell', async () => {
  await h.page.selectOption('#method', 'dbscan');
  await h.page.click('#sweep');
  const rows = await h.page.$$eval('#sweep-table tr', (trs) => trs.map((tr) => tr.children.length));
  assert.ok(rows.length >= 4, `${rows.length} rows`);
  assert.ok(rows.every((n) => n === 6), `cells per row: ${rows}`); // epsilon + 5 min points
  assert.match(await h.page.textContent('#sweep-status'), /best S 0\.\d{3} at epsilon/);
  const best = h.page.locator('#sweep-table td.best');
  assert.equal(await best.count(), 1);
  const [eps, minPoints, score] = await best.evaluate((td) => [td.dataset.eps, td.dataset.minPoints, Number(td.dataset.score)]);
  const scores = await h.page.$$eval('#sweep-table td', (tds) => tds.map((td) => Number(td.dataset.score)));
  assert.equal(Math.max(...scores), score);
  await best.click();
  assert.equal(await h.page.inputValue('#eps'), eps);
  assert.equal(await h.page.inputValue('#minpts'), minPoints);
  // The page's own evaluation of that clustering: S (or the ARI, when no
  // scan is noise, for then S = ARI) is the cell's.
  const text = await h.page.textContent('#accuracy');
  assert.ok(text.includes(`S ${score.toFixed(3)}`) || (!text.includes(' S ') && text.includes(`ARI ${score.toFixed(3)}`)), `${text} vs S ${score}`);
  await h.page.screenshot({ path: join(ARTIFACTS, 'dbscan-sweep.png') });
  await h.page.selectOption('#method', 'hkmeans');
});

test('a worker that dies mid-file is replaced, the file reported, the rest described', async () => {
  await crashOn(h.page, '000095.bin');
  await afterRun(h.page, () => h.page.setInputFiles('#files', realFiles));
  await crashOn(h.page, null);
  const errors = await h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent));
  assert.equal(errors.length, 1);
  assert.match(errors[0], /000095\.bin: the worker failed/);
  assert.match(await h.page.textContent('#cluster-status'), /from 17 scans/);
  // The replaced worker works: describe again (another list, so the input
  // fires), all 18 good files.
  await afterRun(h.page, () => h.page.setInputFiles('#files', [...realFiles, bad]));
  assert.match(await h.page.textContent('#cluster-status'), /from 18 scans/);
});

test('cancel in the middle keeps the scans described so far, clustered', async () => {
  await afterRun(h.page, async () => {
    await h.page.click('#demo-outdoor');
    await h.page.waitForFunction(() => /^([5-9]|\d\d+) \//.test(document.getElementById('progress-text').textContent));
    await h.page.click('#cancel');
  });
  assert.match(await h.page.textContent('#progress-text'), /\(cancelled\)/);
  const n = Number((await h.page.textContent('#cluster-status')).match(/from (\d+) scans/)[1]);
  assert.ok(n >= 5 && n < 300, `${n} scans kept`);
  assert.ok((await inkedPixels(h.page, 'dendrogram')) > 1000);
});

test('a reload during processing keeps the results so far and the names', async () => {
  await afterRun(h.page, () => h.page.click('#demo-indoor'));
  await h.page.locator('#legend input').first().fill('pantry');
  await h.page.click('#demo-indoor');
  await h.page.waitForFunction(() => /^([5-9]|\d\d+) \//.test(document.getElementById('progress-text').textContent));
  // What the progress said is stored: the page shows it once saved.
  const shown = Number((await h.page.textContent('#progress-text')).match(/^(\d+) \//)[1]);
  await h.page.reload();
  await h.page.waitForFunction(() => document.body.dataset.ready === 'true');
  const info = await h.page.textContent('#info');
  const m = info.match(/Restored (\d+) of 40 scans/);
  assert.ok(m, info);
  assert.ok(Number(m[1]) >= shown, `${m[1]} restored, ${shown} shown before the reload`);
  assert.match(await h.page.textContent('#cluster-status'), new RegExp(`from ${m[1]} scans`));
  const names = await h.page.evaluate(() => localStorage.getItem('placecat:names:demo-indoor-1-8'));
  assert.match(names, /pantry/);
  await h.page.screenshot({ path: join(ARTIFACTS, 'restored-after-reload.png') });
});

test('a session saved with a withdrawn preset restores with it, names and all; the menu does not offer it', async () => {
  await afterRun(h.page, () => h.page.click('#demo-indoor'));
  await h.page.locator('#legend input').first().fill('weights');
  // A session saved before the preset was withdrawn: its stored preset.
  await h.page.evaluate(() => new Promise((resolve, reject) => {
    const open = indexedDB.open('placecat', 1);
    open.onerror = () => reject(open.error);
    open.onsuccess = () => {
      const t = open.result.transaction(['sessions'], 'readwrite');
      const store = t.objectStore('sessions');
      store.get('last').onsuccess = (e) => store.put({ ...e.target.result, preset: 'indoor_object_types' });
      t.oncomplete = () => { open.result.close(); resolve(undefined); };
      t.onerror = () => reject(t.error);
    };
  }));
  await h.page.reload();
  await h.page.waitForFunction(() => document.body.dataset.ready === 'true');
  assert.match(await h.page.textContent('#info'), /Restored 40 of 40 scans/);
  assert.equal(await h.page.inputValue('#preset'), 'indoor_object_types');
  assert.match(await h.page.inputValue('#advanced'), /object_layout/);
  const offered = await h.page.$$eval('#preset option', (os) => os.filter((o) => !o.hidden).map((o) => o.value));
  assert.ok(offered.includes('indoor_objects') && !offered.includes('indoor_object_types'), offered.join());
  assert.match(await h.page.evaluate(() => localStorage.getItem('placecat:names:demo-indoor-1-8')), /weights/);
});

const HOLD = 20000; // long beside the 40 scans of the new run, even on a loaded machine
/**
 * Start the outdoor demo (300 scans: the workers compute its Delta matrix,
 * held HOLD ms), do `action` during that step and return how long until the
 * page finished a run after it (ms).
 * @param {() => Promise<void>} action
 */
async function duringMatrixStep(action) {
  try {
    await h.page.evaluate((ms) => { globalThis.holdDeltaRowsMs = ms; globalThis.deltaRowsHeld = 0; }, HOLD);
    await h.page.click('#demo-outdoor');
    await h.page.waitForFunction(() => globalThis.deltaRowsHeld > 0, null, { timeout: 120000 });
    const t0 = Date.now();
    await afterRun(h.page, action);
    return Date.now() - t0;
  } finally {
    await h.page.evaluate(() => { globalThis.holdDeltaRowsMs = 0; });
  }
}

test('a new run started while the workers compute the Delta matrix cancels that step and finishes with its own scans', async () => {
  const took = await duringMatrixStep(() => h.page.click('#demo-indoor'));
  // Queued behind the held matrix tasks, the 40 scans would take more than HOLD.
  assert.ok(took < HOLD * 0.6, `the new run took ${took} ms`);
  assert.match(await h.page.textContent('#progress-text'), /^40 \/ 40 scans.*\(done\)/);
  assert.match(await h.page.textContent('#cluster-status'), /from 40 scans/);
  // The pool's clocks of this run are its own 40 scans', none of the old matrix tasks.
  const types = await h.page.evaluate(() => /** @type {any} */ (performance.getEntriesByName('placecat:pool').at(-1)).detail.map((c) => c.type));
  assert.deepEqual([...new Set(types)], ['simulate']);
  assert.equal(types.length, 40);
  // A run begins by forgetting the earlier runs' measures (the superseded one's matrix step included).
  const counts = await h.page.evaluate(() => ['placecat:pool', 'placecat:run', 'placecat:describe', 'placecat:matrix'].map((n) => performance.getEntriesByName(n).length));
  assert.deepEqual(counts, [1, 1, 1, 0]);
});

test('Cancel while the workers compute the Delta matrix: the page computes it and the run ends at once', async () => {
  const took = await duringMatrixStep(() => h.page.click('#cancel'));
  assert.ok(took < HOLD * 0.6, `the run ended ${took} ms after Cancel`);
  assert.match(await h.page.textContent('#progress-text'), /^300 \/ 300 scans/);
  assert.match(await h.page.textContent('#cluster-status'), /from 300 scans/);
});

test('no console errors and no requests beyond the page origin', async () => {
  assert.deepEqual(h.problems, []);
  // No test hook ships: the page exposes nothing on window for tests.
  assert.equal(await h.page.evaluate(() => typeof window.placecat), 'undefined');
  const foreign = h.requests.filter((u) => !u.startsWith(h.url) && !u.startsWith('blob:') && !u.startsWith('data:'));
  assert.deepEqual(foreign, []);
});
