#include "simulation/step_features.hpp"

#include <algorithm>

namespace talus {

StepFeatures scene_features(const World& world, TangentialLaw tangential) {
  StepFeatures f;
  f.friction = tangential != law_id<Frictionless>;
  f.history = keeps_history(tangential);
  const Particles& p = world.particles;
  const GearDerivatives& g = p.gear;
  f.rolling = has_rolling_resistance(world);
  // without friction or rolling resistance no torque arises, so a grain turns only if it turned
  // from the start
  f.rotation = f.friction;
  const auto turning = [&](std::size_t i) {
    return p.angular_velocity[i] != 0.0 || p.torque[i] != 0.0 ||
           (i < p.torque_previous.size() && p.torque_previous[i] != 0.0) ||
           (!g.empty() && (g.phi2[i] != 0.0 || g.phi3[i] != 0.0 || g.phi4[i] != 0.0));
  };
  for (std::size_t i = 0; i < p.size() && !f.rotation; ++i) f.rotation = p.is_free(i) && turning(i);
  // rolling resistance turns grains only by the spins they have, but they must keep turning
  // freely (a frictionless scene with it takes the general step, below)
  f.rotation = f.rotation || f.rolling;
  f.walls = !world.walls.empty();
  f.driven = !world.drivers.empty();
  const std::uint16_t m = p.empty() ? 0 : p.material.front();
  f.one_material =
      std::all_of(p.material.begin(), p.material.end(), [m](std::uint16_t k) { return k == m; }) &&
      std::all_of(world.walls.begin(), world.walls.end(),
                  [m](const Segment& s) { return s.material == m; });
  f.material = f.one_material ? m : 0;
  f.gravity = world.gravity.x != 0.0 || world.gravity.y != 0.0;
  if (!f.friction && f.rotation) {
    // frictionless grains that turn already (seldom: they were given a spin) keep turning as
    // they are; no specialised step is compiled for that, so the general one takes it
    StepFeatures general = general_features(world);
    general.walls = f.walls;
    general.driven = f.driven;
    return general;
  }
  return f;
}

std::string describe(const StepFeatures& f) {
  std::string s;
  const auto add = [&s](bool leaves_out, const char* what) {
    if (leaves_out) s.append(s.empty() ? "" : ", ").append(what);
  };
  add(!f.friction, "frictionless");
  add(f.friction && !f.history, "history-free");
  add(!f.rotation, "no rotation");
  add(!f.walls, "no walls");
  add(!f.driven, "no drivers");
  add(f.one_material, "one material");
  add(!f.gravity, "no gravity");
  if (s.empty()) s = "general";
  return f.rolling ? s + ", with rolling resistance" : s;
}

} // namespace talus
