#!/usr/bin/env bash
# A file size limit (standing in for a full disk) and an output folder that cannot be made give
# clear errors, a non-zero status, and no corrupt checkpoint.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

# 1. files may not grow past 64 KiB: thermo.csv outgrows that
( ulimit -f 64; "$talus" run collisions --quiet --out "$dir/full" \
    --set output.thermo_interval=0.00005 --set output.checkpoint_interval=0.01 ) 2> "$dir/err.txt"
status=$?
[ "$status" -ne 0 ] || { echo "a full disk went unnoticed"; exit 1; }
grep -q "cannot write $dir/full/.*: File too large" "$dir/err.txt" || { echo "unclear message:"; cat "$dir/err.txt"; exit 1; }
if [ -f "$dir/full/checkpoint.bin" ]; then
  "$talus" checkpoint "$dir/full" > /dev/null || { echo "the checkpoint left behind is corrupt"; exit 1; }
fi
echo "file size limit: status $status, message: $(head -c 200 "$dir/err.txt")"

# 2. the output folder cannot be created (its parent is a file)
touch "$dir/a_file"
"$talus" run collisions --quiet --out "$dir/a_file/run" 2> "$dir/err2.txt"
status=$?
[ "$status" -ne 0 ] || { echo "an impossible output folder was accepted"; exit 1; }
grep -q "a_file" "$dir/err2.txt" || { echo "the message does not name the folder:"; cat "$dir/err2.txt"; exit 1; }
echo "unwritable folder: status $status, message: $(head -c 200 "$dir/err2.txt")"

# 3. what was cut off is cut cleanly: every line of thermo.csv is whole (same column count)
if [ -f "$dir/full/thermo.csv" ]; then
  columns=$(head -1 "$dir/full/thermo.csv" | awk -F, '{print NF}')
  bad=$(awk -F, -v n="$columns" 'NF != n' "$dir/full/thermo.csv" | wc -l)
  [ "$bad" -eq 0 ] || { echo "thermo.csv has $bad broken lines after the write fault"; exit 1; }
  [ -z "$(tail -c 1 "$dir/full/thermo.csv")" ] || { echo "thermo.csv ends mid-line"; exit 1; }
  echo "thermo.csv cut back cleanly to $(wc -l < "$dir/full/thermo.csv") whole lines"
fi

# 4. the limit is hit while a snapshot's collection (particles.pvd) is written: the outputs are cut
# back to the last checkpoint (snapshot files included), run.json says why, and a resume with room
# again ends in the state of a run that never failed
snap=(collisions --quiet --set output.snapshot_interval=0.0005 --set output.checkpoint_interval=0.01
      --set output.thermo_interval=0.01 --set output.track_interval=0.01)
( ulimit -f 8; "$talus" run "${snap[@]}" --out "$dir/snap" ) 2> "$dir/err4.txt"
[ $? -ne 0 ] || { echo "a failed snapshot went unnoticed"; exit 1; }
grep -q "cannot write $dir/snap/particles.pvd: .*the outputs are cut back to the last checkpoint" \
  "$dir/err4.txt" || { echo "snapshot fault, unclear message:"; cat "$dir/err4.txt"; exit 1; }
grep -q '"ended_by": "write_error"' "$dir/snap/run.json" || { echo "run.json does not say why"; exit 1; }
listed=$(grep -c 'file="snapshots/particles_' "$dir/snap/particles.pvd")
present=$(ls "$dir/snap/snapshots" | grep -c '^particles_')
[ "$listed" -eq "$present" ] || { echo "particles.pvd lists $listed snapshots, $present on disk"; exit 1; }
"$talus" resume "$dir/snap" --quiet || { echo "resume after the snapshot fault failed"; exit 1; }
"$talus" run "${snap[@]}" --out "$dir/whole" || { echo "the uninterrupted run failed"; exit 1; }
[ "$("$talus" checkpoint "$dir/snap" | grep state_hash)" = "$("$talus" checkpoint "$dir/whole" | grep state_hash)" ] \
  || { echo "resumed after the snapshot fault: another state"; exit 1; }
cmp -s "$dir/snap/thermo.csv" "$dir/whole/thermo.csv" || { echo "thermo.csv differs after the fault"; exit 1; }
echo "snapshot fault: cut back to $present snapshots, resumed to the same state"

# 5. more particles than this process may allocate (ulimit -v): refused before allocating, with
# the limit named, and no run folder left (not under AddressSanitizer, which reserves terabytes of
# address space and cannot start under such a limit)
if ! ( ulimit -v 2000000; "$talus" --version > /dev/null 2>&1 ); then
  echo "ulimit -v: this build cannot start under a 2 GB address-space limit (a sanitizer?): skipped"
  exit 0
fi
( ulimit -v 2000000; "$talus" run drum --quiet --set particles.count=3000000 --out "$dir/big" ) \
  2> "$dir/err5.txt"
[ $? -ne 0 ] || { echo "a run past ulimit -v was accepted"; exit 1; }
grep -q "ulimit -v" "$dir/err5.txt" || { echo "ulimit -v, unclear message:"; cat "$dir/err5.txt"; exit 1; }
[ ! -e "$dir/big" ] || { echo "a refused run left its folder"; exit 1; }
echo "ulimit -v: $(head -c 200 "$dir/err5.txt")"
