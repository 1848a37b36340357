// Coarse-grained fields of spheres in 3D (post/coarse_grain.hpp) against what they must give, as
// tests/physics/test_coarse_grain.cpp checks them in 2D: fields that integrate to the totals of
// the spheres and contacts they spread; a settled bed whose stress is the weight above each
// height (Weinhart et al. 2012: the coarse-grained fields satisfy the momentum balance exactly);
// a sheared cell whose stress averaged over its period is the cell's own (analysis/stress3.hpp),
// with the velocity of the shear continuous through its sliding side; and snapshots that read back
// as the state they were written from.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "analysis/frame3.hpp"
#include "analysis/stress3.hpp"
#include "cli/builtin_scenarios.hpp"
#include "io/vtk_spheres.hpp"
#include "io/vtp_reader.hpp"
#include "post/chute.hpp"
#include "post/coarse_grain.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/build3.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

constexpr double g_cg3 = 9.81;

Tensor3 outer3(const Vec3& a, const Vec3& b) {
  Tensor3 t;
  t << a.x * b.x, a.x * b.y, a.x * b.z, a.y * b.x, a.y * b.y, a.y * b.z, a.z * b.x, a.z * b.y,
      a.z * b.z;
  return t;
}

// 40 spheres with velocities and masses, two fixed ones, and contacts between them and with
// plates.
Frame3 random_frame3() {
  Frame3 f;
  std::uint32_t seed = 2024;
  const auto uniform = [&] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  for (std::uint32_t i = 0; i < 42; ++i) {
    f.id.push_back(i);
    f.position.push_back({0.05 * uniform(), 0.04 * uniform(), 0.05 + 0.1 * uniform()});
    f.radius.push_back(0.002);
    f.velocity.push_back({uniform() - 0.5, uniform() - 0.5, uniform() - 0.5});
    f.kind.push_back(i < 40 ? 0 : 1);
    f.mass.push_back(0.001 * (1.0 + uniform()));
  }
  for (std::uint32_t k = 0; k < 60; ++k) {
    const auto a = static_cast<std::size_t>(42 * uniform()),
               b = static_cast<std::size_t>(42 * uniform());
    const bool plate = k % 5 == 0;
    const Vec3 to = plate ? f.position[a] + Vec3{0.0, 0.001, -0.0017} : f.position[b];
    Frame3::Chain c{f.position[a], to, 1.0};
    c.force_on_from = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
    c.point = plate ? to : 0.5 * (f.position[a] + to);
    c.from_free = f.kind[a] == 0;
    c.to_free = !plate && f.kind[b] == 0;
    f.chains.push_back(c);
  }
  return f;
}

// Sum f (r - c) over the free spheres' sides of the contacts.
Tensor3 branch_sum(const Frame3& f) {
  Tensor3 sides = Tensor3::Zero();
  for (const Frame3::Chain& c : f.chains) {
    if (c.from_free) sides += outer3(c.force_on_from, c.from - c.point);
    if (c.to_free) sides += outer3(-1.0 * c.force_on_from, c.to - c.point);
  }
  return sides;
}

