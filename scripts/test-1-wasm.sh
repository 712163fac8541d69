#!/usr/bin/env bash
# The wasm API tests in headless Chromium and in Node (tests/web.rs,
# tests/node.rs), with Debian's chromium and chromedriver.
set -euo pipefail
cd "$(dirname "$0")/.."
export CHROMEDRIVER=${CHROMEDRIVER:-/usr/bin/chromedriver}
# chromedriver starts Chromium itself; these flags keep it off the network
# and working as root in a container.
export WASM_BINDGEN_TEST_TIMEOUT=${WASM_BINDGEN_TEST_TIMEOUT:-300}
echo "--- wasm-pack test --headless --chrome (tests/web.rs)"
wasm-pack test --release --headless --chrome -- --no-default-features --test web
echo "--- wasm-pack test --node (tests/node.rs)"
wasm-pack test --release --node -- --no-default-features --test node
