#include "neighbours/neighbour_list.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "neighbours/cell_grid.hpp"
#include "talus/error.hpp"

namespace talus {

double largest_drift2(const NeighbourList& list, const Particles& p, int threads) {
  if (list.reference.size() != p.size()) return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) num_threads(threads) reduction(max : largest)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double d2 = norm2(p.position[i] - list.reference[i]);
    largest = d2 > largest ? d2 : largest; // a NaN position is left to the step's finite check
  }
  return largest;
}

bool particles_moved(const NeighbourList& list, const Particles& p, int threads) {
  return largest_drift2(list, p, threads) > drift_limit2(list);
}

bool needs_rebuild(const NeighbourList& list, const Particles& p, const Segments& walls) {
  return particles_moved(list, p) || walls_moved(list, p, walls, {});
}

bool walls_moved(const NeighbourList& list, const Particles& p, const Segments& walls,
                 const std::vector<std::uint32_t>& driven) {
  if (list.reference.size() != p.size() || list.segment_reference.size() != 2 * walls.size())
    return true;
  const double limit2 = drift_limit2(list);
  for (const auto i : driven)
    if (norm2(p.position[i] - list.reference[i]) > limit2) return true;
  for (std::size_t s = 0; s < walls.size(); ++s)
    if (norm2(walls[s].a - list.segment_reference[2 * s]) > limit2 ||
        norm2(walls[s].b - list.segment_reference[2 * s + 1]) > limit2)
      return true;
  return false;
}

std::uint32_t force_block_rows(std::size_t n) {
  const std::size_t blocks = std::clamp<std::size_t>(std::bit_floor(n / 2048), 2, 16);
  return static_cast<std::uint32_t>(std::max<std::size_t>(1, (n + blocks - 1) / blocks));
}

void index_force_blocks(NeighbourList& list, int threads) {
  const std::size_t n = list.row_offset.size() - 1;
  const std::uint32_t rows = force_block_rows(n);
  const std::size_t blocks = (n + rows - 1) / rows;
  list.block_rows = rows;
  // per block, in parallel: the second particles of its deferred entries (in entry order) and
  // its late particles
  std::vector<std::vector<std::uint32_t>> later(blocks), late(blocks);
  list.deferred_offset.assign(n + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t bi = 0; bi < static_cast<std::ptrdiff_t>(blocks); ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    const std::size_t first = b * rows, last = std::min(n, first + rows);
    for (std::uint32_t e = list.row_offset[first]; e < list.row_offset[last]; ++e)
      if (list.neighbour[e] >= last) later[b].push_back(list.neighbour[e]);
  }
  list.block_first_slot.assign(blocks + 1, 0);
  std::uint32_t slots = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    list.block_first_slot[b] = slots;
    slots += static_cast<std::uint32_t>(later[b].size());
    for (const std::uint32_t j : later[b]) ++list.deferred_offset[j + 1];
  }
  list.block_first_slot[blocks] = slots;
  for (std::size_t k = 0; k < n; ++k) list.deferred_offset[k + 1] += list.deferred_offset[k];
  list.deferred_slot.resize(slots);
  std::vector<std::uint32_t> fill(list.deferred_offset.begin(), list.deferred_offset.end() - 1);
  std::uint32_t slot = 0;
  for (std::size_t b = 0; b < blocks; ++b)
    for (const std::uint32_t j : later[b]) list.deferred_slot[fill[j]++] = slot++;
  list.entry_row.resize(list.neighbour.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t bi = 0; bi < static_cast<std::ptrdiff_t>(blocks); ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    for (std::size_t k = b * rows; k < std::min(n, (b + 1) * rows); ++k) {
      if (list.is_late(k)) late[b].push_back(static_cast<std::uint32_t>(k));
      for (std::uint32_t e = list.row_offset[k]; e < list.row_offset[k + 1]; ++e)
        list.entry_row[e] = static_cast<std::uint8_t>((k - b * rows) % NeighbourList::stretch_rows);
    }
  }
  list.late.clear();
  for (const auto& l : late) list.late.insert(list.late.end(), l.begin(), l.end());
}

