#!/usr/bin/env bash
# talus bench dense2d on a tiny system: it settles and caches the packing, times the steps,
# prints its figures and appends a CSV row; --tiles widens the cached packing without settling
# again; a base smaller than 3 x 3 disks is refused with a message. Figures, not a timing test.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
run() { "$talus" bench dense2d --cache "$dir/cache" --results "$dir/results" "$@"; }
run --n 100 --steps 20 > "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
cat "$dir/out.txt"
grep -q "settling 10 x 10 disks" "$dir/out.txt" || { echo "no settling"; exit 1; }
grep -q "ns per particle-step:" "$dir/out.txt" || exit 1
grep -q "engine memory per particle:" "$dir/out.txt" || exit 1
[ -s "$dir/cache/dense2d_10x10.ckpt" ] || { echo "no cached packing"; exit 1; }
run --n 300 --tiles 3 --steps 20 > "$dir/tiled.txt" || { cat "$dir/tiled.txt"; exit 1; }
cat "$dir/tiled.txt"
grep -q "settled packing from" "$dir/tiled.txt" || { echo "the tiled run settled again"; exit 1; }
grep -q "300 disks (30 x 10)" "$dir/tiled.txt" || { echo "not 3 copies side by side"; exit 1; }
csv=$(ls "$dir"/results/*.csv)
head -1 "$csv" | grep -q "ns_per_particle_step.*engine_bytes_per_particle,skin_m$" || exit 1
[ "$(wc -l < "$csv")" -eq 3 ] || { echo "expected a header and two rows"; cat "$csv"; exit 1; }
# --rounds: the same steps timed again from the same state, the medians reported, one CSV row
run --n 100 --steps 20 --rounds 2 > "$dir/rounds.txt" || { cat "$dir/rounds.txt"; exit 1; }
cat "$dir/rounds.txt"
[ "$(grep -c '^  round [12]: talus ' "$dir/rounds.txt")" -eq 2 ] || { echo "expected 2 rounds"; exit 1; }
grep -q "ns per particle-step: .*(median of 2 rounds)" "$dir/rounds.txt" || exit 1
[ "$(wc -l < "$csv")" -eq 4 ] || { echo "expected a header and three rows"; cat "$csv"; exit 1; }
# --laws thesis: the packing settled and cached with the thesis' laws, apart from the other
run --n 100 --steps 20 --laws thesis > "$dir/thesis.txt" || { cat "$dir/thesis.txt"; exit 1; }
grep -q "the thesis' (hertz, coulomb) laws" "$dir/thesis.txt" || { cat "$dir/thesis.txt"; exit 1; }
[ -s "$dir/cache/dense2d_thesis_10x10.ckpt" ] || { echo "no cached thesis packing"; exit 1; }
grep -q ',dense2d_thesis,' "$csv" || { echo "no dense2d_thesis row"; exit 1; }
run --n 100 --laws hertz 2> "$dir/err.txt" && { echo "--laws hertz was accepted"; exit 1; }
grep -q "hooke" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
run --n 100 --rounds 0 2> "$dir/err.txt" && { echo "--rounds 0 was accepted"; exit 1; }
grep -q "rounds" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
run --n 100 --tiles 50 2> "$dir/err.txt" && { echo "a 1 x 1 base was accepted"; exit 1; }
grep -q "allowed: n / tiles >= 9" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
# bench linear: every size timed in turns, round by round, its median in the table and the CSV;
# a base settled for another time is cached apart
"$talus" bench linear --base 4 --tiles 1,3 --rounds 3 --particle-steps 2000 --min-steps 10 \
  --settle-time 0.05 --cache "$dir/cache" --results "$dir/results" > "$dir/linear.txt" ||
  { cat "$dir/linear.txt"; exit 1; }
cat "$dir/linear.txt"
grep -q "settling 4 x 4 disks for 0.05 s" "$dir/linear.txt" || { echo "no settling"; exit 1; }
[ -s "$dir/cache/dense2d_4x4_0.05s.ckpt" ] || { echo "no cached base packing"; exit 1; }
[ "$(grep -c '^  round ' "$dir/linear.txt")" -eq 3 ] || { echo "expected 3 rounds"; exit 1; }
grep -q "^| 16 | 125 |" "$dir/linear.txt" || { echo "no row for 16 disks, 125 steps"; exit 1; }
grep -q "^| 48 | 42 |" "$dir/linear.txt" || { echo "no row for 48 disks, 42 steps"; exit 1; }
grep -q "largest / smallest median: " "$dir/linear.txt" || exit 1
[ "$(grep -c ',dense2d_linear,' "$csv")" -eq 2 ] || { echo "expected two linear rows"; exit 1; }
# bench threads: one system, a copy per thread count timed in turns, the states compared
"$talus" bench threads --n 100 --threads 1,2 --steps 20 --rounds 2 --cache "$dir/cache" \
  --results "$dir/results" > "$dir/threads.txt" || { cat "$dir/threads.txt"; exit 1; }
cat "$dir/threads.txt"
grep -q "^| 1 | .* | 1.00 | 1.00 |$" "$dir/threads.txt" || { echo "no row for 1 thread"; exit 1; }
grep -q "^| 2 | " "$dir/threads.txt" || { echo "no row for 2 threads"; exit 1; }
grep -q "bit-identical for every thread count: yes" "$dir/threads.txt" || exit 1
[ "$(grep -c ',dense2d_threads,' "$csv")" -eq 2 ] || { echo "expected two threads rows"; exit 1; }
# beside a busy process: the same states, and the busy process gone afterwards
"$talus" bench threads --busy --n 100 --threads 1,2 --steps 20 --rounds 2 --cache "$dir/cache" \
  --results "$dir/results" > "$dir/busy.txt" || { cat "$dir/busy.txt"; exit 1; }
grep -q "beside another process that keeps one core busy" "$dir/busy.txt" || { cat "$dir/busy.txt"; exit 1; }
grep -q "bit-identical for every thread count: yes" "$dir/busy.txt" || exit 1
[ "$(grep -c ',dense2d_threads_busy,' "$csv")" -eq 2 ] || { echo "expected two busy rows"; exit 1; }
"$talus" bench linear --tiles 0 --cache "$dir/cache" 2> "$dir/err.txt" &&
  { echo "--tiles 0 was accepted"; exit 1; }
grep -q -- "--tiles" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
# bench cell: the three cases timed in turns, each with its row in the table and the CSV
"$talus" bench cell --side 10 --steps 20 --rounds 2 --results "$dir/results" > "$dir/cell.txt" ||
  { cat "$dir/cell.txt"; exit 1; }
cat "$dir/cell.txt"
for case in "pressure" "strain rate 0" "no cell"; do
  grep -q "^| $case | " "$dir/cell.txt" || { echo "no row for $case"; exit 1; }
done
[ "$(grep -c ',cell_\(pressure\|rate\|none\),' "$csv")" -eq 3 ] || { echo "expected three cell rows"; exit 1; }
# bench chute: the 3D system flows and is cached, is timed, and LAMMPS (where lmp is installed)
# reads the same state from the data file and times it; too few spheres are refused
chute() { "$talus" bench chute --cache "$dir/cache" --results "$dir/results" "$@"; }
lammps=()
command -v lmp > /dev/null && lammps=(--lammps)
chute --n 1000 --flow-steps 50 --steps 10 "${lammps[@]}" > "$dir/chute.txt" ||
  { cat "$dir/chute.txt"; exit 1; }
cat "$dir/chute.txt"
grep -q "letting the layer flow for 50 steps" "$dir/chute.txt" || exit 1
grep -q "1280 spheres (8 x 4 frozen base, 39 layers above)" "$dir/chute.txt" || exit 1
[ -s "$dir/cache/chute/chute_1000_50steps.ckpt3" ] || { echo "no cached flowing layer"; exit 1; }
grep -q ',chute,1280,10,' "$csv" || { echo "no chute row"; cat "$csv"; exit 1; }
if [ ${#lammps[@]} -gt 0 ]; then
  grep -q "LAMMPS gran/hooke/history: .* ns per particle-step on 1 rank" "$dir/chute.txt" ||
    { cat "$dir/cache/chute/bench.out"; exit 1; }
  grep -q "Loop time of .* for 10 steps with 1280 atoms" "$dir/cache/chute/bench.log" || exit 1
fi
chute --n 1000 --flow-steps 50 --steps 10 > "$dir/chute2.txt" || { cat "$dir/chute2.txt"; exit 1; }
grep -q "flowing layer from" "$dir/chute2.txt" || { echo "the layer flowed again"; exit 1; }
# --steps-with: the specialised step and the general one, in turns, both in the results
chute --n 1000 --flow-steps 50 --steps 10 --rounds 2 --steps-with none > "$dir/chute3.txt" ||
  { cat "$dir/chute3.txt"; exit 1; }
grep -q "the step specialised to it: frictionless, no rotation, one material" "$dir/chute3.txt" ||
  { cat "$dir/chute3.txt"; exit 1; }
grep -q "round 2: specialised .* ns per particle-step, general .*x)" "$dir/chute3.txt" || exit 1
grep -q ',chute_none,1280,10,' "$csv" && grep -q ',chute_none_general,1280,10,' "$csv" ||
  { echo "no frictionless rows"; cat "$csv"; exit 1; }
chute --steps-with none --lammps 2> "$dir/err.txt" && { echo "--steps-with --lammps was accepted"; exit 1; }
chute --steps-with sticky 2> "$dir/err.txt" && { echo "a law that does not exist was accepted"; exit 1; }
grep -q "cundall_strack" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
chute --n 500 2> "$dir/err.txt" && { echo "500 spheres were accepted"; exit 1; }
grep -q "1000" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
exit 0
