#include "scenario/soft_contacts.hpp"

#include <cmath>

#include <fmt/core.h>

#include "talus/law_table.hpp"

namespace talus {

namespace {

// A warning's threshold, half the guard's limit (SimulationConfig::max_overlap_fraction), for an
// estimate that leaves the damping out; and the share a suggested stiffness aims at, where the
// laws still hold.
constexpr double warn_fraction = 0.25;
constexpr double aim_fraction = 0.05;

} // namespace

SoftContact softest_contact(const BuiltScenario& b) {
  const Particles& p = b.world.particles;
  std::size_t heaviest = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && (heaviest == p.size() || p.mass[i] > p.mass[heaviest])) heaviest = i;
  SoftContact worst;
  if (heaviest == p.size()) return worst;
  const double m = p.mass[heaviest], r = p.radius[heaviest];
  for (const MeetingPair& pair : meeting_pairs(b.world)) {
    const PairParameters& pp = b.pairs(pair.a, pair.b);
    const double m_eff = pair.wall ? m : 0.5 * m, r_eff = pair.wall ? r : 0.5 * r;
    const double overlap = with_normal_law(b.config.normal_law, [&]<class N>() {
      return N::peak_overlap(pp, m_eff, r_eff, b.config.impact_speed);
    });
    if (overlap / r > worst.fraction) worst = {overlap / r, pair.a, overlap, m, pair.wall};
  }
  return worst;
}

std::string soft_contact_warning(const Scenario& s, const BuiltScenario& b) {
  const SoftContact c = softest_contact(b);
  if (!(c.fraction > warn_fraction)) return {};
  const Material& m = s.materials.at(c.material);
  // the overlap goes as the stiffness^(-1/power), and the collision time with it
  const double shrink = c.fraction / aim_fraction;
  struct Stiffness {
    const char* name;
    const char* unit;
    double now, fit;
  };
  const Stiffness k = with_normal_law(b.config.normal_law, [&]<class N>() {
    const double now = m.*N::stiffness_key;
    return Stiffness{N::stiffness_name, N::stiffness_unit, now,
                     now * std::pow(shrink, N::stiffness_power)};
  });
  const std::string key = fmt::format("materials.{}.{}", c.material, k.name);
  return fmt::format(
      "{} = {:.3g} {} lets a grain of {:.3g} kg ({} '{}') meeting {} at simulation.impact_speed = "
      "{:.3g} m/s overlap it by {:.3g} m, {:.0f}% of its radius (the run stops at {:.0f}%); {} = "
      "{:.3g} {} keeps that to {:.0f}%, with a timestep of about {:.3g} s",
      key, k.now, k.unit, c.mass, "material", m.name, c.wall ? "a wall" : "a grain like it",
      b.config.impact_speed, c.overlap, 100.0 * c.fraction,
      100.0 * SimulationConfig{}.max_overlap_fraction, key, k.fit, k.unit, 100.0 * aim_fraction,
      b.config.timestep / shrink);
}

} // namespace talus
