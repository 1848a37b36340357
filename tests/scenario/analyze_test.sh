#!/usr/bin/env bash
# talus analyze on a short run: the CSV and JSON outputs hold their documented columns and a
# fitted tail; the charts exist when matplotlib is installed.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$talus" run drum --quiet --out "$dir/run" --set simulation.duration=0.3 \
  --set output.snapshot_interval=0.05 --set packing.settle_max_time=0.3 || exit 1
"$talus" analyze "$dir/run" profiles --from 99 2> /dev/null && { echo "--from past the end was accepted"; exit 1; }
[ -e "$dir/run/analysis" ] && { echo "a failed analysis left an analysis folder"; exit 1; }
"$talus" analyze "$dir/run" all > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
cat "$dir/out.txt"
head -1 "$dir/run/analysis/forces.csv" | grep -q "^f_over_mean,probability_density,count$" || exit 1
grep -q '"beta"' "$dir/run/analysis/forces.json" || exit 1
grep -q "carry less than the mean force" "$dir/out.txt" || exit 1
# the report page shows the scenario and run.json as tables
for words in "<h2>Scenario</h2>" "<td>normal law</td><td>linear</td>" "<td>material 0 'grain'</td><td>density = 2650 kg/m^3" "<h2>Run</h2>" "<td>particle-steps per second (last session)</td>"; do
  grep -qF "$words" "$dir/run/analysis/report.html" || { echo "report.html lacks: $words"; exit 1; }
done
# what does not apply is skipped, saying why: the drum's grains are of one size, about
grep -q "segregation: skipped (the grains' radii span .* too alike to sort by size" "$dir/out.txt" || { echo "segregation not skipped"; exit 1; }
# profiles leave the start-up out unless --from says otherwise
grep -q "profiles: .* from t = .* (the first quarter of the run left out as its start-up" "$dir/out.txt" || { echo "profiles from the start"; exit 1; }
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  [ -s "$dir/run/analysis/thermo.png" ] && [ -s "$dir/run/analysis/forces.png" ] || { echo "charts missing"; exit 1; }
fi
"$talus" analyze "$dir/run" nonsense 2> /dev/null && { echo "a bad analysis name was accepted"; exit 1; }
# coarse-grained fields: the documented columns, and a chart
"$talus" analyze "$dir/run" fields --kernel lucy > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
head -1 "$dir/run/analysis/fields.csv" | grep -q "^y,density,velocity_x,velocity_y,kinetic_xx,kinetic_xy,kinetic_yy,contact_xx,contact_xy,contact_yx,contact_yy$" || { echo "fields.csv columns"; exit 1; }
grep -q '"kernel": "lucy"' "$dir/run/analysis/fields.json" || exit 1
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  [ -s "$dir/run/analysis/fields.png" ] || { echo "fields chart missing"; exit 1; }
fi
# and as maps
"$talus" analyze "$dir/run" fields --map > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
head -1 "$dir/run/analysis/fields_map.csv" | grep -q "^x,y,density,velocity_x,velocity_y,kinetic_xx,kinetic_xy,kinetic_yy,contact_xx,contact_xy,contact_yx,contact_yy$" || { echo "fields_map.csv columns"; exit 1; }
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  [ -s "$dir/run/analysis/fields_map.png" ] || { echo "fields_map chart missing"; exit 1; }
fi
# a chart that fails (a damaged thermo.csv) makes the command fail, naming the chart
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  printf 'not,a,number\0\0\0\n' >> "$dir/run/thermo.csv"
  "$talus" analyze "$dir/run" thermo > "$dir/out.txt" 2>&1 && { cat "$dir/out.txt"; echo "a failed chart exited 0"; exit 1; }
  grep -q "the chart .*thermo.png failed" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
fi
exit 0
