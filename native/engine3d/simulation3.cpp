#include "engine3d/simulation3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include <omp.h>

#include "core/capacity_bytes.hpp"
#include "engine3d/cell3.hpp"
#include "engine3d/contact_visit3.hpp"
#include "engine3d/renumber3.hpp"
#include "talus/error.hpp"
#include "talus/law_table.hpp"

namespace talus {

namespace {

void validate(const Scene3& scene, const Settings3& settings) {
  require(settings.timestep > 0.0 && std::isfinite(settings.timestep),
          "simulation.timestep must be finite and > 0 s");
  require(settings.skin >= 0.0 && std::isfinite(settings.skin),
          "simulation.skin must be finite and >= 0 m");
  require(!scene.materials.empty(), "at least one material is needed");
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& material = scene.materials[m];
    const std::string problem = material_error(settings.normal_law, settings.tangential_law,
                                               material, settings.linear_damping);
    require(problem.empty(), "material " + std::to_string(m) + ": " + problem);
  }
  const auto known = [&](std::uint16_t m) { return m < scene.materials.size(); };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i)
    require(known(scene.spheres.material[i]), "sphere " + std::to_string(i) + " has material " +
                                                  std::to_string(scene.spheres.material[i]) +
                                                  ", which is not defined");
  for (std::size_t w = 0; w < scene.plates.size(); ++w)
    require(known(scene.plates[w].material), "plate " + std::to_string(w) + " has material " +
                                                 std::to_string(scene.plates[w].material) +
                                                 ", which is not defined");
  validate(scene.drivers, scene.plates.size());
  validate(scene.servos, scene.drivers, scene.plates.size());
  const Domain3& d = scene.domain;
  require(d.lo.x < d.hi.x && d.lo.y < d.hi.y && d.lo.z < d.hi.z,
          "the domain needs lo < hi along every axis");
  require(std::isfinite(d.shear_offset) && std::isfinite(d.shear_velocity),
          "the domain's Lees-Edwards offset and slide must be finite");
  require(!d.sheared() || (d.periodic[0] && d.periodic[1]),
          "Lees-Edwards images need a box periodic in x and y");
  if (scene.cell) validate(*scene.cell, d, scene.plates.size());
}

// Whether some material rolls with resistance (a pair rolls with it if either material does:
// the mixed mu_r is the mean of the two).
bool rolls_with_resistance(const std::vector<Material>& materials) {
  return std::ranges::any_of(materials, [](const Material& m) { return m.rolling_friction > 0.0; });
}

double resolved_skin(const Scene3& scene, const Settings3& settings) {
  return settings.skin > 0.0 ? settings.skin : 0.5 * scene.spheres.max_radius();
}

} // namespace

bool turns_spheres(const Scene3& scene, const Settings3& settings) {
  const bool friction = has_friction(settings.tangential_law);
  const bool rolling = rolls_with_resistance(scene.materials);
  const Spheres& s = scene.spheres;
  bool spinning = false;
  for (std::size_t i = 0; i < s.size() && !spinning; ++i)
    spinning = s.is_free(i) && norm2(s.angular_velocity[i]) != 0.0;
  return friction || rolling || spinning;
}

Simulation3::Simulation3(Scene3 scene, Settings3 settings)
    : scene_(std::move(scene)), settings_(settings) {
  set_up();
  for (const Plane& p : scene_.plates) start_.push_back({p.centre, p.normal, p.axis_u});
  drive_plates(scene_.plates, scene_.drivers, start_, 0.0);
  place_servo_plates(scene_.plates, scene_.servos, start_);
  if (scene_.cell) {
    attach_cell(*scene_.cell, scene_.domain, scene_.plates.size());
    set_shear_velocity(&*scene_.cell, scene_.domain);
  }
  list_.with_rolling = rolls_with_resistance(scene_.materials); // rolling springs
  list_.with_springs = general_ || keeps_history(settings_.tangential_law);
  rebuild_list();
  compute_forces();
  drive_cell();
  if (settings_.integrator == Integrator::gear) gear_initialise(gear_, scene_.spheres);
  guard();
}

