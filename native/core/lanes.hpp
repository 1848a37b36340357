#pragma once
// Two contacts, or two particles, side by side: a pair of doubles in one SSE2 register (GCC's
// vector extension, so that + - * / and comparisons read as they do for double), and the few
// functions the contact laws need (talus/number.hpp) for Lanes. Each lane rounds
// exactly as the scalar code does, so a law written with these functions gives the same bits
// either way.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "talus/number.hpp"

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

/// The arithmetic of the contact laws on lanes (talus/number.hpp): each lane rounds as double.
template <> struct Number<Lanes> {
  static Lanes square_root(Lanes x) {
#if defined(__SSE2__)
    return _mm_sqrt_pd(x);
#else
    return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
  }
  static Lanes select(LaneMask condition, Lanes a, Lanes b) {
    return condition ? a : b;
  }
  static Lanes magnitude(Lanes x) { // clears the sign bits
    return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(x) & ~lane_sign_bit);
  }
  static Lanes copy_sign(Lanes size, Lanes sign) {
    return reinterpret_cast<Lanes>((reinterpret_cast<LaneMask>(size) & ~lane_sign_bit) |
                                   (reinterpret_cast<LaneMask>(sign) & lane_sign_bit));
  }
  static Lanes power(Lanes x, double y) { // no SIMD pow: lane by lane, as the scalar code
    return Lanes{std::pow(x[0], y), std::pow(x[1], y)};
  }
  static bool all_zero(Lanes x) {
    return x[0] == 0.0 && x[1] == 0.0;
  }
};

} // namespace talus
