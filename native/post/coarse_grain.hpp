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
// In 3D L is the area of the cross-section (m^2), a stress Pa and a density kg/m^3. The fields
// integrate to the totals: the integral of rho L is the mass, that of sigma_c L is sum f (r - c),
// and at rest div sigma_c balances the weight exactly.
#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/frame3.hpp"
#include "analysis/stress.hpp"
#include "analysis/stress3.hpp"

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
template <class V> struct FieldProfileOf {
  using Tensor = std::conditional_t<std::is_same_v<V, Vec2>, Tensor2, Tensor3>;
  std::vector<double> at;      ///< m, along the axis
  std::vector<double> density; ///< kg/m^2 (2D), kg/m^3 (3D)
  std::vector<V> momentum;     ///< kg/(m s) (2D), kg/(m^2 s) (3D)
  std::vector<Tensor> kinetic; ///< N/m (2D), Pa (3D)
  std::vector<Tensor> contact; ///< N/m (2D), Pa (3D)
  std::size_t frames = 0;
  double across = 0.0; ///< m (2D) or m^2 (3D): the extent across, its mean over the frames
  /// m/s: the mean momentum over the mean density (0 where there is no mass)
  V velocity(std::size_t k) const {
    return density[k] > 0.0 ? (1.0 / density[k]) * momentum[k] : V{};
  }
};
using FieldProfile = FieldProfileOf<Vec2>;
using FieldProfile3 = FieldProfileOf<Vec3>;

/// A profile of spheres in 3D along x, y or z.
struct CgOptions3 {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;     ///< m: w of cg_kernel
  int axis = 2;           ///< the profile's axis: 0 x, 1 y, 2 z
  double lo = 0.0;        ///< m: the first point of the profile along the axis
  double hi = 0.0;        ///< m: the last
  std::size_t points = 0; ///< points from lo to hi, >= 2
  /// m: the extents along the two other axes, whose product is the area the fields are averaged
  /// over; 0 along an axis the frames' box is periodic on: its side in each frame (a cell strains
  /// it). Along the profile's axis the frame's box gives the period where it is periodic, and
  /// across y the images slide by its shear velocity (Lees-Edwards).
  std::array<double, 3> extent{};
  /// m: along a periodic axis, the period each frame's box is scaled to along the axis (its lower
  /// side put at `lo`), so that the frames of a cell that strains add up at the same place in it;
  /// 0: each frame as it is, with its own period.
  double period = 0.0;
};

/// The free grains' fields over `frames`, each with masses and contact force vectors (snapshots
/// since they were recorded); throws InvalidArgument otherwise, or for options out of range.
FieldProfile coarse_grain(const std::vector<Frame>& frames, const CgOptions& o);
/// The free spheres' fields over `frames` (frame3_of's or read_vtp_frame3's, with their
/// contacts); throws InvalidArgument for options out of range or a frame without its box where
/// one is needed.
FieldProfile3 coarse_grain(const std::vector<Frame3>& frames, const CgOptions3& o);

} // namespace talus
