#!/usr/bin/env bash
# The long fuzz runs: each target for SECONDS (default 600) on one core.
# Findings land in fuzz/artifacts/<target>/; copy minimised crashers into
# tests/fuzz_regressions/ so the normal suite keeps them.
set -uo pipefail
cd "$(dirname "$0")"
secs=${SECONDS_PER_TARGET:-600}
[ -d corpus ] || bash seed-corpus.sh
for t in ${TARGETS:-ply pcd kitti poses describe json las e57}; do
  echo "=== $t for ${secs}s"
  cargo +nightly fuzz run "$t" "corpus/$t" -- -max_total_time="$secs" -rss_limit_mb=2048 -timeout=10 -max_len=65536 2>&1 | grep -E "^#[0-9]+.*DONE|Done [0-9]+ runs|SUMMARY|panicked|ERROR|Test unit written" || true
done
