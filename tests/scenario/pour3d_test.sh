#!/bin/sh
# The built-in 3D scenario, short: talus run writes thermo.csv, run.json and snapshots that VTK's
# reader opens (read_vtk3d.py), the spheres come to rest in the box with the energy ledger
# balanced, a run stopped and resumed is the run that never stopped (its ledger too, and with
# the more snapshots resume --set asks), one lengthened with --duration ends as the longer run,
# the ledger stops a run whose energy grows, the stress columns weigh the bed and agree with the
# snapshots' sphere stresses, the plates carry the weight, a servo lid carries its load, a chute's
# flow drags its rough floor, run.json names the step specialised to the scene, talus analyze
# coarse-grains the fields, and the commands that take 2D runs refuse the folder.
set -e
talus="$1"
here="$(dirname "$0")"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
run="$dir/run"
"$talus" run pour3d --out "$run" --quiet --set particles.count=120 --set simulation.duration=0.3 \
  --set output.snapshot_interval=0.05 --set simulation.timestep_factor=20 \
  --set output.energy_ledger=true --set output.stress=true \
  --set "output.stress_regions=[{name='low', region=[0, 0, 0, 0.03, 0.03, 0.004]}]"
for f in thermo.csv run.json scenario.toml particles.pvd walls.pvd; do
  [ -s "$run/$f" ] || { echo "FAIL: no $f"; exit 1; }
done
head -1 "$run/thermo.csv" | grep -q "^time,step,kinetic,rotational,potential,elastic,total,contacts" \
  || { echo "FAIL: thermo.csv header"; exit 1; }
/usr/bin/python3 - "$run/thermo.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first, last = rows[0], rows[-1]
fallen = float(first["potential"]) - float(last["potential"])
assert fallen > 0, (first, last)
# at rest in the box: the motion left is a speck of what the fall released
assert float(last["kinetic"]) < 1e-3 * fallen, (last["kinetic"], fallen)
assert int(last["contacts"]) > 120, last["contacts"]
assert 2.5 < float(last["coordination"]) < 6.5, last["coordination"]
# the energy only fell (the Verlet swing of a contact allowed, a thousandth of what fell)
totals = [float(r["total"]) for r in rows]
assert all(b <= a + 1e-3 * fallen for a, b in zip(totals, totals[1:])), "the energy grew"
# the ledger: what fell went to the dampers and friction (velocity Verlet at 20 steps a
# collision: its first-order error within 1e-2 of it), the plates standing still
dissipated = float(last["dissipated_damper"]) + float(last["dissipated_friction"])
assert abs(float(last["energy_imbalance"])) < 1e-2 * dissipated, (last, dissipated)
assert abs(float(last["wall_work"])) < 1e-12 * dissipated, last["wall_work"]
# the stress over the box (0.03 x 0.03 x 0.12 m): its weight's virial g sum m z (the potential
# column) is V sigma_zz less what the walls' friction carries; the bed still trembles, whose
# accelerations move it by a few percent (tests/engine3d/test_stress3.cpp checks it at rest)
volume = 0.03 * 0.03 * 0.12
s = {k: float(v) for k, v in last.items()}
assert 0.8 < s["stress_zz"] * volume / s["potential"] < 1.1, (s["stress_zz"], s["potential"])
assert s["stress_zz"] > max(s["stress_xx"], s["stress_yy"]) > 0, last
assert abs(s["pressure"] - (s["stress_xx"] + s["stress_yy"] + s["stress_zz"]) / 3) < 1e-9 * s["pressure"]
assert abs(s["fabric_xx"] + s["fabric_yy"] + s["fabric_zz"] - 1) < 1e-6, last
assert s["stress_major"] >= s["stress_intermediate"] >= s["stress_minor"], last
assert s["stress_major_z"] > 0.9, last["stress_major_z"]
print(f"{len(rows)} thermo rows; released {fallen:.3e} J; {last['contacts']} contacts at the end")
PY
# the last snapshot's sphere stresses against the same moment's thermo row: their sum times the
# spheres' volumes is the box's contact stress times its volume (to the 9 digits each is written
# with); the plates carry the weight (the trembling bed's accelerations: a few percent); the
# spheres lie wholly in the box, so its packing fraction is their volume over the box's; the
# named region at the bottom has its own columns
/usr/bin/python3 - "$run" <<'PY'
import csv, math, sys
import xml.etree.ElementTree as ET
run = sys.argv[1]
last = {k: float(v) for k, v in list(csv.DictReader(open(run + "/thermo.csv")))[-1].items()}
arrays = {a.get("Name"): [float(x) for x in a.text.split()]
          for a in ET.parse(run + "/snapshots/spheres_000006.vtp").iter("DataArray")}
