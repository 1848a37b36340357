#pragma once
// One moment of a 3D run as plain arrays, from a running Simulation3 or read back from its
// snapshot files (io/vtp_reader.hpp): what the analyses of 3D runs are computed from. The names
// are 2D's Frame's (analysis/frame.hpp), so that what is written once for both reads either.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "engine3d/simulation3.hpp"

namespace talus {

struct Frame3 {
  double time = 0.0;
  std::vector<std::uint32_t> id; ///< the spheres' ids (stable over a run)
  std::vector<Vec3> position;    ///< m: as the engine holds it (a sphere may have crossed a
                                 ///< periodic side since the list's last build)
  std::vector<double> radius;
  std::vector<Vec3> velocity;
  std::vector<std::uint8_t> kind; ///< 0 free, 1 fixed
  std::vector<double> mass;       ///< kg
  Vec3 box_lo, box_hi;            ///< m: the box then (a cell strains it)
  std::array<bool, 3> periodic{false, false, false};
  double shear_velocity = 0.0; ///< m/s: the x velocity of the image above across y (Lees-Edwards)
  /// A touching contact: the centres (or the centre and the plate's point), the normal force (N),
  /// the force on the sphere at `from`, the contact point, and whether each end is a free sphere.
  struct Chain {
    Vec3 from;
    Vec3 to;
    double force = 0.0;
    Vec3 force_on_from{};
    Vec3 point{};
    bool from_free = true;
    bool to_free = false;
    bool has_vector = true;
  };
  std::vector<Chain> chains;
};

/// The state of a simulation, its contacts with their forces included.
Frame3 frame3_of(const Simulation3& sim);

} // namespace talus
