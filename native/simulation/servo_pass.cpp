// The servo walls' controller step: what each servo's walls feel after the force stage.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/contact_vectors.hpp"
#include "drivers/servo.hpp"
#include "simulation/simulation.hpp"
#include "simulation/wall_pass.hpp"

namespace talus {

namespace {
// A touching contact's tangent stiffness and damping coefficient into a servo's reading, from
// the normal law's own force: both laws are linear in the overlap rate, so the force at rate 1
// less that at rate 0 is the damping coefficient (both positive for an overlap, so no floor
// cuts them).
template <class N>
void read_contact(ServoReading& r, const PairParameters& pair, ContactGeometry g) {
  r.stiffness += N::stiffness(pair, g);
  g.v_normal = 0.0;
  const double resting = N::force(pair, g);
  g.v_normal = -1.0;
  r.damping += N::force(pair, g) - resting;
}
} // namespace

bool Simulation::has_servo() const {
  for (const Driver& d : world_.drivers)
    if (std::holds_alternative<Servo>(d.motion)) return true;
  return false;
}

void Simulation::drive_servos() {
  if (!has_servo()) return;
  const Segments& walls = world_.walls;
  // which servo owns each wall segment, and what its walls feel
  std::vector<std::int32_t>& owner = servo_owner_;
  std::vector<ServoReading>& reading = servo_reading_;
  owner.assign(walls.size(), -1);
  reading.assign(world_.drivers.size(), ServoReading{});
  for (std::size_t k = 0; k < world_.drivers.size(); ++k) {
    const auto* servo = std::get_if<Servo>(&world_.drivers[k].motion);
    if (servo == nullptr) continue;
    for (const auto s : world_.drivers[k].targets.segments) {
      owner[s] = static_cast<std::int32_t>(k);
      reading[k].load -= dot(walls[s].force, servo->direction);
    }
  }
  const Particles& p = world_.particles;
  const LeverShares shares = lever_shares(config_.lever_arm);
  with_normal_law(config_.normal_law, [&]<class N>() {
    for (std::uint32_t i = 0; i < p.size(); ++i)
      for_each_wall_contact(
          p, list_, walls, i, servo_hits_, shares,
          [&](std::uint32_t e, const Segment& s, const ContactGeometry& g) {
            const std::int32_t k = owner[list_.wall_segment[e]];
            if (k < 0) return;
            read_contact<N>(reading[static_cast<std::size_t>(k)], pairs_(p.material[i], s.material),
                            g);
          },
          [](std::uint32_t) {});
  });
  read_servo_particles(reading);
  for (std::size_t k = 0; k < world_.drivers.size(); ++k)
    if (auto* servo = std::get_if<Servo>(&world_.drivers[k].motion))
      servo_advance(*servo, reading[k], config_.timestep);
}

void Simulation::read_servo_particles(std::vector<ServoReading>& reading) {
  const Particles& p = world_.particles;
  std::vector<std::int32_t>& owner = servo_particle_owner_;
  bool any = false;
  owner.assign(p.size(), -1);
  for (std::size_t k = 0; k < world_.drivers.size(); ++k) {
    const auto* servo = std::get_if<Servo>(&world_.drivers[k].motion);
    if (servo == nullptr) continue;
    for (const auto i : world_.drivers[k].targets.particles) {
      owner[i] = static_cast<std::int32_t>(k);
      reading[k].load -= dot(p.force[i], servo->direction);
      any = true;
    }
  }
  if (!any) return;
  // The contacts of the wall particles with grains (two wall particles never meet in the list).
  const LeverShares shares = lever_shares(config_.lever_arm);
  with_normal_law(config_.normal_law, [&]<class N>() {
    for (std::uint32_t i = 0; i < p.size(); ++i)
      for (std::uint32_t e = list_.row_offset[i]; e < list_.row_offset[i + 1]; ++e) {
        const std::uint32_t j = list_.neighbour[e];
        const std::int32_t k = owner[i] >= 0 ? owner[i] : owner[j];
        if (k < 0) continue;
        const Vec2 d = p.position[i] - (p.position[j] + list_.shift(e, world_.domain));
        const double dist2 = norm2(d), reach = p.radius[i] + p.radius[j];
        if (dist2 >= reach * reach || dist2 == 0.0) continue;
        read_contact<N>(reading[static_cast<std::size_t>(k)], pairs_(p.material[i], p.material[j]),
                        pair_geometry(d, std::sqrt(dist2), p.radius[i], p.radius[j], p.mass[i],
                                      p.mass[j], p.velocity[i],
                                      p.velocity[j] + list_.image_velocity(e, world_.domain),
                                      p.angular_velocity[i], p.angular_velocity[j], true, shares));
      }
  });
}

} // namespace talus