// The density integrates to the spheres' mass, the momentum to theirs, and the contact stress to
// the sum of f (r - c) over the spheres' sides of the contacts, each times the area across, along
// each axis. Tolerance 1e-8 relative: as in 2D, the trapezoid rule over a profile reaching 10
// widths past the spheres, to rounding with the Gaussian and (spacing / width)^4 with Lucy's.
TEST(CoarseGrain3, TheFieldsIntegrateToTheTotalsAlongEachAxis) {
  const Frame3 f = random_frame3();
  double mass = 0.0;
  Vec3 momentum{};
  for (std::size_t i = 0; i < f.mass.size(); ++i)
    if (f.kind[i] == 0) mass += f.mass[i], momentum += f.mass[i] * f.velocity[i];
  const Tensor3 sides = branch_sum(f);
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy})
    for (int axis = 0; axis < 3; ++axis) {
      CgOptions3 o;
      o.kernel = k, o.width = 0.004, o.axis = axis, o.lo = -0.05, o.hi = 0.2, o.points = 5001;
      o.extent = {0.05, 0.04, 0.1};
      const FieldProfile3 p = coarse_grain({f}, o);
      const double dx = (o.hi - o.lo) / static_cast<double>(o.points - 1);
      double m = 0.0;
      Vec3 q{};
      Tensor3 s = Tensor3::Zero();
      for (std::size_t j = 0; j < p.at.size(); ++j) {
        const double w = (j == 0 || j + 1 == p.at.size() ? 0.5 : 1.0) * dx * p.across;
        m += w * p.density[j], q += w * p.momentum[j], s += w * p.contact[j];
      }
      const double area = 0.05 * 0.04 * 0.1 / component(Vec3{0.05, 0.04, 0.1}, axis);
      EXPECT_DOUBLE_EQ(p.across, area);
      EXPECT_NEAR(m, mass, 1e-8 * mass) << cg_kernel_name(k) << axis;
      EXPECT_LT(norm(q - momentum), 1e-8 * mass) << cg_kernel_name(k) << axis;
      EXPECT_LT((s - sides).norm(), 1e-8 * sides.norm()) << cg_kernel_name(k) << axis;
    }
}

BuiltScenario3 builtin3(const std::string& name, const std::vector<std::string>& set) {
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == name) return build_scenario3(load_scenario3(b.text, name, set));
  throw InvalidArgument("no built-in " + name);
}

// A bed of 120 frictional spheres come to rest on a flat floor in a box periodic across. Between
// two heights the contact stress changes by the contact forces on the spheres spread there (a
// pair's forces cancel at its contact point), so exactly sigma_zz(z) A = sum_plates f_z Phi(z -
// c_z) - sum_i F_i,z Phi(z - z_i), F_i the sum of the contact forces on sphere i and Phi the
// kernel's integral: to rounding, 1e-9 of the weight. At rest the contact forces on a sphere
// carry its weight, and above the floor's contacts the stress is the weight above z: to 2e-3 of
// the bottom's, the bed's residual motion. The same rule fails a bed twice as heavy.
TEST(CoarseGrain3, ASettledBedsStressIsTheWeightAbove) {
  const BuiltScenario3 b =
      builtin3("pour3d", {"particles.count=120", "geometry.box=[0, 0, 0, 0.015, 0.015, 0.06]",
                          "geometry.periodic=xy"});
  Simulation3 sim(b.scene, b.settings);
  sim.run(static_cast<std::uint64_t>(0.5 / b.settings.timestep));
  const Frame3 f = frame3_of(sim);
  ASSERT_GT(f.chains.size(), 80u);
  std::vector<Vec3> on(f.position.size(), Vec3{}); // contact forces on each sphere, by index
  double weight = 0.0, kinetic = 0.0, top = 0.0;
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    weight += f.mass[i] * g_cg3, top = std::max(top, f.position[i].z);
    kinetic += 0.5 * f.mass[i] * norm2(f.velocity[i]);
  }
  ASSERT_LT(kinetic, 1e-5 * weight * 1.5e-3) << "the bed is not at rest";
  // each pair's force on the sphere at `from` and on its partner, found by their centres (the
  // partner's may be an image across x or y)
  const auto sphere_at = [&](const Vec3& r) {
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      Vec3 d = r - f.position[i];
      d.x -= 0.015 * std::round(d.x / 0.015), d.y -= 0.015 * std::round(d.y / 0.015);
      if (norm(d) < 1e-12) return i;
    }
    ADD_FAILURE() << "no sphere at a contact's end";
    return std::size_t{0};
  };
  for (const Frame3::Chain& c : f.chains) {
    on[sphere_at(c.from)] += c.force_on_from;
    if (c.to_free) on[sphere_at(c.to)] += -1.0 * c.force_on_from;
  }
  const double area = 0.015 * 0.015, bottom = weight / area;
  for (const CgKernel k : {CgKernel::gaussian, CgKernel::lucy}) {
    CgOptions3 o;
    o.kernel = k, o.width = k == CgKernel::gaussian ? 0.001 : 0.002, o.axis = 2;
    o.lo = -0.004, o.hi = 0.03, o.points = 341;
    const FieldProfile3 p = coarse_grain({f}, o);
    EXPECT_DOUBLE_EQ(p.across, area);
    double worst_physical = 0.0, worst_heavier = 0.0;
    for (std::size_t j = 0; j < p.at.size(); ++j) {
      const double z = p.at[j];
      const auto Phi = [&](double x) { return cg_kernel_integral(o.kernel, o.width, x); };
      double exact = 0.0, weight_above = 0.0;
      for (const Frame3::Chain& c : f.chains)
        if (!c.to_free && c.from_free && norm(c.to - c.point) == 0.0) // a plate's
          exact += c.force_on_from.z * Phi(z - c.point.z);
      for (std::size_t i = 0; i < f.position.size(); ++i) {
        exact -= on[i].z * Phi(z - f.position[i].z);
        weight_above += f.mass[i] * g_cg3 * (1.0 - Phi(z - f.position[i].z));
      }
      EXPECT_NEAR(p.contact[j](2, 2), exact / area, 1e-9 * bottom) << z;
      if (z > 4.0 * o.width && z < top) { // clear of the floor's contacts
        worst_physical =
            std::max(worst_physical, std::abs(p.contact[j](2, 2) * area - weight_above));
        worst_heavier =
            std::max(worst_heavier, std::abs(p.contact[j](2, 2) * area - 2.0 * weight_above));
      }
    }
    EXPECT_LT(worst_physical, 2e-3 * weight) << cg_kernel_name(k);
    EXPECT_GT(worst_heavier, 0.2 * weight) << cg_kernel_name(k);
  }
}

