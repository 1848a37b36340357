#pragma once
// The faces of a box as plates. The plate itself, how one is made from a point and a normal, and
// where a sphere touches it are the kernel's (talus/plate.hpp).
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "talus/plate.hpp"

namespace talus {

/// The six faces of the box [lo, hi] as whole planes facing inwards, the top (z = hi.z) left out
/// when `open_top`: a container for pouring.
std::vector<Plane> box_planes(Vec3 lo, Vec3 hi, std::uint16_t material = 0, bool open_top = false);

} // namespace talus
