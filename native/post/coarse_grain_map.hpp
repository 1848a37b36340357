#pragma once
// Coarse-grained fields as maps of the plane (post/coarse_grain.hpp has the formulas and their
// sources): each grain's mass and momentum spread by the kernel phi(x) phi(y), the product of
// the profiles' kernel along both axes (for the Gaussian, the isotropic 2D Gaussian), and each
// contact's f (r - c) spread along its branch by 5-point Gauss-Legendre quadrature on pieces of
// at most half the kernel's width (the profiles integrate the branch exactly; on such pieces the
// kernel is smooth enough that the quadrature changes a field by parts in 1e5, and the totals
// not at all). Grid points are cell centres; a
// kernel is cut off at 5 widths (Gaussian: 4e-6 of its weight) or at its width (Lucy).
#include <cstddef>
#include <vector>

#include "post/coarse_grain.hpp"

namespace talus {

struct CgMapOptions {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0; ///< m
  Vec2 lo, hi;        ///< m: the map's corners
  std::size_t nx = 0, ny = 0;
  Vec2 period{}; ///< m: the periods along x and y (periodic boundaries), 0: none
};

struct FieldMap {
  std::size_t nx = 0, ny = 0;
  double cell_x = 0.0, cell_y = 0.0; ///< m
  Vec2 lo;                           ///< m: the map's lower corner
  std::vector<double> density;       ///< kg/m^2, row by row from the bottom (index iy nx + ix)
  std::vector<Vec2> momentum;        ///< kg/(m s)
  std::vector<Tensor2> kinetic;      ///< N/m
  std::vector<Tensor2> contact;      ///< N/m
  std::size_t frames = 0;
  Vec2 centre(std::size_t k) const; ///< m: the centre of cell k
  Vec2 velocity(std::size_t k) const;
};

/// The free grains' fields over `frames` (with masses and contact force vectors), as a map.
FieldMap coarse_grain_map(const std::vector<Frame>& frames, const CgMapOptions& o);

} // namespace talus