// The spheres of a sheared cell (simple_shear3d made small) a while into their shear: the contact
// stress averaged over the period along y is the cell's own contact stress over its box
// (region_stress), to rounding: 1e-9 of the largest component. Along x and z the same.
TEST(CoarseGrain3, ACellsStressAveragedOverItsPeriodIsItsOwn) {
  const BuiltScenario3 b =
      builtin3("simple_shear3d", {"particles.count=150", "geometry.box=[0, 0, 0, 0.12, 0.1, 0.06]",
                                  "drivers.0.pressure=200"});
  Simulation3 sim(b.scene, b.settings);
  sim.run(static_cast<std::uint64_t>(0.15 / b.settings.timestep));
  const Domain3& d = sim.scene().domain;
  ASSERT_NE(d.shear_offset, 0.0);
  const Tensor3 own = region_stress(sim, d.lo, d.hi).contact;
  ASSERT_GT(own.norm(), 0.0);
  const Frame3 f = frame3_of(sim);
  for (int axis = 0; axis < 3; ++axis) {
    CgOptions3 o;
    o.width = 0.004, o.axis = axis, o.points = 400;
    o.lo = component(d.lo, axis), o.hi = component(d.hi, axis);
    const FieldProfile3 p = coarse_grain({f}, o);
    Tensor3 mean = Tensor3::Zero();
    for (std::size_t j = 0; j + 1 < p.at.size(); ++j) mean += p.contact[j]; // one period
    mean /= static_cast<double>(p.at.size() - 1);
    EXPECT_LT((mean - own).norm(), 1e-9 * own.norm()) << "axis " << axis;
  }
}

