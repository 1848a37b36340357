#pragma once
// What a scene uses, so that a step pays only for that (Simulation chooses the step once per run
// and again whenever the scene changes): the features found in the world and its laws, and the
// compile-time shape of the step built for them. A shape leaves out, with no branch in the hot
// loops: the tangential history (a law without one keeps no springs, clears none and carries
// none across list builds), rotation (frictionless grains that do not turn never will: no torque
// is summed and no angle integrated), the pair-table look-up (one material), gravity and the
// wall contacts.
#include <cstdint>
#include <string>
#include <utility>

#include "simulation/rolling_pass.hpp"
#include "simulation/world.hpp"
#include "talus/law_table.hpp"

namespace talus {

/// The features a scene uses. Each one false lets the step leave something out.
struct StepFeatures {
  bool friction = true;      ///< a tangential law other than `none`
  bool history = true;       ///< the tangential law keeps a spring per contact
  bool rotation = true;      ///< something can turn: friction, or a free grain turning already
  bool walls = true;         ///< wall segments
  bool driven = true;        ///< drivers
  bool one_material = false; ///< every particle and segment is of one material: `material`
  std::uint16_t material = 0;
  bool gravity = true;
  /// rolling resistance (simulation/rolling_pass.hpp): a pass after the force stage, not a
  /// shape of it; its steps are not fused
  bool rolling = false;
  friend bool operator==(const StepFeatures&, const StepFeatures&) = default;
};

/// The features of the world with that tangential law. Frictionless grains that turn already get
/// the general step's features (no step is specialised to them), but for walls and drivers.
StepFeatures scene_features(const World& world, TangentialLaw tangential);
/// Every feature on: the general step, which does everything whatever the scene; rolling
/// resistance, which is not a shape of the step, as the world has it.
inline StepFeatures general_features(const World& world) {
  StepFeatures f;
  f.rolling = has_rolling_resistance(world);
  return f;
}
/// What the step leaves out, for run.json and a run's opening lines: "frictionless, history-free,
/// no rotation, no walls, no drivers, one material, no gravity" (those that apply), or "general"
/// for a step that leaves nothing out; then "with rolling resistance" if it has that pass.
std::string describe(const StepFeatures& f);

/// The compile-time shape of a step (what its loops do): one material, rotation, gravity and
/// history each on or off.
template <bool OneMaterial, bool Rotation, bool Gravity, bool History> struct StepShape {
  static constexpr bool one_material = OneMaterial;
  static constexpr bool rotation = Rotation;
  static constexpr bool gravity = Gravity;
  static constexpr bool history = History;
};
using GeneralShape = StepShape<false, true, true, true>;

/// Calls f.template operator()<S>() with the shape of `features` for the tangential law T. Only
/// the shapes a law can have are compiled: the general one, and the specialised ones in which
/// rotation follows from friction and history from the law (a frictionless scene whose grains
/// turn already, which seldom happens, takes the general step). `with_gravity` false compiles
/// the shapes with gravity only, for the passes that never add the weight.
template <class T, bool with_gravity = true, class F>
decltype(auto) with_step_shape(const StepFeatures& features, F&& f) {
  constexpr bool friction = T::has_friction;
  const bool special = features.friction == friction && features.history == T::has_history &&
                       features.rotation == friction;
  const auto with_material = [&]<bool G>() -> decltype(auto) {
    if (features.one_material)
      return f.template operator()<StepShape<true, friction, G, T::has_history>>();
    return f.template operator()<StepShape<false, friction, G, T::has_history>>();
  };
  if (!special) return f.template operator()<GeneralShape>();
  if constexpr (with_gravity)
    if (!features.gravity) return with_material.template operator()<false>();
  return with_material.template operator()<true>();
}

} // namespace talus
