#!/usr/bin/env bash
# The page's JavaScript: a type check of www/*.js (JSDoc types) against the
# generated www/pkg/placecat.d.ts, then the unit tests in tests/js/ (state,
# CSV, and the engine on the wasm Node build in pkg/node/). Builds pkg/ and
# www/pkg/ first when they are missing or older than the Rust sources.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-www.sh
[ -d node_modules/typescript ] || npm ci --no-audit --no-fund --loglevel=error
echo "--- tsc -p tsconfig.json (www/*.js against www/pkg/placecat.d.ts)"
node_modules/.bin/tsc -p tsconfig.json
echo "--- node --test tests/js/"
node --test tests/js/
