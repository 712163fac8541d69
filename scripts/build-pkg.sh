#!/usr/bin/env bash
# Build the npm package into pkg/: the wasm for the web, bundler and nodejs
# targets (release), and one package.json whose `exports` picks the right
# one. Skips the wasm build when pkg/ is newer than every source file.
set -euo pipefail
cd "$(dirname "$0")/.."

newer() { [ -n "$(find "$@" -newer pkg/package.json -print -quit)" ]; }
if [ "${1:-}" != "--force" ] && [ -f pkg/package.json ] && ! newer src Cargo.toml Cargo.lock; then
  # The wasm is current; only the package's files may need writing again
  # (package.json, the README).
  if newer scripts/assemble-pkg.mjs js/README.md; then
    node scripts/assemble-pkg.mjs
  else
    echo "[build-pkg] pkg/ is up to date" >&2
  fi
  exit 0
fi
rm -rf pkg
for target in web bundler nodejs; do
  dir=$target; [ "$target" = nodejs ] && dir=node
  echo "[build-pkg] wasm-pack build --target $target" >&2
  wasm-pack --quiet build --release --target "$target" --out-dir "pkg/$dir" --out-name placecat --no-pack -- --no-default-features
  # wasm-pack writes these per folder; the package has one of each.
  rm -f "pkg/$dir/.gitignore" "pkg/$dir/package.json" "pkg/$dir/README.md" "pkg/$dir/LICENSE"*
done
node scripts/assemble-pkg.mjs
