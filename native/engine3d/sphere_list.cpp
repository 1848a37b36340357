#include "engine3d/sphere_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "talus/error.hpp"

namespace talus {

namespace {

// A grid of cells at least `range` wide over the spheres (over the box along periodic axes),
// with the spheres sorted into cells by a counting sort.
struct Grid3 {
  std::array<double, 3> lo{}, size{};
  std::array<int, 3> cells{1, 1, 1};
  std::vector<std::uint32_t> start, items;

  // the cell along axis k; a position outside the grid (or NaN) goes to the nearest end cell
  int cell_along(int k, double v) const {
    const double c = std::floor((v - lo[k]) / size[k]);
    if (!(c > 0.0)) return 0;
    return c < cells[k] - 1 ? static_cast<int>(c) : cells[k] - 1;
  }
  std::size_t index(int cx, int cy, int cz) const {
    return (static_cast<std::size_t>(cz) * cells[1] + cy) * cells[0] + cx;
  }
};

// Cells along each axis: as many as fit, at least three along a periodic axis; an open axis of
// a sparse scene is cut into fewer cells so that the grid stays within a few cells per sphere.
std::array<int, 3> cell_counts(const std::array<double, 3>& extent, double range, const Domain3& d,
                               std::size_t n) {
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k) {
    const double fit = std::floor(extent[k] / range);
    c[k] = static_cast<int>(std::clamp(fit, 1.0, 4096.0));
    if (d.periodic[k])
      require(c[k] >= 3, "a periodic axis must be at least 3 interaction ranges long (" +
                             std::to_string(3.0 * range) + " m): it is " +
                             std::to_string(extent[k]) + " m");
  }
  const double most = 8.0 * static_cast<double>(n) + 64.0;
  for (;;) {
    if (1.0 * c[0] * c[1] * c[2] <= most) break;
    int widest = -1;
    for (int k = 0; k < 3; ++k)
      if (!d.periodic[k] && c[k] > 1 && (widest < 0 || c[k] > c[widest])) widest = k;
    if (widest < 0) break;
    c[widest] = (c[widest] + 1) / 2;
  }
  return c;
}

Grid3 make_grid(const Spheres& s, const Domain3& d, double range) {
  Grid3 g;
  std::array<double, 3> extent{};
  for (int k = 0; k < 3; ++k) {
    if (d.periodic[k]) {
      g.lo[k] = component(d.lo, k);
      extent[k] = component(d.hi, k) - g.lo[k];
      continue;
    }
    double lo = component(s.position[0], k), hi = lo;
    for (const Vec3& p : s.position) {
      lo = std::min(lo, component(p, k));
      hi = std::max(hi, component(p, k));
    }
    g.lo[k] = lo;
    extent[k] = hi - lo;
  }
  g.cells = cell_counts(extent, range, d, s.size());
  for (int k = 0; k < 3; ++k) g.size[k] = std::max(extent[k], range) / g.cells[k];
  const std::size_t total = static_cast<std::size_t>(g.cells[0]) * g.cells[1] * g.cells[2];
  std::vector<std::uint32_t> cell_of(s.size());
  g.start.assign(total + 1, 0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec3& p = s.position[i];
    cell_of[i] = static_cast<std::uint32_t>(
        g.index(g.cell_along(0, p.x), g.cell_along(1, p.y), g.cell_along(2, p.z)));
    ++g.start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < total; ++c) g.start[c + 1] += g.start[c];
  g.items.resize(s.size());
  std::vector<std::uint32_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < s.size(); ++i)
    g.items[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  return g;
}

struct Candidate {
  std::uint32_t j;
  Shift3 shift;
};

// The cell next to `home` along axis k by `step` with the periodic image it takes (c and shift
// set), or false where the grid ends along an open axis.
bool neighbour_cell(const Grid3& g, const Domain3& d, int k, int cell, int& c, std::int8_t& shift) {
  c = cell;
  shift = 0;
  if (c >= 0 && c < g.cells[k]) return true;
  if (!d.periodic[k]) return false;
  // beyond one width only across a Lees-Edwards side, whose offset moves the row of cells
  const int widths = c >= 0 ? c / g.cells[k] : -((-c - 1) / g.cells[k] + 1);
  shift = static_cast<std::int8_t>(widths);
  c -= widths * g.cells[k];
  return true;
}

// The pairs (i, j > i) within reach of sphere i, ascending in j.
void row_of(std::size_t i, const Spheres& s, const Grid3& g, const Domain3& d, double skin,
            std::vector<Candidate>& row) {
  row.clear();
  const Vec3& p = s.position[i];
  const std::array<int, 3> home{g.cell_along(0, p.x), g.cell_along(1, p.y), g.cell_along(2, p.z)};
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      int cy = 0, cz = 0;
      std::int8_t sy = 0, sz = 0;
      if (!neighbour_cell(g, d, 1, home[1] + dy, cy, sy) ||
          !neighbour_cell(g, d, 2, home[2] + dz, cz, sz))
        continue;
      // across a Lees-Edwards side the row of cells is offset along x: its three columns are
      // those around i's place less the offset (the cells are at least the range wide)
      const int mx =
          sy == 0 || d.shear_offset == 0.0
              ? home[0]
              : static_cast<int>(std::floor((p.x - sy * d.shear_offset - g.lo[0]) / g.size[0]));
      for (int dx = -1; dx <= 1; ++dx) {
        int cx = 0;
        std::int8_t sx = 0;
        if (!neighbour_cell(g, d, 0, mx + dx, cx, sx)) continue;
        const Vec3 offset = d.image_shift(sx, sy, sz);
        const std::size_t cell = g.index(cx, cy, cz);
        for (std::uint32_t k = g.start[cell]; k < g.start[cell + 1]; ++k) {
          const std::uint32_t j = g.items[k];
          if (j <= i || (!s.is_free(i) && !s.is_free(j))) continue;
          const double reach = s.radius[i] + s.radius[j] + skin;
          if (norm2(p - (s.position[j] + offset)) < reach * reach) row.push_back({j, {sx, sy, sz}});
        }
      }
    }
  std::sort(row.begin(), row.end(),
            [](const Candidate& a, const Candidate& b) { return a.j < b.j; });
}