// Spheres on a lattice moving with a shear flow v_x = gamma_dot (y - y_c) in a box periodic in y
// whose image above slides at gamma_dot L_y (Lees-Edwards): the coarse-grained velocity is the
// flow everywhere, through the sliding side too, to 1e-3 of the slide (the lattice's
// discreteness under a kernel two spacings wide). Without the images' slide the profile bends
// near the side by a large part of it.
TEST(CoarseGrain3, AShearFlowsVelocityRunsOnThroughTheSlidingSide) {
  const double side = 0.1, rate = 3.0, spacing = side / 50.0;
  Frame3 f;
  for (int i = 0; i < 50; ++i) {
    const double y = (i + 0.5) * spacing;
    f.id.push_back(static_cast<std::uint32_t>(i));
    f.position.push_back({0.01, y, 0.01});
    f.radius.push_back(0.4 * spacing);
    f.velocity.push_back({rate * (y - 0.5 * side), 0.0, 0.0});
    f.kind.push_back(0);
    f.mass.push_back(1e-3);
  }
  f.box_lo = {0.0, 0.0, 0.0}, f.box_hi = {0.02, side, 0.02};
  f.periodic = {true, true, true};
  f.shear_velocity = rate * side;
  CgOptions3 o;
  o.width = 2.0 * spacing, o.axis = 1, o.lo = 0.0, o.hi = side, o.points = 201;
  const auto worst = [&](const Frame3& frame) {
    const FieldProfile3 p = coarse_grain({frame}, o);
    double w = 0.0;
    for (std::size_t k = 0; k < p.at.size(); ++k)
      w = std::max(w, std::abs(p.velocity(k).x - rate * (p.at[k] - 0.5 * side)));
    return w;
  };
  EXPECT_LT(worst(f), 1e-3 * rate * side);
  Frame3 still = f;
  still.shear_velocity = 0.0;
  EXPECT_GT(worst(still), 0.2 * rate * side);
}

// A snapshot's spheres and contacts (io/vtk_spheres.hpp) read back (io/vtp_reader.hpp) as the
// frame of the state they were written from: positions and velocities exactly (written as the
// shortest text that reads back to the same double), contacts to their 9 digits.
TEST(CoarseGrain3, ASnapshotReadsBackAsTheStateItWasWrittenFrom) {
  const BuiltScenario3 b = builtin3("simple_shear3d", {"particles.count=200",
                                                       "geometry.box=[0, 0, 0, 0.055, 0.25, 0.055]",
                                                       "drivers.0.max_strain_rate=20"});
  Simulation3 sim(b.scene, b.settings);
  sim.run(static_cast<std::uint64_t>(0.15 / b.settings.timestep));
  const Frame3 f = frame3_of(sim);
  const auto dir =
      std::filesystem::temp_directory_path() / ("talus_frame3_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.vtp") << vtp_spheres(sim.scene());
  std::ofstream(dir / "c.vtp") << vtp_contacts3(sim);
  const Frame3 r = read_vtp_frame3((dir / "s.vtp").string(), f.time, (dir / "c.vtp").string());
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.id, f.id);
  EXPECT_EQ(r.kind, f.kind);
  EXPECT_EQ(r.mass, f.mass);
  ASSERT_EQ(r.position.size(), f.position.size());
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    EXPECT_EQ(norm(r.position[i] - f.position[i]), 0.0);
    EXPECT_EQ(norm(r.velocity[i] - f.velocity[i]), 0.0);
  }
  EXPECT_EQ(norm(r.box_hi - f.box_hi), 0.0);
  EXPECT_EQ(r.periodic, f.periodic);
  EXPECT_EQ(r.shear_velocity, f.shear_velocity);
  ASSERT_EQ(r.chains.size(), f.chains.size());
  ASSERT_GT(f.chains.size(), 0u);
  for (std::size_t k = 0; k < f.chains.size(); ++k) {
    const Frame3::Chain &a = r.chains[k], &e = f.chains[k];
    EXPECT_LE(norm(a.force_on_from - e.force_on_from), 1e-8 * norm(e.force_on_from)) << k;
    EXPECT_LT(norm(a.point - e.point), 1e-10) << k;
    EXPECT_EQ(a.from_free, e.from_free);
    EXPECT_EQ(a.to_free, e.to_free);
  }
}

