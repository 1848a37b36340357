#pragma once
// The system of LAMMPS' chute benchmark (its bench/in.chute) for the native 3D engine: spheres
// flowing down a rough base of frozen spheres, periodic along and across the slope, with the law
// and parameters of the LAMMPS input, in its reduced units (diameter 1, density 1, gravity 1).
#include <cstdint>

#include "engine3d/scene3.hpp"

namespace talus {

struct ChuteBench {
  Scene3 scene;
  Settings3 settings;
  std::size_t nx = 0, ny = 0; ///< base spheres along and across the slope
  std::size_t layers = 0;     ///< layers of free spheres above the base
};

/// The spheres' gran/hooke/history material of in.chute (`200000.0 NULL 50.0 NULL 0.5 0`):
/// density 1, k_n = 2e5, k_t = 2/7 k_n, gamma_n = 50, no tangential damping (dampflag 0),
/// mu = 0.5.
Material chute_bench_material();

/// The layers of free spheres above the base: the box's height in diameters.
inline constexpr std::size_t chute_bench_layers = 39;

/// About n spheres (n >= 1000, InvalidArgument otherwise): a base of nx x ny frozen spheres of
/// diameter 1 on a unit square lattice at z = 0, each raised by up to 0.1 at random (a rough
/// base), nx = 2 ny; above it chute_bench_layers layers of free spheres on the same lattice,
/// their diameters uniform in [0.9, 1), their velocities uniform in [-0.1, 0.1) per component.
/// Periodic in x (down the slope) and y; gravity 1 tilted by 26 degrees down x, as LAMMPS'
/// `fix gravity 1.0 chute 26.0`; linear spring-dashpot and Cundall-Strack; velocity Verlet,
/// dt = 1e-4, skin 0.1 (in.chute's `neighbor 0.1 bin`), the spheres renumbered every 1000 steps
/// (LAMMPS' default atom sort). n = 32,000, in.chute's count, gives a
/// 40 x 20 base.
ChuteBench build_chute_bench(std::size_t n, std::uint64_t seed = 12345);

/// The scene repeated k x k times across its periodic x and y (k >= 1): each sphere with its
/// copies shifted by whole box lengths, with the same velocity and spin, in a box k times as long
/// and as wide. A larger sample of the same state, for the cost against the number of spheres.
/// InvalidArgument where x or y is not periodic, or the scene has plates.
Scene3 tiled_across(const Scene3& scene, std::size_t k);

} // namespace talus
