#include "scenario/contact_pairs.hpp"

#include <fmt/format.h>

#include "scenario/build.hpp"
#include "talus/law_table.hpp"

namespace talus {

namespace {

struct MeanGrain {
  double mass = 0.0, radius = 0.0;
};

// The mean mass and radius of the free grains of material k (of all free grains if none is).
MeanGrain mean_grain(const Particles& p, std::uint16_t k) {
  MeanGrain sum, all;
  std::size_t n = 0, n_all = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i)) continue;
    all.mass += p.mass[i], all.radius += p.radius[i], ++n_all;
    if (p.material[i] == k) sum.mass += p.mass[i], sum.radius += p.radius[i], ++n;
  }
  const MeanGrain& s = n > 0 ? sum : all;
  const double count = static_cast<double>(n > 0 ? n : n_all);
  return count > 0 ? MeanGrain{s.mass / count, s.radius / count} : MeanGrain{};
}

} // namespace

std::string describe_contact_pairs(const World& w, const PairTable& pairs,
                                   const SimulationConfig& c) {
  std::string out =
      "\n# The contact parameters derived for this run (comments: a rerun derives them "
      "again):\n";
  for (const MeetingPair& m : meeting_pairs(w)) {
    const Material &a = w.materials[m.a], &b = w.materials[m.b];
    const PairParameters& p = pairs(m.a, m.b);
    const MeanGrain ga = mean_grain(w.particles, m.a);
    const MeanGrain gb = m.wall ? ga : mean_grain(w.particles, m.b);
    // against a wall: the grain's own mass and radius
    const double m_eff = m.wall ? ga.mass : ga.mass * gb.mass / (ga.mass + gb.mass);
    const double r_eff = m.wall ? ga.radius : ga.radius * gb.radius / (ga.radius + gb.radius);
    out += fmt::format("#   {} with {}{}: restitution {:.6g}, {}\n", a.name, b.name,
                       m.wall ? " (wall)" : "", p.restitution,
                       m_eff > 0.0
                           ? with_normal_law(c.normal_law,
                                             [&]<class N>() {
                                               return N::describe_damping(
                                                   p, m_eff, r_eff, c.impact_speed,
                                                   m.wall ? "a mean grain" : "two mean grains");
                                             })
                           : "no grains");
  }
  return out;
}

} // namespace talus
