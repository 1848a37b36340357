#!/usr/bin/env bash
# The main job: install what is missing, build, and pour grains into a box until they settle.
# Extra arguments go to `talus demo` (see `build/src/talus demo --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/src/talus demo --out runs/demo "$@"
