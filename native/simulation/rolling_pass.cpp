#include "simulation/rolling_pass.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "simulation/wall_pass.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {

bool has_rolling_resistance(const World& world) {
  return std::any_of(world.materials.begin(), world.materials.end(),
                     [](const Material& m) { return m.rolling_friction > 0.0; });
}

RollingKinematics rolling_kinematics(const World& world, std::uint32_t i, std::uint32_t j,
                                     std::int32_t wall) {
  const Particles& p = world.particles;
  const double rim_i = rim_inertia(p.inertia[i], p.mass[i], p.radius[i]);
  if (wall >= 0)
    return {p.angular_velocity[i] - world.walls[static_cast<std::size_t>(wall)].angular_velocity,
            rolling_inertia(rim_i)};
  return {p.angular_velocity[i] - p.angular_velocity[j],
          rolling_inertia(rim_i, rim_inertia(p.inertia[j], p.mass[j], p.radius[j]))};
}

namespace {

template <class N>
void pair_torques(World& world, NeighbourList& list, const PairTable& pairs, double dt,
                  LeverShares shares) {
  Particles& p = world.particles;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
      double& theta = list.rolling[e];
      const std::uint32_t j = list.neighbour[e];
      const PairParameters& pair = pairs(p.material[i], p.material[j]);
      const Vec2 d = p.position[i] - (p.position[j] + list.shift(e, world.domain));
      const double dist2 = norm2(d), reach = p.radius[i] + p.radius[j];
      if (dist2 >= reach * reach || dist2 == 0.0 || pair.rolling_friction == 0.0) {
        theta = 0.0;
        continue;
      }
      const ContactGeometry g =
          pair_geometry(d, std::sqrt(dist2), p.radius[i], p.radius[j], p.mass[i], p.mass[j],
                        p.velocity[i], p.velocity[j] + list.image_velocity(e, world.domain),
                        p.angular_velocity[i], p.angular_velocity[j], true, shares);
      const RollingKinematics k = rolling_kinematics(world, i, j, -1);
      const double m = RollingLaw::torque<N>(pair, g, not_below_zero(N::force(pair, g)), k.spin,
                                             k.inertia, theta, dt);
      p.torque[i] += m;
      p.torque[j] -= m;
    }
}

template <class N>
void wall_torques(World& world, NeighbourList& list, const PairTable& pairs, double dt,
                  LeverShares shares) {
  Particles& p = world.particles;
  std::vector<WallHit> hits;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for_each_wall_contact(
        p, list, world.walls, i, hits, shares,
        [&](std::uint32_t e, const Segment& s, const ContactGeometry& g) {
          const PairParameters& pair = pairs(p.material[i], s.material);
          const auto wall = static_cast<std::int32_t>(list.wall_segment[e]);
          const RollingKinematics k = rolling_kinematics(world, i, i, wall);
          p.torque[i] += RollingLaw::torque<N>(pair, g, not_below_zero(N::force(pair, g)), k.spin,
                                               k.inertia, list.wall_rolling[e], dt);
        },
        [&](std::uint32_t e) { list.wall_rolling[e] = 0.0; });
}

} // namespace

void add_rolling_torques(World& world, NeighbourList& list, const PairTable& pairs,
                         NormalLaw normal, double dt, LeverShares shares) {
  with_normal_law(normal, [&]<class N>() {
    pair_torques<N>(world, list, pairs, dt, shares);
    wall_torques<N>(world, list, pairs, dt, shares);
  });
}

} // namespace talus
