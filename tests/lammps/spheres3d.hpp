#pragma once
// Spheres in a 3D LAMMPS box with pair_style granthesis: the set-up the 3D tests share.
#include <string>
#include <vector>

#include "two_disks.hpp"

namespace talus::lammps_test {

struct Sphere {
  Vec3 position, velocity, spin;
  double radius, mass;
};

inline Material spheres_material() {
  Material m;
  m.young = 1e8;
  m.poisson = 0.3;
  m.normal_stiffness = 1e4;
  m.friction = 0.4;
  m.restitution = 0.6;
  return m;
}

// Spheres in a 3D LAMMPS box, SI units, with no pair style yet: `boundary` and `box` as LAMMPS'
// commands take them.
inline void spheres_in_box(LammpsInstance& l, const std::vector<Sphere>& spheres,
                           const std::string& boundary, const std::string& box) {
  l.commands({"dimension 3", "units si", "atom_style sphere", "atom_modify map array",
              "boundary " + boundary, ghost_velocities, "newton off", "region box block " + box,
              "create_box 1 box"});
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const Sphere& s = spheres[k];
    const std::string id = std::to_string(k + 1);
    l.command(words(
        {"create_atoms 1 single", exact(s.position.x), exact(s.position.y), exact(s.position.z)}));
    l.command(words({"set atom", id, "diameter", exact(2.0 * s.radius)}));
    l.command(words({"set atom", id, "mass", exact(s.mass)}));
    l.command(words({"set atom", id, "vx", exact(s.velocity.x), "vy", exact(s.velocity.y), "vz",
                     exact(s.velocity.z)}));
    double* w = l.lmp()->atom->omega[l.index(static_cast<int>(k) + 1)];
    w[0] = s.spin.x, w[1] = s.spin.y, w[2] = s.spin.z;
  }
}

// The spheres with pair_style granthesis of the laws `laws` and material m.
inline void set_up_3d(LammpsInstance& l, const std::string& laws, const Material& m,
                      const std::vector<Sphere>& spheres, double dt,
                      const std::string& boundary = "f f f",
                      const std::string& box = "-0.1 0.1 -0.1 0.1 -0.1 0.1") {
  spheres_in_box(l, spheres, boundary, box);
  l.commands({words({"pair_style granthesis", laws}), "pair_coeff 1 1 " + pair_coefficient_words(m),
              "neighbor 0.001 bin", words({"timestep", exact(dt)})});
}

} // namespace talus::lammps_test
