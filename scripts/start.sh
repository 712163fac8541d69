#!/usr/bin/env bash
# `npm start`: install what is missing, build what is missing, serve www/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-www.sh
exec node scripts/serve.mjs www