// The spring the old list kept for (i, j) in its row i, or 0 (rows ascend in j).
Vec3 kept_spring(const std::vector<std::uint32_t>& offset, const std::vector<std::uint32_t>& key,
                 const std::vector<Vec3>& spring, std::size_t i, std::uint32_t j) {
  if (i + 1 >= offset.size()) return {};
  const auto first = key.begin() + offset[i], last = key.begin() + offset[i + 1];
  const auto at = std::lower_bound(first, last, j);
  return at != last && *at == j ? spring[static_cast<std::size_t>(at - key.begin())] : Vec3{};
}

} // namespace

void index_second_entries(SphereList& list, std::size_t spheres) {
  list.second_offset.assign(spheres + 1, 0);
  for (const std::uint32_t j : list.neighbour) ++list.second_offset[j + 1];
  for (std::size_t k = 0; k < spheres; ++k) list.second_offset[k + 1] += list.second_offset[k];
  list.second_entry.resize(list.neighbour.size());
  std::vector<std::uint32_t> fill(list.second_offset.begin(), list.second_offset.end() - 1);
  for (std::uint32_t e = 0; e < list.neighbour.size(); ++e)
    list.second_entry[fill[list.neighbour[e]]++] = e;
}

std::vector<std::uint32_t> spheres_by_cell(const Spheres& s, const Domain3& domain, double range) {
  if (s.empty()) return {};
  return make_grid(s, domain, range).items;
}

