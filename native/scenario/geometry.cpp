#include "scenario/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scenario/file/toml_reader.hpp"

namespace talus {

namespace {

void need(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw ScenarioError("key 'geometry." + key + "': " + what);
}

void add(ContainerShape& c, const std::string& group, Vec2 a, Vec2 b) {
  c.groups[group].push_back({a, b});
  c.groups["walls"].push_back({a, b});
}

// Open or closed rectangle with the floor at y = 0 from x = 0 to width.
void rectangle(ContainerShape& c, double w, double h, bool lid) {
  add(c, "floor", {0.0, 0.0}, {w, 0.0});
  add(c, "left", {0.0, h}, {0.0, 0.0});
  add(c, "right", {w, 0.0}, {w, h});
  if (lid) add(c, "lid", {w, h}, {0.0, h});
  c.bounds = {{0.0, 0.0}, {w, h}};
}

// A funnel converging to an orifice centred at (w/2, 0): inclined walls up to the container's
// side, then vertical walls up to y = h. Returns the height of the inclined part.
double funnel(ContainerShape& c, double w, double h, double orifice, double angle_deg) {
  const double slope = std::tan(angle_deg * std::numbers::pi / 180.0);
  const double rise = 0.5 * (w - orifice) * slope;
  const double x0 = 0.5 * (w - orifice), x1 = 0.5 * (w + orifice);
  add(c, "left", {x0, 0.0}, {0.0, rise});
  add(c, "left", {0.0, rise}, {0.0, h});
  add(c, "right", {w, h}, {w, rise});
  add(c, "right", {w, rise}, {x1, 0.0});
  c.gate.push_back({{x0, 0.0}, {x1, 0.0}});
  return rise;
}

// A flat-bottomed silo: vertical walls, a floor with an orifice of width `orifice` centred at
// x = orifice_x, and a bin of the silo's width below it that catches what flows out. A floor
// piece is left out where the orifice meets a side wall.
void flat_silo(ContainerShape& c, const GeometrySection& g) {
  const double w = g.width, h = g.height;
  const auto [x0, x1] = orifice_span(g);
  need(x0 >= 0.0 && x1 <= w, g.orifice_x ? "orifice_x" : "orifice",
       "the orifice (" + std::to_string(x0) + " to " + std::to_string(x1) +
           " m) must lie within the floor, 0 to width = " + std::to_string(w) + " m");
  need(g.orifice < w, "orifice", "needs 0 < orifice < width");
  const double depth = g.bin_depth.value_or(h);
  need(depth > 0.0, "bin_depth", "needs bin_depth > 0 m");
  if (x0 > 0.0) add(c, "floor", {0.0, 0.0}, {x0, 0.0});
  if (x1 < w) add(c, "floor", {x1, 0.0}, {w, 0.0});
  add(c, "left", {0.0, h}, {0.0, 0.0});
  add(c, "right", {w, 0.0}, {w, h});
  add(c, "lower", {0.0, 0.0}, {0.0, -depth});
  add(c, "lower", {0.0, -depth}, {w, -depth});
  add(c, "lower", {w, -depth}, {w, 0.0});
  c.gate.push_back({{x0, 0.0}, {x1, 0.0}});
  c.fill = {{0.0, 0.0}, {w, h}};
  c.bounds = {{0.0, -depth}, {w, h}};
}

} // namespace

bool has_orifice(const GeometrySection& g) {
  return g.builder == "hopper" || g.builder == "hourglass" ||
         (g.builder == "silo" && g.orifice > 0.0);
}

std::pair<double, double> orifice_span(const GeometrySection& g) {
  const double centre = g.builder == "silo" ? g.orifice_x.value_or(0.5 * g.width) : 0.5 * g.width;
  return {centre - 0.5 * g.orifice, centre + 0.5 * g.orifice};
}

ContainerShape build_container(const GeometrySection& g) {
  ContainerShape c;
  const std::string& b = g.builder;
  if (b != "none" && b != "drum") {
    need(g.width > 0.0, "width", "builder '" + b + "' needs width > 0 m");
    need(g.height > 0.0, "height", "builder '" + b + "' needs height > 0 m");
  }
  const bool flat = b == "silo" && g.orifice > 0.0;
  need(flat || !g.orifice_x, "orifice_x",
       "applies only to a silo with an orifice (builder = \"silo\", orifice > 0)");
  need(flat || b == "hopper" || !g.bin_depth, "bin_depth",
       "applies only to a hopper or a silo with an orifice (builder = \"silo\", orifice > 0)");
  if (flat) {
    need(g.height > g.width, "height", "a silo is taller than wide");
    flat_silo(c, g);
  } else if (b == "box" || b == "silo" || b == "window_box" || b == "grain_press") {
    if (b == "silo") need(g.height > g.width, "height", "a silo is taller than wide");
    if (b == "window_box") need(g.width > g.height, "width", "a window box is wider than tall");
    rectangle(c, g.width, g.height, b == "box" || b == "grain_press");
    c.fill = {{0.0, 0.0}, {g.width, b == "grain_press" ? g.height : g.height}};
    if (b == "grain_press") {
      DriverSection d;
      d.type = "translate";
      d.target = "lid";
      d.velocity = {0.0, -g.lid_speed};
      c.drivers.push_back(d);
    }
  } else if (b == "hopper" || b == "hourglass") {
    need(g.orifice > 0.0 && g.orifice < g.width, "orifice", "needs 0 < orifice < width");
    const double rise = funnel(c, g.width, g.height, g.orifice, g.wall_angle);
    need(rise < g.height, "height", "must exceed the funnel's rise " + std::to_string(rise) + " m");
    const double depth = b == "hourglass" ? g.height : g.bin_depth.value_or(0.5 * g.height);
    need(depth > 0.0, "bin_depth", "needs bin_depth > 0 m");
    if (b == "hourglass") { // the lower bulb: the funnel mirrored below the orifice
      const double x0 = 0.5 * (g.width - g.orifice), x1 = 0.5 * (g.width + g.orifice);
      add(c, "lower", {0.0, -rise}, {x0, 0.0});
      add(c, "lower", {x1, 0.0}, {g.width, -rise});
      add(c, "lower", {0.0, -depth}, {0.0, -rise});
      add(c, "lower", {g.width, -rise}, {g.width, -depth});
    } else { // a bin below the hopper catches what flows out
      add(c, "lower", {0.0, -depth}, {0.0, 0.0});
      add(c, "lower", {g.width, 0.0}, {g.width, -depth});
    }
    add(c, "floor", {0.0, -depth}, {g.width, -depth});
    c.fill = {{0.0, rise}, {g.width, g.height}};
    c.bounds = {{0.0, -depth}, {g.width, g.height}};
  } else if (b == "drum") {
    need(g.radius > 0.0, "radius", "the drum needs radius > 0 m");
    const int sides = 72;
    const Vec2 centre{g.radius, g.radius};
    for (int k = 0; k < sides; ++k) {
      const double a0 = 2.0 * std::numbers::pi * k / sides,
                   a1 = 2.0 * std::numbers::pi * (k + 1) / sides;
      add(c, "drum", centre + g.radius * Vec2{std::cos(a0), std::sin(a0)},
          centre + g.radius * Vec2{std::cos(a1), std::sin(a1)});
    }
    const double h = g.radius / std::sqrt(2.0);
    c.fill = {centre - Vec2{h, h}, centre + Vec2{h, h}};
    c.bounds = {{0.0, 0.0}, {2.0 * g.radius, 2.0 * g.radius}};
    DriverSection d;
    d.type = "rotate";
    d.target = "drum";
    d.centre = centre;
    d.angular_velocity = g.angular_velocity;
    if (g.angular_velocity != 0.0) c.drivers.push_back(d);
  } else {
    c.fill = g.box.value_or(Rect{});
    c.bounds = c.fill;
  }
  for (const SegmentSpec& s : g.segments) {
    add(c, s.group, s.a, s.b);
    // the extra walls are part of the container: a grain on them has not escaped it
    if (c.bounds.hi.x > c.bounds.lo.x && c.bounds.hi.y > c.bounds.lo.y)
      for (const Vec2 end : {s.a, s.b}) {
        c.bounds.lo = {std::min(c.bounds.lo.x, end.x), std::min(c.bounds.lo.y, end.y)};
        c.bounds.hi = {std::max(c.bounds.hi.x, end.x), std::max(c.bounds.hi.y, end.y)};
      }
  }
  if (g.gate) { // the gate stays, as walls of its own, instead of closing the orifice for the
                // packing
    need(!c.gate.empty(), "gate",
         "applies only to a container with an orifice (a silo with orifice > 0, a hopper, an "
         "hourglass)");
    for (const SegmentSpec& s : c.gate) add(c, "gate", s.a, s.b);
    c.gate.clear();
  }
  return c;
}

} // namespace talus
