#pragma once
// Frost heave seen cycle by cycle (thesis sec. 5.2, figs. 5.12-5.14): the heights of the stones
// and of tracer fines just before each freeze, and how the stones rise.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/frame.hpp"

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
  std::vector<double> start_depth;    ///< per stone: its top below the bed's top at the start, m
  /// Share of the bed's width covered by stones at the surface (their top within two median
  /// fine diameters of the bed's top), per cycle
  std::vector<double> surface_cover;
};

/// `freeze_times` from frost.csv (the freezes, then the run's end if it logged one); the frames
/// in time order. Sample c is the last frame before time c: the bed at rest after c cycles
/// (a snapshot at the freeze itself may already show the heave). No times: the first frame.
FrostCycles frost_cycles(const std::vector<Frame>& frames, const std::vector<double>& freeze_times,
                         std::size_t tracer_fines = 8);

} // namespace talus
