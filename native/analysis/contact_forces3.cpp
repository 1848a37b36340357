#include "analysis/contact_forces3.hpp"

#include "analysis/frame3.hpp"

namespace talus {

std::vector<ContactRecord3> contact_records3(const Simulation3& sim) {
  const Spheres& s = sim.scene().spheres;
  std::vector<ContactRecord3> out;
  const auto record = [&](std::uint32_t i, std::int64_t j, const ContactGeometry3& g, const Vec3& f,
                          double reach, double to_point) {
    ContactRecord3 c;
    c.i = i, c.j = j, c.from = s.position[i], c.force = f, c.overlap = g.overlap;
    // the normal points from the partner to i
    c.point = s.position[i] - to_point * g.normal;
    c.to = s.position[i] - reach * g.normal;
    c.normal_force = dot(f, g.normal);
    c.tangential_force = norm(f - c.normal_force * g.normal);
    out.push_back(c);
  };
  visit_contact_forces3(
      sim,
      [&](std::uint32_t i, std::uint32_t j, const ContactGeometry3& g, const Vec3& f) {
        record(i, j, g, f, s.radius[i] + s.radius[j] - g.overlap, s.radius[i] - 0.5 * g.overlap);
      },
      [&](std::uint32_t i, std::uint32_t plate, const ContactGeometry3& g, const Vec3& f) {
        const double to_plate = s.radius[i] - g.overlap;
        record(i, -1 - std::int64_t{plate}, g, f, to_plate, to_plate);
      });
  return out;
}

Frame3 frame3_of(const Simulation3& sim) {
  const Scene3& scene = sim.scene();
  const Spheres& s = scene.spheres;
  Frame3 f;
  f.time = sim.time();
  f.id = s.id, f.position = s.position, f.radius = s.radius, f.velocity = s.velocity;
  f.mass = s.mass;
  for (std::size_t i = 0; i < s.size(); ++i) f.kind.push_back(s.is_free(i) ? 0 : 1);
  f.box_lo = scene.domain.lo, f.box_hi = scene.domain.hi, f.periodic = scene.domain.periodic;
  f.shear_velocity = scene.domain.shear_velocity;
  for (const ContactRecord3& c : contact_records3(sim))
    f.chains.push_back({c.from, c.to, c.normal_force, c.force, c.point, s.is_free(c.i),
                        c.j >= 0 && s.is_free(static_cast<std::size_t>(c.j)), true});
  return f;
}

} // namespace talus
