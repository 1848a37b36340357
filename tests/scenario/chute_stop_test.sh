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
# one slope per sweep: a run that ends at another is refused
"$talus" sweep chute_stop "${short[@]}" --set stages.1.duration=0.5 --vary particles.count=100 \
  --out "$dir/t" > /dev/null 2>&1 || fail "second sweep"
sed -i "s/'simulation.gravity' = .*/'simulation.gravity' = [ 3.0, -9.3 ]/" "$dir/t/run-001/scenario.toml"
rm -rf "$dir/s/run-002" && cp -r "$dir/t/run-001" "$dir/s/run-002"
"$talus" analyze "$dir/s" chute 2> "$dir/err" > /dev/null && fail "two slopes accepted"
grep -q "different slopes" "$dir/err" || { cat "$dir/err"; fail "message for two slopes"; }
echo "chute_stop: a shallow layer stops, a deep one flows, h_stop between them"
