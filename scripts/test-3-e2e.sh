#!/usr/bin/env bash
# Browser end-to-end tests of the page (playwright-core driving Debian's
# chromium). Screenshots go to test-artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-www.sh
node --test --test-concurrency=1 tests/e2e/
