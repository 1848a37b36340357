// Simple shear in a sheared (Lees-Edwards) cell, measured from the cell's own stress and packing
// fraction in thermo.csv (post/rheology.hpp, cell_rheology_point).
#include <cmath>

#include <fmt/core.h>

#include "post/block_mean.hpp"
#include "post/line_fit.hpp"
#include "post/rheology.hpp"

namespace talus {

namespace {

struct CellBlock {
  double shear_rate = 0.0, normal_stress = 0.0, shear_stress = 0.0, friction = 0.0;
  double packing = 0.0, inertial = 0.0;
};

CellBlock block_of(const std::vector<CellShearRow>& rows, std::size_t first, std::size_t last,
                   const GrainScale& scale) {
  CellBlock b;
  const auto n = static_cast<double>(last - first);
  for (std::size_t k = first; k < last; ++k) {
    b.shear_rate += rows[k].shear_rate / n, b.normal_stress += rows[k].normal_stress / n;
    b.shear_stress += rows[k].shear_stress / n, b.packing += rows[k].packing / n;
  }
  b.shear_stress = std::abs(b.shear_stress);
  b.friction = b.shear_stress / b.normal_stress;
  b.inertial = std::abs(b.shear_rate) * scale.diameter / std::sqrt(b.normal_stress / scale.density);
  return b;
}

struct ProfileBlock {
  double slope = 0.0;
};

// The least-squares slope of v_x over y of a frame's free grains: their positions need not be
// wrapped, the flow across a sheared cell's side going on as the images do.
template <class FrameT> double profile_slope(const FrameT& f) {
  std::vector<double> y, vx;
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.kind[i] == 0) y.push_back(f.position[i].y), vx.push_back(f.velocity[i].x);
  return fit_line(y, vx).slope;
}

template <class FrameT>
RheologyPoint point_of_frames(const std::vector<CellShearRow>& rows,
                              const std::vector<FrameT>& frames, std::size_t blocks) {
  std::vector<double> slopes;
  for (const FrameT& f : frames) slopes.push_back(profile_slope(f));
  return cell_rheology_point(rows, frames.empty() ? GrainScale{} : grain_scale(frames.front()),
                             slopes, blocks);
}

} // namespace

RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows,
                                  const std::vector<Frame>& frames, std::size_t blocks) {
  return point_of_frames(rows, frames, blocks);
}

RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows,
                                  const std::vector<Frame3>& frames, std::size_t blocks) {
  return point_of_frames(rows, frames, blocks);
}

RheologyPoint cell_rheology_point(const std::vector<CellShearRow>& rows, const GrainScale& scale,
                                  const std::vector<double>& slopes, std::size_t blocks) {
  RheologyPoint r;
  r.frames = slopes.size();
  if (rows.size() < 2 * blocks || slopes.size() < blocks || blocks < 2) {
    r.why_not = fmt::format("{} thermo rows and {} snapshots; at least {} and {} are needed (two "
                            "rows and one snapshot per block)",
                            rows.size(), slopes.size(), 2 * blocks, blocks);
    return r;
  }
  if (scale.grains == 0 || !(scale.density > 0.0)) {
    r.why_not = "the snapshots hold no free grains with their masses";
    return r;
  }
  r.diameter = scale.diameter, r.grain_density = scale.density;
  std::vector<CellBlock> cells;
  std::vector<ProfileBlock> profiles;
  for (std::size_t b = 0; b < blocks; ++b) {
    cells.push_back(
        block_of(rows, rows.size() * b / blocks, rows.size() * (b + 1) / blocks, scale));
    ProfileBlock p;
    const std::size_t f0 = slopes.size() * b / blocks, f1 = slopes.size() * (b + 1) / blocks;
    for (std::size_t k = f0; k < f1; ++k) p.slope += slopes[k] / static_cast<double>(f1 - f0);
    profiles.push_back(p);
  }
  std::tie(r.shear_rate, r.shear_rate_error) = block_mean_error(cells, &CellBlock::shear_rate);
  std::tie(r.pressure, r.pressure_error) = block_mean_error(cells, &CellBlock::normal_stress);
  std::tie(r.shear_stress, r.shear_stress_error) =
      block_mean_error(cells, &CellBlock::shear_stress);
  std::tie(r.friction, r.friction_error) = block_mean_error(cells, &CellBlock::friction);
  std::tie(r.packing, r.packing_error) = block_mean_error(cells, &CellBlock::packing);
  std::tie(r.inertial, r.inertial_error) = block_mean_error(cells, &CellBlock::inertial);
  std::tie(r.profile_shear_rate, r.profile_shear_rate_error) =
      block_mean_error(profiles, &ProfileBlock::slope);
  r.measured = true;
  return r;
}

} // namespace talus
