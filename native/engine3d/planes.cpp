#include "engine3d/planes.hpp"

#include "talus/error.hpp"

namespace talus {

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