namespace {

// A CSR table of (key, history) rows, keys sorted within each row.
struct HistoryRows {
  const std::vector<std::uint32_t>& offset;
  const std::vector<std::uint32_t>& key;
  const std::vector<double>& history;
};

// Sizes `history` to the new rows and copies the history of every entry whose key survives from
// the old row to the new one (a merge of sorted rows); new entries start at 0. The old table is
// used only if it has the same number of rows.
void carry_history(const HistoryRows& old_rows, const std::vector<std::uint32_t>& offset,
                   const std::vector<std::uint32_t>& key, std::vector<double>& history, bool keep,
                   int threads) {
  if (!keep) { // a list that keeps none holds none, and no memory for it
    std::vector<double>().swap(history);
    return;
  }
  history.assign(key.size(), 0.0);
  if (old_rows.offset.size() != offset.size()) return;
  const auto rows = static_cast<std::ptrdiff_t>(offset.size()) - 1;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < rows; ++i) { // rows are independent
    std::uint32_t a = old_rows.offset[i];
    for (std::uint32_t b = offset[i]; b < offset[i + 1]; ++b) {
      while (a < old_rows.offset[i + 1] && old_rows.key[a] < key[b]) ++a;
      if (a < old_rows.offset[i + 1] && old_rows.key[a] == key[b]) history[b] = old_rows.history[a];
    }
  }
}

// A neighbour cell index c along an axis of `cells` cells: false if it lies outside a
// non-periodic axis; else wrapped into range, with `shift` the periodic image (-1, 0 or 1).
bool neighbour_cell(int cells, bool periodic, int& c, std::int8_t& shift) {
  if (c >= 0 && c < cells) return true;
  if (!periodic) return false;
  shift = static_cast<std::int8_t>(c < 0 ? -1 : 1);
  c -= shift * cells;
  return true;
}

// As neighbour_cell along x, where a Lees-Edwards offset may put the column up to two widths
// of the box away.
bool neighbour_x_cell(const CellGrid& grid, int& c, std::int8_t& shift) {
  if (c >= 0 && c < grid.nx) return true;
  if (!grid.periodic_x) return false;
  const int widths = c >= 0 ? c / grid.nx : -((-c + grid.nx - 1) / grid.nx);
  shift = static_cast<std::int8_t>(widths);
  c -= widths * grid.nx;
  return true;
}

// The rows of a block of contiguous particles, built by one thread and joined in order. A cache
// line each: threads push onto neighbouring blocks at the same time.
struct alignas(64) RowBlock {
  std::vector<std::uint32_t> neighbour;
  std::vector<ImageShift> image;
  std::vector<std::uint32_t> count; // entries of each row
};

