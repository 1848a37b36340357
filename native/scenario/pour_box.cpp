#include "scenario/pour_box.hpp"

#include <algorithm>
#include <cmath>

#include "core/random.hpp"
#include "materials/timestep.hpp"
#include "talus/error.hpp"
#include "talus/timestep_advice.hpp"

namespace talus {

PourBox build_pour_box(const PourBoxSpec& spec) {
  require(spec.count > 0, "pour box: count must be > 0");
  require(spec.mean_radius > 0.0, "pour box: mean_radius must be > 0 m");
  require(spec.radius_spread >= 0.0 && spec.radius_spread < 1.0,
          "pour box: radius_spread must be in [0, 1)");
  PourBox out;
  World& w = out.world;
  Material grain;
  grain.name = "grain";
  grain.density = 2650.0;
  grain.normal_stiffness = 1.0e5;
  grain.restitution = 0.5;
  grain.friction = 0.5;
  grain.tangential_damping = 0.0;
  w.materials = {grain};
  w.gravity = {0.0, -spec.gravity};

  const double r_max = spec.mean_radius * (1.0 + spec.radius_spread);
  const double pitch = 2.0 * r_max * 1.05; // lattice spacing: no initial overlaps
  const double width =
      spec.box_width > 0.0
          ? spec.box_width
          : std::ceil(std::sqrt(static_cast<double>(spec.count)) * 1.6) * 2.0 * spec.mean_radius;
  const auto per_row = static_cast<std::size_t>(std::floor((width - 2.0 * r_max) / pitch));
  require(per_row >= 1, "pour box: box_width is smaller than one grain");
  const auto rows = (spec.count + per_row - 1) / per_row;
  const double height = (static_cast<double>(rows) + 2.0) * pitch;

  w.add_wall({0.0, 0.0}, {width, 0.0});
  w.add_wall({0.0, height}, {0.0, 0.0});
  w.add_wall({width, 0.0}, {width, height});
  w.domain.lo = {0.0, 0.0};
  w.domain.hi = {width, height};

  RandomStream rng(spec.seed, 0);
  w.particles.reserve(spec.count);
  for (std::size_t k = 0; k < spec.count; ++k) {
    const std::size_t row = k / per_row, col = k % per_row;
    ParticleSpec p;
    p.radius = spec.mean_radius * (1.0 + spec.radius_spread * rng.uniform(-1.0, 1.0));
    const double jitter = 0.02 * r_max * rng.uniform(-1.0, 1.0);
    p.position = {r_max + pitch * (static_cast<double>(col) + 0.5) + jitter,
                  pitch * (static_cast<double>(row) + 1.0)};
    p.shape = spec.shape;
    w.add_particle(p);
  }

  // timestep: the lightest pair has the shortest collision time
  const double r_min = spec.mean_radius * (1.0 - spec.radius_spread);
  const double m_min = shape_mass(spec.shape, r_min, grain.density, w.disk_thickness);
  const PairParameters pp = PairTable({grain}, 1.0)(0, 0); // linear: no speed enters
  const double m_eff = 0.5 * m_min;
  out.config.timestep =
      linear_collision_time(pp.normal_stiffness, pp.normal_dashpot(m_eff), m_eff) /
      default_timestep_factor;
  out.config.normal_law = law_id<LinearSpringDashpot>;
  out.config.tangential_law = law_id<CundallStrack>;
  out.box_width = width;
  return out;
}

} // namespace talus
