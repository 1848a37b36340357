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
run --n 100 --tiles 50 2> "$dir/err.txt" && { echo "a 1 x 1 base was accepted"; exit 1; }
grep -q "allowed: n / tiles >= 9" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
exit 0
