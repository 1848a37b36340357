#include "engine3d/planes.hpp"

#include <algorithm>
#include <cmath>

#include "talus/error.hpp"

namespace talus {

Plane make_plane(Vec3 centre, Vec3 normal, double half_u, double half_v, std::uint16_t material) {
  const double length = norm(normal);
  require(std::isfinite(length) && length > 0.0, "a plane's normal must be finite and not zero");
  Plane p;
  p.centre = centre;
  p.normal = (1.0 / length) * normal;
  // the axis least aligned with the normal, made perpendicular to it
  const Vec3 n = p.normal;
  const Vec3 seed =
      std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
          ? Vec3{1.0, 0.0, 0.0}
          : (std::abs(n.y) <= std::abs(n.z) ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0});
  const Vec3 u = seed - dot(seed, n) * n;
  p.axis_u = (1.0 / norm(u)) * u;
  require(half_u > 0.0 && half_v > 0.0, "a plate's half-widths must be > 0 m");
  p.half_u = half_u;
  p.half_v = half_v;
  p.material = material;
  return p;
}

Vec3 closest_point(const Plane& plane, const Vec3& p) {
  const Vec3 q = p - plane.centre;
  const double u = std::clamp(dot(q, plane.axis_u), -plane.half_u, plane.half_u);
  const Vec3 v_axis = plane.axis_v();
  const double v = std::clamp(dot(q, v_axis), -plane.half_v, plane.half_v);
  return plane.centre + u * plane.axis_u + v * v_axis;
}

std::vector<Plane> box_planes(Vec3 lo, Vec3 hi, std::uint16_t material, bool open_top) {
  require(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z, "a box needs lo < hi along every axis");
  std::vector<Plane> out;
  out.push_back(make_plane(lo, {1.0, 0.0, 0.0}, unbounded, unbounded, material));
  out.push_back(make_plane(hi, {-1.0, 0.0, 0.0}, unbounded, unbounded, material));
  out.push_back(make_plane(lo, {0.0, 1.0, 0.0}, unbounded, unbounded, material));
  out.push_back(make_plane(hi, {0.0, -1.0, 0.0}, unbounded, unbounded, material));
  out.push_back(make_plane(lo, {0.0, 0.0, 1.0}, unbounded, unbounded, material));
  if (!open_top) out.push_back(make_plane(hi, {0.0, 0.0, -1.0}, unbounded, unbounded, material));
  return out;
}

} // namespace talus
