// Coarse-grained fields (post/coarse_grain.hpp) against what they must give: kernels of unit
// weight, fields that integrate to the totals of the particles and contacts they spread, and a
// settled bed whose coarse-grained stress is the weight above each height (Weinhart et al. 2012:
// the coarse-grained fields satisfy the momentum balance exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "analysis/frame.hpp"
#include "post/chute.hpp"
#include "post/coarse_grain.hpp"
#include "post/coarse_grain_map.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "support/smooth_bed.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

constexpr double g_cg = 9.81;

// Simpson's rule on n (even) intervals.
template <class F> double integral(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int k = 1; k < n; ++k) s += (k % 2 == 1 ? 4.0 : 2.0) * f(a + k * h);
  return s * h / 3.0;
}

// Each kernel weighs 1, and its integral is the integral of it. Tolerance 1e-9: far above
// Simpson's error on 2e4 intervals (Lucy's kernel has a jump in its third derivative at 0).
TEST(CoarseGrain, KernelsWeighOneAndTheirIntegralsAgree) {
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy}) {
    const double w = 0.003;
    EXPECT_NEAR(integral([&](double x) { return cg_kernel(k, w, x); }, -10 * w, 10 * w), 1.0, 1e-9);
    for (const double x : {-1.5 * w, -0.7 * w, -0.1 * w, 0.0, 0.3 * w, 0.9 * w, 2.0 * w})
      EXPECT_NEAR(cg_kernel_integral(k, w, x),
                  integral([&](double u) { return cg_kernel(k, w, u); }, -10 * w, x), 1e-9)
          << cg_kernel_name(k) << " at " << x / w << " w";
    EXPECT_NEAR(cg_kernel_integral(k, w, -10 * w), 0.0, 1e-15);
    EXPECT_NEAR(cg_kernel_integral(k, w, 10 * w), 1.0, 1e-15);
  }
  EXPECT_EQ(cg_kernel(CgKernel::lucy, 1.0, 1.0), 0.0);
  EXPECT_THROW(parse_cg_kernel("box"), InvalidArgument);
}

// 40 grains with velocities and masses, and contacts between them and with walls.
Frame random_frame() {
  Frame f;
  std::uint32_t seed = 12345;
  const auto uniform = [&] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  for (std::uint32_t i = 0; i < 42; ++i) {
    f.id.push_back(i);
    f.position.push_back({0.1 * uniform(), 0.05 + 0.1 * uniform()});
    f.radius.push_back(0.002);
    f.velocity.push_back({uniform() - 0.5, uniform() - 0.5});
    f.force.push_back({});
    f.kind.push_back(i < 40 ? 0 : 1); // two wall particles
    f.material.push_back(0);
    f.mass.push_back(0.001 * (1.0 + uniform()));
  }
  for (std::uint32_t k = 0; k < 60; ++k) {
    const auto a = static_cast<std::size_t>(42 * uniform()),
               b = static_cast<std::size_t>(42 * uniform());
    const bool wall = k % 5 == 0;
    const Vec2 to = wall ? f.position[a] + Vec2{0.0, -0.002} : f.position[b];
    Frame::Chain c{f.position[a], to, 1.0};
    c.force_on_from = {uniform() - 0.5, uniform() - 0.5};
    c.point = wall ? to : 0.5 * (f.position[a] + to);
    c.from_free = f.kind[a] == 0;
    c.to_free = !wall && f.kind[b] == 0;
    c.has_vector = true;
    f.chains.push_back(c);
  }
  return f;
}

