#pragma once
// What the force stage does to a particle as soon as its force is complete (the rows after it
// never name it again): nothing, velocity Verlet's correction, or that and the next step's
// prediction. Each policy's range(first, last) handles the particles [first, last) and reports
// whether they stayed finite and the largest squared displacement.
#include <algorithm>
#include <cstddef>

#include "core/lanes.hpp"
#include "integrate/integrator.hpp"
#include "state/particles.hpp"

namespace talus {

// The loops are not inlined into the stage: its own loops are compiled worse with them
// (docs/performance.md, "Fused passes").
// nothing more: the correction comes after the stage (Gear)
struct NothingMore {
  PassReport range(std::size_t, std::size_t) const { return {}; }
};
// velocity Verlet's correction (single steps); without Rotation the angular velocities are left
// as they are (step_features.hpp)
template <bool Rotation> struct VerletCorrect {
  Particles& p;
  double half, lag;
  [[gnu::noinline]] PassReport range(std::size_t first, std::size_t last) const {
    const double h = half, c = lag; // locals: the stores below could otherwise change the members
    bool finite = true;
    for (std::size_t k = first; k < last; ++k)
      finite = verlet_correct_one<Rotation>(p, k, h, c) && finite;
    return {finite, 0.0};
  }
};
// velocity Verlet's correction and the next step's prediction (Simulation::run): no later row
// names these particles, so nothing in this force stage reads them any more. It also starts the
// next step's forces (start_forces) in force_previous and torque_previous, which the swap after
// this stage makes the next step's force and torque: their lines were just read, so the next
// force stage needs no pass of its own to set them (a pass that waited on memory in large
// systems). Rotation and Gravity: as in start_forces.
template <bool Rotation, bool Gravity> struct VerletCorrectPredict {
  Particles& p;
  double dt, half, lag;
  Vec2 gravity;
  [[gnu::noinline]] PassReport range(std::size_t first, std::size_t last) const {
    const double step = dt, h = half, c = lag;
    const Vec2 g = gravity;
    // two particles at a time, one per lane
    LaneMask finite_lanes = {-1, -1};
    Lanes far{0.0, 0.0};
    std::size_t k = first;
    for (; k + 1 < last; k += 2) {
      const Lanes d2 = verlet_correct_predict_two<Rotation>(p, k, step, h, c, finite_lanes);
      far = select(d2 > far, d2, far);
      start_forces<Gravity, Rotation>(p, k, g, p.force_previous.data(), p.torque_previous.data());
      start_forces<Gravity, Rotation>(p, k + 1, g, p.force_previous.data(),
                                      p.torque_previous.data());
    }
    bool finite = finite_lanes[0] != 0 && finite_lanes[1] != 0;
    double farthest2 = std::max(far[0], far[1]);
    for (; k < last; ++k) {
      finite = verlet_correct_one<Rotation>(p, k, h, c) && finite;
      farthest2 = std::max(farthest2, verlet_predict_one<Rotation>(p, k, step, h, c));
      start_forces<Gravity, Rotation>(p, k, g, p.force_previous.data(), p.torque_previous.data());
    }
    return {finite, farthest2};
  }
};

} // namespace talus
