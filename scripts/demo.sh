#!/usr/bin/env bash
# The main job: install what is missing, build, and run the built-in `drum` scenario (grains
# settled in a drum that then turns for 3 s) into a new run folder runs/drum-DATE-TIME, with its
# pictures, energy and coordination curves (thermo.csv), ParaView snapshots and run.json, then
# every analysis that applies and the one-page report analysis/report.html.
# Extra arguments go to `talus run` (e.g. --set particles.count=600, --threads 2).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
out="runs/drum-$(date +%Y%m%d-%H%M%S)"
build/native/talus run drum --out "$out" "$@"
build/native/talus analyze "$out"
echo "pictures and numbers: $out/analysis/report.html (everything on one page), $out/final.png," \
     "$out/pictures/, $out/analysis/, $out/thermo.csv, $out/particles.pvd (ParaView)"
