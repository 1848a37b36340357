#pragma once
// The wall segments near each atom, for fix granthesis/wall: a pass over every segment for every
// atom at every step costs atoms x segments (a drum of 72 sides), this one only at a build.
// A row holds the segments within the atom's radius and a margin at the build; it stays valid
// while the farthest move of an atom plus that of a segment stays below the margin, since then
// no segment outside the row can have come within the radius. Rows are in segment order, so the
// forces are summed in the order of a pass over every segment.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "talus/segment_contact.hpp"

namespace talus::lammps {

class SegmentNeighbours {
public:
  /// Rows for atoms [0, nlocal) of the group (others get empty rows) against `segments` (each
  /// with end points ax, ay, bx, by), within radius + margin.
  template <class Segments>
  void build(const double* const* x, const double* radius, const int* mask, int groupbit,
             int nlocal, const Segments& segments, double margin) {
    offset_.assign(1, 0);
    segment_.clear();
    x0_.resize(2 * static_cast<std::size_t>(nlocal));
    for (int i = 0; i < nlocal; ++i) {
      x0_[2 * static_cast<std::size_t>(i)] = x[i][0];
      x0_[2 * static_cast<std::size_t>(i) + 1] = x[i][1];
      if (mask[i] & groupbit) {
        const double reach = radius[i] + margin;
        for (std::size_t s = 0; s < segments.size(); ++s) {
          const auto& w = segments[s];
          const SegmentHit h = segment_hit(w.ax, w.ay, w.bx, w.by, x[i][0], x[i][1], reach);
          const double dx = x[i][0] - h.x, dy = x[i][1] - h.y;
          if (dx * dx + dy * dy < reach * reach) segment_.push_back(static_cast<int>(s));
        }
      }
      offset_.push_back(static_cast<int>(segment_.size()));
    }
    ends0_.clear();
    for (const auto& w : segments) ends0_.push_back({w.ax, w.ay, w.bx, w.by});
    margin_ = margin;
    nlocal_ = nlocal;
    built_ = true;
  }

  /// Whether the rows may miss a segment now: never built, other atoms, or atoms and segments
  /// that have moved, together, as far as the margin.
  template <class Segments>
  bool stale(const double* const* x, const int* mask, int groupbit, int nlocal,
             const Segments& segments) const {
    if (!built_ || nlocal != nlocal_ || segments.size() != ends0_.size()) return true;
    double segment_move2 = 0.0; // a rigid motion moves no point of a segment more than its ends
    for (std::size_t s = 0; s < segments.size(); ++s) {
      const auto& w = segments[s];
      const Ends& e = ends0_[s];
      segment_move2 = std::max({segment_move2, square(w.ax - e.ax) + square(w.ay - e.ay),
                                square(w.bx - e.bx) + square(w.by - e.by)});
    }
    double atom_move2 = 0.0;
    for (int i = 0; i < nlocal; ++i)
      if (mask[i] & groupbit)
        atom_move2 =
            std::max(atom_move2, square(x[i][0] - x0_[2 * static_cast<std::size_t>(i)]) +
                                     square(x[i][1] - x0_[2 * static_cast<std::size_t>(i) + 1]));
    return !(std::sqrt(atom_move2) + std::sqrt(segment_move2) < margin_);
  }

  void invalidate() { built_ = false; }
  /// Atom i's segments, ascending: [begin, end) of the row.
  const int* begin(int i) const { return segment_.data() + offset_[static_cast<std::size_t>(i)]; }
  const int* end(int i) const { return segment_.data() + offset_[static_cast<std::size_t>(i) + 1]; }

private:
  struct Ends {
    double ax, ay, bx, by;
  };
  static double square(double v) { return v * v; }

  std::vector<int> offset_;  ///< per atom: its row's start, then the end
  std::vector<int> segment_; ///< the rows, one after another
  std::vector<double> x0_;   ///< the atoms' positions at the build (x, y, ...)
  std::vector<Ends> ends0_;  ///< the segments' end points at the build
  double margin_ = 0.0;      ///< m
  int nlocal_ = 0;
  bool built_ = false;
};

} // namespace talus::lammps
