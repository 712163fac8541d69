#!/usr/bin/env bash
# The package in a Vite app: the package README's vite.config.js, page and
# worker (tests/vite-app/from-readme.mjs takes them from js/README.md)
# with Vite from npm and placecat from the packed tarball, run on the dev
# server and as a production build in headless Chromium (tests/vite-app/run.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tarball=$(bash scripts/pack-pkg.sh "$work")
cp -r tests/vite-app "$work/app"
node tests/vite-app/from-readme.mjs js/README.md "$work/app"
cd "$work/app"
echo "--- npm install vite and the placecat tarball"
npm install --no-audit --no-fund --loglevel=error "$tarball"
echo "--- the app on vite's dev server, then built, in headless Chromium"
node run.mjs "$root"
