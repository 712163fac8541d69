#!/usr/bin/env bash
# Consumption test: pack the built npm package, install the tarball into a
# fresh project, and use it from a plain Node ESM script.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-pkg.sh
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd pkg && npm pack --silent --pack-destination "$work" >/dev/null)
tarball=$(ls "$work"/placecat-*.tgz)
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund --silent "$tarball"
cat > consume.mjs <<'JS'
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { describeScan, DescriptorSet, version } from 'placecat';

const real = process.argv[2];
const files = ['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd', 'velodyne_pair/251370668.pcd', 'velodyne_pair/251371071.pcd'];
const set = new DescriptorSet(undefined, 'indoor');
for (const f of files) {
  const scan = describeScan(readFileSync(`${real}/${f}`), f, undefined, 'indoor', 1000);
  set.add(scan);
}
const { labels } = set.kmeans(2, 'stride', 0);
assert.equal(labels.length, 4);
assert.equal(labels[0], labels[1], 'the two room scans share a category');
assert.equal(labels[2], labels[3], 'the two velodyne scans share a category');
assert.notEqual(labels[0], labels[2]);
const cut = set.hkmeans(0).cutK(2).labels;
assert.equal(cut.length, 4);
assert.ok(cut[0] === cut[1] && cut[2] === cut[3] && cut[0] !== cut[2], `hkmeans cut into 2: ${cut}`);
// The DBSCAN sweep with ground truth: some cell puts room and street apart.
const sweep = set.dbscanSweep(set.epsilonGrid(), [2], ['room', 'room', 'street', 'street']);
assert.ok(sweep.some((p) => p.clusters === 2 && p.score === 1), `sweep: ${JSON.stringify(sweep)}`);
assert.throws(() => set.kmeans(0, 'stride', 0), /k must be at least 1/);
console.log(`placecat ${version()} from the packed tarball: labels ${labels.join(',')}`);
JS
node consume.mjs "$root/../shared/data/real"

# The README's Node example, verbatim, beside the files it names: docs that run.
real="$root/../shared/data/real"
ln -s "$real"/pcl_room/room_scan1.pcd "$real"/pcl_room/room_scan2.pcd \
  "$real"/velodyne_pair/251370668.pcd "$real"/velodyne_pair/251371071.pcd .
node -e '
const text = require("fs").readFileSync(process.argv[1], "utf8");
const block = text.split("```js\n")[1].split("```")[0];
require("fs").writeFileSync("readme-example.mjs", block);
' "$root/README.md"
echo "--- the README's Node example"
node readme-example.mjs
