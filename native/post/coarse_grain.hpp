#pragma once
// Coarse-grained fields (Goldhirsch 2010, "Stress, stress asymmetry and couple stress: from
// discrete particles to continuous fields", Granular Matter 12; Weinhart et al. 2012, "From
// discrete particles to continuum fields near a boundary", Granular Matter 14), as MercuryCG
// computes them, as profiles along one axis: each particle's mass and momentum spread by a
// kernel phi of width w, and each contact's force spread along its branch,
//   rho(y)     = (1/L) sum_i m_i phi(y - y_i)
//   p(y)       = (1/L) sum_i m_i v_i phi(y - y_i),                  V = p / rho
//   sigma_k(y) = (1/L) sum_i m_i v_i v_i phi(y - y_i) - rho V V
//   sigma_c(y) = (1/L) sum_(grain sides) f (r - c) int_0^1 phi(y - r_y - s (c - r)_y) ds
// with L the extent across the axis the fields are averaged over, f the contact's force on the
// grain, r its centre and c the contact point (a pair's two sides add up to the whole branch).
// Compression is positive, as in analysis/stress.hpp; in 2D a stress is N/m and a density kg/m^2.
// The fields integrate to the totals: the integral of rho L is the mass, that of sigma_c L is
// sum f (r - c), and at rest div sigma_c balances the weight exactly.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/stress.hpp"

namespace talus {

enum class CgKernel { gaussian, lucy };

/// "gaussian" or "lucy"; throws InvalidArgument naming the allowed ones.
CgKernel parse_cg_kernel(const std::string& name);
const char* cg_kernel_name(CgKernel k);

/// The kernel along one axis, normalised to 1: a Gaussian of standard deviation w, or Lucy's
/// polynomial (1 + 3q)(1 - q)^3 with q = |x|/w, zero beyond w.
double cg_kernel(CgKernel k, double w, double x);
/// Its integral from -infinity to x.
double cg_kernel_integral(CgKernel k, double w, double x);

struct CgOptions {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;     ///< m: w of cg_kernel
  int axis = 1;           ///< the profile's axis: 0 x, 1 y
  double lo = 0.0;        ///< m: the first point of the profile along the axis
  double hi = 0.0;        ///< m: the last
  std::size_t points = 0; ///< points from lo to hi, >= 2
  double across = 0.0;    ///< m: L, the extent across the axis the fields are averaged over
  double period = 0.0;    ///< m: the period along the axis (periodic boundaries), 0: none
};

/// Fields along the axis, averaged over frames (each frame's kinetic stress about its own V).
struct FieldProfile {
  std::vector<double> at;       ///< m, along the axis
  std::vector<double> density;  ///< kg/m^2
  std::vector<Vec2> momentum;   ///< kg/(m s)
  std::vector<Tensor2> kinetic; ///< N/m
  std::vector<Tensor2> contact; ///< N/m
  std::size_t frames = 0;
  /// m/s: the mean momentum over the mean density (0 where there is no mass)
  Vec2 velocity(std::size_t k) const;
};

/// The free grains' fields over `frames`, each with masses and contact force vectors (snapshots
/// since they were recorded); throws InvalidArgument otherwise, or for options out of range.
FieldProfile coarse_grain(const std::vector<Frame>& frames, const CgOptions& o);

} // namespace talus
