#pragma once
// Frost heave seen cycle by cycle (thesis sec. 5.2, figs. 5.12-5.14): the heights of the stones
// and of tracer fines just before each freeze, and how the stones rise.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace talus {

struct FrostCycles {
  double stone_radius = 0.0;         ///< m: grains at least this large are stones
  std::vector<std::uint32_t> stones; ///< ids, largest first
  std::vector<double> stone_size;    ///< radius of each stone, m
  std::vector<std::uint32_t> fines;  ///< tracer fines: spread evenly in depth at the start
  std::vector<double> time;          ///< s: the snapshot used for each cycle (0: the start)
  std::vector<double> bed_height;    ///< m
  std::vector<std::vector<double>> stone_height; ///< [cycle][stone], centre above the bed bottom
  std::vector<std::vector<double>> fine_height;  ///< [cycle][fine]
  /// (mean stone height - mean fine height) / bed height, per cycle
  std::vector<double> sorting_index;
  std::vector<double> rise_per_cycle; ///< per stone: least-squares slope of height, m per cycle
};

/// `freeze_times` from frost.csv; the frames in time order. Cycle 0 is the first frame, cycle c
/// the last frame before freeze c (snapshots at the freeze itself already show the heave).
FrostCycles frost_cycles(const std::vector<Frame>& frames, const std::vector<double>& freeze_times,
                         std::size_t tracer_fines = 8);

} // namespace talus
