#include "analysis/frame.hpp"

#include "analysis/observables.hpp"

namespace talus {

Frame frame_of(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  Frame f;
  f.time = sim.time();
  f.id.assign(p.id.begin(), p.id.end());
  f.position = p.position;
  f.radius = p.radius;
  f.velocity = p.velocity;
  f.force = p.force;
  f.kind.reserve(p.size());
  for (const Kind k : p.kind) f.kind.push_back(static_cast<std::uint8_t>(k));
  f.material = p.material;
  f.mass = p.mass;
  for (const Segment& s : sim.world().walls) f.walls.emplace_back(s.a, s.b);
  for (const ContactRecord& c : contact_forces(sim))
    f.chains.push_back({c.from, c.to, c.normal_force, c.force, c.point, p.is_free(c.i),
                        c.j >= 0 && p.is_free(static_cast<std::size_t>(c.j)), true});
  return f;
}

} // namespace talus
