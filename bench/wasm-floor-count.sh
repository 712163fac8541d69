#!/usr/bin/env bash
# Instructions per point of each stage of examples/wasm_floor.rs, natively
# and in each wasm build given (docs/wasm-floor.md, "How it was measured"):
# valgrind counts the whole process for N calls of a stage, less the mean
# of three runs with N = 0 (start-up, compiling, loading the file), divided
# by N x the file's points. N is 30 for grid, describe and total, 100 for
# the small stages. Slow: about 20 minutes per file for two wasm builds.
#   bench/wasm-floor-count.sh FILE NATIVE_BIN WASM...
# e.g. bench/wasm-floor-count.sh tests/data/real/kitti00/000094.bin \
#   target/release/examples/wasm_floor before.wasm now.wasm
set -euo pipefail
file=$1 native=$2
shift 2
# Instructions executed by one run: BUILD STAGE N.
count() {
  local build=$1 stage=$2 n=$3 run
  if [ "$build" = native ]; then
    run=("$native")
  else
    # --smc-check: V8 writes the code it runs; --single-threaded keeps its
    # compiler threads (and their share of the count) out.
    run=(--smc-check=all-non-file node --no-liftoff --single-threaded bench/wasm-floor.mjs "$build")
  fi
  valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
    "${run[@]}" "$file" "$stage" "$n" 2>&1 >/dev/null |
    sed -n 's/.*I *refs: *//p' | tr -d ,
}
points=$("$native" "$file" time 0 | sed 's/.*"points":\([0-9]*\).*/\1/')
echo "$file: $points points; instructions per point"
for build in native "$@"; do
  base=$(( ($(count "$build" grid 0) + $(count "$build" grid 0) + $(count "$build" grid 0)) / 3 ))
  for stage_n in read:100 grid:30 classify:100 align:100 hist:100 describe:30 total:30; do
    stage=${stage_n%%:*} n=${stage_n##*:}
    ir=$(count "$build" "$stage" "$n")
    echo "$build $stage $(echo "scale=1; ($ir - $base) / ($n * $points)" | bc)"
  done
done