void build_sphere_list(SphereList& list, Spheres& s, const std::vector<Plane>& plates,
                       const Domain3& domain, double skin) {
  require(skin >= 0.0 && std::isfinite(skin), "the skin must be finite and >= 0 m");
  require(!domain.sheared() ||
              (domain.periodic[0] && domain.periodic[1] && domain.shear_offset >= 0.0 &&
               domain.shear_offset < domain.size().x),
          "Lees-Edwards images need a box periodic in x and y and an offset in [0, L_x)");
  for (std::size_t i = 0; i < s.size(); ++i) {
    int heights = 0;
    s.position[i] = domain.wrap(s.position[i], s.image[i], &heights);
    if (heights != 0 && s.is_free(i)) s.velocity[i].x -= heights * domain.shear_velocity;
  }
  SphereList next;
  next.skin = skin;
  next.box = domain.size();
  next.shear_offset = domain.shear_offset;
  next.with_springs = list.with_springs;
  next.with_rolling = list.with_rolling;
  next.builds = list.builds + 1;
  next.row_offset.assign(1, 0);
  next.plate_offset.assign(1, 0);
  if (!s.empty()) {
    const Grid3 grid = make_grid(s, domain, 2.0 * s.max_radius() + skin);
    std::vector<Candidate> row;
    for (std::size_t i = 0; i < s.size(); ++i) {
      row_of(i, s, grid, domain, skin, row);
      for (const Candidate& c : row) {
        next.neighbour.push_back(c.j);
        next.shift.push_back(c.shift);
        if (next.with_springs)
          next.spring.push_back(kept_spring(list.row_offset, list.neighbour, list.spring, i, c.j));
        if (next.with_rolling)
          next.rolling.push_back(
              kept_spring(list.row_offset, list.neighbour, list.rolling, i, c.j));
      }
      next.row_offset.push_back(static_cast<std::uint32_t>(next.neighbour.size()));
      for (std::uint32_t w = 0; s.is_free(i) && w < plates.size(); ++w) {
        const double reach = s.radius[i] + skin;
        if (norm2(s.position[i] - closest_point(plates[w], s.position[i])) >= reach * reach)
          continue;
        next.plate.push_back(w);
        if (next.with_springs)
          next.plate_spring.push_back(
              kept_spring(list.plate_offset, list.plate, list.plate_spring, i, w));
        if (next.with_rolling)
          next.plate_rolling.push_back(
              kept_spring(list.plate_offset, list.plate, list.plate_rolling, i, w));
      }
      next.plate_offset.push_back(static_cast<std::uint32_t>(next.plate.size()));
    }
  }
  index_second_entries(next, s.size());
  next.reference = s.position;
  for (const Plane& p : plates) next.plate_reference.push_back({p.centre, p.normal, p.axis_u});
  list = std::move(next);
}

double cell_reserve(const SphereList& list, const Domain3& domain, const Spheres& s) {
  const Vec3 now = domain.size();
  if (now.x == list.box.x && now.y == list.box.y && now.z == list.box.z &&
      domain.shear_offset == list.shear_offset)
    return 0.0;
  double shrink = 1.0; // the smallest factor a side shrank by since the build
  for (int k = 0; k < 3; ++k)
    if (component(list.box, k) > 0.0)
      shrink = std::min(shrink, component(now, k) / component(list.box, k));
  return -std::log(shrink) * (2.0 * s.max_radius() + list.skin) +
         std::abs(domain.shear_offset - list.shear_offset);
}

bool list_is_stale(const SphereList& list, const Spheres& s, const std::vector<Plane>& plates,
                   const Domain3& domain) {
  if (list.reference.size() != s.size() || list.plate_reference.size() != plates.size())
    return true;
  const double limit = 0.5 * (list.skin - cell_reserve(list, domain, s));
  if (limit <= 0.0) return true;
  const double limit2 = limit * limit;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!(norm2(s.position[i] - list.reference[i]) <= limit2)) return true;
  for (std::size_t w = 0; w < plates.size(); ++w) {
    const Plane& p = plates[w];
    const PlatePose& then = list.plate_reference[w];
    double moved = norm(p.centre - then.centre);
    const double turn = std::max(norm(p.normal - then.normal), norm(p.axis_u - then.axis_u));
    if (turn > 0.0) {
      double farthest2 = 0.0;
      for (const Vec3& x : s.position) farthest2 = std::max(farthest2, norm2(x - p.centre));
      moved += turn * std::sqrt(farthest2);
    }
    if (!(moved * moved <= limit2)) return true;
  }
  return false;
}

} // namespace talus
