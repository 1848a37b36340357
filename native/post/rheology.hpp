#pragma once
// The rheology of dense granular flow in plane shear at a given pressure (GDR MiDi 2004; da Cruz
// et al. 2005, "Rheophysics of dense granular materials: discrete simulation of plane shear
// flows", Phys. Rev. E 72, 021309): the friction coefficient mu = tau / P and the packing
// fraction phi against the inertial number I = gamma_dot d / sqrt(P / rho), measured in the
// bulk of a layer sheared between two rough walls, and the fits
//   mu(I)  = mu_s + (mu_2 - mu_s) / (I_0 / I + 1)     (Jop, Forterre & Pouliquen 2006)
//   mu(I)  = mu_1 + b I                              (da Cruz et al. 2005, for I < 0.2)
//   phi(I) = phi_max - a I
// with standard errors from the fits' covariance.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/frame3.hpp"
#include "post/coarse_grain.hpp"
#include "post/line_fit.hpp"

namespace talus {

struct RheologyOptions {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;         ///< m: the kernel's width
  double across = 0.0;        ///< m: the layer's length along the flow (the periodic box)
  double bulk_fraction = 0.5; ///< the middle part of the gap between the walls measured
  std::size_t blocks = 4;     ///< consecutive blocks of frames, for the errors
};

/// One steady shear flow: the means over the blocks of frames, with their standard errors.
struct RheologyPoint {
  bool measured = false;
  std::string why_not;
  double base = 0.0, plate = 0.0;                  ///< m: the walls' grain surfaces (mean heights)
  double bulk_lo = 0.0, bulk_hi = 0.0;             ///< m: the band measured
  double diameter = 0.0;                           ///< m: the free grains' mean diameter
  double grain_density = 0.0;                      ///< kg/m^2 (kg/m^3 in 3D): mass over size
  double shear_rate = 0.0, shear_rate_error = 0.0; ///< 1/s: d v_x / d y in the bulk
  double pressure = 0.0, pressure_error = 0.0; ///< N/m (Pa in 3D): sigma_yy, kinetic part included
  double shear_stress = 0.0, shear_stress_error = 0.0; ///< N/m (Pa in 3D): |sigma_xy|
  double friction = 0.0, friction_error = 0.0;         ///< mu = |sigma_xy| / sigma_yy
  double packing = 0.0, packing_error = 0.0;           ///< phi
  double inertial = 0.0, inertial_error = 0.0;         ///< I
  /// 1/s: in a sheared cell, the slope of v_x over y of the grains in the snapshots (the
  /// shear_rate is then the cell's): equal within its error where the shear is uniform
  double profile_shear_rate = 0.0, profile_shear_rate_error = 0.0;
  std::size_t frames = 0;
};

/// One row of a sheared cell's thermo.csv (Lees-Edwards, drivers.hpp Cell): the cell's stress
/// (N/m, kinetic part included), packing fraction and shear rate.
struct CellShearRow {
  double time = 0.0;
  double shear_stress = 0.0;  ///< (sigma_xy + sigma_yx) / 2
  double normal_stress = 0.0; ///< sigma_yy
  double packing = 0.0;
  double shear_rate = 0.0; ///< 1/s: the cell's
};

/// Simple shear in a sheared cell: every grain is in the bulk, so the means over the rows in
/// `blocks` consecutive blocks (with their standard errors) of mu = |sigma_xy| / sigma_yy, phi,
/// and I from the cell's shear rate, with the grains' scale from `scale`; the snapshots' own
/// velocity profile (profile_shear_rate) checks that the shear is uniform. Not measured (why_not)
/// with fewer rows or frames than blocks.
RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows,
                                  const std::vector<Frame>& frames, std::size_t blocks);
/// The same of spheres in 3D (stresses in Pa, the density a sphere's mass over its volume).
RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows,
                                  const std::vector<Frame3>& frames, std::size_t blocks);

/// The free grains' mean diameter (m) and their mass over their area (kg/m^2) in one frame, or
/// of spheres over their volume (kg/m^3).
struct GrainScale {
  double diameter = 0.0, density = 0.0;
  std::size_t grains = 0;
};
GrainScale grain_scale(const Frame& f);
GrainScale grain_scale(const Frame3& f);

/// What both take: the grains' scale and each snapshot's least-squares slope of v_x over y, in
/// time order.
RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows, const GrainScale& scale,
                                  const std::vector<double>& slopes, std::size_t blocks);

/// The flow of the free grains of `frames` (with contact force vectors) between the wall grains
/// below and above them, in the middle `bulk_fraction` of the gap. Not measured (why_not says
/// why) when the frames are fewer than the blocks or the gap is under 8 grain diameters.
RheologyPoint rheology_point(const std::vector<Frame>& frames, const RheologyOptions& o);

/// mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1), least squares (for each I_0 the other two are
/// linear; I_0 is found by a golden-section search on log I_0).
struct MuIFit {
  bool ok = false;
  std::string why_not;
  double mu_s = 0.0, mu_s_error = 0.0;
  double mu_2 = 0.0, mu_2_error = 0.0;
  double i_0 = 0.0, i_0_error = 0.0;
  double rms = 0.0;
  std::size_t points = 0;
};
double mu_of_i(double mu_s, double mu_2, double i_0, double inertial);
/// Needs 4 points at least (3 parameters and a scatter), with I > 0.
MuIFit fit_mu_of_i(const std::vector<double>& inertial, const std::vector<double>& friction);

} // namespace talus
