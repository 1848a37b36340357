#!/usr/bin/env bash
# talus sweep: the runs of a small silo sweep, stopped by SIGTERM and continued with talus
# resume; finished runs are not run again, every run's state equals that of the same talus run,
# the index holds every run, and talus analyze gathers the discharge and the Beverloo fit.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
small=(--set particles.count=150 --set geometry.width=0.12 --set geometry.height=0.25
       --set simulation.duration=0.5 --set packing.settle_max_time=0.3)
sweep="$dir/sweep"

# refused before anything runs: a --vary without values, an unknown key, nothing varied
"$talus" sweep silo_discharge --vary geometry.orifice --out "$sweep" 2> "$dir/err" && fail "no '=' accepted"
grep -q "expected KEY=V1,V2" "$dir/err" || { cat "$dir/err"; fail "message for a --vary without values"; }
"$talus" sweep silo_discharge --vary geometry.orifise=0.05,0.06 --out "$sweep" 2> "$dir/err" && fail "unknown key accepted"
grep -q "orifise" "$dir/err" || { cat "$dir/err"; fail "message for an unknown key"; }
"$talus" sweep silo_discharge --out "$sweep" 2> "$dir/err" && fail "a sweep of nothing accepted"
[ -e "$sweep" ] && fail "a refused sweep left a folder"

# 2 widths x 2 seeds, 2 at a time; SIGTERM once the first run has finished
"$talus" sweep silo_discharge "${small[@]}" --vary geometry.orifice=0.05,0.06 --seeds 2 --jobs 2 \
  --out "$sweep" > "$dir/log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do grep -q '^\[1/4\]' "$dir/log" && break; sleep 0.1; done
grep -q '^\[1/4\]' "$dir/log" || { cat "$dir/log"; fail "no run finished"; }
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || { cat "$dir/log"; fail "exit status $status after SIGTERM, expected 130"; }
grep -q "continue with: talus resume $sweep" "$dir/log" || { cat "$dir/log"; fail "no resume hint"; }
# a run's time is the process's, its settling too: never "in 0 s" for runs of a second or so
grep -q '^\[1/4\] .*: finished at t = 0.5 s in [0-9.]* s' "$dir/log" || { cat "$dir/log"; fail "no time for a finished run"; }
grep -q ' in 0 s' "$dir/log" && { cat "$dir/log"; fail "a run's time given as 0 s"; }
done_before=$(grep -c ',finished,' "$sweep/index.csv")
[ "$done_before" -ge 1 ] && [ "$done_before" -lt 4 ] || { cat "$sweep/index.csv"; fail "$done_before runs finished before the resume"; }
first=$(grep -l '"ended_by": "duration"' "$sweep"/run-*/run.json | head -1)
sum_before=$(md5sum < "$first")

# the same command again is refused with the hint; talus resume finishes the rest
"$talus" sweep silo_discharge "${small[@]}" --vary geometry.orifice=0.05,0.06 --seeds 2 \
  --out "$sweep" 2> "$dir/err" && fail "a second sweep into the same folder accepted"
grep -q "talus resume $sweep" "$dir/err" || { cat "$dir/err"; fail "no resume hint for the same folder"; }
"$talus" resume "$sweep" --jobs 2 > "$dir/log2" 2>&1 || { cat "$dir/log2"; fail "resume"; }
grep -q "($done_before finished before)" "$dir/log2" || { cat "$dir/log2"; fail "resume ran finished runs"; }
[ "$(md5sum < "$first")" = "$sum_before" ] || fail "a finished run was run again"
[ "$(grep -c ',finished,' "$sweep/index.csv")" -eq 4 ] || { cat "$sweep/index.csv"; fail "not all runs finished"; }
head -1 "$sweep/index.csv" | grep -q '^run,geometry.orifice,seed,status,' || fail "index header: $(head -1 "$sweep/index.csv")"
grep -q '"rate"' "$sweep/index.json" || fail "index.json without rates"

# every run equals the same talus run, whether it was stopped and resumed or not
for run in run-002 run-003; do
  case "$run" in run-002) set=(--set geometry.orifice=0.05 --set simulation.seed=2) ;;
                 run-003) set=(--set geometry.orifice=0.06 --set simulation.seed=1) ;; esac
  "$talus" run silo_discharge "${small[@]}" "${set[@]}" --quiet --out "$dir/$run" || fail "talus run"
  a=$("$talus" checkpoint "$sweep/$run" | grep state_hash)
  b=$("$talus" checkpoint "$dir/$run" | grep state_hash)
  [ "$a" = "$b" ] || fail "$run: sweep $a, talus run $b"