// Row i of the list into `out`: the later particles (j > i, one of the two free) within reach
// plus the skin, in ascending j. `row` is scratch space, kept by the caller.
inline void collect_row(const CellGrid& grid, const Particles& p, const Domain& domain, double skin,
                        std::size_t i, std::vector<std::pair<std::uint32_t, ImageShift>>& row,
                        RowBlock& out) {
  std::size_t count = 0; // the row: row[0, count)
  const Vec2 ri = p.position[i];
  const double Ri = p.radius[i] + skin;
  const bool free_i = p.is_free(i);
  const int cy = static_cast<int>(grid.cell_of[i]) / grid.nx; // the cell it was sorted into
  const int cx = static_cast<int>(grid.cell_of[i]) - cy * grid.nx;
  // the candidates of items[k0, k1), seen at the image (sx, sy): no branch per candidate, each is
  // written and kept only if it qualifies (about half do, at random, which a branch predictor
  // cannot learn)
  const auto scan = [&](std::uint32_t k0, std::uint32_t k1, std::int8_t sx, std::int8_t sy) {
    const Vec2 ri_shifted = ri - domain.image_shift(sx, sy);
    if (row.size() < count + (k1 - k0)) row.resize(2 * (count + (k1 - k0)));
    for (std::uint32_t k = k0; k < k1; ++k) {
      const std::uint32_t j = grid.items[k];
      const double reach = Ri + p.radius[j];
      const bool keep =
          (j > i) & (free_i | p.is_free(j)) & (norm2(ri_shifted - p.position[j]) < reach * reach);
      row[count] = {j, ImageShift{sx, sy}};
      count += keep;
    }
  };
  // Items ascend within a cell, so a cell holds a later particle (j > i) only if its last item is
  // one. Cells that hold none are not scanned: where the particles' order follows space (a
  // packing built row by row, for one), that is the row of cells below.
  const auto any_later = [&](std::size_t c0, std::size_t c1) { // cells [c0, c1)
    bool later = false;
    for (std::size_t c = c0; c < c1; ++c)
      later |=
          grid.cell_start[c + 1] > grid.cell_start[c] && grid.items[grid.cell_start[c + 1] - 1] > i;
    return later;
  };
  for (int dy = -1; dy <= 1; ++dy) {
    int ncy = cy + dy;
    std::int8_t sy = 0;
    if (!neighbour_cell(grid.ny, grid.periodic_y, ncy, sy)) continue;
    const std::size_t cell_row = static_cast<std::size_t>(ncy) * grid.nx;
    // across a Lees-Edwards side the row of cells is offset along x: its three columns are those
    // around i's place less the offset (the cells are at least the range wide)
    const int mx = sy == 0 || domain.shear_offset == 0.0
                       ? cx
                       : static_cast<int>(std::floor(
                             (ri.x - sy * domain.shear_offset - grid.origin.x) / grid.cell_size.x));
    if (mx >= 1 && mx + 1 < grid.nx) { // three cells side by side: one stretch of items
      const std::size_t c0 = cell_row + static_cast<std::size_t>(mx) - 1;
      if (any_later(c0, c0 + 3)) scan(grid.cell_start[c0], grid.cell_start[c0 + 3], 0, sy);
      continue;
    }
    for (int dx = -1; dx <= 1; ++dx) {
      int ncx = mx + dx;
      std::int8_t sx = 0;
      if (!neighbour_x_cell(grid, ncx, sx)) continue;
      const std::size_t c = cell_row + static_cast<std::size_t>(ncx);
      if (any_later(c, c + 1)) scan(grid.cell_start[c], grid.cell_start[c + 1], sx, sy);
    }
  }
  // rows are short (a few entries): insertion sort beats std::sort's set-up here
  for (std::size_t m = 1; m < count; ++m)
    for (std::size_t q = m; q > 0 && row[q - 1].first > row[q].first; --q)
      std::swap(row[q - 1], row[q]);
  for (std::size_t m = 0; m < count; ++m) {
    out.neighbour.push_back(row[m].first);
    out.image.push_back(row[m].second);
  }
  out.count.push_back(static_cast<std::uint32_t>(count));
}

// The blocks' rows joined in order into the list, each block into its place.
void join_row_blocks(NeighbourList& list, const std::vector<RowBlock>& block, std::size_t n,
                     int threads) {
  const auto blocks = static_cast<int>(block.size());
  std::vector<std::size_t> block_entry(block.size() + 1, 0);
  for (std::size_t b = 0; b < block.size(); ++b)
    block_entry[b + 1] = block_entry[b] + block[b].neighbour.size();
  list.neighbour.resize(block_entry.back());
  list.image.resize(block_entry.back());
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int bi = 0; bi < blocks; ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    const RowBlock& from = block[b];
    std::copy(from.neighbour.begin(), from.neighbour.end(),
              list.neighbour.begin() + static_cast<std::ptrdiff_t>(block_entry[b]));
    std::copy(from.image.begin(), from.image.end(),
              list.image.begin() + static_cast<std::ptrdiff_t>(block_entry[b]));
    std::size_t i = n * b / static_cast<std::size_t>(blocks);
    auto offset = static_cast<std::uint32_t>(block_entry[b]);
    for (const std::uint32_t c : from.count) list.row_offset[++i] = offset += c;
  }
}