// The density integrates to the grains' mass, the momentum to theirs, and the contact stress
// to the sum of f (r - c) over the grains' sides of the contacts, each times the extent across.
// Tolerance 1e-8 relative: the trapezoid rule over a profile reaching 10 widths past the grains,
// to rounding with the Gaussian; Lucy's kernel, whose third derivative jumps, leaves an error of
// the order of (spacing / width)^4, about 2e-8 here.
TEST(CoarseGrain, TheFieldsIntegrateToTheTotals) {
  const Frame f = random_frame();
  double mass = 0.0;
  Vec2 momentum{};
  for (std::size_t i = 0; i < f.mass.size(); ++i)
    if (f.kind[i] == 0) mass += f.mass[i], momentum += f.mass[i] * f.velocity[i];
  Tensor2 sides = Tensor2::Zero();
  const auto add = [&](Vec2 force, Vec2 centre, Vec2 point) {
    const Vec2 b = centre - point;
    Tensor2 t;
    t << force.x * b.x, force.x * b.y, force.y * b.x, force.y * b.y;
    sides += t;
  };
  for (const Frame::Chain& c : f.chains) {
    if (c.from_free) add(c.force_on_from, c.from, c.point);
    if (c.to_free) add(-1.0 * c.force_on_from, c.to, c.point);
  }
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy}) {
    CgOptions o;
    o.kernel = k, o.width = 0.004, o.axis = 1, o.lo = 0.0, o.hi = 0.2, o.points = 4001;
    o.across = 0.1;
    const FieldProfile p = coarse_grain({f}, o);
    const double dy = (o.hi - o.lo) / static_cast<double>(o.points - 1);
    double m = 0.0;
    Vec2 q{};
    Tensor2 s = Tensor2::Zero();
    for (std::size_t j = 0; j < p.at.size(); ++j) {
      const double w = (j == 0 || j + 1 == p.at.size() ? 0.5 : 1.0) * dy * o.across;
      m += w * p.density[j], q += w * p.momentum[j], s += w * p.contact[j];
    }
    EXPECT_NEAR(m, mass, 1e-8 * mass) << cg_kernel_name(k);
    EXPECT_NEAR(q.x, momentum.x, 1e-8 * mass) << cg_kernel_name(k);
    EXPECT_NEAR(q.y, momentum.y, 1e-8 * mass) << cg_kernel_name(k);
    EXPECT_LT((s - sides).norm(), 1e-8 * sides.norm()) << cg_kernel_name(k);
  }
}

// The maps (post/coarse_grain_map.hpp) integrate to the same totals, cell by cell: the Gaussian
// to 1e-5, its weight beyond its cut-off at 5 widths in the plane (6e-7); Lucy's kernel to 3e-4,
// the midpoint rule on cells a fifth of its width over a kernel whose third derivative jumps
// (measured: 1e-4). Averaged across
// x, the Gaussian map is the profile along y: its density to the same 1e-5, its contact stress
// to 1e-4 of the largest (the branch integrated by quadrature rather than exactly).
TEST(CoarseGrain, TheMapsIntegrateToTheTotalsAndAverageToTheProfiles) {
  const Frame f = random_frame();
  double mass = 0.0;
  Tensor2 sides = Tensor2::Zero();
  for (std::size_t i = 0; i < f.mass.size(); ++i)
    if (f.kind[i] == 0) mass += f.mass[i];
  for (const Frame::Chain& c : f.chains)
    for (const auto& [on, force, centre] : {std::tuple{c.from_free, c.force_on_from, c.from},
                                            std::tuple{c.to_free, -1.0 * c.force_on_from, c.to}}) {
      if (!on) continue;
      const Vec2 b = centre - c.point;
      Tensor2 t;
      t << force.x * b.x, force.x * b.y, force.y * b.x, force.y * b.y;
      sides += t;
    }
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy}) {
    CgMapOptions o;
    o.kernel = k, o.width = 0.004, o.lo = {-0.03, 0.0}, o.hi = {0.13, 0.2}, o.nx = 200;
    o.ny = 250;
    const FieldMap m = coarse_grain_map({f}, o);
    const double area = m.cell_x * m.cell_y;
    double total = 0.0;
    Tensor2 s = Tensor2::Zero();
    for (std::size_t c = 0; c < m.density.size(); ++c)
      total += area * m.density[c], s += area * m.contact[c];
    const double tolerance = k == CgKernel::gaussian ? 1e-5 : 3e-4;
    EXPECT_NEAR(total, mass, tolerance * mass) << cg_kernel_name(k);
    EXPECT_LT((s - sides).norm(), tolerance * sides.norm()) << cg_kernel_name(k);
    if (k != CgKernel::gaussian) continue;
    CgOptions po;
    po.kernel = k, po.width = o.width, po.lo = 0.0 + 0.5 * m.cell_y, po.hi = 0.2 - 0.5 * m.cell_y;
    po.points = o.ny, po.across = o.hi.x - o.lo.x;
    const FieldProfile p = coarse_grain({f}, po);
    double largest = 0.0;
    for (const Tensor2& t : p.contact) largest = std::max(largest, t.norm());
    for (std::size_t row = 0; row < m.ny; ++row) {
      double rho = 0.0;
      Tensor2 sigma = Tensor2::Zero();
      for (std::size_t col = 0; col < m.nx; ++col)
        rho += m.density[row * m.nx + col] / static_cast<double>(m.nx),
            sigma += m.contact[row * m.nx + col] / static_cast<double>(m.nx);
      EXPECT_NEAR(rho, p.density[row], 1e-5 * mass / (po.across * o.width)) << row;
      EXPECT_LT((sigma - p.contact[row]).norm(), 1e-4 * largest) << row;
    }
  }
}

