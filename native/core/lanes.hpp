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

/// What the contact laws need of a GCC vector V of doubles, whose comparisons give the mask M,
/// but its square root (talus/number.hpp): each lane rounds as the double code does.
template <class V, class M> struct VectorNumber {
  static constexpr M sign_bits = M{} + std::numeric_limits<std::int64_t>::min();
  static V select(M condition, V a, V b) { return condition ? a : b; }
  static V magnitude(V x) { // clears the sign bits
    return reinterpret_cast<V>(reinterpret_cast<M>(x) & ~sign_bits);
  }
  static V copy_sign(V size, V sign) {
    return reinterpret_cast<V>((reinterpret_cast<M>(size) & ~sign_bits) |
                               (reinterpret_cast<M>(sign) & sign_bits));
  }
  static V power(V x, double y) { // no SIMD pow: lane by lane, as the scalar code
    V result{};
    for (std::size_t k = 0; k < sizeof(V) / sizeof(double); ++k) result[k] = std::pow(x[k], y);
    return result;
  }
  static bool all_zero(V x) {
    for (std::size_t k = 0; k < sizeof(V) / sizeof(double); ++k)
      if (x[k] != 0.0) return false;
    return true;
  }
};

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
template <> struct Number<Lanes> : VectorNumber<Lanes, LaneMask> {
  static Lanes square_root(Lanes x) {
#if defined(__SSE2__)
    return _mm_sqrt_pd(x);
#else
    return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
  }
};

} // namespace talus
