#include "post/jamming.hpp"

#include <cmath>

#include "post/line_fit.hpp"

namespace talus {

JammingFit fit_jamming(const std::vector<JammingStep>& steps) {
  JammingFit f;
  std::vector<double> p, phi;
  for (const JammingStep& s : steps)
    if (s.pressure > 0.0) p.push_back(s.pressure), phi.push_back(s.packing);
  if (p.size() < 3) {
    f.why_not = "fewer than 3 steps under pressure";
    return f;
  }
  const LineFit packing = fit_line(p, phi);
  if (!(packing.slope > 0.0)) {
    f.why_not = "the packing fraction does not grow with the pressure";
    return f;
  }
  f.phi_j = packing.intercept, f.phi_j_error = packing.intercept_error;
  f.bulk = 1.0 / packing.slope,
  f.bulk_error = packing.slope_error / (packing.slope * packing.slope);
  std::vector<double> root, z;
  for (const JammingStep& s : steps)
    if (s.pressure > 0.0 && s.packing > f.phi_j)
      root.push_back(std::sqrt(s.packing - f.phi_j)), z.push_back(s.coordination);
  if (root.size() < 3) {
    f.why_not = "fewer than 3 steps above phi_J";
    return f;
  }
  const LineFit coordination = fit_line(root, z);
  f.z_j = coordination.intercept, f.z_j_error = coordination.intercept_error;
  f.z_slope = coordination.slope, f.z_slope_error = coordination.slope_error;
  f.measured = true;
  return f;
}

} // namespace talus
