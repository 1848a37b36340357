#pragma once
// Registration of the package's styles with a LAMMPS instance: the styles' names in LAMMPS'
// pair and fix maps, as LAMMPS registers its own. After LAMMPS' `clear`, which builds those maps
// again, call it again.

/// lmp is a LAMMPS_NS::LAMMPS* (void* for callers through ctypes, such as python3-lammps:
/// ctypes.CDLL("libtalus_lammps.so").talus_lammps_register(lmp.lmp)).
extern "C" void talus_lammps_register(void* lmp);
