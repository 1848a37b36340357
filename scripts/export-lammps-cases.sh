#!/bin/bash
# Writes the LAMMPS cases of the thesis' experiments into inputs/<experiment>/lammps/ with
# `talus export lammps` (run from the repository root after building). Each case is its native
# scenario in the thesis' own terms, as the cross-check's cases (validation/) were set up on
# them; the native laws and segment walls export too (granthesis keeps springs, and fix
# granthesis/wall is the segment walls), but these cases stay:
# - the thesis' tangential law, the Coulomb-capped viscous friction (eq. 2.12), for the native
#   scenarios' Cundall-Strack spring; its rate tangential_damping is about the normal dashpot's
#   rate for a pair of mean grains;
# - the thesis' particle walls for segment walls;
# - where particle walls take room: the hourglass holds 1780 grains, not 1859, and the frost box's
#   stones sit a wall particle's radius higher.
# The viscous friction holds no static pile: the hourglass' packing still creeps when its
# settle_max_time (3 s) ends, and export says so; its case starts from there.
# The deck's header repeats the command, and scenario.toml beside it is the native twin.
set -euo pipefail
cd "$(dirname "$0")/.."
talus=build/native/talus
coulomb() { echo "--set simulation.tangential_law=coulomb --set materials[0].tangential_damping=$1"; }
walls="--set geometry.walls=particles"

export_case() { # name, then the overrides
  local name=$1
  shift
  echo "== $name"
  "$talus" export lammps "inputs/$name/scenario.toml" "inputs/$name/lammps" --quiet --replace "$@"
}

export_case collisions
export_case hourglass $(coulomb 5000) $walls --set particles.count=1780
export_case silo_shake $(coulomb 5000)
export_case force_network $(coulomb 5000) $walls
export_case drum $(coulomb 5000) $walls
export_case frost_heave $(coulomb 2e5) $walls --set geometry.wall_particle_radius=2e-5 \
  --set 'particles.list[0].position=[0.0025,0.00032]' \
  --set 'particles.list[1].position=[0.0055,0.00022]' \
  --set 'particles.list[2].position=[0.0085,0.00017]'
