#!/usr/bin/env bash
# One run folder, one process: a second talus run or resume on a folder in use is refused with the
# holder's pid; two resumes at once leave one whole thermo.csv. A run killed while settling (no
# checkpoint yet) is started again by talus resume; one killed just after its start resumes from
# the checkpoint every run writes at t = 0. talus export lammps never writes into a run folder.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'kill -KILL $(jobs -p) 2>/dev/null; rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
wait_for() { for _ in $(seq 1 400); do [ -e "$1" ] && return 0; sleep 0.05; done; fail "no $1"; }

# the drum settles for seconds: the folder and its lock exist from the start
settle=(drum --quiet --set simulation.duration=0.05 --set packing.settle_max_time=3)
"$talus" run "${settle[@]}" --out "$dir/a" &
pid=$!
wait_for "$dir/a/scenario.toml"
sleep 0.2
out=$("$talus" resume "$dir/a" 2>&1) && fail "a resume of a folder in use succeeded"
echo "$out" | grep -q "in use by process $pid" || fail "resume: $out"
out=$("$talus" run "${settle[@]}" --out "$dir/a" 2>&1) && fail "a second run on a folder in use"
echo "$out" | grep -q "in use by process $pid" || fail "run: $out"
echo "ok: a folder in use is refused, naming process $pid"

kill -KILL "$pid"
wait "$pid" 2>/dev/null
[ -e "$dir/a/checkpoint.bin" ] && fail "killed too late: the run had started stepping"
# a requeue that resumes after each kill: each resume starts the run again while settling, and
# is killed there too, twice; the third finishes
for kill in 1 2; do
  "$talus" resume "$dir/a" > "$dir/resume$kill.txt" 2>&1 &
  pid=$!
  for _ in $(seq 1 400); do grep -q "settling: t" "$dir/resume$kill.txt" && break; sleep 0.05; done
  grep -q "stopped before its first checkpoint (while settling, say): starting it again" \
    "$dir/resume$kill.txt" || fail "resume $kill said: $(cat "$dir/resume$kill.txt")"
  kill -KILL "$pid"
  wait "$pid" 2>/dev/null
  [ -e "$dir/a/checkpoint.bin" ] && fail "resume $kill killed too late: the run had started stepping"
done
"$talus" resume "$dir/a" --quiet || fail "the third resume of a run killed while settling"
grep -q '"ended_by": "duration"' "$dir/a/run.json" || fail "the restarted run did not finish"
echo "ok: a run killed while settling, twice more while resumed, starts again and finishes"

# killed at its very start, before it wrote its scenario: the lock file, the snapshots folder and
# a half-written scenario.toml.tmp; talus run into it starts afresh, resume says so
mkdir -p "$dir/s/snapshots"
echo 1 > "$dir/s/.lock"
echo "[simul" > "$dir/s/scenario.toml.tmp"
out=$("$talus" resume "$dir/s" 2>&1) && fail "resume of a run killed at its start succeeded"
echo "$out" | grep -q "stopped at its start; start it again with: talus run SCENARIO --out $dir/s" ||
  fail "resume of a run killed at its start said: $out"
"$talus" run "${settle[@]}" --set packing.settle_max_time=0.05 --out "$dir/s" ||
  fail "talus run into a folder killed at its start"
[ -e "$dir/s/scenario.toml.tmp" ] && fail "the half-written scenario was left"
# a sweep folder is never taken for such a run
mkdir -p "$dir/w/logs"
echo 1 > "$dir/w/.lock"
echo "{}" > "$dir/w/sweep.json"
out=$("$talus" run "${settle[@]}" --out "$dir/w" 2>&1) && fail "talus run into a sweep folder"
[ -e "$dir/w/sweep.json" ] && [ -d "$dir/w/logs" ] || fail "talus run cleared a sweep folder"
echo "ok: a run killed at its start starts again; a sweep folder is left alone"

# killed right after its start: the t = 0 checkpoint is there to resume from
fast=(drum --quiet --set particles.count=100 --set packing.settle_max_time=0.05
      --set simulation.duration=0.3 --set output.checkpoint_interval=10)
"$talus" run "${fast[@]}" --out "$dir/b" &
pid=$!
wait_for "$dir/b/checkpoint.bin"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
"$talus" resume "$dir/b" --quiet || fail "resume after a kill at the start"
echo "ok: a run killed at its start resumes"

# two resumes at once: one is refused, the other finishes; time never runs backwards
"$talus" run "${fast[@]}" --set simulation.duration=1 --out "$dir/c" --stop-at 0.05 || [ $? -eq 4 ] || fail "--stop-at run"
"$talus" resume "$dir/c" --quiet > "$dir/r1.txt" 2>&1 &
p1=$!
"$talus" resume "$dir/c" --quiet > "$dir/r2.txt" 2>&1 &
p2=$!
wait "$p1"; s1=$?
wait "$p2"; s2=$?
if ! { [ "$s1" -eq 0 ] && [ "$s2" -ne 0 ]; } && ! { [ "$s2" -eq 0 ] && [ "$s1" -ne 0 ]; }; then
  fail "two resumes: statuses $s1 and $s2 (one must succeed, one be refused)"
fi
grep -q "is in use by process [0-9]" "$dir/r1.txt" "$dir/r2.txt" || fail "no refusal: $(cat "$dir"/r?.txt)"
awk -F, 'NR > 1 { if ($1 + 0 < last) { print "time runs backwards at line " NR; exit 1 }
                  last = $1 + 0 }' "$dir/c/thermo.csv" || fail "thermo.csv"
