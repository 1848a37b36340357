// The touching contacts of the current state, one by one, for analyses and the guard's
// diagnosis: the same geometry as the force stage's, in plain doubles.
#include <vector>

#include "simulation/simulation.hpp"
#include "simulation/wall_pass.hpp"

namespace talus {

void Simulation::for_each_contact(const std::function<void(const ContactView&)>& f) const {
  const Particles& p = world_.particles;
  const LeverShares shares = lever_shares(config_.lever_arm);
  ContactView v;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t e = list_.row_offset[i]; e < list_.row_offset[i + 1]; ++e) {
      const std::uint32_t j = list_.neighbour[e];
      const Vec2 d = p.position[i] - (p.position[j] + list_.shift(e, world_.domain));
      const double dist2 = norm2(d), reach = p.radius[i] + p.radius[j];
      if (dist2 >= reach * reach || dist2 == 0.0) continue;
      v.i = i;
      v.j = j;
      v.wall = -1;
      v.geometry =
          pair_geometry(d, std::sqrt(dist2), p.radius[i], p.radius[j], p.mass[i], p.mass[j],
                        p.velocity[i], p.velocity[j] + list_.image_velocity(e, world_.domain),
                        p.angular_velocity[i], p.angular_velocity[j], true, shares);
      v.parameters = &pairs_(p.material[i], p.material[j]);
      v.history = list_.keeps_history ? list_.history[e] : 0.0;
      v.rolling = list_.keeps_rolling ? list_.rolling[e] : 0.0;
      f(v);
    }
  }
  std::vector<WallHit> hits;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for_each_wall_contact(
        p, list_, world_.walls, i, hits, shares,
        [&](std::uint32_t e, const Segment& s, const ContactGeometry& g) {
          v.i = i;
          v.j = i;
          v.wall = static_cast<std::int32_t>(list_.wall_segment[e]);
          v.geometry = g;
          v.parameters = &pairs_(p.material[i], s.material);
          v.history = list_.keeps_history ? list_.wall_history[e] : 0.0;
          v.rolling = list_.keeps_rolling ? list_.wall_rolling[e] : 0.0;
          f(v);
        },
        [](std::uint32_t) {});
}

} // namespace talus
