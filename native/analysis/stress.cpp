#include "analysis/stress.hpp"

#include <cmath>
#include <numbers>

#include "analysis/observables.hpp"

namespace talus {

namespace {

Tensor2 outer(Vec2 a, Vec2 b) {
  Tensor2 t;
  t << a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y;
  return t;
}

// Calls f(particle, the force on it, the branch from its centre to the contact point) for both
// members of every contact of `contacts` that are free grains (a periodic partner's branch from
// its image's centre).
template <class F>
void for_each_grain_side(const Particles& p, const std::vector<ContactRecord>& contacts, F&& f) {
  for (const ContactRecord& c : contacts) {
    if (p.is_free(c.i)) f(c.i, c.force, c.point - c.from);
    if (c.j >= 0 && p.is_free(static_cast<std::size_t>(c.j)))
      f(static_cast<std::size_t>(c.j), -c.force, c.point - c.to);
  }
}

} // namespace

Principal principal(const Tensor2& t) {
  const Tensor2 symmetric = 0.5 * (t + t.transpose());
  const Eigen::SelfAdjointEigenSolver<Tensor2> solver(symmetric);
  // eigenvalues in increasing order
  Principal out{solver.eigenvalues()(1), solver.eigenvalues()(0), 0.0};
  const Eigen::Vector2d major = solver.eigenvectors().col(1);
  out.angle = std::atan2(major.y(), major.x());
  if (out.angle <= -std::numbers::pi / 2) out.angle += std::numbers::pi;
  if (out.angle > std::numbers::pi / 2) out.angle -= std::numbers::pi;
  return out;
}

RegionStress region_stress(const Simulation& sim, Vec2 lo, Vec2 hi) {
  RegionStress s;
  s.area = (hi.x - lo.x) * (hi.y - lo.y);
  const Particles& p = sim.world().particles;
  // where a grain is: in a periodic box, its wrapped position (between two list builds a grain
  // may have crossed the box's side unwrapped)
  const Domain& box = sim.world().domain;
  const auto inside = [&](Vec2 r, Vec2 a, Vec2 b) { return inside_box(box.wrap(r), a, b); };
  const std::vector<ContactRecord> contacts = contact_forces(sim);
  // the contact part: each grain in the region with each of its contacts
  for_each_grain_side(p, contacts, [&](std::size_t i, Vec2 force, Vec2 branch) {
    if (inside(p.position[i], lo, hi)) s.contact -= outer(force, branch);
  });
  // the fabric: grain-grain contacts with a member in the region, once each
  for (const ContactRecord& c : contacts) {
    if (c.j < 0) continue;
    const auto j = static_cast<std::size_t>(c.j);
    if (!p.is_free(c.i) || !p.is_free(j)) continue;
    if (!inside(p.position[c.i], lo, hi) && !inside(p.position[j], lo, hi)) continue;
    const Vec2 d = c.from - c.to;
    const double length = norm(d);
    if (!(length > 0.0)) continue;
    s.fabric += outer(d / length, d / length);
    ++s.contacts;
  }
  if (s.contacts) s.fabric /= static_cast<double>(s.contacts);
  // the kinetic part, about the grains' mean velocity
  double mass = 0.0;
  Vec2 momentum;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && inside(p.position[i], lo, hi))
      mass += p.mass[i], momentum += p.mass[i] * p.velocity[i], ++s.grains;
  const Vec2 mean = mass > 0.0 ? momentum / mass : Vec2{};
  // in a sheared cell (Lees-Edwards) about the shear's flow too, v_x = shear rate (y - y_mean)
  const double shear_rate = box.shear_velocity / box.size().y;
  double y_mean = 0.0;
  if (shear_rate != 0.0 && mass > 0.0) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_free(i) && inside(p.position[i], lo, hi))
        y_mean += p.mass[i] * box.wrap(p.position[i]).y;
    y_mean /= mass;
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && inside(p.position[i], lo, hi)) {
      Vec2 u = p.velocity[i] - mean;
      if (shear_rate != 0.0) u.x -= shear_rate * (box.wrap(p.position[i]).y - y_mean);
      s.kinetic += p.mass[i] * outer(u, u);
    }
  if (s.area > 0.0) s.contact /= s.area, s.kinetic /= s.area;
  return s;
}

std::vector<Tensor2> particle_stresses(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  std::vector<Tensor2> out(p.size(), Tensor2::Zero());
  for_each_grain_side(p, contact_forces(sim), [&](std::size_t i, Vec2 force, Vec2 branch) {
    out[i] -= outer(force, branch);
  });
  for (std::size_t i = 0; i < p.size(); ++i) out[i] /= std::numbers::pi * p.radius[i] * p.radius[i];
  return out;
}

} // namespace talus
