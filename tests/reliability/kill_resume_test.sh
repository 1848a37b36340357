#!/usr/bin/env bash
# SIGKILL a run at random moments, several times, resuming after each kill; the final state must
# be bit-identical (same state hash) to an uninterrupted run of the same scenario.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
args=(drum --quiet --set particles.count=100 --set packing.settle_max_time=0.05
      --set simulation.duration=0.4 --set output.checkpoint_interval=0.01)
"$talus" run "${args[@]}" --out "$dir/whole" || { echo "uninterrupted run failed"; exit 1; }
reference=$("$talus" checkpoint "$dir/whole" | grep state_hash)

RANDOM=7 # reproducible kill times
"$talus" run "${args[@]}" --out "$dir/part" &
pid=$!
kills=0
for round in 1 2 3 4 5; do
  # wait for a first checkpoint, then a random 0.1 to 0.6 s more, then SIGKILL
  for _ in $(seq 1 200); do [ -f "$dir/part/checkpoint.bin" ] && break; sleep 0.05; done
  sleep "0.$((RANDOM % 5 + 1))"
  if kill -KILL "$pid" 2>/dev/null; then kills=$((kills + 1)); fi
  wait "$pid" 2>/dev/null
  "$talus" resume "$dir/part" --quiet &
  pid=$!
done
wait "$pid"
status=$?
[ "$status" -eq 0 ] || { echo "the last resume ended with status $status"; exit 1; }
result=$("$talus" checkpoint "$dir/part" | grep state_hash)
echo "killed $kills times; uninterrupted: $reference; killed and resumed: $result"
[ "$kills" -ge 3 ] || { echo "too few kills landed ($kills) to test anything"; exit 1; }
[ "$reference" = "$result" ] || { echo "states differ"; exit 1; }
cmp -s "$dir/whole/thermo.csv" "$dir/part/thermo.csv" || { echo "thermo.csv differs"; exit 1; }
# a kill after the last checkpoint (while drawing the pictures) leaves a run that has ended:
# resuming it completes the pictures and records nothing twice
snapshots=$(ls "$dir/part/snapshots" | wc -l)
"$talus" resume "$dir/part" --quiet || { echo "resuming the ended run failed"; exit 1; }
cmp -s "$dir/whole/thermo.csv" "$dir/part/thermo.csv" || { echo "resume of an ended run added thermo rows"; exit 1; }
[ "$(ls "$dir/part/snapshots" | wc -l)" -eq "$snapshots" ] || { echo "resume of an ended run added snapshots"; exit 1; }
