#include "engine3d/renumber3.hpp"

#include <algorithm>

#include "talus/error.hpp"

namespace talus {

namespace {

template <class T> void permute(std::vector<T>& v, const std::vector<std::uint32_t>& old_of_new) {
  if (v.empty()) return;
  std::vector<T> out(v.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = v[old_of_new[k]];
  v = std::move(out);
}

struct Entry {
  std::uint32_t j;
  Shift3 shift;
  Vec3 spring, rolling;
};

// The pair entries under the new numbering, row by row with each row ascending in j.
void renumber_pairs(SphereList& l, const std::vector<std::uint32_t>& new_of_old) {
  const std::size_t n = new_of_old.size();
  std::vector<std::vector<Entry>> rows(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e) {
      const std::uint32_t a = new_of_old[i], b = new_of_old[l.neighbour[e]];
      const Vec3 spring = l.with_springs ? l.spring[e] : Vec3{};
      const Vec3 rolling = l.with_rolling ? l.rolling[e] : Vec3{};
      if (a < b) {
        rows[a].push_back({b, l.shift[e], spring, rolling});
        continue;
      }
      const Shift3 back{static_cast<std::int8_t>(-l.shift[e].x),
                        static_cast<std::int8_t>(-l.shift[e].y),
                        static_cast<std::int8_t>(-l.shift[e].z)};
      rows[b].push_back({a, back, -spring, -rolling});
    }
  l.neighbour.clear(), l.shift.clear(), l.spring.clear(), l.rolling.clear();
  l.row_offset.assign(1, 0);
  for (std::vector<Entry>& row : rows) {
    std::ranges::sort(row, {}, &Entry::j);
    for (const Entry& x : row) {
      l.neighbour.push_back(x.j), l.shift.push_back(x.shift);
      if (l.with_springs) l.spring.push_back(x.spring);
      if (l.with_rolling) l.rolling.push_back(x.rolling);
    }
    l.row_offset.push_back(static_cast<std::uint32_t>(l.neighbour.size()));
  }
  index_second_entries(l, n);
}

// Each sphere's plate entries move with it, in their order.
void renumber_plates(SphereList& l, const std::vector<std::uint32_t>& old_of_new) {
  SphereList out;
  out.plate_offset.assign(1, 0);
  for (const std::uint32_t i : old_of_new) {
    for (std::uint32_t e = l.plate_offset[i]; e < l.plate_offset[i + 1]; ++e) {
      out.plate.push_back(l.plate[e]);
      if (l.with_springs) out.plate_spring.push_back(l.plate_spring[e]);
      if (l.with_rolling) out.plate_rolling.push_back(l.plate_rolling[e]);
    }
    out.plate_offset.push_back(static_cast<std::uint32_t>(out.plate.size()));
  }
  l.plate_offset = std::move(out.plate_offset), l.plate = std::move(out.plate);
  l.plate_spring = std::move(out.plate_spring), l.plate_rolling = std::move(out.plate_rolling);
}

} // namespace

void renumber_spheres(Spheres& s, SphereList& list, GearState3& gear,
                      const std::vector<std::uint32_t>& old_of_new) {
  const std::size_t n = s.size();
  require(old_of_new.size() == n && list.row_offset.size() == n + 1 &&
              list.plate_offset.size() == n + 1,
          "a renumbering takes every sphere once, with the list built for them");
  std::vector<std::uint32_t> new_of_old(n, static_cast<std::uint32_t>(n));
  for (std::uint32_t k = 0; k < n; ++k) {
    require(old_of_new[k] < n && new_of_old[old_of_new[k]] == n,
            "a renumbering takes every sphere once");
    new_of_old[old_of_new[k]] = k;
  }
  sphere_fields(s, [&](auto& v) { permute(v, old_of_new); });
  for (auto* v : {&gear.r2, &gear.r3, &gear.r4, &gear.w2, &gear.w3, &gear.w4})
    permute(*v, old_of_new);
  renumber_pairs(list, new_of_old);
  renumber_plates(list, old_of_new);
  permute(list.reference, old_of_new);
}

} // namespace talus
