// The defaults the page suggests from the data: the preset from far
// points, the dendrogram's axis, the map's site subsample.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rangeShare, suggestPreset, suggestionText, siteSubsample, choiceReason } from '../../www/suggest.js';
import { axis, defaultScale, logFloor, heightLabel } from '../../www/scale.js';

test('the share of points beyond 15 m is horizontal, skips non-finite points, and picks the preset at 14 %', () => {
  // (9, 12, 50): 15 m away horizontally however high, not beyond; (11, 11, 0): 15.6 m.
  const xyz = Float32Array.from([9, 12, 50, 11, 11, 0, NaN, 0, 0, 0, 16, -1]);
  assert.deepEqual(rangeShare(xyz), { far: 2 / 3, points: 3 });
  assert.deepEqual(rangeShare(new Float32Array(0)), { far: 0, points: 0 });
  assert.equal(suggestPreset(0.14), 'outdoor_hellinger');
  assert.equal(suggestPreset(0.139), 'indoor');
  assert.equal(suggestionText({ preset: 'outdoor_hellinger', far: 0.256, from: 'a.bin' }), 'outdoor_hellinger suggested: 26 % of the points of a.bin lie beyond 15 m (14 % or more: open space)');
  assert.equal(suggestionText({ preset: 'indoor', far: 0.003, from: 'b.pcd' }), 'indoor suggested: 0 % of the points of b.pcd lie beyond 15 m (under 14 %: a room or hall)');
});

test('the site subsample keeps at most 400 x, y pairs within 30 m, evenly strided', () => {
  // 3000 points at x = i / 100 (0 to 29.99 m), y = 1, and 10 beyond 30 m.
  const xyz = Float32Array.from({ length: 3010 * 3 }, (_, i) => (i % 3 === 0 ? (i < 9000 ? i / 300 : 40) : i % 3 === 1 ? 1 : 0));
  const site = siteSubsample(xyz);
  assert.equal(site.length, 2 * 375); // stride 8 over 3000 points
  assert.deepEqual([...site.slice(0, 4)], [0, 1, 0.07999999821186066, 1]);
  assert.ok(Math.max(...site.filter((_, i) => i % 2 === 0)) < 30);
  assert.equal(siteSubsample(Float32Array.from([1, 2, 3])).length, 2);
});

test('each axis maps 0 to the bottom, the top to 1, and back (dragging works in every scale)', () => {
  for (const scale of /** @type {const} */ (['linear', 'sqrt', 'log'])) {
    const a = axis(scale, 16, 0.01);
    assert.equal(a.at(0), 0, scale);
    assert.ok(Math.abs(a.at(16) - 1) < 1e-12, scale);
    for (const h of [0.01, 0.05, 0.3, 2, 15]) assert.ok(Math.abs(a.height(a.at(h)) - h) < 1e-9 * 16, `${scale} ${h}`);
  }
  // On the log axis the lowest merges are well above the leaves: a merge at
  // 0.05 under a root at 16 sits 0.3 % up a linear axis, 6 % up a square
  // root one, 24 % up the log one (lowest merge 0.01).
  assert.ok(axis('linear', 16, 0.01).at(0.05) < 0.004);
  assert.ok(axis('sqrt', 16, 0.01).at(0.05) > 0.05);
  assert.ok(axis('log', 16, 0.01).at(0.05) > 0.24);
});

test('the default scale follows the root / median merge ratio; the log floor is the lowest merge', () => {
  const tree = (heights) => heights.map((height) => ({ height, children: [1] }));
  assert.deepEqual(defaultScale(tree([1, 0.5, 0.3]), 1), { scale: 'linear', ratio: 2, merges: 3 });
  assert.equal(defaultScale(tree([16, 0.5, 0.3]), 16).scale, 'sqrt');
  assert.equal(defaultScale(tree([16, 0.05, 0.01]), 16).scale, 'log');
  assert.equal(logFloor(tree([16, 0.05, 0.01, 0]), 16.8), 0.01);
  assert.equal(heightLabel(0), '0');
  assert.equal(heightLabel(16.08), '16.1');
  assert.equal(heightLabel(0.01234), '0.0123');
});

test('the first cut says why: the silhouette that decided one category or more, or the rule\'s best score', () => {
  assert.equal(choiceReason({ k: 1, rule: 'silhouette_gap', one_category: 0.384 }), 'the scans are alike under this descriptor, no grouping stands out (best mean silhouette 0.38, under 0.5)');
  assert.equal(choiceReason({ k: 3, rule: 'silhouette_gap', one_category: 0.71 }), "the gap statistic's choice (best mean silhouette 0.71)");
  assert.equal(choiceReason({ k: 4, rule: 'silhouette_gap' }), "the silhouette gap rule's best score");
  assert.equal(choiceReason({ k: 1, rule: 'gap' }), 'the gap rule finds no structure to split');
});
