#!/bin/sh
# Ctrl-C (SIGINT) stops a run after writing a checkpoint, with exit status 130; resume finishes it.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$talus" run drum --out "$dir/run" --quiet --set simulation.duration=100 --set particles.count=100 \
  --set output.checkpoint_interval=1000 &
pid=$!
# wait until the run has started stepping (thermo.csv has rows), then interrupt it
for _ in $(seq 1 300); do
  [ -f "$dir/run/thermo.csv" ] && [ "$(wc -l < "$dir/run/thermo.csv")" -gt 3 ] && break
  sleep 0.1
done
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || { echo "exit status $status, expected 130"; exit 1; }
[ -f "$dir/run/checkpoint.bin" ] || { echo "no checkpoint after SIGINT"; exit 1; }
grep -q '"ended_by": "signal"' "$dir/run/run.json" || { echo "run.json does not say signal"; exit 1; }
echo "interrupted with status 130 and a checkpoint"

# SIGTERM while settling: a word that says so and how to go on, status 130, and resume starts
# the run again
"$talus" run drum --out "$dir/settling" --set simulation.duration=0.02 --set particles.count=100 \
  --set packing.settle_max_time=5 > "$dir/settling.out" 2> "$dir/settling.err" &
pid=$!
for _ in $(seq 1 300); do grep -q "settling: t" "$dir/settling.out" && break; sleep 0.05; done
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || { cat "$dir/settling.err"; echo "exit status $status while settling"; exit 1; }
grep -q "interrupted while settling.*talus resume $dir/settling" "$dir/settling.err" ||
  { cat "$dir/settling.err"; echo "no word of the interrupted settling"; exit 1; }
"$talus" resume "$dir/settling" --quiet || { echo "resume after an interrupted settling"; exit 1; }
echo "interrupted while settling with status 130; resume started it again"
