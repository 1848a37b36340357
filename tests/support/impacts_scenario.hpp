#pragma once
// Two impacts in one scenario, for the tests of what a run records of its contacts: disks 0 and
// 1 meet head-on at `speed` each; disk 2, far from them, falls at 2 `speed` onto a rigid floor
// segment. Both gaps are 1 mm: both impacts begin at 5 ms. No gravity, no friction: every impact
// is at the speed it is given. The timestep is t_c / 500 of the pair (the wall contact's is
// shorter by 2^(1/5) at most). `output` is the [output] section's extra lines.
#include <string>

#include <fmt/format.h>

#include "scenario/file/load.hpp"

namespace talus::testing {

inline Scenario two_impacts(const std::string& law, double restitution, double speed,
                            const std::string& integrator, const std::string& output) {
  const std::string text = fmt::format(R"(name = "impacts"
[simulation]
duration = 0.02
timestep = "auto"
timestep_factor = 500
integrator = "{0}"
normal_law = "{1}"
tangential_law = "coulomb"
gravity = [0.0, 0.0]
impact_speed = {2}
[[materials]]
name = "grain"
density = 2650.0
young = 5.0e7
normal_stiffness = 2.0e5
restitution = {3}
friction = 0.0
[[materials]]
name = "floor"
rigid = true
restitution = {3}
[particles]
shape = "disk"
[[particles.list]]
position = [-0.0055, 0.0]
radius = 0.005
velocity = [{4}, 0.0]
[[particles.list]]
position = [0.0055, 0.0]
radius = 0.005
velocity = [-{4}, 0.0]
[[particles.list]]
position = [0.1, 0.006]
radius = 0.005
velocity = [0.0, -{2}]
[geometry]
wall_material = "floor"
[[geometry.segments]]
a = [0.05, 0.0]
b = [0.15, 0.0]
[output]
picture = false
{5}
)",
                                       integrator, law, 2.0 * speed, restitution, speed, output);
  return load_scenario(text, "impacts.toml");
}

} // namespace talus::testing