mass, radius, stress = arrays["mass"], arrays["radius"], arrays["stress"]
assert len(stress) == 9 * len(mass), len(stress)
volumes = [4 / 3 * math.pi * r ** 3 for r in radius]
box = 0.03 * 0.03 * 0.12
summed = sum(v * stress[9 * i + 8] for i, v in enumerate(volumes)) / box
contact_zz = last["stress_zz"] - last["kinetic_stress_zz"]
assert abs(summed / contact_zz - 1) < 1e-7, (summed, contact_zz)
carried = -sum(last[f"force_{s}_z"] for s in ["left", "right", "front", "back", "floor"])
assert 0.95 < carried / (9.81 * sum(mass)) < 1.05, (carried, 9.81 * sum(mass))
assert last["force_left_x"] < 0 < last["force_right_x"], last
assert abs(last["region_packing_fraction"] - sum(volumes) / box) < 2e-9, last
assert last["low_region_packing_fraction"] > 10 * last["region_packing_fraction"], last
assert last["low_stress_zz"] > last["stress_zz"] > 0, last
for p in ["", "low_"]:
    assert 3 < last[p + "load_bearing_coordination"] < 7, last
    assert 0 <= last[p + "rattler_fraction"] < 0.5, last
PY
/usr/bin/python3 "$here/read_vtk3d.py" "$run" 0.03,0.03,0.12 || [ $? -eq 77 ]
# a lid held at 100 Pa by a servo comes down to the bed and carries 100 Pa times its face; the
# default stress region ends at the lid, so its packing fraction is the spheres' volume over the
# box below the lid
"$talus" run pour3d --out "$dir/servo" --quiet --set particles.count=40 --set simulation.duration=0.15 \
  --set "geometry.box=[0, 0, 0, 0.03, 0.03, 0.02]" --set geometry.open_top=false \
  --set "drivers=[{type='servo', target='lid', stress=100.0}]" --set output.snapshot_interval=0.15 \
  --set output.stress=true
/usr/bin/python3 - "$dir/servo" <<'PY'
import csv, math, sys
import xml.etree.ElementTree as ET
run = sys.argv[1]
last = {k: float(v) for k, v in list(csv.DictReader(open(run + "/thermo.csv")))[-1].items()}
assert abs(last["force_lid_z"] / (100.0 * 0.03 * 0.03) - 1) < 1e-2, last["force_lid_z"]
down = last["servo_lid_displacement"]
assert 0.01 < down < 0.02, down
radius = [[float(x) for x in a.text.split()]
          for a in ET.parse(run + "/snapshots/spheres_000001.vtp").iter("DataArray")
          if a.get("Name") == "radius"][0]
below = sum(4 / 3 * math.pi * r ** 3 for r in radius) / (0.03 * 0.03 * (0.02 - down))
assert abs(last["region_packing_fraction"] - below) < 1e-6, (last["region_packing_fraction"], below)
PY
# a chute: gravity tilted down x over a rough floor of glued spheres, periodic across; the flow
# drags the glued spheres down the slope and weighs on them
"$talus" run pour3d --out "$dir/chute" --quiet --set particles.count=100 --set simulation.duration=0.1 \
  --set geometry.periodic=xy --set geometry.rough_floor=true --set "simulation.gravity=[4.3, 0, -8.8]" \
  --set output.snapshot_interval=0.05