void build_pairs(NeighbourList& list, const Particles& p, const Domain& domain, double skin,
                 int threads) {
  const std::size_t n = p.size();
  CellGrid grid;
  grid.build(p.position, domain, 2.0 * p.max_radius() + skin, threads);

  std::vector<std::uint32_t> old_offset = std::move(list.row_offset);
  std::vector<std::uint32_t> old_neighbour = std::move(list.neighbour);
  std::vector<double> old_history = std::move(list.history);
  std::vector<double> old_rolling = std::move(list.rolling);

  list.row_offset.resize(n + 1);
  list.row_offset[0] = 0;
  // four blocks per thread, taken one at a time (rows at the bottom of a packing have more
  // neighbours than those at the top), joined in order: the list does not depend on the count
  const int blocks =
      threads == 1 ? 1 : std::max(1, std::min<int>(4 * threads, static_cast<int>(n / 256) + 1));
  std::vector<RowBlock> block(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int bi = 0; bi < blocks; ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    const std::size_t first = n * b / static_cast<std::size_t>(blocks),
                      last = n * (b + 1) / static_cast<std::size_t>(blocks);
    RowBlock& out = block[b];
    out.count.reserve(last - first);
    // about as many entries as the last list had per row, and some room
    out.neighbour.reserve(n > 0 ? old_neighbour.size() * (last - first) / n * 11 / 10 + 16 : 0);
    out.image.reserve(out.neighbour.capacity());
    std::vector<std::pair<std::uint32_t, ImageShift>> row;
    for (std::size_t i = first; i < last; ++i) collect_row(grid, p, domain, skin, i, row, out);
  }
  join_row_blocks(list, block, n, threads);
  carry_history({old_offset, old_neighbour, old_history}, list.row_offset, list.neighbour,
                list.history, list.keeps_history, threads);
  carry_history({old_offset, old_neighbour, old_rolling}, list.row_offset, list.neighbour,
                list.rolling, list.keeps_rolling, threads);
}

void build_walls(NeighbourList& list, const Particles& p, const Segments& walls, double skin,
                 int threads) {
  const std::size_t n = p.size();
  std::vector<std::uint32_t> old_offset = std::move(list.wall_offset);
  std::vector<std::uint32_t> old_segment = std::move(list.wall_segment);
  std::vector<double> old_history = std::move(list.wall_history);
  std::vector<double> old_rolling = std::move(list.wall_rolling);

  list.wall_offset.assign(n + 1, 0);
  list.wall_segment.clear();
  if (walls.empty()) {
    list.wall_history.clear();
    list.wall_rolling.clear();
    return;
  }
  // rows in blocks of contiguous particles, side by side, joined in order (a few segments each)
  const int blocks = std::max(1, std::min<int>(threads, static_cast<int>(n / 4096) + 1));
  std::vector<std::vector<std::uint32_t>> segment(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int bi = 0; bi < blocks; ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    const std::size_t first = n * b / static_cast<std::size_t>(blocks),
                      last = n * (b + 1) / static_cast<std::size_t>(blocks);
    for (std::size_t i = first; i < last; ++i) {
      if (p.is_free(i)) {
        const double reach = p.radius[i] + skin;
        for (std::size_t s = 0; s < walls.size(); ++s)
          if (norm2(p.position[i] - closest_point(walls[s], p.position[i])) < reach * reach)
            segment[b].push_back(static_cast<std::uint32_t>(s));
      }
      list.wall_offset[i + 1] = static_cast<std::uint32_t>(segment[b].size()); // within the block
    }
  }
  std::uint32_t base = 0;
  for (std::size_t b = 0; b < segment.size(); ++b) {
    const std::size_t first = n * b / segment.size(), last = n * (b + 1) / segment.size();
    for (std::size_t i = first; i < last; ++i) list.wall_offset[i + 1] += base;
    base += static_cast<std::uint32_t>(segment[b].size());
    list.wall_segment.insert(list.wall_segment.end(), segment[b].begin(), segment[b].end());
  }
  carry_history({old_offset, old_segment, old_history}, list.wall_offset, list.wall_segment,
                list.wall_history, list.keeps_history, threads);
  carry_history({old_offset, old_segment, old_rolling}, list.wall_offset, list.wall_segment,
                list.wall_rolling, list.keeps_rolling, threads);
}

} // namespace

