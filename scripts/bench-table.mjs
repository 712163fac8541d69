// docs/benchmarks.md (+ .json) from criterion's results in target/criterion:
// throughput per stage, and ratios against the peers measured in the same
// run (ply-rs, the fixed-stride copy floor). Run after `cargo bench --bench stages`.
import { readFileSync, readdirSync, existsSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const root = new URL('..', import.meta.url).pathname;
const crit = join(root, 'target/criterion');
// BENCH_BASELINE: the criterion folder of a previous build's run on the
// same inputs (e.g. main built in another target dir and run alternately
// with this one): its medians become the "previous" column and the ratio.
const baselineDir = process.env.BENCH_BASELINE;
const rows = [];
const previous = new Map();
function walk(dir, into) {
  for (const e of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    if (e.isDirectory() && e.name === 'new' && existsSync(join(p, 'estimates.json'))) {
      const est = JSON.parse(readFileSync(join(p, 'estimates.json'), 'utf8'));
      const meta = JSON.parse(readFileSync(join(p, 'benchmark.json'), 'utf8'));
      const ns = est.median.point_estimate;
      const elements = meta.throughput?.Elements ?? null;
      into({ id: meta.full_id, group: meta.group_id, func: meta.function_id, param: meta.value_str, seconds: ns / 1e9, elements, perSecond: elements ? elements / (ns / 1e9) : null });
    } else if (e.isDirectory() && e.name !== 'report') walk(p, into);
  }
}
walk(crit, (r) => rows.push(r));
if (baselineDir) walk(baselineDir, (r) => previous.set(r.id, r));
rows.sort((a, b) => a.id.localeCompare(b.id));
const find = (func, param) => rows.find((r) => r.func === func && r.param === param);
const m = (x) => (x / 1e6).toFixed(1);
const lines = ['# Native benchmarks', '', `criterion medians on this machine (\`cargo bench --bench stages\`, then \`node scripts/bench-table.mjs\`), ${new Date().toISOString().slice(0, 10)}. Single-threaded except the Delta matrix (rayon, all cores).`, ''];
lines.push('## Reading PLY: placecat against ply-rs and the memory floor (same bytes, same run)', '', '| file | placecat Mpts/s | ply-rs Mpts/s | stride-copy floor Mpts/s | placecat / ply-rs | placecat / floor |', '|---|---|---|---|---|---|');
for (const size of ['100k', '1M']) for (const fmt of ['ply_binary', 'ply_ascii']) {
  const me = find(`${fmt}/placecat`, size);
  if (!me) continue;
  const peer = find(`${fmt}/ply-rs`, size);
  const floor = fmt === 'ply_binary' ? find(`${fmt}/stride_copy_floor`, size) : null;
  lines.push(`| ${fmt.replace('ply_', '')} ${size} | ${m(me.perSecond)} | ${peer ? m(peer.perSecond) : '-'} | ${floor ? m(floor.perSecond) : '-'} | ${peer ? (me.perSecond / peer.perSecond).toFixed(1) + 'x' : '-'} | ${floor ? (me.perSecond / floor.perSecond).toFixed(2) : '-'} |`);
}
const ndtRows = rows.filter((r) => r.group === 'parts' && r.func === 'ndt_histogram');
if (ndtRows.length) {
  // Every part kind the bench describes (PartKind::ALL), then the
  // indoor_clutter parts together; throughput in points a second.
  lines.push('', '## Descriptor parts against the NDT histogram (docs/parts.md; same scans, same run, one core)', '', '| part | scan | median time | throughput | NDT histogram time | NDT histogram throughput | part / NDT (time) |', '|---|---|---|---|---|---|---|');
  for (const ndt of ndtRows) for (const r of rows.filter((x) => x.group === 'parts' && x.param === ndt.param && x.func !== 'ndt_histogram')) {
    lines.push(`| ${r.func} | ${r.param} | ${(r.seconds * 1e3).toFixed(2)} ms | ${m(r.perSecond)} Mpts/s | ${(ndt.seconds * 1e3).toFixed(2)} ms | ${m(ndt.perSecond)} Mpts/s | ${(r.seconds / ndt.seconds).toFixed(2)} |`);
  }
  const paper = rows.find((r) => r.group === 'parts_distance' && r.func === 'delta_matrix_paper');
  const plus = rows.find((r) => r.group === 'parts_distance' && r.func === 'delta_matrix_indoor_plus');
  if (paper && plus) lines.push('', `Delta matrix of ${paper.param} scans (all cores): paper ${(paper.seconds * 1e3).toFixed(1)} ms, indoor_plus ${(plus.seconds * 1e3).toFixed(1)} ms (${(plus.seconds / paper.seconds).toFixed(2)}x).`);
  const hellinger = rows.find((r) => r.group === 'parts_distance' && r.func === 'delta_matrix_hellinger');
  if (paper && hellinger) lines.push('', `The same NDT histograms under the Hellinger distance (outdoor_hellinger's, docs/hellinger.md): ${(hellinger.seconds * 1e3).toFixed(1)} ms (${(hellinger.seconds / paper.seconds).toFixed(2)}x the paper's).`);
}
// Spectral clustering against k-means++ and the tree on the same matrix
// (src/cluster/spectral: its dense eigen-decomposition grows with n³).
const spectral = rows.filter((r) => r.group === 'cluster' && r.func === 'spectral_k5');
if (spectral.length) {
  lines.push('', '## Spectral clustering against k-means and the tree (same descriptors, same run, one core)', '', '| scans | spectral | k-means++ | tree | spectral / k-means++ | spectral / tree |', '|---|---|---|---|---|---|');
  for (const r of spectral.sort((a, b) => Number(a.param) - Number(b.param))) {
    const km = find('kmeans_pp_k5', r.param);
    const tree = find('hkmeans_tree', r.param);
    if (!km || !tree) continue;
    const t = (s) => (s < 1 ? (s * 1e3).toFixed(2) + ' ms' : s.toFixed(2) + ' s');
    lines.push(`| ${r.param} | ${t(r.seconds)} | ${t(km.seconds)} | ${t(tree.seconds)} | ${(r.seconds / km.seconds).toFixed(0)}x | ${(r.seconds / tree.seconds).toFixed(0)}x |`);
  }
}
const time = (s) => (s < 1e-3 ? (s * 1e6).toFixed(1) + ' µs' : s < 1 ? (s * 1e3).toFixed(2) + ' ms' : s.toFixed(2) + ' s');
const withBaseline = previous.size > 0;
lines.push('', '## Every stage', '');
if (withBaseline) lines.push(`"previous": the same benchmark of the build in \`${baselineDir}\`, run on this machine in the same session; speed-up = previous time / this time.`, '');
lines.push(withBaseline ? '| benchmark | median time | throughput | previous | speed-up |' : '| benchmark | median time | throughput |', withBaseline ? '|---|---|---|---|---|' : '|---|---|---|');
for (const r of rows) {
  const unit = r.group === 'cluster' && r.func === 'delta_matrix' ? 'pairs/s' : r.group === 'cluster' ? 'scans/s' : 'points/s';
  const cells = [r.id, time(r.seconds), r.perSecond ? m(r.perSecond) + ` M${unit}` : '-'];
  if (withBaseline) {
    const p = previous.get(r.id);
    cells.push(p ? time(p.seconds) : '-', p ? (p.seconds / r.seconds).toFixed(2) + 'x' : '-');
  }
  lines.push(`| ${cells.join(' | ')} |`);
}
writeFileSync(join(root, 'docs/benchmarks.md'), lines.join('\n') + '\n');
writeFileSync(join(root, 'docs/benchmarks.json'), JSON.stringify(withBaseline ? rows.map((r) => ({ ...r, previousSeconds: previous.get(r.id)?.seconds ?? null })) : rows, null, 2) + '\n');
console.log(lines.join('\n'));