/usr/bin/python3 - "$dir/chute/thermo.csv" <<'PY'
import csv, sys
last = {k: float(v) for k, v in list(csv.DictReader(open(sys.argv[1])))[-1].items()}
assert last["force_fixed_x"] > 0 > last["force_fixed_z"], last
assert last["kinetic"] > 0, last
PY
# its analysis: two layers are too shallow for Bagnold's profile, and chute.json says why
"$talus" analyze "$dir/chute" chute > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
grep -q '"measured": false, "why_not": "the flow is' "$dir/chute/analysis/chute.json" \
  || { cat "$dir/chute/analysis/chute.json"; exit 1; }
# run.json says what the step left out: one material here; without friction, rotation too
grep -q '"step": "one material"' "$run/run.json" || { echo "FAIL: run.json's step"; exit 1; }
"$talus" run pour3d --out "$dir/frictionless" --quiet --set particles.count=30 \
  --set simulation.duration=0.01 --set simulation.tangential_law=none
grep -q '"step": "frictionless, no rotation, one material"' "$dir/frictionless/run.json" \
  || { echo "FAIL: the frictionless run's step"; exit 1; }
for command in render movie checkpoint; do
  if "$talus" "$command" "$run" > "$dir/out.txt" 2>&1; then echo "FAIL: $command took a 3D run"; exit 1; fi
  grep -q "is a run of spheres in 3D" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
done
# talus analyze: the thermo chart, the contact force distribution, the coarse-grained fields
# along gravity's axis from the snapshots' spheres and contacts, whose density integrates to the
# spheres' mass, and the report; the 2D analyses refuse
"$talus" analyze "$run" > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
[ -s "$run/analysis/report.html" ] || { echo "FAIL: no report.html of a 3D run"; exit 1; }
grep -q '"contacts": [1-9]' "$run/analysis/forces.json" || { echo "FAIL: no force distribution"; exit 1; }
head -1 "$run/analysis/fields.csv" | grep -q "^z,density,velocity_x,velocity_y,velocity_z,kinetic_xx" \
  || { echo "FAIL: fields.csv header"; exit 1; }
/usr/bin/python3 - "$run/analysis/fields.json" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))
assert f["dimension"] == 3 and f["axis"] == "z" and f["frames"] == 7, f
assert abs(f["mass_integral"] - f["mass"]) < 1e-6 * f["mass"], f
PY
"$talus" analyze "$run" fields --axis x --kernel lucy > /dev/null || { echo "FAIL: fields along x"; exit 1; }
head -1 "$run/analysis/fields.csv" | grep -q "^x,density" || { echo "FAIL: fields along x"; exit 1; }
if "$talus" analyze "$run" janssen > "$dir/out.txt" 2>&1; then echo "FAIL: janssen took a 3D run"; exit 1; fi
grep -q "is a run of spheres in 3D, whose analyses are thermo, forces, fields, rheology and chute" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
if "$talus" analyze "$run" rheology > "$dir/out.txt" 2>&1; then echo "FAIL: rheology of a bed"; exit 1; fi
grep -q "rheology is that of a sheared cell" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
if "$talus" analyze "$run" fields --map > "$dir/out.txt" 2>&1; then echo "FAIL: a 3D map"; exit 1; fi
grep -q "maps are of 2D runs" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
# stopped at a checkpoint and resumed, with outputs past the checkpoint left behind by a run that
# died (a row of thermo.csv, a snapshot): the same files as a run that never stopped
short="--quiet --set particles.count=60 --set simulation.duration=0.1 --set simulation.timestep_factor=20
       --set output.snapshot_interval=0.02 --set output.checkpoint_interval=0.03
       --set output.energy_ledger=true"
