#include "drivers/cell.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/vec3.hpp"
#include "simulation/world.hpp"
#include "talus/error.hpp"

namespace talus {

template <class V> void require_controller_keys(const CellOf<V>& c) {
  require(std::isfinite(c.max_strain_rate) && c.max_strain_rate > 0.0,
          "cell driver: a pressure needs max_strain_rate > 0 (1/s)");
  require(c.relaxation > 0.0 && c.relaxation <= 1.0,
          "cell driver: relaxation must be in (0, 1] (the fraction of the stress' error closed "
          "per step: above 1 the cell overshoots)");
}

template void require_controller_keys(const CellOf<Vec2>&);
template void require_controller_keys(const CellOf<Vec3>&);

void attach_cell(Cell& c, const Domain& d) {
  require(std::isfinite(c.strain_rate.x) && std::isfinite(c.strain_rate.y),
          "cell driver: strain_rate must be finite (1/s)");
  require((c.strain_rate.x == 0.0 || d.periodic_x) && (c.strain_rate.y == 0.0 || d.periodic_y),
          "cell driver: strain_rate deforms a direction that is not periodic; the cell is the "
          "periodic box (geometry.periodic)");
  require(std::isfinite(c.pressure) && c.pressure >= 0.0,
          "cell driver: pressure must be >= 0 N/m (0: the rate mode)");
  if (c.pressure > 0.0) {
    require(d.periodic_x && d.periodic_y,
            "cell driver: a pressure needs a box periodic in x and y (geometry.periodic = \"xy\")");
    require(c.strain_rate.x == 0.0 && c.strain_rate.y == 0.0,
            "cell driver: give strain_rate or pressure, not both");
    require_controller_keys(c);
  }
  require(std::isfinite(c.shear_rate), "cell driver: shear_rate must be finite (1/s)");
  if (c.shear_rate != 0.0) {
    require(d.periodic_x && d.periodic_y,
            "cell driver: a shear_rate needs a box periodic in x and y (geometry.periodic = "
            "\"xy\"): the images across y slide along x");
    require(c.strain_rate.x == 0.0,
            "cell driver: a sheared cell keeps its width: strain_rate along x must be 0");
  }
  c.rate = 0.0;
  c.strain = {};
  c.shear_strain = 0.0;
}

void require_cell_fits(const World& w) {
  const auto cells = std::count_if(w.drivers.begin(), w.drivers.end(), [](const Driver& d) {
    return std::holds_alternative<Cell>(d.motion);
  });
  if (cells == 0) return;
  // what the affine remap would leave behind: walls, and grains that drivers or holds move
  require(cells == 1, "two cell drivers; the periodic box has one");
  require(w.walls.empty(),
          "a deforming cell with wall segments: they do not follow the cell; use builder = "
          "\"none\" with a periodic box (a rough wall of fixed grains follows it)");
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    require(w.particles.kind[i] != Kind::moved,
            "a deforming cell with particle " + std::to_string(i) +
                " of kind 'moved': driven or held grains do not follow the cell");
}

Vec2 cell_strain_rate(const Cell& c, const Domain& d) {
  if (c.pressure <= 0.0) return c.strain_rate;
  if (c.shear_rate != 0.0) return {0.0, c.rate};
  return {d.periodic_x ? c.rate : 0.0, d.periodic_y ? c.rate : 0.0};
}

template <class V> double cell_rate(const CellOf<V>& c, const CellReading& r, double dt) {
  const double error = r.pressure - c.pressure; // > 0: the grains push too hard, expand
  const double rate = r.stiffness > 0.0 ? c.relaxation * error / (r.stiffness * dt)
                                        : std::copysign(c.max_strain_rate, error);
  return std::clamp(rate, -c.max_strain_rate, c.max_strain_rate);
}

template double cell_rate(const CellOf<Vec2>&, const CellReading&, double);
template double cell_rate(const CellOf<Vec3>&, const CellReading&, double);

} // namespace talus
