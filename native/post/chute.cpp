#include "post/chute.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <fmt/core.h>

#include "post/rheology.hpp"

namespace talus {

namespace {

// The coordinate across the layer: y of the plane, z of space.
double normal_of(Vec2 v) {
  return v.y;
}
double normal_of(const Vec3& v) {
  return v.z;
}

// The top of the base: the highest wall grain's top, the mean over the frames.
template <class FrameT> double base_top(const std::vector<FrameT>& frames, bool& found) {
  double sum = 0.0;
  found = true;
  for (const FrameT& f : frames) {
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] != 0) top = std::max(top, normal_of(f.position[i]) + f.radius[i]);
    if (!std::isfinite(top)) found = false;
    sum += top;
  }
  return sum / static_cast<double>(frames.size());
}

// The highest free grain's top over the frames.
template <class FrameT> double highest_grain(const std::vector<FrameT>& frames) {
  double top = -std::numeric_limits<double>::infinity();
  for (const FrameT& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) top = std::max(top, normal_of(f.position[i]) + f.radius[i]);
  return top;
}

// The profiles of the coarse-grained fields from the base up, in the flow's frame: velocity
// down the slope (the sign of g_x), friction, packing, and I from the local shear rate; the
// normal axis n is y in 2D, z in 3D.
template <class Profile>
void fill_profiles(const Profile& p, double base, double sign, const GrainScale& g, ChuteFlow& c) {
  constexpr int n_axis = std::is_same_v<Profile, FieldProfile> ? 1 : 2;
  const std::size_t n = p.at.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto s = p.contact[k] + p.kinetic[k];
    c.z.push_back(p.at[k] - base);
    c.velocity.push_back(sign * p.velocity(k).x);
    c.packing.push_back(p.density[k] / g.density);
    c.friction.push_back(s(n_axis, n_axis) > 0.0
                             ? std::abs(0.5 * (s(0, n_axis) + s(n_axis, 0))) / s(n_axis, n_axis)
                             : NAN);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
    const double rate = (c.velocity[b] - c.velocity[a]) / (c.z[b] - c.z[a]);
    const double pressure = p.contact[k](n_axis, n_axis) + p.kinetic[k](n_axis, n_axis);
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

// The flow over the base whatever the dimension: gravity's components down the slope (signed)
// and into the base, and profile(lo, hi, points) coarse-graining the frames across the layer.
template <class FrameT, class Profile>
ChuteFlow chute_of(const std::vector<FrameT>& frames, double g_slope, double g_normal, double width,
                   double margin, const Profile& profile) {
  ChuteFlow c;
  c.frames = frames.size();
  c.angle = std::atan(std::abs(g_slope) / g_normal);
  const GrainScale g = grain_scale(frames.front());
  bool found = false;
  c.base = base_top(frames, found);
  if (g.grains == 0 || !found) {
    c.why_not = "no free grains, or no wall grains under them (a chute has a rough base)";
    return c;
  }
  c.diameter = g.diameter, c.grain_density = g.density;
  const double lo = c.base, hi = highest_grain(frames) + 2.0 * width;
  const auto points =
      static_cast<std::size_t>(std::clamp(std::ceil(4.0 * (hi - lo) / width) + 1.0, 50.0, 4000.0));
  fill_profiles(profile(lo, hi, points), c.base, g_slope > 0.0 ? 1.0 : -1.0, g, c);
  c.depth = depth_of(c);
  c.band_lo = margin * c.diameter, c.band_hi = c.depth - margin * c.diameter;
  if (!(c.band_hi - c.band_lo >= 4.0 * c.diameter)) {
    c.why_not = fmt::format("the flow is {:.3g} grain diameters deep; at least {:.3g} are needed",
                            c.depth / c.diameter, 2.0 * margin + 4.0);
    return c;
  }
  fit_band(c, g_normal);
  c.measured = c.bagnold.ok;
  if (!c.measured) c.why_not = c.bagnold.why_not;
  return c;
}

} // namespace

ChuteFlow chute_flow(const std::vector<Frame>& frames, const ChuteOptions& o) {
  if (!(-o.gravity.y > 0.0) || o.gravity.x == 0.0) {
    ChuteFlow c;
    c.frames = frames.size();
    c.why_not = "gravity does not point into the base (along -y) and down a slope (along x)";
    return c;
  }
  return chute_of(frames, o.gravity.x, -o.gravity.y, o.width, o.margin,
                  [&](double lo, double hi, std::size_t points) {
                    CgOptions cg;
                    cg.kernel = o.kernel, cg.width = o.width, cg.axis = 1, cg.across = o.across;
                    cg.lo = lo, cg.hi = hi, cg.points = points;
                    return coarse_grain(frames, cg);
                  });
}

ChuteFlow chute_flow(const std::vector<Frame3>& frames, const ChuteOptions3& o) {
  if (!(-o.gravity.z > 0.0) || o.gravity.x == 0.0 || o.gravity.y != 0.0) {
    ChuteFlow c;
    c.frames = frames.size();
    c.why_not = "gravity does not point into the base (along -z) and down a slope along x (and "
                "not along y)";
    return c;
  }
  return chute_of(frames, o.gravity.x, -o.gravity.z, o.width, o.margin,
                  [&](double lo, double hi, std::size_t points) {
                    CgOptions3 cg; // across: the periodic box along x and y of each frame
                    cg.kernel = o.kernel, cg.width = o.width, cg.axis = 2;
                    cg.lo = lo, cg.hi = hi, cg.points = points;
                    return coarse_grain(frames, cg);
                  });
}

} // namespace talus
