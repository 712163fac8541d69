// Writes the package README's example files into the app: every ```js
// block whose first line is `// PATH` or `// PATH: what it is` (e.g.
// `// src/worker.js: ...`) becomes PATH under the app folder, verbatim.
// Usage: node from-readme.mjs README APP_DIR
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';

const [readme, app] = process.argv.slice(2);
const blocks = readFileSync(readme, 'utf8').split('```js\n').slice(1).map((b) => b.split('```')[0]);
const wrote = [];
for (const block of blocks) {
  const path = block.match(/^\/\/ ([\w./-]+\.m?js)(:|\n)/)?.[1];
  if (!path || path === 'example.mjs') continue;
  mkdirSync(dirname(join(app, path)), { recursive: true });
  writeFileSync(join(app, path), block);
  wrote.push(path);
}
const want = ['vite.config.js', 'src/worker.js', 'src/main.js'];
for (const w of want) if (!wrote.includes(w)) throw new Error(`${readme} has no \`// ${w}\` example`);
console.log(`from ${readme}: ${wrote.join(', ')}`);
