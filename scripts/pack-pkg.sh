#!/usr/bin/env bash
# Build pkg/ if stale and pack it into DIR; prints the tarball's path. Used by
# the tests that install the package as a user would (test-2-package.sh,
# test-2b-vite.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-pkg.sh
(cd pkg && npm pack --silent --pack-destination "$1" >/dev/null)
ls "$1"/placecat-*.tgz
