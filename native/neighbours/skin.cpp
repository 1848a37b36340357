#include "neighbours/skin.hpp"

#include <algorithm>
#include <cmath>

#include "neighbours/cell_grid.hpp"

namespace talus {

namespace {
// rebuild cost (in entry tests per step) / packing fraction: a wider skin makes rebuilds rarer
// and each step test more entries. Since the force stage tests only the contact candidates, an
// entry beyond them costs a test about every fifth of a list's life, so the best value is large
// (measured on dense2d: docs/performance.md, "Contact candidates")
constexpr double rebuild_cost_over_packing_fraction = 256.0;
} // namespace

double automatic_skin(double speed, double dt, double mean_radius, double max_radius,
                      const Domain& domain) {
  double skin = std::sqrt(rebuild_cost_over_packing_fraction * speed * dt * mean_radius);
  if (!std::isfinite(skin)) skin = mean_radius;
  skin = std::clamp(skin, 0.1 * mean_radius, mean_radius);
  const Vec2 size = domain.size();
  for (const auto& [periodic, length] :
       {std::pair{domain.periodic_x, size.x}, std::pair{domain.periodic_y, size.y}})
    if (periodic) {
      const double room = 0.99 * (length / min_periodic_cells - 2.0 * max_radius);
      if (room > 0.0) skin = std::min(skin, room);
    }
  return skin;
}

double automatic_skin(const Particles& p, const Segments& walls, const Domain& domain, double dt) {
  // one thread, in index order: the sum of the radii, and so the skin and the list, must not
  // depend on the thread count (a pass over the radii is cheap against a rebuild)
  double fastest2 = 0.0, radii = 0.0, all_radii = 0.0;
  std::size_t free = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    all_radii += p.radius[i];
    if (p.kind[i] != Kind::fixed) // free grains, and wall grains moved by drivers
      fastest2 = std::max(fastest2, norm2(p.velocity[i]));
    if (p.is_free(i)) {
      radii += p.radius[i];
      ++free;
    }
  }
  for (const Segment& s : walls) // the ends of moving walls trigger rebuilds too
    fastest2 = std::max({fastest2, norm2(s.velocity_at(s.a)), norm2(s.velocity_at(s.b))});
  // and Lees-Edwards images sliding past the grains (Simulation::update_cell_reserve)
  fastest2 = std::max(fastest2, domain.shear_velocity * domain.shear_velocity);
  const double mean = free > 0
                          ? radii / static_cast<double>(free)
                          : all_radii / static_cast<double>(std::max<std::size_t>(1, p.size()));
  return automatic_skin(std::sqrt(fastest2), dt, mean, p.max_radius(), domain);
}

} // namespace talus
