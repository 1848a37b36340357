#include "state/particles.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include "talus/error.hpp"

namespace talus {

double shape_mass(Shape shape, double radius, double density, double thickness) {
  switch (shape) {
  case Shape::disk:
    return density * std::numbers::pi * radius * radius * thickness;
  case Shape::sphere:
    return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
  }
  return 0.0;
}

double shape_inertia(Shape shape, double mass, double radius) {
  switch (shape) {
  case Shape::disk:
    return 0.5 * mass * radius * radius;
  case Shape::sphere:
    return 0.4 * mass * radius * radius;
  }
  return 0.0;
}

std::size_t Particles::count(Kind k) const {
  return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k));
}

double Particles::max_radius() const {
  return radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
}

double Particles::min_radius() const {
  return radius.empty() ? 0.0 : *std::min_element(radius.begin(), radius.end());
}

void Particles::reserve(std::size_t n) {
  position.reserve(n);
  velocity.reserve(n);
  force.reserve(n);
  angle.reserve(n);
  angular_velocity.reserve(n);
  torque.reserve(n);
  radius.reserve(n);
  mass.reserve(n);
  inertia.reserve(n);
  inv_mass.reserve(n);
  inv_inertia.reserve(n);
  material.reserve(n);
  kind.reserve(n);
  id.reserve(n);
  image.reserve(n);
}

std::size_t Particles::add(const ParticleSpec& s) {
  const std::string which = "particle " + std::to_string(size());
  require(s.radius > 0.0, which + ": radius must be > 0 m");
  require(s.mass > 0.0, which + ": mass must be > 0 kg");
  require(s.inertia > 0.0, which + ": moment of inertia must be > 0 kg m^2");
  const bool free = s.kind == Kind::free;
  position.push_back(s.position);
  velocity.push_back(s.velocity);
  force.push_back({});
  angle.push_back(s.angle);
  angular_velocity.push_back(s.angular_velocity);
  torque.push_back(0.0);
  radius.push_back(s.radius);
  mass.push_back(s.mass);
  inertia.push_back(s.inertia);
  inv_mass.push_back(free ? 1.0 / s.mass : 0.0);
  inv_inertia.push_back(free ? 1.0 / s.inertia : 0.0);
  material.push_back(s.material);
  kind.push_back(s.kind);
  id.push_back(static_cast<std::uint32_t>(id.size()));
  image.push_back({});
  gear = {}; // derivatives are (re)initialised by the integrator
  return size() - 1;
}

void Particles::set_held(std::size_t i, bool held) {
  kind[i] = held ? Kind::moved : Kind::free;
  inv_mass[i] = held ? 0.0 : 1.0 / mass[i];
  inv_inertia[i] = held ? 0.0 : 1.0 / inertia[i];
  velocity[i] = {};
  angular_velocity[i] = 0.0;
  if (!gear.empty()) {
    gear.r2[i] = gear.r3[i] = gear.r4[i] = {};
    gear.phi2[i] = gear.phi3[i] = gear.phi4[i] = 0.0;
  }
  if (i < force_previous.size()) force_previous[i] = {}, torque_previous[i] = 0.0;
}

namespace {
template <class T>
void permute_field(std::vector<T>& v, const std::vector<std::uint32_t>& order, int threads) {
  if (v.size() != order.size()) return; // an unused field (the other integrator's history)
  std::vector<T> old = std::move(v);
  v.resize(order.size());
  const auto n = static_cast<std::ptrdiff_t>(order.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < n; ++k) v[k] = old[order[k]];
}
} // namespace

void Particles::permute(const std::vector<std::uint32_t>& order, int threads) {
  for_each_field([&](auto& v) { permute_field(v, order, threads); });
}

} // namespace talus
