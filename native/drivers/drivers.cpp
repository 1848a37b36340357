#include "drivers/drivers.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "drivers/cell.hpp"
#include "simulation/world.hpp"
#include "talus/error.hpp"
#include "talus/vibration.hpp"

namespace talus {

namespace {
// The width of the servo's walls across its direction: the span of their segments' end points
// and of their wall particles (each to its edge) on the perpendicular. A row of touching grains
// across a periodic box spans the box.
double width_across(const Servo& s, const DriverTargets& t, const Particles& p,
                    const Segments& walls) {
  const Vec2 side = across(s.direction);
  double lo = 0.0, hi = 0.0;
  bool first = true;
  const auto span = [&](double u_lo, double u_hi) {
    lo = first ? u_lo : std::min(lo, u_lo), hi = first ? u_hi : std::max(hi, u_hi), first = false;
  };
  for (const auto k : t.segments)
    for (const Vec2 end : {walls[k].a, walls[k].b}) span(dot(end, side), dot(end, side));
  for (const auto i : t.particles)
    span(dot(p.position[i], side) - p.radius[i], dot(p.position[i], side) + p.radius[i]);
  return hi - lo;
}

void attach_servo(Servo& s, const DriverTargets& t, const Particles& p, const Segments& walls) {
  const double l = norm(s.direction);
  require(l > 0.0, "servo driver: direction must be a non-zero vector");
  s.direction = s.direction / l;
  require(!t.segments.empty() || !t.particles.empty(),
          "servo driver: its group has no wall segment and no wall particle");
  for (const auto k : t.segments)
    require(k < walls.size(), "driver: segment index " + std::to_string(k) + " out of range");
  for (const auto i : t.particles)
    require(i < p.size(), "driver: particle index " + std::to_string(i) + " out of range");
  require(std::isfinite(s.slide_speed), "servo driver: slide_speed must be finite (m/s)");
  require(std::isfinite(s.max_speed) && s.max_speed > 0.0,
          "servo driver: max_speed must be > 0 m/s");
  require(s.relaxation > 0.0 && s.relaxation <= 1.0,
          "servo driver: relaxation must be in (0, 1] (the fraction of the load's error closed "
          "per step: above 1 the wall overshoots)");
  require(std::isfinite(s.force) && std::isfinite(s.stress) && s.stress >= 0.0,
          "servo driver: force (N) and stress (N/m) must be finite, stress >= 0");
  if (s.stress > 0.0) {
    const double width = width_across(s, t, p, walls);
    require(width > 0.0, "servo driver: stress needs walls with a width across direction "
                         "(these are parallel to it); give force instead");
    s.force = s.stress * width;
  }
  s.displacement = 0.0;
  s.speed = 0.0;
}
} // namespace

void attach(Driver& d, const World& w) {
  const Particles& p = w.particles;
  const Segments& walls = w.walls;
  if (auto* v = std::get_if<Vibrate>(&d.motion)) {
    const double l = norm(v->direction);
    require(l > 0.0, "vibrate driver: direction must be a non-zero vector");
    require(v->amplitude >= 0.0 && v->frequency >= 0.0,
            "vibrate driver: amplitude (m) and frequency (Hz) must be >= 0");
    v->direction = v->direction / l;
  }
  if (auto* s = std::get_if<Servo>(&d.motion)) attach_servo(*s, d.targets, p, walls);
  if (auto* c = std::get_if<Cell>(&d.motion)) {
    require(d.targets.particles.empty() && d.targets.segments.empty(),
            "cell driver: it moves the periodic box and every grain with it, not a target");
    attach_cell(*c, w.domain);
  }
  d.particle_origin.clear();
  d.angle_origin.clear();
  for (const auto i : d.targets.particles) {
    require(i < p.size(), "driver: particle index " + std::to_string(i) + " out of range");
    require(p.kind[i] == Kind::moved,
            "driver: particle " + std::to_string(i) + " must be of kind 'moved' to be driven");
    d.particle_origin.push_back(p.position[i]);
    d.angle_origin.push_back(p.angle[i]);
  }
  d.segment_origin.clear();
  for (const auto s : d.targets.segments) {
    require(s < walls.size(), "driver: segment index " + std::to_string(s) + " out of range");
    d.segment_origin.push_back(walls[s].a);
    d.segment_origin.push_back(walls[s].b);
  }
}

std::string attached_driver_problem(const Driver& d, const Particles& p, const Segments& walls) {
  for (const auto i : d.targets.particles)
    if (i >= p.size() || p.kind[i] != Kind::moved)
      return "driver: particle " + std::to_string(i) + " out of range or not of kind 'moved'";
  for (const auto s : d.targets.segments)
    if (s >= walls.size()) return "driver: segment " + std::to_string(s) + " out of range";
  if (d.particle_origin.size() != d.targets.particles.size() ||
      d.angle_origin.size() != d.targets.particles.size() ||
      d.segment_origin.size() != 2 * d.targets.segments.size())
    return "driver: not one origin per target";
  return "";
}

namespace {
struct Pose {
  Vec2 offset;        // translation (Vibrate, Translate)
  Vec2 velocity;      // translation velocity
  double angle = 0.0; // rotation angle (Rotate)
  double omega = 0.0; // rotation rate
  Vec2 centre;
};

Pose pose_at(const Motion& m, double t) {
  Pose pose;
  if (const auto* v = std::get_if<Vibrate>(&m)) {
    const VibrationState s = vibration_at(v->amplitude, v->frequency, v->phase, t);
    pose.offset = s.displacement * v->direction;
    pose.velocity = s.velocity * v->direction;
  } else if (const auto* tr = std::get_if<Translate>(&m)) {
    pose.offset = t * tr->velocity;
    pose.velocity = tr->velocity;
  } else if (const auto* servo = std::get_if<Servo>(&m)) {
    const Vec2 side = across(servo->direction);
    pose.offset = servo->displacement * servo->direction + (t * servo->slide_speed) * side;
    pose.velocity = servo->speed * servo->direction + servo->slide_speed * side;
  } else if (const auto* r = std::get_if<Rotate>(&m)) {
    pose.angle = r->angular_velocity * t;
    pose.omega = r->angular_velocity;
    pose.centre = r->centre;
  }
  return pose;
}

Vec2 place(const Pose& pose, Vec2 origin) {
  if (pose.omega == 0.0 && pose.angle == 0.0) return origin + pose.offset;
  const double c = std::cos(pose.angle), s = std::sin(pose.angle);
  const Vec2 d = origin - pose.centre;
  return pose.centre + Vec2{c * d.x - s * d.y, s * d.x + c * d.y};
}
} // namespace

void apply(const Driver& d, double t, Particles& p, Segments& walls) {
  const Pose pose = pose_at(d.motion, t - d.start_time);
  for (std::size_t k = 0; k < d.targets.particles.size(); ++k) {
    const auto i = d.targets.particles[k];
    p.position[i] = place(pose, d.particle_origin[k]);
    p.velocity[i] = pose.velocity + cross(pose.omega, p.position[i] - pose.centre);
    p.angle[i] = d.angle_origin[k] + pose.angle;
    p.angular_velocity[i] = pose.omega;
  }
  for (std::size_t k = 0; k < d.targets.segments.size(); ++k) {
    Segment& s = walls[d.targets.segments[k]];
    s.a = place(pose, d.segment_origin[2 * k]);
    s.b = place(pose, d.segment_origin[2 * k + 1]);
    s.velocity = pose.velocity;
    s.angular_velocity = pose.omega;
    s.pivot = pose.centre;
  }
}

} // namespace talus
