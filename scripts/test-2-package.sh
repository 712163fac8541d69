#!/usr/bin/env bash
# Consumption test: pack the built npm package, install the tarball into a
# fresh project, and use it from a plain Node ESM script.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tarball=$(bash scripts/pack-pkg.sh "$work")
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund --silent "$tarball"
cat > consume.mjs <<'JS'
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { describePoints, describeScan, DescriptorSet, readScan, version } from 'placecat';

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
// Bytes as an ArrayBuffer (what fetch and File.arrayBuffer() give), and the
// same points from memory: one descriptor.
const buf = readFileSync(`${real}/${files[0]}`);
const arrayBuffer = buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.byteLength);
const fromBuffer = readScan(arrayBuffer, files[0]);
assert.equal(fromBuffer.count, 112586);
const again = new DescriptorSet(undefined, 'indoor');
again.add(describeScan(arrayBuffer, files[0]));
again.add(describePoints(fromBuffer.positions(), 'room in memory'));
assert.equal(again.delta(0, 1), 0);
assert.throws(() => describePoints(new Float32Array(4), 'four.xyz'), /^Error: four\.xyz: .*4 numbers is not a multiple of 3/);
assert.throws(() => readScan('room.pcd', 'room.pcd'), /^Error: room\.pcd: the bytes must be a Uint8Array or an ArrayBuffer, not a string/);
console.log(`placecat ${version()} from the packed tarball: labels ${labels.join(',')}`);
JS
node consume.mjs "$root/tests/data/real"

# The READMEs' Node examples, verbatim, beside the files they name: docs
# that run. The package's own README (js/README.md, shipped as the
# package's README.md) and the repository's.
real="$root/tests/data/real"
ln -s "$real"/pcl_room/room_scan1.pcd "$real"/pcl_room/room_scan2.pcd \
  "$real"/velodyne_pair/251370668.pcd "$real"/velodyne_pair/251371071.pcd .
first_js_block() {
  node -e '
const text = require("fs").readFileSync(process.argv[1], "utf8");
process.stdout.write(text.split("```js\n")[1].split("```")[0]);
' "$1"
}
cmp -s "$root/js/README.md" node_modules/placecat/README.md || { echo "the package does not ship js/README.md as its README"; exit 1; }
first_js_block "$root/js/README.md" > pkg-readme-example.mjs
echo "--- the package README's Node example"
out=$(node pkg-readme-example.mjs)
echo "$out" | tail -3
# What its comments promise: rooms apart from street, and the scan in
# memory classified as street.
echo "$out" | grep -q "^\[ 0, 0, 1, 1 \]" || { echo "expected labels [ 0, 0, 1, 1 ]"; exit 1; }
echo "$out" | grep -q "name: 'street'" || { echo "expected the points in memory classified as street"; exit 1; }
first_js_block "$root/README.md" > readme-example.mjs
echo "--- the repository README's Node example"
node readme-example.mjs >/dev/null

# The .d.ts promises what the objects hold: every interface the API returns
# has exactly the keys of the object that comes back, and null (not
# undefined) where a value may be missing.
cat > shapes.mjs <<'JS'
import { readFileSync } from 'node:fs';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import * as pc from 'placecat';

