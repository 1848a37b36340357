#pragma once
// A frictionless bed of 120 grains settled in a box 0.06 m wide and 0.12 m high with smooth
// walls, floor at y = 0: a static packing whose stress the stress tests check against its weight.

namespace talus::testing {

inline constexpr const char* smooth_bed = R"(
name = "bed"
[[materials]]
name = "smooth"
friction = 0.0
[particles]
count = 120
material = "smooth"
size = { distribution = "uniform", mean_radius = 0.003, spread = 0.0005 }
[packing]
method = "sedimentation"
settle_energy = 1e-9
settle_max_time = 3.0
[geometry]
builder = "box"
width = 0.06
height = 0.12
wall_material = "smooth"
)";

} // namespace talus::testing
