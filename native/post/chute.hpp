#pragma once
// A steady flow down a rough incline (GDR MiDi 2004; Silbert et al. 2001, Phys. Rev. E 64,
// 051302): the coarse-grained profiles across the layer, Bagnold's velocity profile fitted to
// them,
//   v(z) = v_b + c (h^(3/2) - (h - z)^(3/2)),     z above the base, h the flow's depth,
// which a constant inertial number I gives, c = (2/3) (I / d) sqrt(phi g cos theta), and in the
// bulk the friction |sigma_xy| / sigma_yy, which a steady flow holds at tan theta, and I.
#include <string>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/frame3.hpp"
#include "post/coarse_grain.hpp"
#include "post/line_fit.hpp"

namespace talus {

struct ChuteOptions {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;  ///< m: the kernel's width
  double across = 0.0; ///< m: the incline's length (the periodic box)
  Vec2 gravity{};      ///< m/s^2: down the slope along +x or -x, into the base along -y
  double margin = 2.0; ///< diameters left out of the fits by the base and by the surface
};

struct ChuteFlow {
  bool measured = false;
  std::string why_not;
  double angle = 0.0;         ///< rad: the incline, atan(|g_x| / -g_y)
  double base = 0.0;          ///< m: the base grains' top
  double depth = 0.0;         ///< m: h, from the base to where the packing falls to half
  double diameter = 0.0;      ///< m: the free grains' mean
  double grain_density = 0.0; ///< kg/m^2 (kg/m^3 in 3D)
  // the profiles from the base to above the surface
  std::vector<double> z;        ///< m above the base
  std::vector<double> velocity; ///< m/s along the slope
  std::vector<double> packing;
  std::vector<double> friction; ///< |sigma_xy| / sigma_yy
  std::vector<double> inertial; ///< gamma_dot d / sqrt(sigma_yy / rho)
  // in the band fitted (margin diameters from the base and the surface)
  double band_lo = 0.0, band_hi = 0.0;                                 ///< m above the base
  double bulk_friction = 0.0, bulk_inertial = 0.0, bulk_packing = 0.0; ///< means over the band
  LineFit bagnold;               ///< v against h^(3/2) - (h - z)^(3/2): intercept v_b, slope c
  double bagnold_inertial = 0.0; ///< the I that c implies: (3/2) c d / sqrt(phi g cos theta)
  LineFit straight;              ///< v against z, for comparison: a profile of uniform shear rate
  std::size_t frames = 0;
};

/// The flow of the free grains of `frames` (with contact force vectors) over the wall grains
/// of the base. Not measured (why_not) without wall grains, or when the flow is under
/// 2 margin + 4 diameters deep.
ChuteFlow chute_flow(const std::vector<Frame>& frames, const ChuteOptions& o);

/// A chute of spheres: down the slope along x, the base's normal along z, periodic along x and y
/// (the frames' box gives the area the fields are averaged over).
struct ChuteOptions3 {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;  ///< m: the kernel's width
  Vec3 gravity{};      ///< m/s^2: down the slope along +x or -x, into the base along -z
  double margin = 2.0; ///< diameters left out of the fits by the base and by the surface
};
/// The same of spheres in 3D (packing a volume fraction; friction |sigma_xz| / sigma_zz); the
/// fields ChuteFlow calls y and sigma_yy are z and sigma_zz.
ChuteFlow chute_flow(const std::vector<Frame3>& frames, const ChuteOptions3& o);

} // namespace talus
