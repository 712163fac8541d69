// The page's bag choices (www/bag.js) and the names and poses of bag clouds
// in the page's state (www/state.js, www/files.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { thinningOf, isCloudType, isPoseType, hasPoses } from '../../www/bag.js';
import { baseName, isBag, isScan } from '../../www/files.js';
import * as S from '../../www/state.js';

test('the default thinning is one cloud a metre with poses, every cloud without; the wording says which', () => {
  assert.deepEqual(thinningOf('auto', 7, true), { everyMetres: 1, thinning: 'one cloud every 1 m along the path' });
  assert.deepEqual(thinningOf('auto', 7, false), { every: 1, thinning: 'every cloud (the bag has no poses)' });
  assert.deepEqual(thinningOf('metres', 2.5, true), { everyMetres: 2.5, thinning: 'one cloud every 2.5 m along the path' });
  assert.deepEqual(thinningOf('metres', 2.5, false), { every: 1, thinning: 'every cloud (no poses to measure 2.5 m by)' });
  assert.deepEqual(thinningOf('metres', -1, true).everyMetres, 1);
  assert.deepEqual(['every 2nd cloud', 'every 3rd cloud', 'every 11th cloud', 'every 12th cloud', 'every 21st cloud', 'every cloud'],
    [2, 3, 11, 12, 21, 0].map((n) => thinningOf('every', n, true).thinning));
});

test('bag types as ROS 1 and rosbag2 spell them', () => {
  assert.ok(isCloudType('sensor_msgs/PointCloud2') && isCloudType('sensor_msgs/msg/PointCloud2'));
  assert.ok(!isCloudType('sensor_msgs/PointCloud'));
  assert.ok(isPoseType('nav_msgs/msg/Odometry') && isPoseType('tf2_msgs/TFMessage'));
  assert.ok(!isPoseType('geometry_msgs/PoseStamped'));
  // As the reader chooses: the only odometry topic, else tf; two odometry topics and no tf give none.
  const t = (...types) => types.map((type) => ({ type }));
  assert.deepEqual([t('nav_msgs/Odometry'), t('nav_msgs/Odometry', 'nav_msgs/Odometry'), t('nav_msgs/Odometry', 'nav_msgs/Odometry', 'tf2_msgs/TFMessage'), t()].map(hasPoses),
    [true, false, true, false]);
  // .db3 is taken as a bag to be refused with its message, not passed over.
  assert.ok(isBag('a/run.BAG') && isBag('x.mcap') && isScan('x.mcap') && isBag('x.db3') && !isBag('metadata.yaml'));
  assert.ok(['a.las', 'b.LAZ', 'c.e57', 'd.ply'].every(isScan) && !isScan('notes.txt') && !isScan('e57.json'));
});

test('a bag cloud keeps its topic in its name; only the folders before the bag go', () => {
  assert.equal(baseName('data/run.bag:/os/points:000012'), 'run.bag:/os/points:000012');
  assert.equal(baseName('a/b/c.pcd'), 'c.pcd');
  assert.equal(baseName('site/s.e57:Level 1/Scan 3'), 's.e57:Level 1/Scan 3');
  const r = (name, pose) => ({ name, pose, preview: new Float32Array(3) });
  const s = S.finishRun(S.initialState(), [[r('run.bag:/p:000000', { position: [0, 0, 0], yaw: 0 }), r('run.bag:/p:000002', { position: [1, 0, 0], yaw: 0 })], undefined]);
  assert.deepEqual(s.scans.map((x) => x.name), ['run.bag:/p:000000', 'run.bag:/p:000002']);
  // Their poses from the bag make the map, with headings.
  const p = S.posesOf(s);
  assert.deepEqual([p.usePoses, p.drawSite, p.poses[1]?.position], [true, true, [1, 0, 0]]);
  // One cloud without a pose: no map, and the page says why.
  const part = S.posesOf(S.finishRun(S.initialState(), [[r('run.bag:/p:000000', undefined), r('run.bag:/p:000002', { position: [1, 0, 0], yaw: 0 })]]));
  assert.equal(part.usePoses, false);
  assert.match(part.note, /1 of 2 scans have no pose/);
});

test('a bag input becomes a bag task with its topic and thinning', () => {
  const t = S.taskOf({ name: 'run.bag', bag: { topic: '/p', hasPoses: true, everyMetres: 1, thinning: '' } }, /** @type {any} */ ({}));
  assert.deepEqual([t.type, t.topic, t.every, t.everyMetres], ['bag', '/p', undefined, 1]);
});