"$talus" run pour3d --out "$dir/whole" $short
status=0; "$talus" run pour3d --out "$dir/parts" $short --stop-at 0.045 || status=$?
[ "$status" -eq 4 ] || { echo "FAIL: --stop-at exited with $status, not 4"; exit 1; }
echo "0.05,1,2,3" >> "$dir/parts/thermo.csv"
cp "$dir/parts/snapshots/spheres_000002.vtp" "$dir/parts/snapshots/spheres_000003.vtp"
"$talus" resume "$dir/parts" --quiet
for f in thermo.csv particles.pvd walls.pvd contacts.pvd $(cd "$dir/whole" && ls snapshots/*); do
  cmp -s "$dir/whole/$f" "$dir/parts/$f" || { echo "FAIL: $f differs after a resume"; exit 1; }
done
[ "$(ls "$dir/parts/snapshots" | wc -l)" -eq "$(ls "$dir/whole/snapshots" | wc -l)" ] \
  || { echo "FAIL: the snapshots after a resume are not the whole run's"; exit 1; }
# resume --set changes a 3D run's outputs' intervals and nothing else: more snapshots from the
# checkpoint on, the same thermo rows and end as the run that never stopped; physics is refused
status=0; "$talus" run pour3d --out "$dir/more" $short --stop-at 0.045 || status=$?
[ "$status" -eq 4 ] || { echo "FAIL: --stop-at exited with $status, not 4"; exit 1; }
"$talus" resume "$dir/more" --quiet --set output.snapshot_interval=0.01
grep -q "^snapshot_interval = 0.01$" "$dir/more/scenario.toml" || { echo "FAIL: scenario.toml"; exit 1; }
cmp -s "$dir/whole/thermo.csv" "$dir/more/thermo.csv" || { echo "FAIL: thermo.csv after --set"; exit 1; }
[ "$(ls "$dir/more/snapshots" | wc -l)" -gt "$(ls "$dir/whole/snapshots" | wc -l)" ] \
  || { echo "FAIL: no more snapshots after resume --set"; exit 1; }
cmp -s "$(ls "$dir"/whole/snapshots/spheres_*.vtp | tail -1)" \
  "$(ls "$dir"/more/snapshots/spheres_*.vtp | tail -1)" || { echo "FAIL: the end differs"; exit 1; }
if "$talus" resume "$dir/more" --set "simulation.gravity=[0, 0, -5]" > "$dir/out.txt" 2>&1; then
  echo "FAIL: resume --set changed gravity"; exit 1
fi
grep -q "changes only its outputs' intervals .*allowed: output.thermo_interval" "$dir/out.txt" \
  || { cat "$dir/out.txt"; exit 1; }
# a finished run is refused without --duration, and a --duration not beyond its time; run on
# with --duration it ends where the run that was that long from the start ends, to the bit
if "$talus" resume "$dir/whole" > "$dir/out.txt" 2>&1; then echo "FAIL: a finished run resumed"; exit 1; fi
grep -q "has ended at t = .*--duration T" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
if "$talus" resume "$dir/whole" --duration 0.05 > "$dir/out.txt" 2>&1; then
  echo "FAIL: a shorter --duration was taken"; exit 1
fi
grep -q "the run is at t = .* already" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
"$talus" resume "$dir/whole" --duration 0.13 --quiet
"$talus" run pour3d --out "$dir/long" $short --set simulation.duration=0.13
grep -q "^duration = 0.13$" "$dir/whole/scenario.toml" || { echo "FAIL: scenario.toml not lengthened"; exit 1; }
last() { ls "$1"/snapshots/spheres_*.vtp | tail -1; }
cmp -s "$(last "$dir/whole")" "$(last "$dir/long")" \
  || { echo "FAIL: a lengthened run does not end as the run that long from the start"; exit 1; }
# Gear at 5 steps a collision gains energy with no overlap near the guard's limit: the ledger
# stops the run, saying so, and run.json says why it ended
status=0
"$talus" run pour3d --out "$dir/gains" --quiet --set particles.count=200 --set simulation.duration=0.3 \
  --set simulation.integrator=gear --set simulation.timestep_factor=5 --set output.energy_ledger=true \
  > "$dir/out.txt" 2>&1 || status=$?
[ "$status" -ne 0 ] || { echo "FAIL: a run gaining energy went on"; exit 1; }
grep -q "the energy grew by .* (the energy ledger" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
grep -q '"ended_by": "unstable"' "$dir/gains/run.json" || { echo "FAIL: run.json"; exit 1; }
# and a resolved 3D scenario reruns as it is
"$talus" run "$run/scenario.toml" --out "$dir/again" --quiet --set simulation.duration=0.01
echo "pour3d: run, snapshots read back, fields analysed, stopped and resumed as one run, 2D commands refuse it"
