#pragma once
// Two contacts, or two particles, side by side: a pair of doubles in one SSE2 register (GCC's
// vector extension, so that + - * / and comparisons read as they do for double), and the few
// functions the contact laws need, written once for double and once for Lanes. Each lane rounds
// exactly as the scalar code does, so a law written with these functions gives the same bits
// either way (docs/performance.md: "Two contacts per register").
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace talus {

using Lanes = double __attribute__((vector_size(16)));
using LaneMask = std::int64_t __attribute__((vector_size(16))); // a comparison's result
inline constexpr LaneMask lane_sign_bit = {std::numeric_limits<std::int64_t>::min(),
                                           std::numeric_limits<std::int64_t>::min()};

/// a[0] and a[1] as lanes, and back.
inline Lanes lanes_at(const double* a) {
  Lanes v;
  std::memcpy(&v, a, sizeof v);
  return v;
}
inline void store_lanes(double* a, Lanes v) {
  std::memcpy(a, &v, sizeof v);
}

/// The x and the y of a[0] and a[1] (two {x, y} pairs of doubles, such as Vec2) as lanes, and
/// back.
template <class XY> std::pair<Lanes, Lanes> components_at(const XY* a) {
  static_assert(sizeof(XY) == 2 * sizeof(double) && std::is_trivially_copyable_v<XY>);
  Lanes first, second;
  std::memcpy(&first, a, sizeof first);
  std::memcpy(&second, a + 1, sizeof second);
  return {Lanes{first[0], second[0]}, Lanes{first[1], second[1]}};
}
template <class XY> void store_components(XY* a, Lanes x, Lanes y) {
  static_assert(sizeof(XY) == 2 * sizeof(double) && std::is_trivially_copyable_v<XY>);
  const Lanes first{x[0], y[0]}, second{x[1], y[1]};
  std::memcpy(static_cast<void*>(a), &first, sizeof first);
  std::memcpy(static_cast<void*>(a + 1), &second, sizeof second);
}

inline double square_root(double x) {
  return std::sqrt(x);
}
inline Lanes square_root(Lanes x) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(x);
#else
  return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

/// a where `condition` holds, else b. Both are evaluated: neither may have side effects.
inline double select(bool condition, double a, double b) {
  return condition ? a : b;
}
inline Lanes select(LaneMask condition, Lanes a, Lanes b) {
  return condition ? a : b;
}

/// std::max(x, 0.0): 0 for a negative x, x itself otherwise (NaN stays NaN).
template <class R> R not_below_zero(R x) {
  return select(x < 0.0, R{}, x);
}

/// std::min(a, b): b if b < a, else a.
template <class R> R smaller(R a, R b) {
  return select(b < a, b, a);
}

inline double magnitude(double x) {
  return std::abs(x);
}
inline Lanes magnitude(Lanes x) { // clears the sign bits
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(x) & ~lane_sign_bit);
}

/// The magnitude of `size` with the sign of `sign` (std::copysign).
inline double copy_sign(double size, double sign) {
  return std::copysign(size, sign);
}
inline Lanes copy_sign(Lanes size, Lanes sign) {
  return reinterpret_cast<Lanes>((reinterpret_cast<LaneMask>(size) & ~lane_sign_bit) |
                                 (reinterpret_cast<LaneMask>(sign) & lane_sign_bit));
}

} // namespace talus