Simulation3::Simulation3(SimulationState3 state, Settings3 settings, bool)
    : scene_(std::move(state.scene)), settings_(settings), list_(std::move(state.list)),
      start_(std::move(state.start)), last_(state.last), gear_(std::move(state.gear)),
      time_(state.time), steps_(state.steps) {
  set_up();
  require(start_.size() == scene_.plates.size(),
          "a saved state's start poses are not one per plate");
  fit_springs(); // a state saved under another law (or step) has springs it needs not, or lacks
  const std::size_t derivatives =
      settings_.integrator == Integrator::gear ? scene_.spheres.size() : 0;
  for (const auto* v : {&gear_.r2, &gear_.r3, &gear_.r4, &gear_.w2, &gear_.w3, &gear_.w4})
    require(v->size() == derivatives,
            "a saved state's Gear derivatives are not one per sphere of a Gear run");
}

Simulation3 Simulation3::restore(SimulationState3 state, Settings3 settings) {
  return Simulation3(std::move(state), settings, true);
}

// What both constructors check and derive: the scene and settings valid, the pair table, the
// damper's lag and the threads.
void Simulation3::set_up() {
  validate(scene_, settings_);
  table_ = PairTable(scene_.materials, settings_.impact_speed, settings_.linear_damping);
  lag_ = verlet_lag(settings_.verlet_velocity);
  require(settings_.threads >= 0, "simulation.threads must be >= 0 (0: all cores)");
  const int asked = settings_.threads > 0 ? settings_.threads : omp_get_max_threads();
  const auto worth = static_cast<int>(std::max<std::size_t>(1, scene_.spheres.size() / 500));
  threads_ = std::max(1, std::min(asked, worth));
  rotation_ = general_ || turns_spheres(scene_, settings_);
}

void Simulation3::use_general_step(bool general) {
  general_ = general;
  rotation_ = general_ || turns_spheres(scene_, settings_);
  fit_springs();
}

// Springs where the law keeps a history or the step is the general one: gained (a contact's
// spring then starts from 0; a law without history never moves it) or let go.
void Simulation3::fit_springs() {
  list_.with_springs = general_ || keeps_history(settings_.tangential_law);
  if (list_.with_springs) {
    list_.spring.resize(list_.pair_count());
    list_.plate_spring.resize(list_.plate.size());
  } else {
    list_.spring = {}, list_.plate_spring = {};
  }
  force_pass_.list_changed();
}

// In the 2D engine's words and order (simulation/step_features.hpp, describe).
std::string Simulation3::step_description() const {
  if (general_) return "general";
  const bool friction = has_friction(settings_.tangential_law);
  std::string words;
  const auto add = [&words](bool leaves_out, const char* what) {
    if (leaves_out) words.append(words.empty() ? "" : ", ").append(what);
  };
  add(!friction, "frictionless");
  add(friction && !list_.with_springs, "history-free");
  add(!rotation_, "no rotation");
  add(table_.material_count() == 1, "one material");
  return words.empty() ? "general" : words;
}

void Simulation3::compute_forces() {
  last_ = force_pass_.compute(scene_, list_, table_, settings_, threads_, rotation_, !general_);
}

// Velocity Verlet as the 2D engine's (integrate/integrator.hpp): the velocity the contact laws
// see while F(t + dt) is computed is v(t) + (1 + lag) dt/2 a(t).
void Simulation3::step() {
  if (settings_.sort_interval > 0 && steps_ > 0 && steps_ % settings_.sort_interval == 0)
    sort_spheres();
  if (settings_.integrator == Integrator::gear) return gear_step();
  Spheres& s = scene_.spheres;
  const double dt = settings_.timestep, half = 0.5 * dt;
  const auto n = static_cast<std::ptrdiff_t>(s.size());
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Vec3 kick = (half * s.inv_mass[i]) * s.force[i];
    s.position[i] += dt * (s.velocity[i] + kick);
    s.velocity[i] += (1.0 + lag_) * kick;
    if (!rotation_) continue;
    const Vec3 spin_kick = (half * s.inv_inertia[i]) * s.torque[i];
    s.angular_velocity[i] += (1.0 + lag_) * spin_kick;
  }
  std::swap(s.force, s.force_previous);
  if (rotation_) std::swap(s.torque, s.torque_previous);
  forces_after_the_move();
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    s.velocity[i] += (half * s.inv_mass[i]) * (s.force[i] - lag_ * s.force_previous[i]);
    if (!rotation_) continue;
    s.angular_velocity[i] +=
        (half * s.inv_inertia[i]) * (s.torque[i] - lag_ * s.torque_previous[i]);
  }
  ++steps_;
  time_ = static_cast<double>(steps_) * dt;
  guard();
}

