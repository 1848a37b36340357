// Stage 6 of a step, the stability guard: a non-finite state, an overlap too deep or a grain
// escaped stops the run with InstabilityError and the true diagnosis.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "simulation/simulation.hpp"
#include "talus/error.hpp"

namespace talus {

// The deepest contact, its collision time, and the cause of its depth: a timestep that resolves
// the contact in too few steps (then a smaller one is proposed), or an impact too fast for the
// stiffness, which no timestep cures.
void Simulation::describe_deepest_contact(std::ostringstream& msg) const {
  const Particles& p = world_.particles;
  ContactView worst;
  double ratio = -1.0;
  for_each_contact([&](const ContactView& v) {
    const double r =
        v.geometry.overlap / std::min(p.radius[v.i], v.wall < 0 ? p.radius[v.j] : p.radius[v.i]);
    if (r > ratio) ratio = r, worst = v;
  });
  if (ratio < 0.0) {
    msg << ". Try a smaller timestep (about the collision time / 50), softer materials or lower "
           "speeds.";
    return;
  }
  const PairParameters& pp = *worst.parameters;
  const ContactGeometry& g = worst.geometry;
  const double k =
      with_normal_law(config_.normal_law, [&]<class N>() -> double { return N::stiffness(pp, g); });
  const double tc = std::numbers::pi * std::sqrt(g.m_eff / k);
  const double steps = tc / config_.timestep;
  const double radius = std::min(p.radius[worst.i], worst.wall < 0 ? p.radius[worst.j] : 1e300);
  const Vec2 dv = p.velocity[worst.i] - (worst.wall < 0 ? p.velocity[worst.j] : Vec2{});
  msg << " between particle id " << p.id[worst.i] << " at (" << p.position[worst.i].x << ", "
      << p.position[worst.i].y << ") m and "
      << (worst.wall < 0 ? "particle id " + std::to_string(p.id[worst.j])
                         : "wall segment " + std::to_string(worst.wall))
      << "; their collision time is about " << tc << " s, which the timestep resolves in " << steps
      << " steps";
  if (steps < min_steps_per_contact) {
    msg << ". The timestep is too large for this contact: a timestep of about " << tc / 50.0
        << " s (collision time / 50) would resolve it.";
    return;
  }
  const double per_step = norm(dv) * config_.timestep, limit = config_.max_overlap_fraction;
  if (per_step > 0.25 * limit * radius) { // one step closes a good part of the allowed overlap
    msg << ", but at " << norm(dv) << " m/s they close in by " << per_step
        << " m per step: the timestep is too large for this speed; a timestep of about "
        << 0.02 * radius / norm(dv) << " s (a fiftieth of the radius per step) would resolve it.";
    return;
  }
  // resolved in time and in space: the grains met too fast for their stiffness. An undamped
  // contact reaches the limit from an impact speed of limit R omega, and the impact speed is
  // about sqrt(v^2 + (omega xi)^2) from the state now (its energy).
  const double omega = std::sqrt(k / g.m_eff);
  const double impact = std::sqrt(norm2(dv) + omega * omega * g.overlap * g.overlap);
  msg << ", so the timestep is not the cause: they met at about " << impact
      << " m/s, and with this stiffness an impact faster than about " << limit * radius * omega
      << " m/s overlaps past the limit. Use stiffer materials or lower speeds.";
}

void Simulation::guard() const {
  const Particles& p = world_.particles;
  const bool finite = finite_;
  const bool box =
      config_.escape_hi.x > config_.escape_lo.x && config_.escape_hi.y > config_.escape_lo.y;
  if (box && steps_ % 16 == 0) {
    const Domain& d = world_.domain;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 r = p.position[i];
      const bool out =
          (!d.periodic_x && (r.x < config_.escape_lo.x || r.x > config_.escape_hi.x)) ||
          (!d.periodic_y && (r.y < config_.escape_lo.y || r.y > config_.escape_hi.y));
      if (out && p.is_free(i)) {
        std::ostringstream msg;
        msg << "unstable at step " << steps_ << " (t = " << time_ << " s, dt = " << config_.timestep
            << " s): particle id " << p.id[i] << " left the domain at (" << r.x << ", " << r.y
            << ") m, speed " << norm(p.velocity[i])
            << " m/s. A grain shot out by an overlap too deep for the timestep: try a smaller "
               "timestep (about the collision time / 50), or check for a gap in the walls.";
        throw InstabilityError(msg.str());
      }
    }
  }
  if (finite && forces_.deepest_overlap() <= config_.max_overlap_fraction) return;

  std::ostringstream msg;
  msg << "unstable at step " << steps_ << " (t = " << time_ << " s, dt = " << config_.timestep
      << " s): ";
  if (!finite) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!std::isfinite(p.position[i].x + p.position[i].y + p.velocity[i].x + p.velocity[i].y)) {
        msg << "particle id " << p.id[i] << " has a non-finite position or velocity";
        break;
      }
    msg << (steps_ <= 1 ? ": a non-finite value in the input (a position, velocity, radius or "
                          "material value)."
                        : ": a value grew without bound, most often from a timestep far too "
                          "large for the stiffest contact (try about the collision time / 50).");
  } else {
    msg << "an overlap reached " << forces_.deepest_overlap() << " of the smaller radius (limit "
        << config_.max_overlap_fraction << ")";
    describe_deepest_contact(msg);
  }
  throw InstabilityError(msg.str());
}

} // namespace talus
