// ROS bags through the page's file input (tests/data/bags, written by
// rosbags: make_walk_bags.py and make_bags.py): each bag is read in slices
// in a worker and yields its clouds as scans, named as the CLI names them,
// thinned one a metre by default (the walk's clouds lie 0.56 m apart: 0, 2,
// 4, 6 of 8 are kept), with the bag's odometry as the map's poses. A bag
// with no cloud topic, one with a truncated chunk and rosbag2 SQLite
// storage (.db3) are listed with their messages while the others are
// described.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { start, afterRun, inkedPixels, ARTIFACTS, ROOT } from './harness.mjs';

const BAGS = join(ROOT, 'tests/data/bags');
const bag = (name) => join(BAGS, name);
const kept = (b, idx) => idx.map((i) => `${b}:/points:${String(i).padStart(6, '0')}`);

let h;
/** The files of the first test, dropped again after the reload. @type {string[]} */
let dropped = [];
before(async () => { h = await start(); });
after(async () => { await h?.close(); });

/** The exported categories CSV as [file, category] rows. */
async function exported() {
  const [download] = await Promise.all([h.page.waitForEvent('download'), h.page.click('#export-csv')]);
  return readFileSync(await download.path(), 'utf8').trim().split('\n').slice(1).map((r) => r.split(','));
}

const text = (sel) => h.page.textContent(sel);
const errors = () => h.page.$$eval('#errors li', (li) => li.map((x) => x.textContent));

test('two bags (ROS 1, rosbag2) and two damaged ones: the clouds kept a metre apart are described with their poses, the damage listed', async () => {
  const db3 = join(mkdtempSync(join(tmpdir(), 'placecat-e2e-')), 'old_0.db3');
  writeFileSync(db3, 'SQLite format 3\0');
  dropped = [...['walk.bag', 'walk.mcap', 'bad_no_cloud.bag', 'bad_truncated.bag'].map(bag), db3];
  await afterRun(h.page, () => h.page.setInputFiles('#files', dropped));
  // Progress counts the clouds read: 8 + 8 + 5 (truncated) + 1 for each bag that cannot be opened.
  assert.match(await text('#progress-text'), /^23 \/ 23 clouds.*\(done\)/);
  const names = (await exported()).map(([f]) => f);
  assert.deepEqual(names, [...kept('walk.bag', [0, 2, 4, 6]), ...kept('walk.mcap', [0, 2, 4, 6])]);
  assert.match(await text('#cluster-status'), /from 8 scans/);
  const note = await text('#bag-note');
  assert.match(note, /walk\.bag, \/points: 4 of 8 clouds kept \(one cloud every 1 m along the path\)/);
  assert.match(note, /walk\.mcap, \/points: 4 of 8 clouds kept/);
  assert.match(note, /bad_no_cloud\.bag: not read/);
  const errs = await errors();
  assert.ok(errs.some((e) => e.startsWith('bad_no_cloud.bag: ROS bag: no sensor_msgs/PointCloud2 topic; topics: /odom')), errs.join('\n'));
  assert.ok(errs.some((e) => e.startsWith('old_0.db3: ROS bag: rosbag2 SQLite storage (.db3) is not read, only MCAP')), errs.join('\n'));
  assert.ok(errs.some((e) => /^bad_truncated\.bag: ROS bag: topic \/points: chunk at byte \d+: lz4 chunk cannot be decompressed/.test(e)), errs.join('\n'));
  // The truncated bag's other clouds were read (too sparse for a descriptor, and said so).
  assert.ok(errs.some((e) => e.startsWith('bad_truncated.bag:/points:000004: no descriptor')), errs.join('\n'));
  assert.ok(errs.every((e) => !e.startsWith('walk.')), errs.join('\n'));
  // The bags' odometry places the scans: a trajectory map, not the strip.
  assert.match(await text('#map-caption'), /^Trajectory map/);
  assert.ok((await inkedPixels(h.page, 'map')) > 500);
  await h.page.screenshot({ path: join(ARTIFACTS, 'bags.png') });
  assert.deepEqual(h.problems, []);
});

test('the thinning is the user\'s: every cloud, every 3rd, then back to the default, with the same topic', async () => {
  await afterRun(h.page, () => h.page.selectOption('#bag-thin', 'every')); // N is 1: every cloud
  const all = [0, 1, 2, 3, 4, 5, 6, 7];
  assert.deepEqual((await exported()).map(([f]) => f), [...kept('walk.bag', all), ...kept('walk.mcap', all)]);
  assert.match(await text('#bag-note'), /walk\.bag, \/points: 8 of 8 clouds kept \(every cloud\)/);
  const step = (v) => h.page.$eval('#bag-step', (e, v) => { e.value = v; e.dispatchEvent(new Event('change')); }, v);
  await afterRun(h.page, () => step('3'));
  assert.deepEqual((await exported()).map(([f]) => f), [...kept('walk.bag', [0, 3, 6]), ...kept('walk.mcap', [0, 3, 6])]);
  assert.match(await text('#bag-note'), /walk\.bag, \/points: 3 of 8 clouds kept \(every 3rd cloud\)/);
  await step('1');
  await afterRun(h.page, () => h.page.selectOption('#bag-thin', 'auto'));
  assert.equal((await exported()).length, 8);
});

test('a category name given to bag clouds survives a reload and the same bags dropped again', async () => {
  await h.page.locator('#legend input').first().fill('corridor');
  await h.page.locator('#legend input').first().dispatchEvent('change');
  const before = await exported();
  assert.ok(before.some(([, c]) => c === 'corridor'), before.join('\n'));
  await h.page.reload();
  await h.page.waitForFunction(() => document.body.dataset.ready === 'true');
  // Names are kept per data set, the files dropped (as for scan files).
  await afterRun(h.page, () => h.page.setInputFiles('#files', dropped));
  assert.deepEqual(await exported(), before);
});

test('a bag with two cloud topics asks which to read, listing them; files dropped meanwhile drop the question', async () => {
  const runsBefore = Number(await h.page.evaluate(() => document.body.dataset.runs));
  await h.page.setInputFiles('#files', [bag('two_cloud_topics.bag')]);
  await h.page.waitForSelector('#bag-topic-box:not([hidden])');
  await afterRun(h.page, () => h.page.setInputFiles('#files', [bag('walk.bag')]));
  assert.equal(await h.page.isHidden('#bag-topic-box'), true);
  assert.match(await text('#cluster-status'), /from 4 scans/);
  await h.page.setInputFiles('#files', [bag('two_cloud_topics.bag')]);
  await h.page.waitForSelector('#bag-topic-box:not([hidden])');
  assert.match(await text('#bag-topic-file'), /two_cloud_topics\.bag has 2 PointCloud2 topics/);
  const options = await h.page.$$eval('#bag-topic option', (o) => o.map((x) => x.value));
  assert.deepEqual(options, ['/front/points', '/rear/points']);
  await h.page.selectOption('#bag-topic', '/rear/points');
  await afterRun(h.page, () => h.page.click('#bag-topic-read'));
  // Its one small cloud has too few points for a descriptor: the error names the topic read.
  const errs = await errors();
  assert.ok(errs.some((e) => e.startsWith('two_cloud_topics.bag:/rear/points:000000: no descriptor')), errs.join('\n'));
  assert.match(await text('#bag-note'), /two_cloud_topics\.bag, \/rear\/points: 0 of 1 clouds kept/);
  // The question dropped earlier never started a run of its own.
  assert.equal(await h.page.evaluate(() => document.body.dataset.runs), String(runsBefore + 2));
});
