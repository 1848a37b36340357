// A [[drivers]] entry's keys (docs/scenarios.md, "[[drivers]]"): each type's own, and the others
// refused with the type that has them.
#include "scenario/file/driver_keys.hpp"

#include <limits>
#include <string>

namespace talus {

namespace {

using keys::inf;

// A servo's keys (docs/scenarios.md): one target, force or stress, and a direction given.
void read_servo(TableReader& r, DriverSection& d, double impact_speed) {
  d.force = r.number("force", 0.0, -inf, inf, "N");
  d.stress = r.number("stress", 0.0, 0.0, inf, ">= 0 N/m");
  d.max_speed = r.number("max_speed", impact_speed, 1e-12, inf, "> 0 m/s");
  d.relaxation = r.number("relaxation", d.relaxation, 1e-9, 1.0, "in (0, 1]");
  d.slide_speed = r.number("slide_speed", 0.0, -inf, inf, "a finite speed in m/s");
  if (d.type != "servo") {
    for (const char* key : {"force", "stress", "max_speed", "slide_speed"})
      if (r.has(key)) r.fail(key, "only a servo driver has it (this one is " + d.type + ")");
    if (d.type != "cell" && r.has("relaxation"))
      r.fail("relaxation", "only a servo or cell driver has it (this one is " + d.type + ")");
    return;
  }
  if (r.has("force") == r.has("stress"))
    r.fail("force", "a servo needs one target: force (N) or stress (N/m), not both");
  if (!r.has("direction"))
    r.fail("direction", "a servo needs it: the way its walls move to press on the grains, "
                        "[0, -1] for a lid");
}

// A cell's keys (docs/scenarios.md): a strain rate, or a pressure with its fastest rate; no
// target (it moves the periodic box).
void read_cell(TableReader& r, DriverSection& d) {
  d.strain_rate = r.vec2("strain_rate", d.strain_rate);
  d.pressure = r.number("pressure", 0.0, 1e-300, inf, "> 0 N/m");
  d.max_strain_rate = r.number("max_strain_rate", 0.0, 1e-300, inf, "> 0 1/s");
  d.shear_rate = r.number("shear_rate", 0.0, -inf, inf, "1/s");
  if (d.type != "cell") {
    for (const char* key : {"strain_rate", "pressure", "max_strain_rate", "shear_rate"})
      if (r.has(key)) r.fail(key, "only a cell driver has it (this one is " + d.type + ")");
    return;
  }
  d.target = "";
  if (r.has("target"))
    r.fail("target", "a cell driver moves the periodic box and every grain with it: no target");
  if (r.has("strain_rate") && r.has("pressure"))
    r.fail("strain_rate", "a cell takes strain_rate = [x, y] (1/s) or pressure (N/m), not both");
  if (!r.has("strain_rate") && !r.has("pressure") && !r.has("shear_rate"))
    r.fail("strain_rate", "a cell needs strain_rate = [x, y] (1/s), pressure (N/m) or "
                          "shear_rate (1/s)");
  if (r.has("shear_rate") && d.strain_rate.x != 0.0)
    r.fail("strain_rate", "a sheared cell keeps its width: strain_rate = [0, y]");
  if (r.has("pressure") && !r.has("max_strain_rate"))
    r.fail("max_strain_rate", "a cell held at a pressure needs it: its fastest strain rate, 1/s "
                              "(slow enough for the grains to follow: a quasi-static compression)");
  if (!r.has("pressure") && r.has("max_strain_rate"))
    r.fail("max_strain_rate", "only a cell held at a pressure has it");
}

} // namespace

DriverSection read_driver(TableReader& r, double impact_speed) {
  DriverSection d;
  d.type = r.choice("type", "", {"vibrate", "translate", "rotate", "servo", "cell"});
  d.target = r.text("target", d.target);
  d.amplitude = r.number("amplitude", 0.0, 0.0, inf, ">= 0 m");
  d.frequency = r.number("frequency", 0.0, 0.0, inf, ">= 0 Hz");
  d.phase = r.number("phase", 0.0, -inf, inf, "rad");
  d.direction = r.vec2("direction", d.direction);
  d.velocity = r.vec2("velocity", d.velocity);
  d.centre = r.vec2("centre", d.centre);
  d.angular_velocity = r.number("angular_velocity", 0.0, -inf, inf, "rad/s");
  read_servo(r, d, impact_speed);
  read_cell(r, d);
  return d;
}

} // namespace talus
