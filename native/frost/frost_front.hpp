#pragma once
// A freezing-front model of frost heave in 2D (docs/model.md, "Frost heave: the front model";
// after Kessler and Werner 2003, Washburn's frost push and frost pull, and Stefan's law).
//
// The bed is cut into vertical columns about a stone wide. A freeze-thaw cycle:
//  1. Freeze: a front descends from each column's surface; the time it takes to reach a depth
//     follows a layered Stefan estimate from the column's make-up, so it runs ahead beneath
//     stones, which conduct heat better and hold no water (frost push). It stops at the
//     permafrost depth. With conductivity_ratio = stone_water = 1 stones are thermally like
//     the soil and the front is level: frost pull alone.
//  2. Grains above the front are frozen: held in place, moving only with their column's heave;
//     free grains still feel them. A fine freezes when its centre is above the front, a stone
//     when its top is (the frozen layer grips it).
//  3. Fines crossing the front add heave: heave strain x front step x the fine share of what
//     was crossed. The stiff crust rides on its highest lens within the crust length, so a
//     stone narrower than that is lifted by the fines beside it. A frozen grain moves up by the
//     heave at its x (linear between column centres), or more if a grain it rests on does.
//  4. Thaw: a thaw front descends from the heaved surface to the bottom of the frozen layer;
//     a fine is released when its centre has thawed, a stone only when the ice under it has:
//     the cavity the heave opened beneath a gripped stone holds segregation ice, pure ice that
//     takes 1 / ice_content times the latent heat of as much frozen soil, so the thaw front
//     (in soil-equivalent depth) must go that much further below the cavity's floor, past the
//     frozen layer if need be (frost pull: thawed fines slump into the cavity first); frozen
//     fines under the cavity thaw as much later. ice_content defaults to the fines' measured
//     pore fraction (saturated). Released grains settle under gravity; thawed fines may take
//     a weaker material (wet, thaw-weakened soil) until the next freeze.
// The engine does the rest: frozen grains are held particles (Simulation::hold).
#include <cstdint>
#include <string>
#include <vector>

#include "simulation/simulation.hpp"

namespace talus {

struct FrostFrontParameters {
  double permafrost_depth = 0.0;   ///< m below the surface: nothing deeper freezes
  double heave_strain = 0.1;       ///< heave per unit depth of frozen fines
  double conductivity_ratio = 3.0; ///< stone / soil thermal conductivity (1: no contrast)
  double stone_water = 0.0;        ///< stone / soil latent heat per volume (0: dry stones)
  double crust_length = 0.0;       ///< m: the crust rides on its highest lens this far away
  double column_width = 0.0;       ///< m
  double stone_radius = 0.0;       ///< m: grains this large or larger are stones
  double freeze_time = 1.0;        ///< s: the front's descent to permafrost in pure fines
  double thaw_time = 1.0;          ///< s: the thaw front's descent through the frozen layer
  bool frost_pull = true;          ///< stones thaw out by the ice under them (else their centre)
  /// Ice per volume of frozen fines (saturated: their pore fraction). 0: the fines' pore
  /// fraction in the bed, measured at each freeze's start.
  double ice_content = 0.0;
  int thawed_material = -1;        ///< fines take this material when thawed (-1: unchanged)
  double x_min = 0.0, x_max = 0.0; ///< m: the bed's horizontal extent
};

/// Throws InvalidArgument naming the parameter and its allowed values.
void check(const FrostFrontParameters& p);

class FrostFront {
public:
  enum class Phase : int { idle = 0, freezing = 1, thawing = 2 };

  explicit FrostFront(FrostFrontParameters p);

  /// Starts a freeze at time t: surfaces and the columns' Stefan tables from the grains now.
  void start_freeze(Simulation& sim);
  /// Advances the phase to time sim.time(): freezes, heaves or releases grains. Returns true
  /// when the phase has just ended (the freeze moves on to the thaw by itself; the thaw ends
  /// idle with every grain free).
  bool advance(Simulation& sim);

  Phase phase() const { return phase_; }
  std::size_t columns() const { return surface_.size(); }
  /// The column x lies in (x_min and beyond it: the first; x_max and beyond: the last).
  std::size_t column_of(double x) const;
  /// The freezing front's depth below each column's surface, m.
  const std::vector<double>& front_depth() const { return front_; }
  /// Heave so far this cycle, per column, m.
  const std::vector<double>& heave() const { return heave_; }
  /// Ice per volume of frozen fines this freeze (the parameter, or the measured pore fraction).
  double ice_content() const { return ice_content_; }
  const FrostFrontParameters& parameters() const { return p_; }

  /// The model's state as numbers, for a checkpoint, and back.
  std::vector<double> save() const;
  void load(const std::vector<double>& numbers, std::size_t particles);

private:
  bool is_stone(const Particles& p, std::size_t i) const;
  /// A per-column quantity at x: linear between the columns' centres, flat beyond the outer ones.
  double heave_at(const std::vector<double>& per_column, double x) const;
  /// Raises each grain's lift `up` to that of any grain it rests on (frozen or free; touching
  /// from above), from the bottom up.
  void lift_resting_grains(const Particles& p, std::vector<double>& up) const;
  double front_at(std::size_t c, double target) const;
  void start_thaw(Simulation& sim);
  /// At the freeze's start: each column's surface (surface_) and the slices' thickness.
  void find_surface(const Particles& p);
  /// Per column and slice below the surface, the area of stones and of fines in it.
  void slice_areas(const Particles& p, std::vector<std::vector<double>>& stone,
                   std::vector<std::vector<double>>& fine) const;
  /// The ice per volume of frozen fines when the scenario gives none: saturated, their pore
  /// fraction, measured from the band between a fine diameter below the surface (rough) and the
  /// permafrost depth, across the grains' width, in the slices that hold grains (not below the
  /// floor).
  double pore_fraction(const Particles& p, const std::vector<std::vector<double>>& stone,
                       const std::vector<std::vector<double>>& fine) const;
  /// The front's time to each slice (time_) and the slices' fine shares (fines_).
  void stefan_tables(const std::vector<std::vector<double>>& stone,
                     const std::vector<std::vector<double>>& fine);
  /// The front moved on to `target` (units of D^2/2); returns each column's heave from the
  /// fines it crossed.
  std::vector<double> descend_front(double target);
  /// A freezing call: the front to `target`, the grains it passed held, the frozen ones lifted.
  void freeze(Simulation& sim, double target);
  /// A thawing call at u = elapsed / thaw_time: thawed grains freed; true once all are.
  bool thaw(Simulation& sim, double u);

  FrostFrontParameters p_;
  Phase phase_ = Phase::idle;
  double phase_start_ = 0.0;
  double dz_ = 0.0;                        ///< slice thickness of the Stefan tables
  std::vector<double> surface_;            ///< per column, y at the freeze's start
  std::vector<double> front_;              ///< per column, depth below surface_
  std::vector<double> heave_;              ///< per column, this cycle's heave
  std::vector<std::vector<double>> time_;  ///< per column: time (units of D^2/2) to each slice
  std::vector<std::vector<double>> fines_; ///< per column: fine share of each slice
  std::vector<std::uint8_t> frozen_;       ///< per particle: held by the frost
  std::vector<double> material_;           ///< per particle: its material before the thaw
  std::vector<double> release_level_;      ///< per particle: thaw front y a stone thaws out at
  std::vector<double> thaw_delay_;         ///< per particle: soil-equivalent depth of cavity ice
                                           ///< above a frozen fine (in a stone's shadow), m
  double ice_content_ = 1.0;               ///< this freeze's ice per volume of frozen fines
};

} // namespace talus
