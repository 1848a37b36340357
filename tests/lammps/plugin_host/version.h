#pragma once
// The test host's LAMMPS version string (a real LAMMPS tree has its own version.h).
#define LAMMPS_VERSION "test host"
