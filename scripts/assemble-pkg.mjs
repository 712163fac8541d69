// Writes pkg/package.json (version from Cargo.toml), pkg/README.md (the
// package's own, for JS users: js/README.md) and the size note used by the
// README.
import { readFileSync, writeFileSync, copyFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';

const cargo = readFileSync('Cargo.toml', 'utf8');
const field = (name) => cargo.match(new RegExp(`^${name} = "(.*)"`, 'm'))[1];

const pkg = {
  name: 'placecat',
  version: field('version'),
  description: field('description'),
  license: field('license'),
  keywords: ['lidar', 'point-cloud', 'place-categorisation', 'clustering', 'ndt', 'wasm'],
  type: 'module',
  main: './node/placecat.js',
  module: './bundler/placecat.js',
  types: './bundler/placecat.d.ts',
  // Each condition brings its own declarations: Node and bundlers get the
  // API without the web target's init(), which they do not export.
  exports: {
    '.': {
      node: { types: './node/placecat.d.ts', default: './node/placecat.js' },
      browser: { types: './bundler/placecat.d.ts', default: './bundler/placecat.js' },
      default: { types: './bundler/placecat.d.ts', default: './bundler/placecat.js' },
    },
    './web': { types: './web/placecat.d.ts', default: './web/placecat.js' },
    './bundler': { types: './bundler/placecat.d.ts', default: './bundler/placecat.js' },
    './node': { types: './node/placecat.d.ts', default: './node/placecat.js' },
    './web/placecat_bg.wasm': './web/placecat_bg.wasm',
    './package.json': './package.json',
  },
  files: ['web/', 'bundler/', 'node/', 'README.md'],
  // The bundler build runs start-up code (wasm instantiation) on import.
  sideEffects: ['./bundler/placecat.js', './bundler/placecat_bg.js', './node/placecat.js'],
};
writeFileSync('pkg/package.json', JSON.stringify(pkg, null, 2) + '\n');
// wasm-pack's nodejs output is CommonJS; mark its folder so.
writeFileSync('pkg/node/package.json', JSON.stringify({ type: 'commonjs' }) + '\n');
copyFileSync('js/README.md', 'pkg/README.md');

const wasm = readFileSync('pkg/web/placecat_bg.wasm');
const gz = gzipSync(wasm, { level: 9 }).length;
console.error(`[build-pkg] placecat_bg.wasm: ${(wasm.length / 1024).toFixed(0)} KiB, ${(gz / 1024).toFixed(0)} KiB gzipped`);