// A layer of spheres on a simple cubic lattice over a base of fixed ones, periodic along x and y,
// moving down the slope with Bagnold's profile v(z) = v_b + c (h^1.5 - (h - z)^1.5): the chute
// analysis (post/chute.hpp) finds the base, the depth within a diameter, and c to 2% (the lattice's
// layers under a kernel as wide as a radius), the Bagnold fit far closer than a straight line's;
// a straight profile is fitted no better by Bagnold's than by the line. Gravity that does not
// point into the base along -z, or a layer without a base, is not measured, saying why.
Frame3 chute_layer(double c, bool bagnold) {
  Frame3 f;
  const double r = 0.001, a = 0.002, base = 2.0 * r, h = 15 * a;
  f.box_lo = {0.0, 0.0, 0.0}, f.box_hi = {0.02, 0.02, 0.1};
  f.periodic = {true, true, false};
  const auto add = [&](Vec3 at, Vec3 v, std::uint8_t kind) {
    f.id.push_back(static_cast<std::uint32_t>(f.id.size()));
    f.position.push_back(at), f.velocity.push_back(v), f.radius.push_back(r),
        f.kind.push_back(kind);
    f.mass.push_back(2500.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r);
  };
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      add({(i + 0.5) * a, (j + 0.5) * a, r}, {}, 1);
      for (int k = 0; k < 15; ++k) {
        const double z = (k + 0.5) * a; // above the base's top
        const double v = bagnold ? 0.1 + c * (std::pow(h, 1.5) - std::pow(h - z, 1.5))
                                 : 0.1 + c * std::sqrt(h) * z;
        add({(i + 0.5) * a, (j + 0.5) * a, base + z}, {v, 0.0, 0.0}, 0);
      }
    }
  return f;
}

TEST(CoarseGrain3, AChuteLayersBagnoldProfileIsFoundAgain) {
  ChuteOptions3 o;
  o.width = 0.001, o.gravity = {4.0, 0.0, -8.95};
  const ChuteFlow flow = chute_flow({chute_layer(30.0, true)}, o);
  ASSERT_TRUE(flow.measured) << flow.why_not;
  EXPECT_NEAR(flow.base, 0.002, 1e-12);
  EXPECT_NEAR(flow.depth, 0.03, 0.002);
  EXPECT_NEAR(flow.bagnold.slope, 30.0, 0.02 * 30.0);
  EXPECT_LT(flow.bagnold.rms, 0.2 * flow.straight.rms);
  EXPECT_NEAR(flow.angle, std::atan(4.0 / 8.95), 1e-12);
  const ChuteFlow straight = chute_flow({chute_layer(30.0, false)}, o);
  ASSERT_TRUE(straight.measured) << straight.why_not;
  EXPECT_GT(straight.bagnold.rms, 2.0 * straight.straight.rms);
  o.gravity = {4.0, 1.0, -8.95};
  EXPECT_FALSE(chute_flow({chute_layer(30.0, true)}, o).measured);
  Frame3 no_base = chute_layer(30.0, true);
  for (auto& k : no_base.kind) k = 0;
  o.gravity = {4.0, 0.0, -8.95};
  EXPECT_FALSE(chute_flow({no_base}, o).measured);
}

TEST(CoarseGrain3, BadOptionsAreRefused) {
  const Frame3 f = random_frame3();
  CgOptions3 o;
  o.width = 0.002, o.lo = 0.0, o.hi = 0.1, o.points = 10, o.extent = {0.05, 0.04, 0.0};
  o.axis = 1; // across: x and z, and the frame has no box to take z's extent from
  EXPECT_THROW(coarse_grain({f}, o), InvalidArgument);
  o.axis = 3;
  EXPECT_THROW(coarse_grain({f}, o), InvalidArgument);
  o.axis = 2, o.width = 0.0;
  EXPECT_THROW(coarse_grain({f}, o), InvalidArgument);
}

} // namespace
} // namespace talus
