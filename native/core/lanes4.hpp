#pragma once
// Four contacts side by side: four doubles in one AVX register (GCC's vector extension), for a
// build with AVX2 (CMake's TALUS_AVX2). Each lane rounds as the scalar code does: -mavx2 enables
// no fused multiply-add, so none is contracted.
#include <cstdint>

#if !defined(__AVX2__)
#error "core/lanes4.hpp is for builds with AVX2 (-mavx2)"
#endif
#include <immintrin.h>

#include "core/lanes.hpp"
#include "talus/number.hpp"

namespace talus {

using Lanes4 = double __attribute__((vector_size(32)));
using LaneMask4 = std::int64_t __attribute__((vector_size(32)));

template <> struct Number<Lanes4> : VectorNumber<Lanes4, LaneMask4> {
  static Lanes4 square_root(Lanes4 x) { return _mm256_sqrt_pd(x); }
};

} // namespace talus
