#pragma once
// Prescribed motion of wall particles (kind `moved`) and segment walls. A driver remembers where
// its targets were when the run started and sets their position and velocity at any time t.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/vec2.hpp"
#include "drivers/cell_of.hpp"
#include "state/particles.hpp"
#include "state/walls.hpp"

namespace talus {

/// What a driver moves: particle indices (must be of kind `moved`) and segment indices.
struct DriverTargets {
  std::vector<std::uint32_t> particles;
  std::vector<std::uint32_t> segments;
};

/// Sinusoidal vibration: displacement = amplitude sin(2 pi frequency t + phase) along direction.
struct Vibrate {
  Vec2 direction{0.0, 1.0}; ///< normalised on attach
  double amplitude = 0.0;   ///< m
  double frequency = 0.0;   ///< Hz
  double phase = 0.0;       ///< rad
};

/// Constant velocity (the thesis' grain press): displacement = velocity t.
struct Translate {
  Vec2 velocity{}; ///< m/s
};

/// Rotation about a fixed centre at a constant rate (a rotating drum).
struct Rotate {
  Vec2 centre{};
  double angular_velocity = 0.0; ///< rad/s, counter-clockwise positive
};

/// A wall held at a target load by a servo controller (docs/model.md, "Servo walls"): after each
/// step the wall takes the speed along `direction` that would close the fraction `relaxation` of
/// the load's error in the next step if the grains stood still, given the stiffness and the
/// damping of the wall's contacts (servo.hpp). Drives wall segments or wall particles (of kind
/// `moved`), and may slide them across its direction at a set speed (a shear cell's plate).
struct Servo {
  Vec2 direction{0.0,
                 -1.0};    ///< the way the wall moves to press on the grains; normalised on attach
  double force = 0.0;      ///< N: the load wanted (stress times the wall's width, on attach)
  double stress = 0.0;     ///< N/m: the load per width of the wall across direction, or 0
  double max_speed = 0.0;  ///< m/s: the fastest the wall moves, either way
  double relaxation = 0.5; ///< the fraction of the error closed per step, in (0, 1]
  double displacement = 0.0; ///< m along direction since start_time (the controller's state)
  double speed = 0.0;        ///< m/s along direction, chosen after the last step
  /// m/s: the walls also move at this speed along `across(direction)`, a quarter turn
  /// anticlockwise from direction ([1, 0] for a lid pressing down)
  double slide_speed = 0.0;
};

/// The way a servo's walls slide: its direction turned a quarter turn anticlockwise.
inline Vec2 across(Vec2 direction) {
  return {-direction.y, direction.x};
}

using Cell = CellOf<Vec2>;

using Motion = std::variant<Vibrate, Translate, Rotate, Servo, Cell>;

struct Driver {
  Motion motion;
  DriverTargets targets;
  /// s: when the motion started, the time its origins were captured at (0 for a run's drivers;
  /// a driver changed during a run starts again from where its targets are then)
  double start_time = 0.0;
  // captured at attach: reference positions and angles of the targets at start_time
  std::vector<Vec2> particle_origin;
  std::vector<double> angle_origin;
  std::vector<Vec2> segment_origin; ///< a, b, a, b, ...
};

struct World;

/// Checks the motion and the targets in the world `w` and records the targets' reference
/// positions (the time origin, start_time); a servo starts at rest where its walls are, a cell
/// at rest as it is.
void attach(Driver& d, const World& w);
/// For a driver read back from a checkpoint (attached when it was saved): what does not fit the
/// particles and walls, in words, or "" (its targets in range, a particle target of kind moved,
/// an origin for each).
std::string attached_driver_problem(const Driver& d, const Particles& p, const Segments& walls);
/// Sets positions and velocities of the targets at time t (t - start_time into the motion).
void apply(const Driver& d, double t, Particles& p, Segments& walls);

} // namespace talus
