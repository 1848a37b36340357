#pragma once
// The jamming point of frictionless disks from a run let down in steps of pressure (O'Hern,
// Silbert, Liu & Nagel 2003, Phys. Rev. E 68, 011306): at each step the packing fraction phi and
// the coordination Z of the load-bearing network (rattlers out) at rest, and the fits
//   phi = phi_J + p / B            (linear springs: the pressure grows as phi - phi_J),
//   Z = Z_J + A sqrt(phi - phi_J)  (the excess coordination's square-root law),
// whose phi_J and Z_J the literature gives as about 0.84 and 4 (the isostatic 2d) for 50:50
// disks of size ratio 1.4.
#include <string>
#include <vector>

namespace talus {

/// One step of pressure, at rest: means over its last part.
struct JammingStep {
  std::string name;
  double pressure = 0.0;             ///< N/m, the region's (half the trace of its stress)
  double packing = 0.0;              ///< the region's packing fraction
  double coordination = 0.0;         ///< of the load-bearing network
  double coordination_spread = 0.0;  ///< its standard deviation over the rows averaged
  double rattlers = 0.0;             ///< fraction of the region's grains
  double kinetic_over_elastic = 0.0; ///< at the step's end: how near rest it came
};

struct JammingFit {
  bool measured = false;
  std::string why_not;
  double phi_j = 0.0, phi_j_error = 0.0;     ///< the jamming packing fraction
  double bulk = 0.0, bulk_error = 0.0;       ///< B, N/m: dp/dphi
  double z_j = 0.0, z_j_error = 0.0;         ///< the coordination at phi_J
  double z_slope = 0.0, z_slope_error = 0.0; ///< A
};

/// The fits over the steps (at least three, at different pressures).
JammingFit fit_jamming(const std::vector<JammingStep>& steps);

} // namespace talus
