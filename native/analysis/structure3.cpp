#include "analysis/structure3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <Eigen/Dense>

#include "analysis/observables.hpp"
#include "analysis/rattlers.hpp"
#include "engine3d/contact_visit3.hpp"
#include "talus/law_table.hpp"

namespace talus {

namespace {

constexpr int gauss_points = 16;

struct GaussRule {
  std::array<double, gauss_points> node{}, weight{};
};

// The Gauss-Legendre rule on [-1, 1] by Golub and Welsch (1969): its nodes are the eigenvalues of
// the Jacobi matrix of the Legendre polynomials, its weights twice the squared first components of
// the unit eigenvectors.
GaussRule gauss_legendre() {
  Eigen::Matrix<double, gauss_points, gauss_points> jacobi =
      Eigen::Matrix<double, gauss_points, gauss_points>::Zero();
  for (int k = 1; k < gauss_points; ++k)
    jacobi(k, k - 1) = jacobi(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<decltype(jacobi)> solver(jacobi);
  GaussRule rule;
  for (int k = 0; k < gauss_points; ++k) {
    rule.node[static_cast<std::size_t>(k)] = solver.eigenvalues()(k);
    const double v = solver.eigenvectors()(0, k);
    rule.weight[static_cast<std::size_t>(k)] = 2.0 * v * v;
  }
  return rule;
}

bool inside_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y && p.z >= lo.z && p.z < hi.z;
}

} // namespace

double sphere_box_volume(Vec3 c, double r, Vec3 lo, Vec3 hi) {
  const double whole = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const Vec3 below = c - lo, above = hi - c;
  if (std::min({below.x, below.y, below.z, above.x, above.y, above.z}) >= r) return whole;
  const double z0 = std::max(lo.z, c.z - r), z1 = std::min(hi.z, c.z + r);
  if (z1 <= z0 || c.x - r >= hi.x || c.x + r <= lo.x || c.y - r >= hi.y || c.y + r <= lo.y)
    return 0.0;
  // the heights where the slice's circle (radius rho) reaches an edge (at distance d in the
  // plane) or a corner: there the area's slope changes
  std::vector<double> cuts{z0, z1};
  const auto add_cut = [&](double d2) {
    if (d2 >= r * r) return;
    const double h = std::sqrt(r * r - d2);
    for (const double z : {c.z - h, c.z + h})
      if (z > z0 && z < z1) cuts.push_back(z);
  };
  for (const double dx : {below.x, above.x}) {
    add_cut(dx * dx);
    for (const double dy : {below.y, above.y}) add_cut(dx * dx + dy * dy);
  }
  for (const double dy : {below.y, above.y}) add_cut(dy * dy);
  std::sort(cuts.begin(), cuts.end());
  static const GaussRule rule = gauss_legendre();
  const Vec2 centre{c.x, c.y}, rect_lo{lo.x, lo.y}, rect_hi{hi.x, hi.y};
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double from = cuts[k], span = cuts[k + 1] - cuts[k];
    for (std::size_t q = 0; q < rule.node.size(); ++q) {
      // z = from + span (3u^2 - 2u^3), u in [0, 1]: flat at both ends, so that where a slice
      // first reaches a side (the area rising as a power 3/2 of the height) the integrand in u
      // is smooth and the rule keeps its order
      const double u = 0.5 * (1.0 + rule.node[q]);
      const double z = from + span * u * u * (3.0 - 2.0 * u), dz = span * 6.0 * u * (1.0 - u);
      const double rho = std::sqrt(std::max(0.0, r * r - (z - c.z) * (z - c.z)));
      volume += 0.5 * rule.weight[q] * dz * disk_rectangle_area(centre, rho, rect_lo, rect_hi);
    }
  }
  return std::clamp(volume, 0.0, whole);
}

double packing_fraction(const Simulation3& sim, Vec3 lo, Vec3 hi) {
  const Vec3 span = hi - lo;
  const double region = span.x * span.y * span.z;
  if (!(region > 0.0)) return 0.0;
  const Spheres& s = sim.scene().spheres;
  const Domain3& box = sim.scene().domain;
  // across a Lees-Edwards side the images sit an offset along x: one more width each way
  const int nx = box.periodic[0] ? (box.shear_offset != 0.0 ? 2 : 1) : 0,
            ny = box.periodic[1] ? 1 : 0, nz = box.periodic[2] ? 1 : 0;
  double covered = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.is_free(i)) continue;
    Image3 crossed{};
    const Vec3 r = box.wrap(s.position[i], crossed);
    for (int a = -nx; a <= nx; ++a)
      for (int b = -ny; b <= ny; ++b)
        for (int k = -nz; k <= nz; ++k)
          covered += sphere_box_volume(r + box.image_shift(a, b, k), s.radius[i], lo, hi);
  }
  return covered / region;
}

int contacts_needed(const Simulation3& sim) {
  if (!has_friction(sim.settings().tangential_law)) return 4;
  const auto& m = sim.scene().materials;
  return std::all_of(m.begin(), m.end(), [](const Material& x) { return x.friction == 0.0; }) ? 4
                                                                                              : 3;
}

LoadBearing load_bearing(const Simulation3& sim, Vec3 lo, Vec3 hi, int needed) {
  const Scene3& scene = sim.scene();
  const Spheres& s = scene.spheres;
  // each free sphere's partners: other free spheres by index, plates and fixed spheres as -1
  std::vector<std::vector<std::int64_t>> partners(s.size());
  const auto partner = [&](std::uint32_t j) {
    return s.is_free(j) ? static_cast<std::int64_t>(j) : std::int64_t{-1};
  };
  for_each_contact3(
      scene, sim.list(), sim.table(), lever_shares(sim.settings().lever_arm),
      [&](std::uint32_t i, std::uint32_t, std::uint32_t j, const ContactGeometry3&,
          const PairParameters&) {
        if (s.is_free(i)) partners[i].push_back(partner(j));
        if (s.is_free(j)) partners[j].push_back(partner(i));
      },
      [&](std::uint32_t i, std::uint32_t, std::uint32_t, const ContactGeometry3&,
          const PairParameters&) {
        if (s.is_free(i)) partners[i].push_back(-1);
      });
  std::vector<bool> free(s.size());
  for (std::uint32_t i = 0; i < s.size(); ++i) free[i] = s.is_free(i);
  // a periodic box's sphere where it is: wrapped (it may have crossed since the list's build)
  return load_bearing_of(partners, free, needed, [&](std::uint32_t i) {
    Image3 crossed{};
    return inside_box(scene.domain.wrap(s.position[i], crossed), lo, hi);
  });
}

} // namespace talus
