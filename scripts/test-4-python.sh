#!/usr/bin/env bash
# The Python package (python/): build the abi3 wheel with the README's
# command, install it into a virtual environment with the test tools, and
# run pytest (python/tests): parity with the Rust results and the CLI,
# pickling, errors, models, a Dask LocalCluster run over 200 files, and the
# README's Python example in a fresh venv.
#
# The venv is made once under the target folder and reused (a stamp holds
# the requirements it was made with); PyPI is used for installs only.
# Run time on the 2-core dev machine, shared with five other builds (load
# 8 to 14): pytest 1 to 1.7 min (the Dask run ~25 s of it); with a changed
# crate add the wheel's release build and the crate's clippy (~5-8 min
# together at that load), and on a fresh machine the venv (~1 min).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
target=${CARGO_TARGET_DIR:-$root/target}
venv=$target/pyvenv
reqs="maturin>=1.5,<2 pytest numpy scipy dask[distributed] pyarrow fsspec"

say() { echo "[python] $*" >&2; }

if [ ! -x "$venv/bin/python" ] || [ "$(cat "$venv/.placecat-reqs" 2>/dev/null)" != "$reqs" ]; then
  say "making the venv $venv ($reqs)"
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --upgrade pip
  # shellcheck disable=SC2086 # one word a requirement
  "$venv/bin/pip" install --quiet $reqs
  echo "$reqs" > "$venv/.placecat-reqs"
fi

# The Python crate is a workspace member outside default-members, so the
# root's fmt and clippy steps do not see it: lint it here, in a target
# folder of its own (maturin sets PyO3's build environment differently, and
# sharing one folder would rebuild pyo3 and the wheel after every clippy).
cargo fmt -p placecat-python --check
CARGO_TARGET_DIR=$target/python-clippy cargo clippy -p placecat-python --quiet -- -D warnings

# The CLI every Python result is compared with (already built by
# `cargo test --release` in npm test; then this is a no-op).
cargo build --release --quiet --bin placecat

# The wheel, by the README's command (Python section), in a target folder of
# its own: the core built without its default features writes the same
# unhashed deps/libplacecat.so (its cdylib) as the CLI's build, and sharing
# a folder would rebuild both every run.
wheels=$target/wheels
rm -f "$wheels"/placecat-*.whl
CARGO_TARGET_DIR=$target/python-wheel \
  "$venv/bin/maturin" build --release -m python/Cargo.toml -o "$wheels" --quiet
wheel=$(ls "$wheels"/placecat-*.whl)
"$venv/bin/pip" install --quiet --force-reinstall --no-deps "$wheel"

PLACECAT_CLI=$target/release/placecat PLACECAT_WHEEL=$wheel PLACECAT_REQUIRE_PKG=1 \
  "$venv/bin/pytest" -q -p no:cacheprovider python/tests
