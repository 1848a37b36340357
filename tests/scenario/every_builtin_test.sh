#!/usr/bin/env bash
# Every command on the run folder of every built-in scenario (short versions): talus render with
# chains and tracks, talus movie, talus analyze with its report. New built-ins are picked up from
# `talus scenarios`; one without a short version here fails the test, so none is left out.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL ($name): $*"; exit 1; }
for name in $("$talus" scenarios | awk '{print $1}'); do
  common=(--quiet --out "$dir/$name" --set output.snapshot_interval=0.02 --set output.checkpoint_interval=0)
  case "$name" in
    collisions) short=(--set simulation.duration=0.06) ;;
    drum) short=(--set particles.count=80 --set simulation.duration=0.1 --set packing.settle_max_time=0.1) ;;
    force_network) short=(--set particles.count=80 --set simulation.duration=0.1) ;;
    frost_heave) short=(--set particles.count=300 --set simulation.duration=0.08 --set packing.settle_max_time=0.05
                        --set frost.min_interval=0.02 --set frost.kinetic_threshold=1e3
                        --set frost.heave_factor=1.02) ;;
    frost_front) short=(--set particles.count=200 --set simulation.duration=0.6 --set packing.settle_max_time=0.1
                        --set frost.freeze_time=0.1 --set frost.thaw_time=0.1 --set frost.heave_strain=0.1
                        --set frost.min_interval=0.02 --set frost.kinetic_threshold=1e-1 --set frost.cycles=1) ;;
    hourglass) short=(--set particles.count=150 --set simulation.duration=0.1 --set packing.settle_max_time=0.2) ;;
    silo_discharge) short=(--set particles.count=150 --set geometry.width=0.12 --set geometry.height=0.25
                           --set simulation.duration=0.2 --set packing.settle_max_time=0.3) ;;
    silo_shake) short=(--set particles.count=60 --set simulation.duration=0.1 --set packing.settle_max_time=0.1) ;;
    tilted_box) short=(--set particles.count=60 --set simulation.duration=0.2 --set stages.1.duration=0.05
                       --set stages.2.duration=0.05) ;;
    silo_gate) short=(--set particles.count=60 --set stages.0.duration=0.15 --set stages.2.count=5) ;;
    heap) short=(--set particles.count=80 --set stages.1.duration=0.1 --set stages.2.duration=0.2) ;;
    jamming) short=(--set particles.count=100 --set "geometry.box=[0,0,0.16,0.16]"
                    --set "packing.region=[0,0,0.16,0.16]" --set stages.0.duration=0.3
                    --set stages.1.duration=0.1 --set stages.2.duration=0.1 --set stages.3.duration=0.1
                    --set stages.4.duration=0.1 --set stages.5.duration=0.1) ;;
    janssen) short=(--set particles.count=300 --set geometry.height=0.3 --set packing.settle_max_time=0.2
                    --set stages.0.duration=0.02 --set stages.1.duration=0.03) ;;
    shear) short=(--set simulation.duration=0.6) ;;
    simple_shear) short=(--set simulation.duration=0.6) ;;
    chute) short=(--set simulation.duration=0.4) ;;
    chute_stop) short=(--set particles.count=100 --set stages.0.duration=0.2 --set stages.1.duration=0.2) ;;
    pour3d) echo "pour3d: spheres in 3D, run and read back by pour3d_test.sh"; continue ;;
    simple_shear3d) # spheres in 3D: the pictures are 2D's; the run, its columns, its analyses
      "$talus" run "$name" "${common[@]}" --set simulation.duration=0.3 || fail "run"
      head -1 "$dir/$name/thermo.csv" | grep -q "cell_shear_strain" || fail "no cell columns"
      "$talus" analyze "$dir/$name" > /dev/null || fail "analyze"
      head -1 "$dir/$name/analysis/fields.csv" | grep -q "^y,density" || fail "no fields along y"
      grep -q '"measured": ' "$dir/$name/analysis/rheology.json" || fail "no rheology.json"
      continue ;;
    *) fail "no short version in $0" ;;
  esac
  "$talus" run "$name" "${common[@]}" "${short[@]}" || fail "run"
  run="$dir/$name"
  layers=(--chains)
  [ -f "$run/track.csv" ] && layers+=(--tracks)
  "$talus" render "$run" --color force "${layers[@]}" --width 400 > /dev/null || fail "render ${layers[*]}"
  [ -n "$(ls "$run/pictures")" ] || fail "no picture"
  if command -v ffmpeg > /dev/null; then
    "$talus" movie "$run" --width 400 > /dev/null || fail "movie"
    [ -s "$run/movie.mp4" ] || fail "no movie"
  fi
  "$talus" analyze "$run" > "$dir/$name.txt" || { cat "$dir/$name.txt"; fail "analyze"; }
  grep -q "skipped" "$dir/$name.txt" && grep "skipped" "$dir/$name.txt"
  [ -s "$run/analysis/report.html" ] || fail "no report.html"
  [ -s "$run/analysis/profiles.csv" ] || fail "no profiles.csv"
  [ -f "$run/track.csv" ] && { [ -s "$run/analysis/tracks.csv" ] || fail "no tracks.csv"; }
  case "$name" in
    hourglass|silo_discharge) [ -s "$run/analysis/discharge.json" ] || fail "no discharge.json" ;;
    silo_shake) [ -s "$run/analysis/segregation.csv" ] || fail "no segregation.csv" ;;
    heap) [ -s "$run/analysis/repose.json" ] || fail "no repose.json" ;;
    janssen) [ -s "$run/analysis/janssen.json" ] || fail "no janssen.json" ;;
    jamming) [ -s "$run/analysis/jamming.json" ] || fail "no jamming.json" ;;
    shear|simple_shear) [ -s "$run/analysis/rheology.json" ] || fail "no rheology.json" ;;
    chute) [ -s "$run/analysis/chute.json" ] || fail "no chute.json" ;;
    frost_heave|frost_front) [ -s "$run/analysis/frost.csv" ] || fail "no analysis/frost.csv"
                 [ "$(wc -l < "$run/frost.csv")" -ge 2 ] || fail "no freeze in frost.csv" ;;
  esac
  if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
    grep -q "data:image/png;base64" "$run/analysis/report.html" || fail "report without charts"
  fi
  echo "$name: render, movie, analyze and report.html"
done