done

# the gathered discharge, the Beverloo fit with n = 3/2 (two widths are too few for n free),
# and one result against the varied key
"$talus" analyze "$sweep" discharge > "$dir/an" 2>&1 || { cat "$dir/an"; fail "analyze discharge"; }
[ "$(wc -l < "$sweep/analysis/discharge.csv")" -eq 5 ] || fail "analysis/discharge.csv rows"
grep -q "n = 3/2: W = A (D/d - k)^n" "$dir/an" || { cat "$dir/an"; fail "no fit with n = 3/2"; }
grep -q '"ok": true' "$sweep/analysis/beverloo.json" || fail "beverloo.json without a fit"
"$talus" analyze "$sweep" final_coordination > "$dir/an2" 2>&1 || { cat "$dir/an2"; fail "analyze a result"; }
[ "$(wc -l < "$sweep/analysis/final_coordination.csv")" -eq 3 ] || fail "final_coordination.csv rows"
"$talus" analyze "$sweep" no_such_result 2> "$dir/err" && fail "an unknown result accepted"
grep -q "its results: .*final_coordination" "$dir/err" || { cat "$dir/err"; fail "unknown result message"; }
# SIGKILL of the sweep: its runs stop at a checkpoint by themselves, and resume finishes them
killed="$dir/killed"
"$talus" sweep silo_discharge "${small[@]}" --seeds 2 --jobs 2 --out "$killed" > "$dir/log3" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$killed/run-001/thermo.csv" ] && [ -f "$killed/run-002/thermo.csv" ] && break
  sleep 0.1
done
kill -KILL "$pid"
wait "$pid" 2> /dev/null
for _ in $(seq 1 30); do pgrep -f "$killed/run-" > /dev/null || break; sleep 0.1; done
pgrep -f "$killed/run-" > /dev/null && fail "runs go on after the sweep was killed"
grep -q '"ended_by": "signal"' "$killed"/run-00[12]/run.json || fail "no run stopped at a checkpoint"
# run-002 as if killed at its very start (the lock, the snapshots folder, a half-written
# scenario): resume starts it afresh
find "$killed/run-002" -mindepth 1 -maxdepth 1 ! -name .lock -exec rm -rf {} +
mkdir "$killed/run-002/snapshots"
echo "[simul" > "$killed/run-002/scenario.toml.tmp"
"$talus" resume "$killed" > "$dir/log4" 2>&1 || { cat "$dir/log4"; fail "resume after SIGKILL"; }
[ "$(grep -c ',finished,' "$killed/index.csv")" -eq 2 ] || { cat "$killed/index.csv"; fail "not finished after SIGKILL and resume"; }
# a sweep of a 3D scenario: each run's scenario resolved as spheres, its runs run and indexed,
# and talus analyze SWEEP rheology measures each sheared cell (too few points for the fits)
shear3d="$dir/shear3d"
"$talus" sweep simple_shear3d --vary drivers.0.shear_rate=2,4 --set particles.count=200 \
  --set "geometry.box=[0, 0, 0, 0.055, 0.25, 0.055]" --set simulation.duration=0.3 \
  --set output.snapshot_interval=0.025 --set output.thermo_interval=0.01 --jobs 2 \
  --out "$shear3d" > "$dir/log5" 2>&1 || { cat "$dir/log5"; fail "3D sweep"; }
grep -q "^dimension = 3$" "$shear3d/scenarios/run-002.toml" || fail "run-002's scenario is not 3D"
grep -q "^shear_rate = 4\.0$" "$shear3d/scenarios/run-002.toml" || fail "run-002's shear rate"
[ "$(grep -c ',finished,' "$shear3d/index.csv")" -eq 2 ] || { cat "$shear3d/index.csv"; fail "3D runs not finished"; }
"$talus" analyze "$shear3d" rheology > "$dir/log6" 2>&1 || { cat "$dir/log6"; fail "3D sweep rheology"; }
[ "$(grep -c '^run-00[12],' "$shear3d/analysis/rheology_points.csv")" -eq 2 ] \
  || { cat "$shear3d/analysis/rheology_points.csv"; fail "3D rheology points"; }
echo "sweep: stopped, resumed, identical to talus run, gathered; SIGKILL stops its runs; 3D"
