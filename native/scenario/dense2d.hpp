#pragma once
// The reference benchmark system (inputs/dense2d/README.md): NX x NY polydisperse disks on a floor,
// periodic in x, under gravity, with the LAMMPS input's contact law and parameters.
#include "simulation/simulation.hpp"

namespace talus {

struct Dense2d {
  World world;
  SimulationConfig config;
};

/// The LAMMPS input's grain material: density 1000 kg/m^3, k_n = 1e5 N/m, k_t = 2/7 k_n,
/// gamma_n = 100 1/s, gamma_t = 50 1/s, mu = 0.5.
Material dense2d_material();

/// The thesis' laws on the benchmark's grains (viscoelastic Hertz, the Coulomb-capped viscous
/// friction), as inputs/dense2d/lammps-bench.in sets them for pair_style granthesis: E = 1.5e9
/// Pa and nu = 0.3 give about k_n = 1e5 N/m's force at the settled packing's deepest overlaps,
/// A = 2e-6 s, gamma_t = 50 1/s, mu = 0.5.
Material dense2d_thesis_material();

/// The dense2d world and config switched to the thesis' laws (dense2d_thesis_material, hertz and
/// coulomb), as `talus bench dense2d --laws thesis` settles and times it.
void use_thesis_laws(World& world, SimulationConfig& config);

/// The unsettled lattice: diameters uniform in [8.5, 9.5] mm on a 1 cm square lattice (as the
/// LAMMPS input's `lattice sq 0.01`), density 1000 kg/m^3 with LAMMPS' sphere mass and disc
/// inertia (I = m r^2 / 2); k_n = 1e5 N/m, k_t = 2/7 k_n, gamma_n = 100 1/s, gamma_t = 50 1/s,
/// mu = 0.5, the same law on the floor at y = 0; velocity Verlet, dt = 1e-5 s, skin 1 mm.
/// `count` > 0 keeps only the first `count` lattice sites (rows fill from the floor up).
Dense2d build_dense2d(std::size_t nx, std::size_t ny, std::uint64_t seed = 12345,
                      std::size_t count = 0);

/// `copies` settled dense2d packings side by side along x. The base is periodic in x, so the
/// copies fit edge to edge and the result is itself a settled packing, `copies` times as wide,
/// without settling again: every per-particle field is repeated (positions shifted by the base
/// width, ids renumbered), and the contact history of each pair is that of the base pair it
/// copies. The neighbour list is rebuilt with `skin`.
SimulationState tile_dense2d(const SimulationState& base, std::size_t copies, double skin);

} // namespace talus
