#include "post/chute.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "post/rheology.hpp"

namespace talus {

namespace {

// The top of the base: the highest wall grain's top, the mean over the frames.
double base_top(const std::vector<Frame>& frames, bool& found) {
  double sum = 0.0;
  found = true;
  for (const Frame& f : frames) {
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] != 0) top = std::max(top, f.position[i].y + f.radius[i]);
    if (!std::isfinite(top)) found = false;
    sum += top;
  }
  return sum / static_cast<double>(frames.size());
}

// The highest free grain's top over the frames.
double highest_grain(const std::vector<Frame>& frames) {
  double top = -std::numeric_limits<double>::infinity();
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) top = std::max(top, f.position[i].y + f.radius[i]);
  return top;
}

// The profiles of the coarse-grained fields from the base up, in the flow's frame: velocity
// down the slope (the sign of g_x), friction, packing, and I from the local shear rate.
void fill_profiles(const FieldProfile& p, double base, double sign, const GrainScale& g,
                   ChuteFlow& c) {
  const std::size_t n = p.at.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Tensor2 s = p.contact[k] + p.kinetic[k];
    c.z.push_back(p.at[k] - base);
    c.velocity.push_back(sign * p.velocity(k).x);
    c.packing.push_back(p.density[k] / g.density);
    c.friction.push_back(s(1, 1) > 0.0 ? std::abs(0.5 * (s(0, 1) + s(1, 0))) / s(1, 1) : NAN);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
    const double rate = (c.velocity[b] - c.velocity[a]) / (c.z[b] - c.z[a]);
    const double pressure = p.contact[k](1, 1) + p.kinetic[k](1, 1);
    c.inertial.push_back(
        pressure > 0.0 ? std::abs(rate) * g.diameter / std::sqrt(pressure / g.density) : NAN);
  }
}

// h: the highest point where the packing is at least half the median of the layer's.
double depth_of(const ChuteFlow& c) {
  std::vector<double> dense;
  for (const double phi : c.packing)
    if (phi > 0.3) dense.push_back(phi);
  if (dense.empty()) return 0.0;
  std::nth_element(dense.begin(), dense.begin() + static_cast<std::ptrdiff_t>(dense.size() / 2),
                   dense.end());
  const double half = 0.5 * dense[dense.size() / 2];
  double h = 0.0;
  for (std::size_t k = 0; k < c.z.size(); ++k)
    if (c.packing[k] >= half) h = c.z[k];
  return h;
}

void fit_band(ChuteFlow& c, double gravity_normal) {
  std::vector<double> z, v, bagnold_x;
  double mu = 0.0, in = 0.0, phi = 0.0;
  const double h = c.depth;
  for (std::size_t k = 0; k < c.z.size(); ++k) {
    if (c.z[k] < c.band_lo || c.z[k] > c.band_hi) continue;
    z.push_back(c.z[k]), v.push_back(c.velocity[k]);
    bagnold_x.push_back(std::pow(h, 1.5) - std::pow(h - c.z[k], 1.5));
    mu += c.friction[k], in += c.inertial[k], phi += c.packing[k];
  }
  const auto n = static_cast<double>(z.size());
  c.bulk_friction = mu / n, c.bulk_inertial = in / n, c.bulk_packing = phi / n;
  c.bagnold = fit_line(bagnold_x, v);
  c.straight = fit_line(z, v);
  c.bagnold_inertial =
      1.5 * c.bagnold.slope * c.diameter / std::sqrt(c.bulk_packing * gravity_normal);
}

} // namespace

ChuteFlow chute_flow(const std::vector<Frame>& frames, const ChuteOptions& o) {
  ChuteFlow c;
  c.frames = frames.size();
  const double g_normal = -o.gravity.y;
  if (!(g_normal > 0.0) || o.gravity.x == 0.0) {
    c.why_not = "gravity does not point into the base (along -y) and down a slope (along x)";
    return c;
  }
  c.angle = std::atan(std::abs(o.gravity.x) / g_normal);
  const GrainScale g = grain_scale(frames.front());
  bool found = false;
  c.base = base_top(frames, found);
  if (g.grains == 0 || !found) {
    c.why_not = "no free grains, or no wall grains under them (a chute has a rough base)";
    return c;
  }
  c.diameter = g.diameter, c.grain_density = g.density;
  CgOptions cg;
  cg.kernel = o.kernel, cg.width = o.width, cg.axis = 1, cg.across = o.across;
  cg.lo = c.base;
  cg.hi = highest_grain(frames) + 2.0 * o.width;
  cg.points = static_cast<std::size_t>(
      std::clamp(std::ceil(4.0 * (cg.hi - cg.lo) / o.width) + 1.0, 50.0, 4000.0));
  fill_profiles(coarse_grain(frames, cg), c.base, o.gravity.x > 0.0 ? 1.0 : -1.0, g, c);
  c.depth = depth_of(c);
  c.band_lo = o.margin * c.diameter, c.band_hi = c.depth - o.margin * c.diameter;
  if (!(c.band_hi - c.band_lo >= 4.0 * c.diameter)) {
    c.why_not = fmt::format("the flow is {:.3g} grain diameters deep; at least {:.3g} are needed",
                            c.depth / c.diameter, 2.0 * o.margin + 4.0);
    return c;
  }
  fit_band(c, g_normal);
  c.measured = c.bagnold.ok;
  if (!c.measured) c.why_not = c.bagnold.why_not;
  return c;
}

} // namespace talus
