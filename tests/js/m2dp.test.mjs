// M2DP on the wasm build against the native one: its part values on every
// real file of tests/data/real, as the Node build in pkg/node/ computes
// them, must have the FNV-1a digests (of their f32 bits) that the native
// build recorded in tests/fixtures/parts_digests.json (tests/it/parts.rs,
// x86-64 Linux, glibc's libm). M2DP turns its points by f64 cos/sin/atan2
// and takes nalgebra's SVD (hypot): std calls the C library's libm
// natively and a Rust port of musl's libm in wasm32, so the two builds
// could differ in a last bit; this test says whether they do.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';

const wasm = createRequire(import.meta.url)('../../pkg/node/placecat.js');
const real = new URL('../data/real/', import.meta.url);
const digests = JSON.parse(readFileSync(new URL('../fixtures/parts_digests.json', import.meta.url), 'utf8'));

/** FNV-1a (64 bits) over the little-endian bytes of the values as f32, as tests/it/parts.rs. */
function fnv(values) {
  const bytes = new Uint8Array(new Float32Array(values).buffer);
  let h = 0xcbf29ce484222325n;
  for (const b of bytes) h = BigInt.asUintN(64, (h ^ BigInt(b)) * 0x100000001b3n);
  return h.toString(16).padStart(16, '0');
}

test('M2DP on wasm gives the native build\'s values bit for bit on the 18 real scans', () => {
  const files = readFileSync(new URL('groups.csv', real), 'utf8').trim().split('\n').slice(1).map((l) => l.split(',')[0]);
  assert.equal(files.length, 18);
  const differ = [];
  for (const file of files) {
    const scan = wasm.describeScan(readFileSync(new URL(file, real)), file, { ndt_weight: 0, parts: [{ kind: 'm2dp', weight: 1 }] }, 'indoor');
    const parts = JSON.parse(scan.descriptorJson()).parts;
    scan.free();
    assert.equal(parts.length, 1);
    assert.equal(parts[0].kind, 'm2dp');
    assert.equal(parts[0].values.length, 384, 'two bins a value, 192 values');
    const want = digests[`M2dp/${file}`];
    assert.ok(want, `no native digest for ${file}`);
    if (fnv(parts[0].values) !== want) differ.push(file);
  }
  assert.deepEqual(differ, [], 'M2DP differs between wasm and native');
});

test('the digest is that of the values: one changed bit changes it', () => {
  const v = [0.25, 0.75];
  const w = new Float32Array(v);
  new Uint32Array(w.buffer)[0] ^= 1;
  assert.notEqual(fnv(v), fnv([...w]));
});
