// The PLY parsers compared, run the same way in Node and in Chromium
// (bundled by esbuild for the browser): placecat's wasm readScan, three.js
// PLYLoader, @loaders.gl/ply. Each parses the same bytes; median of runs.
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { parse } from '@loaders.gl/core';
import { PLYLoader as LoadersGlPly } from '@loaders.gl/ply';

/** A PLY of n lidar-like points: float x, y, z, intensity. */
export function makePly(n, binary) {
  const header = `ply\nformat ${binary ? 'binary_little_endian' : 'ascii'} 1.0\nelement vertex ${n}\nproperty float x\nproperty float y\nproperty float z\nproperty float intensity\nend_header\n`;
  let seed = 12345;
  const rand = () => ((seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 4294967296);
  const head = new TextEncoder().encode(header);
  if (binary) {
    const body = new Float32Array(n * 4);
    for (let i = 0; i < n; i++) {
      const r = 2 + rand() * 40, a = rand() * 2 * Math.PI, e = (rand() - 0.7) * 0.5;
      body.set([r * Math.cos(a), r * Math.sin(a), r * Math.sin(e), rand() * 255], i * 4);
    }
    const out = new Uint8Array(head.length + body.byteLength);
    out.set(head);
    out.set(new Uint8Array(body.buffer), head.length);
    return out;
  }
  const lines = [header];
  for (let i = 0; i < n; i++) {
    const r = 2 + rand() * 40, a = rand() * 2 * Math.PI, e = (rand() - 0.7) * 0.5;
    lines.push(`${(r * Math.cos(a)).toFixed(4)} ${(r * Math.sin(a)).toFixed(4)} ${(r * Math.sin(e)).toFixed(4)} ${(rand() * 255).toFixed(1)}\n`);
  }
  return new TextEncoder().encode(lines.join(''));
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** Points per second (median of `runs`) for each parser on `bytes`. */
export async function compare(placecat, bytes, n, runs = 5) {
  const parsers = {
    placecat: async () => {
      const s = placecat.readScan(bytes, 'bench.ply');
      const c = s.count;
      s.free();
      return c;
    },
    'three.js PLYLoader': async () => {
      const buf = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
      return new PLYLoader().parse(buf).attributes.position.count;
    },
    '@loaders.gl/ply': async () => {
      const buf = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
      const mesh = await parse(buf, LoadersGlPly, { worker: false });
      return mesh.attributes.POSITION.value.length / 3;
    },
  };
  const out = {};
  for (const [name, fn] of Object.entries(parsers)) {
    const times = [];
    for (let r = 0; r < runs + 1; r++) {
      const t0 = performance.now();
      const got = await fn();
      const dt = performance.now() - t0;
      if (got !== n) throw new Error(`${name} read ${got} of ${n} points`);
      if (r > 0) times.push(dt); // the first run warms up
    }
    out[name] = n / (median(times) / 1000);
  }
  return out;
}
