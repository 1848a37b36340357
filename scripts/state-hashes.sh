#!/usr/bin/env bash
# Prints the final state hash of a short run of every built-in scenario, and of a few variants
# with the other laws and integrators, one line each: "NAME HASH". Two trees that print the same
# lines compute the same physics to the bit (the hash covers every particle's state; see
# `talus checkpoint`). Used to show that a refactoring changed nothing:
#   scripts/state-hashes.sh build/native/talus > before.txt   (then after, and diff)
set -euo pipefail
talus="${1:?usage: scripts/state-hashes.sh PATH/TO/talus}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

short_of() {
  case "$1" in
    collisions) echo "--set simulation.duration=0.06" ;;
    drum) echo "--set particles.count=80 --set simulation.duration=0.1 --set packing.settle_max_time=0.1" ;;
    force_network) echo "--set particles.count=80 --set simulation.duration=0.1" ;;
    frost_heave) echo "--set particles.count=300 --set simulation.duration=0.08 --set packing.settle_max_time=0.05
                  --set frost.min_interval=0.02 --set frost.kinetic_threshold=1e3 --set frost.heave_factor=1.02" ;;
    frost_front) echo "--set particles.count=200 --set simulation.duration=0.6 --set packing.settle_max_time=0.1
                  --set frost.freeze_time=0.1 --set frost.thaw_time=0.1 --set frost.heave_strain=0.1
                  --set frost.min_interval=0.02 --set frost.kinetic_threshold=1e-1 --set frost.cycles=1" ;;
    heap) echo "--set particles.count=80 --set stages.1.duration=0.1 --set stages.2.duration=0.2" ;;
    jamming) echo "--set particles.count=100 --set geometry.box=[0,0,0.16,0.16]
                  --set packing.region=[0,0,0.16,0.16] --set stages.0.duration=0.3
                  --set stages.1.duration=0.1 --set stages.2.duration=0.1 --set stages.3.duration=0.1
                  --set stages.4.duration=0.1 --set stages.5.duration=0.1" ;;
    janssen) echo "--set particles.count=300 --set geometry.height=0.3 --set packing.settle_max_time=0.2
                  --set stages.0.duration=0.02 --set stages.1.duration=0.03" ;;
    hourglass) echo "--set particles.count=150 --set simulation.duration=0.1 --set packing.settle_max_time=0.2" ;;
    silo_discharge) echo "--set particles.count=150 --set geometry.width=0.12 --set geometry.height=0.25
                  --set simulation.duration=0.2 --set packing.settle_max_time=0.3" ;;
    silo_shake) echo "--set particles.count=60 --set simulation.duration=0.1 --set packing.settle_max_time=0.1" ;;
    tilted_box) echo "--set particles.count=60 --set simulation.duration=0.2 --set stages.1.duration=0.05
                  --set stages.2.duration=0.05" ;;
    silo_gate) echo "--set particles.count=60 --set stages.0.duration=0.15 --set stages.2.count=5" ;;
    shear) echo "--set simulation.duration=0.3" ;;
    chute) echo "--set simulation.duration=0.1" ;;
    chute_stop) echo "--set particles.count=100 --set stages.0.duration=0.05 --set stages.1.duration=0.05" ;;
    *) echo "scripts/state-hashes.sh: no short version of '$1'" >&2; exit 1 ;;
  esac
}

hash_of() { # LABEL NAME ARGS...
  local label="$1" name="$2"
  shift 2
  # shellcheck disable=SC2046
  "$talus" run "$name" --quiet --out "$dir/$label" --set output.snapshot_interval=0 --set "output.pictures=[]" \
    --set output.checkpoint_interval=0 $(short_of "$name") "$@" > /dev/null
  echo "$label $("$talus" checkpoint "$dir/$label" | awk '/state_hash/ {print $2}')"
}

for name in $("$talus" scenarios | awk '{print $1}'); do
  hash_of "$name" "$name"
done
hash_of drum-hertz-mindlin-verlet drum --set simulation.normal_law=hertz \
  --set simulation.tangential_law=mindlin --set simulation.integrator=verlet
hash_of drum-hertz-coulomb drum --set simulation.normal_law=hertz --set simulation.tangential_law=coulomb
hash_of hourglass-verlet-2threads hourglass --set simulation.integrator=verlet --threads 2
hash_of hourglass-2threads hourglass --threads 2 --set particles.count=1200
hash_of heap-verlet-2threads heap --set simulation.integrator=verlet --threads 2
