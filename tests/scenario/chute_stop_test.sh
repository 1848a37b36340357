#!/usr/bin/env bash
# talus analyze SWEEP chute on a short sweep of the built-in chute_stop: a layer 5 diameters deep
# stops once the slope is let down to 17 degrees, one 15 deep flows on, and h_stop is bracketed
# between them; a sweep whose layers end on different slopes is refused with the reason.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
short=(--set stages.0.duration=1.0 --set stages.1.duration=3.0 --set output.snapshot_interval=0.25
       --set "output.pictures=[]")
"$talus" sweep chute_stop "${short[@]}" --vary particles.count=100,300 --out "$dir/s" > "$dir/log" 2>&1 \
  || { cat "$dir/log"; fail "sweep"; }
"$talus" analyze "$dir/s" chute > "$dir/an" 2>&1 || { cat "$dir/an"; fail "analyze chute"; }
grep -q "run-001: .* stopped" "$dir/an" || { cat "$dir/an"; fail "the shallow layer did not stop"; }
grep -q "run-002: .* flowing" "$dir/an" || { cat "$dir/an"; fail "the deep layer did not flow"; }
grep -q '"sharp": true' "$dir/s/analysis/chute_stop.json" || fail "h_stop not bracketed"
[ "$(wc -l < "$dir/s/analysis/chute_stop.csv")" -eq 3 ] || fail "chute_stop.csv rows"
# slopes swept too (a vector's values in --vary): one layer on two slopes, stopped on the gentle
# one and flowing on the steep one, each slope reported apart
"$talus" sweep chute_stop "${short[@]}" --set particles.count=100 \
  --vary 'stages.1.set.simulation.gravity=[2.868166,-9.38135],[3.355218,-9.218385]' \
  --out "$dir/t" > "$dir/log" 2>&1 || { cat "$dir/log"; fail "sweep over slopes"; }
"$talus" analyze "$dir/t" chute > "$dir/an" 2>&1 || { cat "$dir/an"; fail "analyze two slopes"; }
grep -q "h_stop at 17.00 deg: every layer stopped" "$dir/an" || { cat "$dir/an"; fail "17 deg"; }
grep -q "h_stop at 20.00 deg: every layer flows" "$dir/an" || { cat "$dir/an"; fail "20 deg"; }
grep -q '"\[2.868166,-9.38135\]"' "$dir/t/analysis/chute_stop.csv" \
  || { cat "$dir/t/analysis/chute_stop.csv"; fail "a vector value quoted in the CSV"; }
[ "$(grep -c angle_deg "$dir/t/analysis/chute_stop.json")" -eq 2 ] || fail "two slopes in the JSON"
"$talus" sweep chute_stop --vary 'simulation.gravity=[1,2' --out "$dir/u" 2> "$dir/err" \
  && fail "an unclosed bracket accepted"
grep -q "without its" "$dir/err" || { cat "$dir/err"; fail "message for an unclosed bracket"; }
echo "chute_stop: a shallow layer stops, a deep one flows, h_stop between them; slopes swept"
