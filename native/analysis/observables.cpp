#include "analysis/observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "talus/rolling_resistance.hpp"

namespace talus {

Energies energies(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  const Vec2 g = sim.world().gravity;
  Energies e;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i)) continue;
    e.translational += 0.5 * p.mass[i] * norm2(p.velocity[i]);
    e.rotational += 0.5 * p.inertia[i] * p.angular_velocity[i] * p.angular_velocity[i];
    e.gravitational -= p.mass[i] * dot(g, p.position[i]);
  }
  const SimulationConfig& c = sim.config();
  with_contact_law(c.normal_law, c.tangential_law, [&]<class N, class T>() {
    sim.for_each_contact([&](const ContactView& v) {
      e.elastic += contact_elastic_energy<N, T>(*v.parameters, v.geometry, v.history);
      if (v.rolling != 0.0)
        e.elastic += RollingLaw::elastic_energy<N>(*v.parameters, v.geometry, v.rolling);
    });
  });
  return e;
}

Vec2 linear_momentum(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  Vec2 m;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) m += p.mass[i] * p.velocity[i];
  return m;
}

double angular_momentum(const Simulation& sim, Vec2 point) {
  const Particles& p = sim.world().particles;
  double l = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i))
      l += p.mass[i] * cross(p.position[i] - point, p.velocity[i]) +
           p.inertia[i] * p.angular_velocity[i];
  return l;
}

std::size_t contact_count(const Simulation& sim) {
  std::size_t n = 0;
  sim.for_each_contact([&](const ContactView&) { ++n; });
  return n;
}

double coordination_number(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  double contacts = 0.0; // sum over free particles of their contacts
  sim.for_each_contact([&](const ContactView& v) {
    if (p.is_free(v.i)) contacts += 1.0;
    if (v.wall < 0 && p.is_free(v.j)) contacts += 1.0;
  });
  const std::size_t n = p.count(Kind::free);
  return n ? contacts / static_cast<double>(n) : 0.0;
}

std::vector<ContactRecord> contact_forces(const Simulation& sim) {
  std::vector<ContactRecord> out;
  const Particles& p = sim.world().particles;
  const SimulationConfig& c = sim.config();
  with_contact_law(c.normal_law, c.tangential_law, [&]<class N, class T>() {
    sim.for_each_contact([&](const ContactView& v) {
      double history = v.history; // a copy: measuring must not advance the spring
      const ContactForce f = contact_force<N, T>(*v.parameters, v.geometry, history, 0.0);
      ContactRecord r;
      r.i = v.i;
      r.from = p.position[v.i];
      const ContactGeometry& g = v.geometry;
      if (v.wall < 0) { // the centres are a_i + a_j apart along n
        r.j = v.j;
        r.to = r.from - (g.arm_i + g.arm_j) * normal_of(g);
      } else { // the wall's nearest point is R - xi = a_i - xi/2 from the centre
        r.j = -1 - v.wall;
        r.to = r.from - (g.arm_i - 0.5 * g.overlap) * normal_of(g);
      }
      r.point = r.from - g.arm_i * normal_of(g);
      r.overlap = g.overlap;
      r.overlap_rate = g.overlap_rate();
      r.m_eff = g.m_eff;
      r.normal_force = f.normal_force;
      r.force = force_of(f);
      r.tangential_force = dot(r.force, tangent_of(v.geometry));
      ContactGeometry at_rest = g;
      at_rest.v_normal = 0.0;
      r.elastic_force = N::force(*v.parameters, at_rest);
      r.stiffness = N::stiffness(*v.parameters, g);
      out.push_back(r);
    });
  });
  return out;
}

Vec2 force_on_particles(const Simulation& sim, const std::vector<std::uint32_t>& indices) {
  Vec2 f;
  for (const auto i : indices) f += sim.world().particles.force[i];
  return f;
}

namespace {
// Area of {(x, y) in disk of radius r at the origin : x <= a, y <= b}. Integrates the chord
// clipped at b over x = r sin(theta), which is smooth on each piece between kinks; 20-point
// Gauss-Legendre per piece is exact to round-off for the polynomial-in-trig integrand pieces.
double quadrant_area(double r, double a, double b) {
  if (a <= -r || b <= -r) return 0.0;
  a = std::min(a, r);
  b = std::min(b, r);
  // chord length at x: from -s(x) to min(b, s(x)), s = sqrt(r^2 - x^2)
  const auto integrand = [&](double th) {
    const double s = r * std::cos(th);
    const double top = std::min(b, s);
    return std::max(0.0, top + s) * r * std::cos(th);
  };
  std::vector<double> cuts{-std::numbers::pi / 2, std::asin(a / r)};
  if (std::abs(b) < r) {
    const double k = std::acos(std::abs(b) / r); // where s(x) = |b|
    for (double c : {-k, k})
      if (c > cuts[0] && c < cuts[1]) cuts.push_back(c);
  }
  std::sort(cuts.begin(), cuts.end());
  static constexpr double xg[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195,
                                    0.5108670019508271, 0.6360536807265150, 0.7463319064601508,
                                    0.8391169718222188, 0.9122344282513259, 0.9639719272779138,
                                    0.9931285991850949};
  static constexpr double wg[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820,
                                    0.1316886384491766, 0.1181945319615184, 0.1019301198172404,
                                    0.0832767415767048, 0.0626720483341091, 0.0406014298003869,
                                    0.0176140071391521};
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double m = 0.5 * (cuts[k] + cuts[k + 1]), h = 0.5 * (cuts[k + 1] - cuts[k]);
    for (int q = 0; q < 10; ++q)
      area += h * wg[q] * (integrand(m - h * xg[q]) + integrand(m + h * xg[q]));
  }
  return area;
}
} // namespace

double disk_rectangle_area(Vec2 c, double r, Vec2 lo, Vec2 hi) {
  const Vec2 l = lo - c, h = hi - c;
  const double a = quadrant_area(r, h.x, h.y) - quadrant_area(r, l.x, h.y) -
                   quadrant_area(r, h.x, l.y) + quadrant_area(r, l.x, l.y);
  return std::max(0.0, a);
}

double packing_fraction(const Simulation& sim, Vec2 lo, Vec2 hi) {
  const Particles& p = sim.world().particles;
  const double region = (hi.x - lo.x) * (hi.y - lo.y);
  if (region <= 0.0) return 0.0;
  // in a periodic box, a grain where it is (wrapped) and its images: the parts of it past the
  // box's sides are in the region through them
  const Domain& box = sim.world().domain;
  const Vec2 l = box.size();
  const int nx = box.periodic_x ? 1 : 0, ny = box.periodic_y ? 1 : 0;
  double covered = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i)) continue;
    const Vec2 r = box.wrap(p.position[i]);
    for (int sx = -nx; sx <= nx; ++sx)
      for (int sy = -ny; sy <= ny; ++sy)
        covered += disk_rectangle_area(r + Vec2{sx * l.x, sy * l.y}, p.radius[i], lo, hi);
  }
  return covered / region;
}

double disc_area_fraction(const Simulation& sim, Vec2 centre, double radius) {
  const Particles& p = sim.world().particles;
  double covered = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && norm(p.position[i] - centre) < radius) covered += p.radius[i] * p.radius[i];
  return covered / (radius * radius); // the factors pi cancel
}

} // namespace talus