const dir = createRequire(import.meta.url).resolve('placecat/package.json').replace(/package\.json$/, '');
const dts = readFileSync(`${dir}node/placecat.d.ts`, 'utf8');
// One API for all three targets: the web's declarations are the others'
// plus init().
assert.equal(readFileSync(`${dir}bundler/placecat.d.ts`, 'utf8'), dts, 'bundler and node declare the same API');
assert.ok(readFileSync(`${dir}web/placecat.d.ts`, 'utf8').startsWith(dts), 'web declares the same API, then init()');
// Keys declared `key?:` may be left out (serde skips them at their
// default, e.g. DescriptorParams' ndt_weight and parts for the paper's
// presets); every other declared key must be there, and nothing else.
const declared = (name, optional = false) => {
  const body = dts.match(new RegExp(`export interface ${name} \\{([^}]*)\\}`))?.[1];
  assert.ok(body, `interface ${name} in the .d.ts`);
  const lines = body.replace(/\/\*\*[\s\S]*?\*\//g, '').split('\n').map((l) => l.trim().match(/^(\w+)(\??):/)).filter(Boolean);
  return lines.filter((m) => optional || !m[2]).map((m) => m[1]).sort();
};
const same = (name, obj) => {
  const keys = Object.keys(obj).sort();
  const all = declared(name, true);
  assert.deepEqual(keys.filter((k) => !all.includes(k)), [], `${name}: keys the .d.ts does not declare`);
  assert.deepEqual(declared(name).filter((k) => !keys.includes(k)), [], `${name}: declared keys missing`);
};

const real = process.argv[2];
const set = new pc.DescriptorSet(undefined, 'indoor');
const scans = ['pcl_room/room_scan1.pcd', 'pcl_room/room_scan2.pcd', 'velodyne_pair/251370668.pcd'].map((f) => pc.describeScan(readFileSync(`${real}/${f}`), f, undefined, 'indoor', 100));
for (const s of scans) set.add(s);
same('Summary', scans[0].summary());
same('DescriptorParams', pc.presetParams('outdoor'));
// Parameters come back Required<DescriptorParams>: every declared key, also
// those the core's JSON leaves out at their defaults (ndt_weight, parts,
// scale), for the paper's presets as for free_space and a median-scaled set.
// (Every preset's keys are checked with the Preset literals below.)
const allKeys = declared('DescriptorParams', true);
// sensor_height is null when not given, and the .d.ts says so (tsify would
// otherwise declare a bare number).
assert.match(dts.match(/export interface DescriptorParams \{[^}]*\}/)[0], /sensor_height\?: number \| null;/, 'sensor_height declared number | null');
const indoor = pc.presetParams('indoor');
const indoorKeys = Object.keys(indoor);
assert.deepEqual([indoor.ndt_weight, indoor.parts, indoor.scale, indoor.sensor_height], [1, [], 'fixed', null], 'the defaults the core leaves out');
// ... in the struct's order, as the page's parameter box shows them.
assert.deepEqual([indoorKeys[0], ...indoorKeys.slice(-4)], ['preset', 'ndt_weight', 'parts', 'scale', 'sensor_height'], 'the struct\'s order');
const medianSet = new pc.DescriptorSet({ scale: 'median' }, 'free_space');
assert.deepEqual(Object.keys(medianSet.params()).sort(), allKeys, 'free_space params scaled by medians');
assert.equal(medianSet.params().scale, 'median');
// A given sensor height comes back as given, and a bad one is an Error
// that names the field.
assert.equal(pc.validateParams({ sensor_height: 1.15 }, 'indoor_columns').sensor_height, 1.15);
assert.throws(() => pc.validateParams({ sensor_height: -1 }, 'indoor_columns'), /sensor_height/);
assert.deepEqual(pc.validateParams(pc.presetParams('indoor_columns'), 'indoor'), pc.presetParams('indoor_columns'), 'params round-trip through validateParams');
medianSet.free();
same('DescriptorParams', set.params());
same('KMeansResult', set.kmeans(2, 'stride', 0));
const tree = set.hkmeans(0);
same('Cut', tree.cutK(2));
const nodes = tree.nodes();
same('TreeNode', nodes[0]);
assert.equal(nodes[0].parent, null, 'the root has parent null');
const ev = pc.DescriptorSet.evaluate(['room', 'room', 'street'], tree.cutK(2).labels);
same('Evaluation', ev);
same('Confusion', ev.confusion);
const sweep = set.dbscanSweep([0.5], [2]);
same('SweepPoint', sweep[0]);
assert.equal(sweep[0].ari, null, 'no truth: ari is null');
const model = set.buildModel(Int32Array.from(tree.cutK(2).labels), [[0, 'a'], [1, 'b']]);
same('Classification', model.classify(scans[0]));
same('CategorySummary', model.categories()[0]);
same('KMedoidsResult', set.kmedoids(2, 0));
same('SpectralResult', set.spectral(2, 0));
const simulated = new pc.Simulator('indoor', 1, 1).scan(0);
same('SimulatedScan', simulated);
assert.ok(simulated.bytes instanceof Uint8Array, 'a simulated scan comes as PLY bytes');
const poses = pc.parsePoses('a.pcd,1,2\nb.pcd,3,4\n', 'poses.csv');
same('Poses', poses);
same('Pose', poses.poses[0]);
assert.equal(poses.poses[0].time, null, 'a CSV pose has time null');
// A ROS bag served a range at a time (as a worker serves File.slice).
const bag = readFileSync(`${real}/../bags/ros1_corridor.bag`);
const readBag = (offset, length) => bag.subarray(offset, offset + length);
const topics = pc.bagTopics(bag.length, readBag, 'corridor.bag');
same('TopicInfo', topics[0]);
assert.deepEqual(topics.map((t) => `${t.name} ${t.count}`), ['/odom 2', '/points 2']);
const clouds = new pc.BagClouds(bag.length, readBag, 'corridor.bag');
const cloud = clouds.next();
assert.equal(cloud.name, 'corridor.bag:/points:000000');
same('Pose', cloud.pose());
assert.deepEqual(clouds.next().pose().position, [0.5, 0.25, 0]);
assert.equal(clouds.next(), undefined, 'two clouds, then undefined');
// An E57 survey the same way: four stations with their poses.
const e57 = readFileSync(`${real}/../survey/survey.e57`);
const stations = new pc.E57Scans(e57.length, (offset, length) => e57.subarray(offset, offset + length), 'survey.e57');
assert.equal(stations.total, 4);
const office = (stations.next(), stations.next());
assert.equal(office.name, 'survey.e57:office');
same('Pose', office.pose());
assert.deepEqual(office.pose().position, [10, 2, 0.5]);
assert.equal(scans[0].pose(), null, 'a file has no pose');
// The hand-written literal types name only values the API takes.
const literals = (name) => dts.match(new RegExp(`export type ${name} = ([^;]*);`))[1].split('|').map((x) => JSON.parse(x.trim()));
for (const p of literals('Preset')) {
  assert.equal(pc.presetParams(p).preset, p);
  assert.deepEqual(Object.keys(pc.presetParams(p)).sort(), allKeys, `${p}: every declared key`);
}
assert.deepEqual(literals('Preset'), pc.presetNotes().map((n) => n.name), 'the Preset type names every preset, in the core\'s order');
for (const s of literals('Seeding')) assert.equal(set.kmeans(2, s, 0).labels.length, 3, s);
console.log('the .d.ts interfaces match the objects returned');
JS
node shapes.mjs "$real"