// The vertical stress of a settled bed (testing::smooth_bed). Between two heights the contact
// stress changes by the contact forces on the grains spread there (the pairs' forces cancel at
// their contact points), so exactly sigma_yy(y) L = sum_walls f_y Phi(y - c_y) - sum_i (F_i,y + m_i
// g) Phi(y - y_i), Phi the kernel's integral, F_i the net force on grain i (its contact forces and
// weight): to rounding, 1e-9. At rest F_i = 0, and above the floor's contacts the stress is the
// weight above y: to 2e-3 of the bottom's, the bed's residual vibration (E_kin < 1e-9 sum m g R).
TEST(CoarseGrain, ASettledBedsStressIsTheWeightAbove) {
  BuiltScenario b = build_scenario(load_scenario(testing::smooth_bed, "bed.toml"));
  const Simulation sim(std::move(b.world), b.config);
  const Frame f = frame_of(sim);
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy}) {
    CgOptions o;
    o.kernel = k, o.width = k == CgKernel::gaussian ? 0.003 : 0.006;
    o.lo = -0.01, o.hi = 0.06, o.points = 141, o.across = 0.06;
    const FieldProfile p = coarse_grain({f}, o);
    double top = 0.0, bottom_weight = 0.0;
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) top = std::max(top, f.position[i].y), bottom_weight += f.mass[i] * g_cg;
    bottom_weight /= o.across;
    double worst_physical = 0.0, worst_wrong_g = 0.0;
    for (std::size_t j = 0; j < p.at.size(); ++j) {
      const double y = p.at[j];
      const auto Phi = [&](double x) { return cg_kernel_integral(o.kernel, o.width, x); };
      double exact = 0.0, weight_above = 0.0, heavier = 0.0;
      for (const Frame::Chain& c : f.chains)
        if (!c.to_free && c.from_free) exact += c.force_on_from.y * Phi(y - c.point.y);
      for (std::size_t i = 0; i < f.position.size(); ++i) {
        if (f.kind[i] != 0) continue;
        exact -= (f.force[i].y + f.mass[i] * g_cg) * Phi(y - f.position[i].y);
        weight_above += f.mass[i] * g_cg * (1.0 - Phi(y - f.position[i].y));
        heavier += 2.0 * f.mass[i] * g_cg * (1.0 - Phi(y - f.position[i].y));
      }
      EXPECT_NEAR(p.contact[j](1, 1), exact / o.across, 1e-9 * bottom_weight) << y;
      if (y > 4.0 * o.width && y < top) { // clear of the floor's contacts
        worst_physical =
            std::max(worst_physical, std::abs(p.contact[j](1, 1) * o.across - weight_above));
        worst_wrong_g = std::max(worst_wrong_g, std::abs(p.contact[j](1, 1) * o.across - heavier));
      }
    }
    EXPECT_LT(worst_physical, 2e-3 * bottom_weight * o.across) << cg_kernel_name(k);
    // the same rule fails a wrong input: the weight of a bed twice as heavy
    EXPECT_GT(worst_wrong_g, 0.2 * bottom_weight * o.across) << cg_kernel_name(k);
  }
}

TEST(CoarseGrain, BadOptionsAndOldSnapshotsAreRefused) {
  Frame f = random_frame();
  CgOptions o;
  o.width = 0.0, o.lo = 0.0, o.hi = 0.1, o.points = 10, o.across = 0.1;
  EXPECT_THROW(coarse_grain({f}, o), InvalidArgument);
  o.width = 0.002;
  f.mass.clear();
  EXPECT_THROW(coarse_grain({f}, o), InvalidArgument);
  // the analyses built on it refuse such snapshots by name too, never reading masses they lack
  // (a LAMMPS run made into a run folder without masses crashed the chute analysis)
  f.position[40].y = f.position[41].y = 0.04; // the wall grains: a base under the others
  ChuteOptions c;
  c.width = 0.002, c.across = 0.1, c.gravity = {3.0, -9.0};
  EXPECT_THROW(chute_flow({f, f}, c), InvalidArgument);
}

} // namespace
} // namespace talus
