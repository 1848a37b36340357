#pragma once
// A 3D vector of doubles: positions, velocities, forces, spins and torques of spheres. The type
// is the contact laws' own (talus/vector3.hpp), so that the engine hands its vectors to the laws
// as they are; here what the engine needs beyond the laws.
#include <cmath>

#include "talus/vector3.hpp"

namespace talus {

inline Vec3& operator-=(Vec3& a, const Vec3& b) {
  a = a - b;
  return a;
}
inline double norm2(const Vec3& a) {
  return dot(a, a);
}
inline double norm(const Vec3& a) {
  return std::sqrt(norm2(a));
}
/// Component k (0: x, 1: y, 2: z), for loops over the axes.
inline double& component(Vec3& a, int k) {
  return k == 0 ? a.x : (k == 1 ? a.y : a.z);
}
inline double component(const Vec3& a, int k) {
  return k == 0 ? a.x : (k == 1 ? a.y : a.z);
}

} // namespace talus
