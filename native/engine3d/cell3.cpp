#include "engine3d/cell3.hpp"

#include <array>
#include <cmath>

#include "engine3d/contact_visit3.hpp"
#include "talus/contact_force.hpp"
#include "talus/error.hpp"
#include "talus/law_table.hpp"

namespace talus {

void validate(const Cell3& c, const Domain3& d, std::size_t plates) {
  const auto finite = [](const Vec3& v) { return std::isfinite(v.x + v.y + v.z); };
  require(finite(c.strain_rate), "cell driver: strain_rate must be finite (1/s)");
  for (int k = 0; k < 3; ++k)
    require(component(c.strain_rate, k) == 0.0 || d.periodic[static_cast<std::size_t>(k)],
            "cell driver: strain_rate deforms an axis that is not periodic; the cell is the "
            "periodic box (geometry.periodic)");
  require(plates == 0, "a deforming cell with plates: they do not follow it; make every axis "
                       "periodic (geometry.periodic = \"xyz\")");
  require(std::isfinite(c.pressure) && c.pressure >= 0.0,
          "cell driver: pressure must be >= 0 Pa (0: the rate mode)");
  require(std::isfinite(c.shear_rate), "cell driver: shear_rate must be finite (1/s)");
  const bool sheared = c.shear_rate != 0.0;
  if (sheared) {
    require(d.periodic[0] && d.periodic[1],
            "cell driver: a shear_rate needs a box periodic in x and y (geometry.periodic): the "
            "images across y slide along x");
    require(c.strain_rate.x == 0.0,
            "cell driver: a sheared cell keeps its width: strain_rate along x must be 0");
  }
  if (c.pressure > 0.0) {
    require(sheared || (d.periodic[0] && d.periodic[1] && d.periodic[2]),
            "cell driver: a pressure needs a box periodic along every axis (geometry.periodic = "
            "\"xyz\"): the cell strains them alike");
    require(finite(c.strain_rate) && c.strain_rate.x == 0.0 && c.strain_rate.y == 0.0 &&
                c.strain_rate.z == 0.0,
            "cell driver: give strain_rate or pressure, not both");
    require_controller_keys(c);
  }
}

void attach_cell(Cell3& c, const Domain3& d, std::size_t plates) {
  validate(c, d, plates);
  c.rate = 0.0;
  c.strain = {};
  c.shear_strain = 0.0;
}

Vec3 cell_strain_rate(const Cell3& c) {
  if (c.pressure <= 0.0) return c.strain_rate;
  if (c.shear_rate != 0.0) return {0.0, c.rate, 0.0};
  return {c.rate, c.rate, c.rate};
}

void set_shear_velocity(const Cell3* c, Domain3& d) {
  // without a cell the images stop where they are
  d.shear_velocity = c == nullptr ? 0.0 : c->shear_rate * d.size().y;
}

namespace {

// The box's sides by exp(rate dt) about its lower corner, every sphere and its build position
// with it.
void strain_box(Domain3& d, Spheres& s, SphereList& list, const Vec3& rate, double dt,
                int threads) {
  const Vec3 f{std::exp(rate.x * dt), std::exp(rate.y * dt), std::exp(rate.z * dt)};
  const Vec3 lo = d.lo, size = d.size();
  d.hi = lo + Vec3{size.x * f.x, size.y * f.y, size.z * f.z};
  const auto scale = [&](const Vec3& r) {
    const Vec3 b = r - lo;
    return lo + Vec3{b.x * f.x, b.y * f.y, b.z * f.z};
  };
  const bool same = list.reference.size() == s.size();
  const auto n = static_cast<std::ptrdiff_t>(s.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    s.position[i] = scale(s.position[i]);
    if (same) list.reference[i] = scale(list.reference[i]);
  }
}

} // namespace

void deform_cell(Cell3& c, Domain3& d, Spheres& s, SphereList& list, double dt, int threads) {
  const Vec3 rate = cell_strain_rate(c);
  c.strain += dt * rate;
  if (rate.x != 0.0 || rate.y != 0.0 || rate.z != 0.0) // a shear alone moves no sphere
    strain_box(d, s, list, rate, dt, threads);
  set_shear_velocity(&c, d); // with the height after the strain
  d.shear_offset += d.shear_velocity * dt;
  c.shear_strain += c.shear_rate * dt;
}

void reduce_shear_offset(Domain3& d) {
  if (d.shear_offset == 0.0) return;
  const double width = d.size().x;
  d.shear_offset -= width * std::floor(d.shear_offset / width);
  if (d.shear_offset >= width) d.shear_offset = 0.0; // the rounding case -tiny
}

namespace {
// The reading's sums over stretches of rows fixed by the sphere count, added in order: the same
// bits whatever the thread count (as 2D's cell reading).
constexpr std::ptrdiff_t reading_chunks = 64;
} // namespace

CellReading cell_reading(const Cell3& c, const Scene3& scene, const SphereList& list,
                         const PairTable& table, const Settings3& settings, int threads) {
  const Spheres& s = scene.spheres;
  const bool across = c.shear_rate != 0.0; // sigma_yy, else the mean stress
  const LeverShares shares = lever_shares(settings.lever_arm);
  const auto n = static_cast<std::ptrdiff_t>(s.size());
  std::array<double, reading_chunks> virial{}, stiffness{};
  with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t q = 0; q < reading_chunks; ++q) {
      double w = 0.0, kc = 0.0;
      auto on_pair = [&](std::uint32_t i, std::uint32_t e, std::uint32_t j,
                         const ContactGeometry3& g, const PairParameters& p) {
        const Vec3 d = s.position[i] - (s.position[j] + list.offset(e, scene.domain));
        const double dist2 = norm2(d);
        if (across) {                      // F_y d_y: the tangential force counts here
          Vec3 spring = list.spring_at(e); // a copy: reading must not advance it
          w += contact_force<N, T>(p, g, spring, 0.0).force.y * d.y;
          kc += N::stiffness(p, g) * d.y * d.y * d.y * d.y / dist2;
        } else { // the trace of f d: the tangential force is across d and adds nothing
          w += N::force(p, g) * std::sqrt(dist2);
          kc += N::stiffness(p, g) * dist2;
        }
      };
      for (std::ptrdiff_t i = n * q / reading_chunks; i < n * (q + 1) / reading_chunks; ++i)
        for_each_pair_contact_of(scene, list, table, shares, static_cast<std::uint32_t>(i),
                                 on_pair);
      virial[static_cast<std::size_t>(q)] = w;
      stiffness[static_cast<std::size_t>(q)] = kc;
    }
  });
  double w = 0.0, k = 0.0;
  for (std::size_t q = 0; q < virial.size(); ++q) w += virial[q], k += stiffness[q];
  double mass = 0.0;
  Vec3 momentum{};
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.is_free(i)) mass += s.mass[i], momentum += s.mass[i] * s.velocity[i];
  const Vec3 mean = mass > 0.0 ? (1.0 / mass) * momentum : Vec3{};
  double kinetic = 0.0; // the trace of sum m u u, or its yy
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.is_free(i)) {
      const Vec3 u = s.velocity[i] - mean;
      kinetic += s.mass[i] * (across ? u.y * u.y : norm2(u));
    }
  const Vec3 size = scene.domain.size();
  const double volume = size.x * size.y * size.z;
  if (across) return {.pressure = (w + kinetic) / volume, .stiffness = k / volume};
  return {.pressure = (w + kinetic) / (3.0 * volume), .stiffness = k / (3.0 * volume)};
}

} // namespace talus
