#!/usr/bin/env bash
# Build the npm package if needed and put its web build beside the page.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-pkg.sh
rm -rf www/pkg
mkdir -p www/pkg
cp pkg/web/placecat.js pkg/web/placecat_bg.wasm pkg/web/placecat.d.ts www/pkg/
