// The deforming periodic cell (docs/model.md, "Deforming cell"): its strain for the step, the
// grains following it, and the pressure controller's reading after the force stage.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "drivers/cell.hpp"
#include "simulation/simulation.hpp"

namespace talus {

const Cell* Simulation::cell_driver() const {
  for (const Driver& d : world_.drivers)
    if (const auto* c = std::get_if<Cell>(&d.motion)) return c;
  return nullptr;
}

Cell* Simulation::mutable_cell() {
  return const_cast<Cell*>(std::as_const(*this).cell_driver());
}

void Simulation::update_cell_reserve(double max_radius) {
  const Vec2 now = world_.domain.size(), built = list_.box;
  double shrink = 1.0; // the smallest factor a side shrank by since the build
  if (built.x > 0.0) shrink = std::min(shrink, now.x / built.x);
  if (built.y > 0.0) shrink = std::min(shrink, now.y / built.y);
  // A pair the list left out was at least reach + skin apart at the build; the strain closes
  // such a gap by at most (1 - shrink) times that, and -ln(shrink) bounds it so that its growth
  // since the candidates were chosen also bounds what closed since then (ln adds up).
  // Lees-Edwards: the images across y have slid by the offset's change since the build
  cell_reserve_ = cell_driver() == nullptr
                      ? 0.0
                      : -std::log(shrink) * (2.0 * max_radius + list_.skin) +
                            std::abs(world_.domain.shear_offset - list_.shear_offset);
}

void Simulation::set_shear_velocity() {
  const Cell* c = cell_driver();
  Domain& d = world_.domain;
  // the images across y slide at the shear rate times the height; without a cell (a stage took
  // it away) they stop where they are
  d.shear_velocity = c == nullptr ? 0.0 : c->shear_rate * d.size().y;
}

void Simulation::reduce_shear_offset() {
  Domain& d = world_.domain;
  if (d.shear_offset == 0.0) return;
  // between builds the offset runs on (the list's entries were chosen with it); at a build it
  // comes back into [0, L_x), the images being the same a width further on
  const double width = d.size().x;
  d.shear_offset -= width * std::floor(d.shear_offset / width);
  if (d.shear_offset >= width) d.shear_offset = 0.0; // the rounding case -tiny
}

bool Simulation::deform_cell() {
  Cell* c = mutable_cell();
  Domain& d = world_.domain;
  if (c == nullptr) {
    set_shear_velocity();
    return false;
  }
  const Vec2 rate = cell_strain_rate(*c, d);
  const double dt = config_.timestep;
  const Vec2 f{std::exp(rate.x * dt), std::exp(rate.y * dt)};
  const Vec2 lo = d.lo, size = d.size();
  d.hi = lo + Vec2{size.x * f.x, size.y * f.y};
  c->strain += dt * rate;
  set_shear_velocity(); // Lees-Edwards, with the height after the strain
  d.shear_offset += d.shear_velocity * dt;
  c->shear_strain += c->shear_rate * dt;
  // every grain, fixed ones too (a rough wall of glued grains is part of the cell), and the
  // build positions with them: the drift test then sees the grains' own moves only
  Particles& p = world_.particles;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const bool same = list_.reference.size() == p.size();
  double largest = 0.0; // radius, for the reserve: in this pass rather than one more
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : largest)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    largest = std::max(largest, p.radius[i]);
    const Vec2 r = p.position[i] - lo;
    p.position[i] = lo + Vec2{r.x * f.x, r.y * f.y};
    if (same) {
      const Vec2 b = list_.reference[i] - lo;
      list_.reference[i] = lo + Vec2{b.x * f.x, b.y * f.y};
    }
  }
  update_cell_reserve(largest);
  return drifted(0.0);
}

namespace {
// The reading's sums over stretches of rows fixed by the particle count, added in order: the
// same bits whatever the thread count.
constexpr std::ptrdiff_t reading_chunks = 64;
} // namespace

CellReading Simulation::cell_reading() const {
  const Particles& p = world_.particles;
  const Domain& d = world_.domain;
  const LeverShares shares = lever_shares(config_.lever_arm);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  // a sheared cell holds sigma_yy (drivers/cell.hpp, CellReading), else the mean stress
  const Cell* cell = cell_driver();
  const bool across = cell != nullptr && cell->shear_rate != 0.0;
  std::array<double, reading_chunks> virial{}, stiffness{};
  with_contact_law(config_.normal_law, config_.tangential_law, [&]<class N, class T>() {
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::ptrdiff_t k = 0; k < reading_chunks; ++k) {
      double w = 0.0, s = 0.0;
      for (std::ptrdiff_t i = n * k / reading_chunks; i < n * (k + 1) / reading_chunks; ++i)
        for (std::uint32_t e = list_.row_offset[i]; e < list_.row_offset[i + 1]; ++e) {
          const std::uint32_t j = list_.neighbour[e];
          const Vec2 dij = p.position[i] - (p.position[j] + list_.shift(e, d));
          const double dist2 = norm2(dij), reach = p.radius[i] + p.radius[j];
          if (dist2 >= reach * reach || dist2 == 0.0) continue;
          const double dist = std::sqrt(dist2);
          const PairParameters& pair = pairs_(p.material[i], p.material[j]);
          const ContactGeometry g =
              pair_geometry(dij, dist, p.radius[i], p.radius[j], p.mass[i], p.mass[j],
                            p.velocity[i], p.velocity[j] + list_.image_velocity(e, d),
                            p.angular_velocity[i], p.angular_velocity[j], true, shares);
          if (across) { // F_y d_y: the tangential force counts here
            double spring = list_.keeps_history ? list_.history[e] : 0.0; // measured, not moved
            w += force_of(contact_force<N, T>(pair, g, spring, 0.0)).y * dij.y;
            s += N::stiffness(pair, g) * dij.y * dij.y * dij.y * dij.y / dist2;
          } else { // the trace of f d: the tangential force is across d and adds nothing to it
            w += N::force(pair, g) * dist;
            s += N::stiffness(pair, g) * dist2;
          }
        }
      virial[static_cast<std::size_t>(k)] = w;
      stiffness[static_cast<std::size_t>(k)] = s;
    }
  });
  double mass = 0.0;
  Vec2 momentum;
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.is_free(static_cast<std::size_t>(i)))
      mass += p.mass[i], momentum += p.mass[i] * p.velocity[i];
  const Vec2 mean = mass > 0.0 ? momentum / mass : Vec2{};
  double kinetic = 0.0; // the trace of sum m u u, or its yy
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.is_free(static_cast<std::size_t>(i))) {
      const Vec2 u = p.velocity[i] - mean;
      kinetic += p.mass[i] * (across ? u.y * u.y : norm2(u));
    }
  double w = 0.0, s = 0.0;
  for (std::size_t k = 0; k < virial.size(); ++k) w += virial[k], s += stiffness[k];
  const Vec2 size = d.size();
  const double area = size.x * size.y;
  if (across) return {.pressure = (w + kinetic) / area, .stiffness = s / area};
  return {.pressure = 0.5 * (w + kinetic) / area, .stiffness = 0.5 * s / area};
}

void Simulation::drive_cell() {
  Cell* c = mutable_cell();
  if (c == nullptr || c->pressure <= 0.0) return;
  c->rate = cell_rate(*c, cell_reading(), config_.timestep);
}

} // namespace talus
