#!/bin/sh
# A short run of a built-in scenario, then VTK's reader opens every snapshot (read_vtk.py).
set -e
talus="$1"
here="$(dirname "$0")"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$talus" run collisions --out "$dir/run" --quiet --set simulation.duration=0.02
/usr/bin/python3 "$here/read_vtk.py" "$dir/run"
