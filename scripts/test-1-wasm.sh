#!/usr/bin/env bash
# The wasm API tests in headless Chromium and in Node (tests/web.rs,
# tests/node.rs), with Debian's chromium and chromedriver, and the library's
# #[wasm_bindgen_test] unit tests in Node.
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
echo "--- wasm-pack test --node (the library's wasm unit tests: the wasm voxel index)"
# In a debug build: the release profile's LTO made this 2 min 16 s against
# 43 s (loaded machine); the release wasm is checked end to end by
# tests/wasm_api/descriptor_digests.rs above.
wasm-pack test --node -- --no-default-features --lib