void Simulation3::sort_spheres() {
  Spheres& s = scene_.spheres;
  const double range = 2.0 * s.max_radius() + list_.skin;
  renumber_spheres(s, list_, gear_, spheres_by_cell(s, scene_.domain, range));
  force_pass_.list_changed();
}

void Simulation3::forces_after_the_move() {
  const double dt = settings_.timestep;
  if (scene_.cell) deform_cell(*scene_.cell, scene_.domain, scene_.spheres, list_, dt, threads_);
  drive_plates(scene_.plates, scene_.drivers, start_, static_cast<double>(steps_ + 1) * dt);
  place_servo_plates(scene_.plates, scene_.servos, start_);
  if (list_is_stale(list_, scene_.spheres, scene_.plates, scene_.domain)) {
    guard();
    rebuild_list();
  }
  compute_forces();
  drive_servos();
  drive_cell();
}

void Simulation3::rebuild_list() {
  reduce_shear_offset(scene_.domain);
  try {
    build_sphere_list(list_, scene_.spheres, scene_.plates, scene_.domain,
                      resolved_skin(scene_, settings_));
  } catch (const InvalidArgument& e) { // a box too small for the grid: say who made it so
    if (!scene_.cell || steps_ == 0) throw;
    std::ostringstream msg;
    msg << e.what() << " at t = " << time_
        << " s: the deforming cell shrank the box to this; end it sooner or hold it at a "
           "pressure";
    throw InvalidArgument(msg.str());
  }
  force_pass_.list_changed();
}

// The cell's controller takes its rate for the next step from the reading after this one.
void Simulation3::drive_cell() {
  if (!scene_.cell || scene_.cell->pressure <= 0.0) return;
  Cell3& c = *scene_.cell;
  c.rate =
      cell_rate(c, cell_reading(c, scene_, list_, table_, settings_, threads_), settings_.timestep);
}

// Each servo reads its plate after the force pass: the spheres' push against its direction and
// the normal law's tangent stiffness and damping coefficient summed over the plate's touching
// contacts (both laws are linear in the overlap rate: the force at rate 1 less that at rate 0
// is the damping coefficient), then takes its speed for the next step.
void Simulation3::drive_servos() {
  if (scene_.servos.empty()) return;
  std::vector<ServoReading>& reading = servo_reading_; // kept: no allocation a step
  std::vector<std::int32_t>& owner = servo_owner_;
  reading.assign(scene_.servos.size(), ServoReading{});
  owner.assign(scene_.plates.size(), -1);
  for (std::size_t k = 0; k < scene_.servos.size(); ++k) {
    const PlateServo& servo = scene_.servos[k];
    owner[servo.plate] = static_cast<std::int32_t>(k);
    reading[k].load = -dot(scene_.plates[servo.plate].force, servo.direction);
  }
  with_normal_law(settings_.normal_law, [&]<class N>() {
    for_each_plate_contact3(scene_, list_, table_, lever_shares(settings_.lever_arm),
                            [&](std::uint32_t, std::uint32_t, std::uint32_t plate,
                                ContactGeometry3 g, const PairParameters& p) {
                              const std::int32_t k = owner[plate];
                              if (k < 0) return;
                              ServoReading& r = reading[static_cast<std::size_t>(k)];
                              r.stiffness += N::stiffness(p, g);
                              g.v_normal = 0.0;
                              const double resting = N::force(p, g);
                              g.v_normal = -1.0;
                              r.damping += N::force(p, g) - resting;
                            });
  });
  for (std::size_t k = 0; k < scene_.servos.size(); ++k)
    servo_advance(scene_.servos[k], reading[k], settings_.timestep);
}