void build_neighbour_list(NeighbourList& list, Particles& p, const Segments& walls,
                          const Domain& domain, double skin, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  if (domain.any_periodic()) {
    const Vec2 l = domain.size();
    require(!domain.sheared() || (domain.periodic_x && domain.periodic_y &&
                                  domain.shear_offset >= 0.0 && domain.shear_offset < l.x),
            "Lees-Edwards images need a box periodic in x and y and an offset in [0, L_x)");
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const Vec2 was = p.position[i];
      int heights = 0;
      p.position[i] = domain.wrap(was, &heights);
      // the boundaries crossed, counted for the unwrapped position (Domain::unwrapped): the
      // widths only, not the images' offset
      const double across = was.x - p.position[i].x - heights * domain.shear_offset;
      p.image[i].x += static_cast<std::int32_t>(std::nearbyint(across / l.x));
      p.image[i].y += heights;
      if (heights != 0 && p.is_free(static_cast<std::size_t>(i)))
        p.velocity[i].x -= heights * domain.shear_velocity;
    }
  }
  list.skin = skin;
  list.box = domain.size();
  list.shear_offset = domain.shear_offset;
  build_pairs(list, p, domain, skin, threads);
  build_walls(list, p, walls, skin, threads);
  index_force_blocks(list, threads);
  list.reference.resize(p.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) list.reference[i] = p.position[i];
  list.segment_reference.resize(2 * walls.size());
  for (std::size_t s = 0; s < walls.size(); ++s) {
    list.segment_reference[2 * s] = walls[s].a;
    list.segment_reference[2 * s + 1] = walls[s].b;
  }
  ++list.builds;
}

void renumber_neighbour_list(NeighbourList& list, const std::vector<std::uint32_t>& order,
                             const std::vector<std::uint32_t>& new_of_old, int threads) {
  const std::size_t n = order.size();
  const bool kept = list.keeps_history, rolls = list.keeps_rolling;
  struct Entry {
    std::uint32_t j;
    ImageShift image;
    double history;
    double rolling; // seen from the first particle: its sign turns with the pair
  };
  // every pair under its new first particle, in rows
  std::vector<std::uint32_t> offset(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e)
      ++offset[std::min(new_of_old[i], new_of_old[list.neighbour[e]]) + 1];
  for (std::size_t k = 0; k < n; ++k) offset[k + 1] += offset[k];
  std::vector<Entry> entries(offset[n]);
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
      const std::uint32_t a = new_of_old[i], b = new_of_old[list.neighbour[e]];
      const ImageShift s = list.image[e];
      const double spring = kept ? list.history[e] : 0.0;
      const double theta = rolls ? list.rolling[e] : 0.0;
      entries[fill[std::min(a, b)]++] =
          a < b
              ? Entry{b, s, spring, theta}
              : Entry{a,
                      ImageShift{static_cast<std::int8_t>(-s.sx), static_cast<std::int8_t>(-s.sy)},
                      spring, -theta};
    }
  const auto rows = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < rows; ++k) // short rows: insertion sort by the second particle
    for (std::uint32_t m = offset[k] + 1; m < offset[k + 1]; ++m)
      for (std::uint32_t q = m; q > offset[k] && entries[q - 1].j > entries[q].j; --q)
        std::swap(entries[q - 1], entries[q]);
  list.row_offset = std::move(offset);
  const auto count = static_cast<std::ptrdiff_t>(entries.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t e = 0; e < count; ++e) {
    list.neighbour[e] = entries[e].j;
    list.image[e] = entries[e].image;
    if (kept) list.history[e] = entries[e].history;
    if (rolls) list.rolling[e] = entries[e].rolling;
  }
  // wall rows follow their particles
  std::vector<std::uint32_t> wall_offset(n + 1, 0), wall_segment;
  std::vector<double> wall_history, wall_rolling;
  wall_segment.reserve(list.wall_segment.size());
  wall_history.reserve(list.wall_history.size());
  wall_rolling.reserve(list.wall_rolling.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = order[k];
    for (std::uint32_t e = list.wall_offset[i]; e < list.wall_offset[i + 1]; ++e) {
      wall_segment.push_back(list.wall_segment[e]);
      if (kept) wall_history.push_back(list.wall_history[e]);
      if (rolls) wall_rolling.push_back(list.wall_rolling[e]);
    }
    wall_offset[k + 1] = static_cast<std::uint32_t>(wall_segment.size());
  }
  list.wall_offset = std::move(wall_offset);
  list.wall_segment = std::move(wall_segment);
  list.wall_history = std::move(wall_history);
  list.wall_rolling = std::move(wall_rolling);
  if (list.reference.size() == n) {
    std::vector<Vec2> reference(n);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t k = 0; k < rows; ++k) reference[k] = list.reference[order[k]];
    list.reference = std::move(reference);
  }
  index_force_blocks(list, threads);
}

} // namespace talus
