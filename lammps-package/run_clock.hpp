#pragma once
// The simulation time of a fix that must carry it across a restart file. LAMMPS (29 Sep 2021)
// counts time as atime + (ntimestep - atimestep) dt; after read_restart it has atime 0 and moves
// atimestep to the restart's step only when the next run begins, so the time read when a fix is
// defined again is not the time of that run. The clock takes the restart's time up at the run's
// setup instead, when LAMMPS' own count has settled.
#include "update.h"

namespace talus::lammps {

class RunClock {
public:
  /// s: the time now, as it was in the run that wrote the restart file.
  double now(const LAMMPS_NS::Update& u) const {
    if (resumed_) return resumed_at_; // no run since read_restart: time has not moved
    return offset_ + u.atime + static_cast<double>(u.ntimestep - u.atimestep) * u.dt;
  }
  /// From a fix's restart(): the time the restart file was written at.
  void resume(double t) {
    resumed_ = true;
    resumed_at_ = t;
  }
  /// From a fix's setup(), before it looks at the time.
  void setup(const LAMMPS_NS::Update& u) {
    if (!resumed_) return;
    resumed_ = false;
    offset_ = 0.0;
    offset_ = resumed_at_ - now(u);
  }

private:
  double offset_ = 0.0; ///< s: added to LAMMPS' time
  bool resumed_ = false;
  double resumed_at_ = 0.0;
};

} // namespace talus::lammps
