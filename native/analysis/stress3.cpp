#include "analysis/stress3.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "analysis/contact_forces3.hpp"

namespace talus {

namespace {

Tensor3 outer(const Vec3& a, const Vec3& b) {
  Tensor3 t;
  t << a.x * b.x, a.x * b.y, a.x * b.z, a.y * b.x, a.y * b.y, a.y * b.z, a.z * b.x, a.z * b.y,
      a.z * b.z;
  return t;
}

// Whether sphere i's centre lies in [lo, hi): where it is wrapped into a periodic box (between
// two list builds a sphere may have crossed the box's side unwrapped).
bool inside(const Simulation3& sim, std::size_t i, const Vec3& lo, const Vec3& hi) {
  Image3 crossed{};
  const Vec3 r = sim.scene().domain.wrap(sim.scene().spheres.position[i], crossed);
  return r.x >= lo.x && r.x < hi.x && r.y >= lo.y && r.y < hi.y && r.z >= lo.z && r.z < hi.z;
}

// Every contact's force on a sphere with its branch, as on_side(i, f, l) (a pair calls it for
// both spheres, a plate for its sphere), and on_pair(i, j, n) once for each sphere-sphere
// contact.
template <class OnSide, class OnPair>
void visit_contact_forces(const Simulation3& sim, OnSide&& on_side, OnPair&& on_pair) {
  const Spheres& s = sim.scene().spheres;
  visit_contact_forces3(
      sim,
      [&](std::uint32_t i, std::uint32_t j, const ContactGeometry3& g, const Vec3& f) {
        // the middle of the overlap, from each centre
        const double half = 0.5 * g.overlap;
        on_side(i, f, -(s.radius[i] - half) * g.normal);
        on_side(j, -f, (s.radius[j] - half) * g.normal);
        on_pair(i, j, g.normal);
      },
      [&](std::uint32_t i, std::uint32_t, const ContactGeometry3& g, const Vec3& f) {
        // the plate's point, nearest the centre
        on_side(i, f, -(s.radius[i] - g.overlap) * g.normal);
      });
}

// The contact part and the fabric of the spheres in [lo, hi).
void add_contacts(const Simulation3& sim, Vec3 lo, Vec3 hi, RegionStress3& out) {
  const Spheres& s = sim.scene().spheres;
  const auto in = [&](std::uint32_t i) { return s.is_free(i) && inside(sim, i, lo, hi); };
  visit_contact_forces(
      sim,
      [&](std::uint32_t i, const Vec3& f, const Vec3& l) {
        if (in(i)) out.contact -= outer(f, l);
      },
      [&](std::uint32_t i, std::uint32_t j, const Vec3& n) {
        if (!s.is_free(i) || !s.is_free(j) || (!in(i) && !in(j))) return;
        out.fabric += outer(n, n);
        ++out.contacts;
      });
  if (out.contacts > 0) out.fabric /= static_cast<double>(out.contacts);
}

} // namespace

Principal3 principal(const Tensor3& t) {
  const Tensor3 symmetric = 0.5 * (t + t.transpose());
  const Eigen::SelfAdjointEigenSolver<Tensor3> solver(symmetric);
  // the solver's eigenvalues ascend: the major one is the last
  Principal3 out;
  for (int k = 0; k < 3; ++k) {
    out.values(k) = solver.eigenvalues()(2 - k);
    out.directions.col(k) = solver.eigenvectors().col(2 - k);
  }
  return out;
}

RegionStress3 region_stress(const Simulation3& sim, Vec3 lo, Vec3 hi) {
  RegionStress3 out;
  out.volume = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  add_contacts(sim, lo, hi, out);
  // the kinetic part, about the spheres' mean velocity and, in a sheared cell, the shear's flow
  // gamma_dot (y - <y>) along x: the spheres' fluctuations, not the flow (as in 2D). The height
  // is where the sphere is held, not wrapped: a sphere past the upper side keeps the velocity of
  // the flow there until the list's build wraps both
  const Spheres& s = sim.scene().spheres;
  const double shear = sim.scene().cell ? sim.scene().cell->shear_rate : 0.0;
  double mass = 0.0, y_sum = 0.0;
  Vec3 momentum{};
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.is_free(i) && inside(sim, i, lo, hi)) {
      mass += s.mass[i], momentum += s.mass[i] * s.velocity[i], ++out.spheres;
      if (shear != 0.0) y_sum += s.mass[i] * s.position[i].y;
    }
  const Vec3 mean = mass > 0.0 ? (1.0 / mass) * momentum : Vec3{};
  const double y_mean = mass > 0.0 ? y_sum / mass : 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.is_free(i) && inside(sim, i, lo, hi)) {
      Vec3 u = s.velocity[i] - mean;
      if (shear != 0.0) u.x -= shear * (s.position[i].y - y_mean);
      out.kinetic += s.mass[i] * outer(u, u);
    }
  if (out.volume > 0.0) out.contact /= out.volume, out.kinetic /= out.volume;
  return out;
}

std::vector<Tensor3> sphere_stresses(const Simulation3& sim) {
  const Spheres& s = sim.scene().spheres;
  std::vector<Tensor3> out(s.size(), Tensor3::Zero());
  visit_contact_forces(
      sim, [&](std::uint32_t i, const Vec3& f, const Vec3& l) { out[i] -= outer(f, l); },
      [](std::uint32_t, std::uint32_t, const Vec3&) {});
  for (std::size_t i = 0; i < s.size(); ++i)
    out[i] /= 4.0 / 3.0 * std::numbers::pi * s.radius[i] * s.radius[i] * s.radius[i];
  return out;
}

std::string stress_thermo_header(const std::string& prefix) {
  std::string head;
  for (const char* name :
       {"stress_xx",         "stress_xy",           "stress_xz",         "stress_yx",
        "stress_yy",         "stress_yz",           "stress_zx",         "stress_zy",
        "stress_zz",         "kinetic_stress_xx",   "kinetic_stress_yy", "kinetic_stress_zz",
        "kinetic_stress_xy", "kinetic_stress_xz",   "kinetic_stress_yz", "pressure",
        "stress_major",      "stress_intermediate", "stress_minor",      "stress_major_x",
        "stress_major_y",    "stress_major_z",      "fabric_xx",         "fabric_yy",
        "fabric_zz",         "fabric_xy",           "fabric_xz",         "fabric_yz"})
    head += "," + prefix + name;
  return head;
}

std::string stress_thermo_columns(const RegionStress3& s) {
  const Tensor3 t = s.total();
  const Principal3 p = principal(t);
  Eigen::Vector3d major = p.directions.col(0);
  // an eigenvector's sign is the solver's choice: the one with its largest component positive
  Eigen::Index largest = 0;
  major.cwiseAbs().maxCoeff(&largest);
  if (major(largest) < 0.0) major = -major;
  std::string out;
  const auto add = [&out](double v) { out += fmt::format(",{:.9e}", v); };
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) add(t(a, b));
  const Tensor3& k = s.kinetic;
  for (const double v : {k(0, 0), k(1, 1), k(2, 2), k(0, 1), k(0, 2), k(1, 2)}) add(v);
  add(t.trace() / 3.0);
  for (int m = 0; m < 3; ++m) add(p.values(m));
  for (int m = 0; m < 3; ++m) add(major(m));
  const Tensor3& f = s.fabric;
  for (const double v : {f(0, 0), f(1, 1), f(2, 2), f(0, 1), f(0, 2), f(1, 2)}) add(v);
  return out;
}

} // namespace talus