# And a TypeScript user's code compiles against them in strict mode
# (wasm-bindgen's classes declare [Symbol.dispose]: lib esnext.disposable).
# Node resolution gets the node declarations, which need nothing more.
cat > typed.ts <<'TS'
import { BagClouds, DescriptorSet, E57Scans, Simulator, bagTopics, describePoints, describeScan, presetParams, type DescribedScan, type Cut, type Evaluation, type SweepPoint, type DescriptorParams } from 'placecat';
const params: Required<DescriptorParams> = presetParams('indoor');
const set = new DescriptorSet({ voxel_size: params.voxel_size }, 'indoor');
const cut: Cut = set.hkmeans(0).cutK(2);
const ev: Evaluation = DescriptorSet.evaluate(['a'], cut.labels);
const best: SweepPoint | undefined = set.dbscanSweep(set.epsilonGrid(), [2]).find((p) => (p.score ?? 0) > 0.5);
const firstName: string | null = ev.confusion.cluster_class[0][1];
const radius: number = set.buildModel(Int32Array.from(cut.labels), { 0: 'room' }).categories()[0].radius;
const km = set.kmeans(2, 'stride', 0).labels.length + new Simulator('indoor', 1).length;
const medoid: number = set.kmedoids(2, 0).medoids[0];
const bytes: Uint8Array = new Simulator('indoor', 1, 1).scan(0).bytes;
const fromPoints: number = describePoints(new Float32Array(9), 'three points', { voxel_size: 1 }).summary().points;
const fromBuffer: string = describeScan(new ArrayBuffer(0), 'empty.ply').format;
const clouds = new BagClouds(3, (offset: number, length: number) => new Uint8Array(length), 'a.bag', '/points', 1);
const next: DescribedScan | undefined = clouds.next();
const topicCount: number = bagTopics(3, () => new ArrayBuffer(3), 'a.bag')[0].count;
const station: DescribedScan | undefined = new E57Scans(3, (offset: number, length: number) => new Uint8Array(length), 'a.e57', null, 'indoor', 100).next();
export const used = [next?.pose()?.position[0], station?.name, topicCount, fromPoints, fromBuffer, cut.threshold, ev.accuracy, best?.epsilon, firstName, radius, km, medoid, bytes.length];
TS
echo "--- no public method returns or takes 'any' (the raw wasm exports aside)"
if grep -vE '^\s*readonly [A-Za-z0-9_]+: \(' node_modules/placecat/web/placecat.d.ts | grep -nE ': any\b'; then
  echo "the .d.ts above leaves a public type as any"; exit 1
fi
echo "--- tsc --strict on a TypeScript consumer"
tsc_with() { local lib=$1; shift; "$root/node_modules/.bin/tsc" --noEmit --strict --target es2022 --lib "$lib" --module nodenext --moduleResolution nodenext "$@"; }
tsc() { tsc_with es2022,esnext.disposable "$@"; }
tsc typed.ts
# Node has no init(): importing it from 'placecat' is an error, not a crash
# at run time. The browser build has it (and takes WebAssembly types: dom).
cat > node-init.ts <<'TS'
import init from 'placecat';
init();
TS
if out=$(tsc node-init.ts); then echo "node-init.ts compiled: Node was given the web declarations"; exit 1; fi
echo "$out" | grep -q "node-init.ts(2,1): error TS2349" || { echo "$out"; exit 1; }
cat > web-init.ts <<'TS'
import init, { DescriptorSet } from 'placecat/web';
await init();
export const n: number = new DescriptorSet(undefined, 'indoor').length;
TS
tsc_with es2022,esnext.disposable,dom --module es2022 --moduleResolution bundler web-init.ts
# ... and a typo in a seeding or a result field does not.
cat > typo.ts <<'TS'
import { DescriptorSet } from 'placecat';
const set = new DescriptorSet(undefined, 'indoor');
set.kmeans(2, 'strided', 0);
export const t = set.hkmeans(0).cutK(2).threshhold;
TS
if out=$(tsc typo.ts); then echo "typo.ts compiled"; exit 1; fi
echo "$out" | grep -q "typo.ts(3,15): error TS2345" || { echo "$out"; exit 1; }
echo "$out" | grep -q "typo.ts(4,41): error TS2551" || { echo "$out"; exit 1; }
echo "typo.ts is rejected: $(echo "$out" | grep -c error) errors"
