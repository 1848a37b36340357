#include "neighbours/neighbour_list.hpp"

#include <algorithm>

#include "neighbours/cell_grid.hpp"

namespace talus {

bool needs_rebuild(const NeighbourList& list, const Particles& p, const Segments& walls) {
  if (list.reference.size() != p.size() || list.segment_reference.size() != 2 * walls.size())
    return true;
  const double limit2 = 0.25 * list.skin * list.skin;
  bool moved = false;
  for (std::size_t i = 0; i < p.size(); ++i)
    moved |= norm2(p.position[i] - list.reference[i]) > limit2;
  for (std::size_t s = 0; s < walls.size(); ++s) {
    moved |= norm2(walls[s].a - list.segment_reference[2 * s]) > limit2;
    moved |= norm2(walls[s].b - list.segment_reference[2 * s + 1]) > limit2;
  }
  return moved;
}

namespace {

// Copies the history of entries whose key survives from the old row to the new row. Both rows
// are sorted by key.
void carry_history(const std::uint32_t* old_key, const double* old_history, std::size_t old_n,
                   const std::uint32_t* new_key, double* new_history, std::size_t new_n) {
  std::size_t a = 0;
  for (std::size_t b = 0; b < new_n; ++b) {
    while (a < old_n && old_key[a] < new_key[b]) ++a;
    new_history[b] = (a < old_n && old_key[a] == new_key[b]) ? old_history[a] : 0.0;
  }
}

void build_pairs(NeighbourList& list, const Particles& p, const Domain& domain, double skin) {
  const std::size_t n = p.size();
  CellGrid grid;
  grid.build(p.position, domain, 2.0 * p.max_radius() + skin);
  const Vec2 box = domain.size();

  std::vector<std::uint32_t> old_offset = std::move(list.row_offset);
  std::vector<std::uint32_t> old_neighbour = std::move(list.neighbour);
  std::vector<double> old_history = std::move(list.history);
  const bool can_carry = old_offset.size() == n + 1;

  list.row_offset.assign(n + 1, 0);
  list.neighbour.clear();
  list.image.clear();
  std::vector<std::pair<std::uint32_t, ImageShift>> row;
  for (std::size_t i = 0; i < n; ++i) {
    row.clear();
    const Vec2 ri = p.position[i];
    const int cx = grid.cell_x(ri.x), cy = grid.cell_y(ri.y);
    for (int dy = -1; dy <= 1; ++dy) {
      int ncy = cy + dy;
      std::int8_t sy = 0;
      if (ncy < 0 || ncy >= grid.ny) {
        if (!grid.periodic_y) continue;
        sy = static_cast<std::int8_t>(ncy < 0 ? -1 : 1);
        ncy -= sy * grid.ny;
      }
      for (int dx = -1; dx <= 1; ++dx) {
        int ncx = cx + dx;
        std::int8_t sx = 0;
        if (ncx < 0 || ncx >= grid.nx) {
          if (!grid.periodic_x) continue;
          sx = static_cast<std::int8_t>(ncx < 0 ? -1 : 1);
          ncx -= sx * grid.nx;
        }
        const Vec2 shift{sx * box.x, sy * box.y};
        const std::size_t c = static_cast<std::size_t>(ncy) * grid.nx + ncx;
        for (std::uint32_t k = grid.cell_start[c]; k < grid.cell_start[c + 1]; ++k) {
          const std::uint32_t j = grid.items[k];
          if (j <= i || (!p.is_free(i) && !p.is_free(j))) continue;
          const double reach = p.radius[i] + p.radius[j] + skin;
          if (norm2(ri - (p.position[j] + shift)) < reach * reach)
            row.emplace_back(j, ImageShift{sx, sy});
        }
      }
    }
    std::sort(row.begin(), row.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [j, img] : row) {
      list.neighbour.push_back(j);
      list.image.push_back(img);
    }
    list.row_offset[i + 1] = static_cast<std::uint32_t>(list.neighbour.size());
  }

  list.history.assign(list.neighbour.size(), 0.0);
  if (can_carry) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t o0 = old_offset[i], o1 = old_offset[i + 1];
      const std::uint32_t n0 = list.row_offset[i], n1 = list.row_offset[i + 1];
      carry_history(old_neighbour.data() + o0, old_history.data() + o0, o1 - o0,
                    list.neighbour.data() + n0, list.history.data() + n0, n1 - n0);
    }
  }

  // transpose: for each particle, the entries where it is the second partner, in entry order
  list.col_offset.assign(n + 1, 0);
  for (const std::uint32_t j : list.neighbour) ++list.col_offset[j + 1];
  for (std::size_t k = 0; k < n; ++k) list.col_offset[k + 1] += list.col_offset[k];
  list.col_entry.resize(list.neighbour.size());
  std::vector<std::uint32_t> fill(list.col_offset.begin(), list.col_offset.end() - 1);
  for (std::size_t e = 0; e < list.neighbour.size(); ++e)
    list.col_entry[fill[list.neighbour[e]]++] = static_cast<std::uint32_t>(e);
}

void build_walls(NeighbourList& list, const Particles& p, const Segments& walls, double skin) {
  const std::size_t n = p.size();
  std::vector<std::uint32_t> old_offset = std::move(list.wall_offset);
  std::vector<std::uint32_t> old_segment = std::move(list.wall_segment);
  std::vector<double> old_history = std::move(list.wall_history);
  const bool can_carry = old_offset.size() == n + 1;

  list.wall_offset.assign(n + 1, 0);
  list.wall_segment.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (p.is_free(i)) {
      const double reach = p.radius[i] + skin;
      for (std::size_t s = 0; s < walls.size(); ++s)
        if (norm2(p.position[i] - closest_point(walls[s], p.position[i])) < reach * reach)
          list.wall_segment.push_back(static_cast<std::uint32_t>(s));
    }
    list.wall_offset[i + 1] = static_cast<std::uint32_t>(list.wall_segment.size());
  }
  list.wall_history.assign(list.wall_segment.size(), 0.0);
  if (can_carry) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t o0 = old_offset[i], o1 = old_offset[i + 1];
      const std::uint32_t n0 = list.wall_offset[i], n1 = list.wall_offset[i + 1];
      carry_history(old_segment.data() + o0, old_history.data() + o0, o1 - o0,
                    list.wall_segment.data() + n0, list.wall_history.data() + n0, n1 - n0);
    }
  }
}

} // namespace

void build_neighbour_list(NeighbourList& list, Particles& p, const Segments& walls,
                          const Domain& domain, double skin) {
  if (domain.any_periodic())
    for (Vec2& r : p.position) r = domain.wrap(r);
  list.skin = skin;
  build_pairs(list, p, domain, skin);
  build_walls(list, p, walls, skin);
  list.reference = p.position;
  list.segment_reference.resize(2 * walls.size());
  for (std::size_t s = 0; s < walls.size(); ++s) {
    list.segment_reference[2 * s] = walls[s].a;
    list.segment_reference[2 * s + 1] = walls[s].b;
  }
  ++list.builds;
}

} // namespace talus