echo "ok: of two resumes at once one is refused; thermo.csv runs forward"

# talus export lammps: a run folder (locked or not) and a non-empty folder are refused, nothing
# written; --replace writes over a previous export only
before=$(cd "$dir/b" && ls -la --time-style=+%s.%N | md5sum)
out=$("$talus" export lammps collisions "$dir/b" --quiet 2>&1) && fail "an export into a run folder"
echo "$out" | grep -q "holds a run or a sweep" || fail "export into a run folder said: $out"
out=$("$talus" export lammps collisions "$dir/b" --quiet --replace 2>&1) && fail "--replace into a run folder"
[ "$(cd "$dir/b" && ls -la --time-style=+%s.%N | md5sum)" = "$before" ] || fail "the refused export touched the run folder"
"$talus" run "${settle[@]}" --out "$dir/e" > /dev/null &
pid=$!
wait_for "$dir/e/scenario.toml"
out=$("$talus" export lammps collisions "$dir/e" --quiet 2>&1) && fail "an export into a folder in use"
echo "$out" | grep -q "in use by process $pid" || fail "export into a folder in use said: $out"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
mkdir -p "$dir/x" && echo note > "$dir/x/notes.txt"
out=$("$talus" export lammps collisions "$dir/x" --quiet 2>&1) && fail "an export into a non-empty folder"
echo "$out" | grep -q "already exists and is not empty.*--replace" || fail "export into a non-empty folder said: $out"
"$talus" export lammps collisions "$dir/x2" --quiet || fail "an export into a new folder"
"$talus" export lammps collisions "$dir/x2" --quiet --replace || fail "an export over an export"
echo "ok: talus export lammps refuses run folders and non-empty folders"

# a run whose folder is deleted under it stops saying so, and writes nothing into the folder of
# another run started there; deleted and not replaced, it makes nothing again
long=(drum --quiet --set particles.count=150 --set packing.settle_max_time=0.05
      --set simulation.duration=50 --set output.snapshot_interval=0.005)
"$talus" run "${long[@]}" --out "$dir/del" 2> "$dir/del.txt" &
pid=$!
wait_for "$dir/del/snapshots/particles_000002.vtp"
until rm -rf "$dir/del" 2> /dev/null; do :; done # the run may add a snapshot meanwhile
"$talus" run "${settle[@]}" --out "$dir/del" > /dev/null 2>&1 &
other=$!
wait_for "$dir/del/scenario.toml"
wait "$pid"
status=$?
[ "$status" -eq 1 ] || fail "a run whose folder was replaced exited $status: $(cat "$dir/del.txt")"
grep -q "'$dir/del' was replaced under the running run.*writes nothing more" "$dir/del.txt" ||
  grep -q "'$dir/del' was deleted under the running run.*writes nothing more" "$dir/del.txt" ||
  grep -q "'$dir/del' were deleted under the running run.*writes nothing more" "$dir/del.txt" ||
  fail "a run whose folder was replaced said: $(cat "$dir/del.txt")"
[ -z "$(ls "$dir/del/snapshots")" ] || fail "the replaced run wrote into the new run's folder"
kill -KILL "$other"
wait "$other" 2>/dev/null
# a long run into $dir/NAME whose PATH (under $dir) is deleted once its third snapshot is
# there; its stderr in $dir/NAME.txt, its exit status 1 asked for
delete_under_run() {
  "$talus" run "${long[@]}" --out "$dir/$1" 2> "$dir/$1.txt" &
  local run=$!
  wait_for "$dir/$1/snapshots/particles_000002.vtp"
  until rm -rf "$dir/$2" 2> /dev/null; do :; done
  wait "$run"
  local code=$?
  [ "$code" -eq 1 ] || fail "a run whose $2 was deleted exited $code: $(cat "$dir/$1.txt")"
}
delete_under_run gone gone
grep -q "'$dir/gone' was deleted under the running run" "$dir/gone.txt" ||
  fail "a run whose folder was deleted said: $(cat "$dir/gone.txt")"
[ -e "$dir/gone" ] && fail "a run whose folder was deleted made it again"
# a folder whose files are deleted (rm -rf caught halfway, before it reaches the lock) gives the
# same diagnosis, not a full disk's
delete_under_run half half/snapshots
grep -q "files of the run folder '$dir/half' were deleted under the running run.*No such file" \
  "$dir/half.txt" || fail "a run whose snapshots were deleted said: $(cat "$dir/half.txt")"
[ -e "$dir/half/snapshots" ] && fail "a run whose snapshots were deleted wrote them again"
echo "ok: a run whose folder is deleted or replaced stops, writing nothing there"

# a failed checkpoint write can leave only checkpoint.prev.bin: talus checkpoint reads what
# resume reads
mv "$dir/b/checkpoint.bin" "$dir/b-checkpoint.bin"
[ -e "$dir/b/checkpoint.prev.bin" ] || cp "$dir/b-checkpoint.bin" "$dir/b/checkpoint.prev.bin"
"$talus" checkpoint "$dir/b" | grep -q "^state_hash" || fail "talus checkpoint with checkpoint.prev.bin only"
echo "ok: talus checkpoint reads the previous checkpoint when it is the only one"