// Gear as the 2D engine's: the contact laws see the predicted positions, velocities and spins.
void Simulation3::gear_step() {
  const double dt = settings_.timestep;
  gear_predict(gear_, scene_.spheres, dt, threads_, rotation_);
  forces_after_the_move();
  gear_correct(gear_, scene_.spheres, dt, threads_, rotation_);
  ++steps_;
  time_ = static_cast<double>(steps_) * dt;
  guard();
}

void Simulation3::run(std::uint64_t steps) {
  for (std::uint64_t k = 0; k < steps; ++k) step();
}

void Simulation3::guard() const {
  const Spheres& s = scene_.spheres;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec3& r = s.position[i];
    const Vec3& v = s.velocity[i];
    if (std::isfinite(r.x + r.y + r.z + v.x + v.y + v.z)) continue;
    std::ostringstream msg;
    msg << "sphere " << s.id[i] << " has a non-finite position or velocity at step " << steps_
        << " (t = " << time_ << " s): the timestep is too long for the stiffest contact";
    throw InstabilityError(msg.str());
  }
  if (last_.deepest <= settings_.max_overlap_fraction) return;
  std::ostringstream msg;
  msg << "at step " << steps_ << " (t = " << time_ << " s) "
      << deepest_contact(scene_, list_, settings_)
      << " (allowed: " << settings_.max_overlap_fraction
      << "): the contact is too soft for the load, or the timestep too long";
  throw InstabilityError(msg.str());
}

double Simulation3::coordination() const {
  const Spheres& s = scene_.spheres;
  std::size_t free = 0, ends = 0; // contact ends on free spheres
  for (std::size_t i = 0; i < s.size(); ++i) free += s.is_free(i) ? 1 : 0;
  if (free == 0) return 0.0;
  ends = last_.on_plates;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::uint32_t e = list_.row_offset[i]; e < list_.row_offset[i + 1]; ++e) {
      const std::uint32_t j = list_.neighbour[e];
      const Vec3 d = s.position[i] - (s.position[j] + list_.offset(e, scene_.domain));
      const double reach = s.radius[i] + s.radius[j];
      if (norm2(d) >= reach * reach) continue;
      ends += (s.is_free(i) ? 1 : 0) + (s.is_free(j) ? 1 : 0);
    }
  return static_cast<double>(ends) / static_cast<double>(free);
}

Energies3 Simulation3::energies() const {
  const Spheres& s = scene_.spheres;
  Energies3 e;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.is_free(i)) continue;
    e.kinetic += 0.5 * s.mass[i] * norm2(s.velocity[i]);
    e.rotational += 0.5 * s.inertia[i] * norm2(s.angular_velocity[i]);
    e.potential -=
        s.mass[i] * dot(scene_.gravity, scene_.domain.unwrapped(s.position[i], s.image[i]));
  }
  e.elastic = contact_elastic_energy(scene_, list_, table_, settings_);
  return e;
}

std::size_t Simulation3::footprint_bytes() const {
  const Spheres& s = scene_.spheres;
  const SphereList& l = list_;
  std::size_t b = 0;
  const auto add = [&b](const auto&... v) { ((b += capacity_bytes(v)), ...); };
  sphere_fields(s, [&](const auto& v) { add(v); });
  add(l.row_offset, l.neighbour, l.shift, l.spring, l.second_offset, l.second_entry, l.plate_offset,
      l.plate, l.plate_spring, l.rolling, l.plate_rolling, l.reference, l.plate_reference);
  add(gear_.r2, gear_.r3, gear_.r4, gear_.w2, gear_.w3, gear_.w4);
  return b + force_pass_.bytes();
}

} // namespace talus
