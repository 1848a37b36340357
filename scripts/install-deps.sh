#!/usr/bin/env bash
# Installs the Debian packages talus needs to build and test, if any are missing.
set -euo pipefail

packages=(
  g++ cmake ninja-build     # compiler and build
  libgtest-dev              # tests (GoogleTest)
  libfmt-dev libcli11-dev   # formatting, command line
  libcairo2-dev pkg-config  # pictures
  libtomlplusplus-dev       # scenario files
  nlohmann-json3-dev        # sweep plans and indexes (JSON)
  libeigen3-dev             # linear algebra (fits)
  python3-vtk9              # tests: VTK reads the snapshots as ParaView does
  ffmpeg                    # talus movie
  python3-matplotlib        # talus analyze: charts
  python3-scipy             # the cross-check's pass rule (Student's t quantiles)
  lammps                    # talus bench --lammps: the reference engine on the same system
  liblammps-dev             # the LAMMPS package (lammps-package/): pair_style granthesis
  python3-lammps            # its tests: the styles registered in LAMMPS' Python module
  liggghts libliggghts-dev  # the same pair style in LIGGGHTS (lammps-package/liggghts/)
  pybind11-dev python3-dev  # the Python module (python/)
  python3-pytest            # its tests
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "talus: installing missing Debian packages: ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
