#include "simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <omp.h>

#include "core/capacity_bytes.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/list_check.hpp"
#include "neighbours/skin.hpp"
#include "simulation/rolling_pass.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// The settings chosen by name in a scenario arrive here as ids; one from a restored checkpoint
// was only checksummed, and an id outside its list would quietly select another law or scheme.
void validate_choices(const SimulationConfig& c) {
  const auto within = [](auto id, std::size_t count) {
    return static_cast<std::size_t>(id) < count;
  };
  require(within(c.normal_law, NormalLaws::size),
          "simulation.normal_law: id " + std::to_string(static_cast<int>(c.normal_law)) +
              " is not a law; allowed: " + law_names<NormalLaw>());
  require(within(c.tangential_law, TangentialLaws::size),
          "simulation.tangential_law: id " + std::to_string(static_cast<int>(c.tangential_law)) +
              " is not a law; allowed: " + law_names<TangentialLaw>());
  require(within(c.integrator, 2), "simulation.integrator: id " +
                                       std::to_string(static_cast<int>(c.integrator)) +
                                       " is not an integrator; allowed: gear, verlet");
  require(within(c.verlet_velocity, 2), "simulation.verlet_velocity: id " +
                                            std::to_string(static_cast<int>(c.verlet_velocity)) +
                                            " is not a choice; allowed: predicted, half_step");
  require(within(c.lever_arm, 3), "simulation.lever_arm: id " +
                                      std::to_string(static_cast<int>(c.lever_arm)) +
                                      " is not a choice; allowed: contact_point, radius, granular");
}

void validate_setup(const World& w, const SimulationConfig& c) {
  validate_choices(c);
  require(std::isfinite(c.timestep) && c.timestep > 0.0,
          "simulation.timestep = " + std::to_string(c.timestep) + " s; allowed: > 0");
  require(c.skin >= 0.0, "simulation.skin must be >= 0 m (0: automatic)");
  require(c.threads >= 0, "simulation.threads must be >= 0 (0: all cores)");
  require(c.max_overlap_fraction > 0.0, "simulation.max_overlap_fraction must be > 0");
  require(std::isfinite(c.impact_speed) && c.impact_speed > 0.0,
          "simulation.impact_speed = " + std::to_string(c.impact_speed) + " m/s; allowed: > 0");
  for (const Material& m : w.materials) {
    const std::string problem = material_error(c.normal_law, c.tangential_law, m, c.linear_damping);
    require(problem.empty(), problem);
  }
  for (std::size_t i = 0; i < w.particles.size(); ++i) {
    require(w.particles.material[i] < w.materials.size(),
            "particle " + std::to_string(i) + ": material index out of range");
    require(static_cast<int>(w.particles.kind[i]) <= static_cast<int>(Kind::moved),
            "particle " + std::to_string(i) + ": kind " +
                std::to_string(static_cast<int>(w.particles.kind[i])) +
                " is not one; allowed: 0 (free), 1 (fixed), 2 (moved)");
  }
  for (const Segment& s : w.walls)
    require(s.material < w.materials.size(), "wall: material index out of range");
  require_cell_fits(w);
}

} // namespace

Simulation::Simulation(World world, SimulationConfig config)
    : Simulation(SimulationState{std::move(world), {}, 0.0, 0}, config, false) {}

Simulation Simulation::restore(SimulationState state, SimulationConfig config) {
  return Simulation(std::move(state), config, true);
}

Simulation::Simulation(SimulationState state, SimulationConfig config, bool restoring)
    : world_(std::move(state.world)), config_(config), list_(std::move(state.neighbours)),
      forces_(config.normal_law, config.tangential_law, config.timestep,
              verlet_lag(config.verlet_velocity), config.lever_arm),
      time_(state.time), steps_(state.steps), clock_time_(state.clock_time),
      clock_step_(state.clock_step) {
  validate_setup(world_, config_);
  pairs_ = PairTable(world_.materials, config_.impact_speed, config_.linear_damping);
  const int wanted = config_.threads > 0 ? config_.threads : omp_get_max_threads();
  const std::size_t per_thread = std::max<std::size_t>(1, config_.min_particles_per_thread);
  const auto useful = static_cast<int>(std::min<std::size_t>(
      world_.particles.size() / per_thread + 1, static_cast<std::size_t>(wanted)));
  threads_ = max_threads_ = std::max(1, useful);
  if (restoring) { // a saved state is indexed without checks from here on: it must fit
    const std::string list =
        neighbour_list_problem(list_, world_.particles.size(), world_.walls.size());
    require(list.empty(), "restored state: the neighbour list does not fit the particles: " + list);
    for (const Driver& d : world_.drivers) {
      const std::string driver = attached_driver_problem(d, world_.particles, world_.walls);
      require(driver.empty(), "restored state: " + driver);
    }
  }
  list_moved();
  choose_features();
  if (restoring) {
    index_force_blocks(list_); // derived from the rows, not stored
    update_cell_reserve(world_.particles.max_radius());
    return;
  }
  for (std::size_t i = 0; i < world_.particles.size(); ++i)
    if (world_.particles.kind[i] == Kind::fixed) { // a fixed wall particle never moves
      world_.particles.velocity[i] = {};
      world_.particles.angular_velocity[i] = 0.0;
    }
  for (Driver& d : world_.drivers) {
    attach(d, world_);
    apply(d, 0.0, world_.particles, world_.walls);
  }
  set_shear_velocity();
  rebuild_list(1);
  forces_.compute(world_, list_, pairs_, ForceStage::Finish::nothing, drift_bound_, threads_,
                  features_);
  if (features_.rolling) // with no time passed: the springs stay as they are
    add_rolling_torques(world_, list_, pairs_, config_.normal_law, 0.0,
                        lever_shares(config_.lever_arm));
  if (config_.integrator == Integrator::gear) gear_initialise(world_.particles);
}

void Simulation::step() {
  advance(false);
}

void Simulation::use_general_step(bool general) {
  general_step_ = general;
  choose_features();
}

void Simulation::choose_features() {
  features_ =
      general_step_ ? general_features(world_) : scene_features(world_, config_.tangential_law);
  features_stale_ = false;
  list_.keeps_rolling = features_.rolling;
  if (!features_.rolling) {
    std::vector<double>().swap(list_.rolling);
    std::vector<double>().swap(list_.wall_rolling);
  } else {
    if (list_.rolling.size() != list_.neighbour.size())
      list_.rolling.assign(list_.neighbour.size(), 0.0);
    if (list_.wall_rolling.size() != list_.wall_segment.size())
      list_.wall_rolling.assign(list_.wall_segment.size(), 0.0);
  }
  list_.keeps_history = features_.history;
  if (!features_.history) {
    std::vector<double>().swap(list_.history); // and its memory
    std::vector<double>().swap(list_.wall_history);
    return;
  }
  // a list from a step that kept none (a history-free law's) starts with its springs at 0
  if (list_.history.size() != list_.neighbour.size())
    list_.history.assign(list_.neighbour.size(), 0.0);
  if (list_.wall_history.size() != list_.wall_segment.size())
    list_.wall_history.assign(list_.wall_segment.size(), 0.0);
}

void Simulation::advance(bool fuse) {
  if (features_stale_) choose_features(); // edits happen between run() calls: nothing is fused
  // the rolling pass comes between forces and correction; a servo reads the contacts between
  // the force stage and the next prediction, which a fused step does at once
  fuse = fuse && !features_.rolling && !has_servo() && cell_driver() == nullptr;
  // from the clock's origin, not by adding dt: no rounding builds up (and with the origin at 0,
  // the same bits as (steps + 1) dt)
  const double t_next =
      clock_time_ + static_cast<double>(steps_ + 1 - clock_step_) * config_.timestep;
  bool drifted = predict();
  move_bodies(t_next);
  drifted = deform_cell() || drifted;
  update_neighbours(drifted);
  const PassReport forces = contacts(fuse);
  if (features_.driven) drive_servos();
  drive_cell();
  correct(fuse, forces);
  ++steps_;
  time_ = t_next;
  guard();
}

bool Simulation::predict() {
  if (predicted_) { // by the last step's fused pass
    predicted_ = false;
    return drifted(predicted_displacement2_);
  }
  // forces started by the last stage count only between two steps of one run() (a fused step
  // that finished): anything a caller does between run() calls may change them
  forces_.forces_started(false);
  if (config_.sort_interval > 0 && steps_ % config_.sort_interval == 0) sort_particles();
  Particles& p = world_.particles;
  const double dt = config_.timestep;
  const bool rotation = features_.rotation;
  return drifted(
      config_.integrator == Integrator::verlet
          ? verlet_predict(p, dt, threads_, verlet_lag(config_.verlet_velocity), rotation)
          : gear_predict(p, dt, threads_, rotation));
}

void Simulation::move_bodies(double t) {
  if (!features_.driven) return;
  for (const Driver& d : world_.drivers) apply(d, t, world_.particles, world_.walls);
  // a driven grain that slides out of a periodic box comes in on the other side, as free ones
  // do (the move past the skin rebuilds the list, with its new image)
  if (world_.domain.any_periodic())
    for (const Driver& d : world_.drivers)
      for (const auto i : d.targets.particles)
        world_.particles.position[i] = world_.domain.wrap(world_.particles.position[i]);
}

void Simulation::update_neighbours(bool drifted) {
  if (driven_stale_) list_moved();
  const bool rebuild =
      drifted || list_stale_ || walls_moved(list_, world_.particles, world_.walls, driven_);
  list_stale_ = false;
  if (rebuild) rebuild_list(threads_);
}

PassReport Simulation::contacts(bool fuse) {
  using Finish = ForceStage::Finish;
  const Finish finish = config_.integrator != Integrator::verlet || features_.rolling
                            ? Finish::nothing
                        : fuse ? Finish::verlet_correct_predict
                               : Finish::verlet_correct;
  PassReport report = forces_.compute(world_, list_, pairs_, finish,
                                      drift_bound_ + 0.5 * cell_reserve_, threads_, features_);
  if (features_.rolling) {
    add_rolling_torques(world_, list_, pairs_, config_.normal_law, config_.timestep,
                        lever_shares(config_.lever_arm));
    if (config_.integrator == Integrator::verlet)
      report.finite = verlet_correct(world_.particles, config_.timestep, threads_,
                                     verlet_lag(config_.verlet_velocity));
  }
  // while the overlap is there (in a step that velocity Verlet fused, the grains are already
  // predicted one timestep on, and the diagnosis names the deepest contact there)
  if (forces_.deepest_overlap() > config_.max_overlap_fraction) guard();
  return report;
}

void Simulation::correct(bool fuse, const PassReport& forces) {
  Particles& p = world_.particles;
  const bool verlet = config_.integrator == Integrator::verlet;
  if (fuse) {
    PassReport seam = forces;
    if (verlet) {
      std::swap(p.force, p.force_previous); // as verlet_predict leaves them
      std::swap(p.torque, p.torque_previous);
    } else {
      seam = gear_correct_predict(p, config_.timestep, world_.gravity, threads_, features_.rotation,
                                  features_.gravity);
    }
    forces_.forces_started(true); // by the fused pass, for the next force stage
    finite_ = seam.finite;
    predicted_displacement2_ = seam.displacement2;
    predicted_ = true;
  } else if (verlet) {
    finite_ = forces.finite;
  } else {
    const PassReport corrected = gear_correct(p, config_.timestep, threads_, features_.rotation);
    finite_ = corrected.finite;
    drift_bound_ += std::sqrt(corrected.displacement2);
  }
}

void Simulation::rebuild_list(int threads) {
  reduce_shear_offset();
  try {
    build_neighbour_list(list_, world_.particles, world_.walls, world_.domain, next_skin(),
                         threads);
  } catch (const InvalidArgument& e) { // a box too small for the grid: say who made it so
    if (cell_driver() == nullptr || steps_ == 0) throw;
    throw InvalidArgument(std::string(e.what()) + " at t = " + std::to_string(time_) +
                          " s: the deforming cell shrank the box to this; end it sooner (a "
                          "stage's duration or condition) or hold it at a pressure");
  }
  drift_bound_ = 0.0;
  cell_reserve_ = 0.0;
  forces_.list_changed();
}

bool Simulation::drifted(double displacement2) {
  drift_bound_ += std::sqrt(displacement2);
  // a deforming cell's strain takes its share of the skin first (update_cell_reserve)
  const double reserve = 0.5 * cell_reserve_;
  if (drift_bound_ + reserve <= drift_margin * 0.5 * list_.skin) return false;
  ++drift_tests_;
  const double largest2 = largest_drift2(list_, world_.particles, threads_);
  const double limit = 0.5 * list_.skin - reserve;
  if (limit <= 0.0 || largest2 > limit * limit) return true; // particles_moved's test, less it
  const double moved = std::sqrt(largest2);
  // The positions were compared with the build's: the farthest move is the new bound. A bound
  // that sums every pass's farthest move soon overstates it (the farthest grains change from pass
  // to pass), and an unknown one (after a restore or an edit) would otherwise compare the
  // positions and choose the candidates again at every step until the next build.
  if (moved < drift_bound_) {
    forces_.drift_bound_lowered(drift_bound_, moved);
    drift_bound_ = moved;
  }
  return false;
}

double Simulation::next_skin() const {
  // config_.skin stays 0 for the automatic skin (it is saved in checkpoints), so that a resumed
  // run chooses its skins as the uninterrupted one does
  return config_.skin > 0.0
             ? config_.skin
             : automatic_skin(world_.particles, world_.walls, world_.domain, config_.timestep);
}

void Simulation::sort_particles() {
  Particles& p = world_.particles;
  if (p.size() < 2) return;
  // The cells' order: bands of `band` cells side by side, each band row by row from the bottom,
  // the particles of a cell in ascending index (the grid's counting sort): a function of the
  // positions alone. A band's rows are at most 256 cells long, so a particle's neighbours above
  // it follow it within a few hundred particles however wide the system is (rows across a very
  // wide strip measured slower, and narrower bands too: docs/performance.md, "Renumbering").
  CellGrid grid;
  grid.build(p.position, world_.domain, 2.0 * p.max_radius(), threads_);
  constexpr int band = 256;
  std::vector<std::uint32_t> order;
  order.reserve(p.size());
  for (int x0 = 0; x0 < grid.nx; x0 += band)
    for (int cy = 0; cy < grid.ny; ++cy)
      for (int cx = x0; cx < std::min(grid.nx, x0 + band); ++cx) {
        const std::size_t c = static_cast<std::size_t>(cy) * static_cast<std::size_t>(grid.nx) +
                              static_cast<std::size_t>(cx);
        order.insert(order.end(), grid.items.begin() + grid.cell_start[c],
                     grid.items.begin() + grid.cell_start[c + 1]);
      }
  new_of_old_.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    new_of_old_[order[k]] = static_cast<std::uint32_t>(k);
  p.permute(order, threads_);
  renumber_neighbour_list(list_, order, new_of_old_, threads_);
  for (Driver& d : world_.drivers)
    for (std::uint32_t& i : d.targets.particles) i = new_of_old_[i];
  list_moved();
  forces_.list_changed();
  ++renumberings_;
}

void Simulation::list_moved() {
  // drivers move only Kind::moved particles (attach checks), and held ones are Kind::moved too
  driven_.clear();
  for (std::size_t i = 0; i < world_.particles.size(); ++i)
    if (world_.particles.kind[i] == Kind::moved) driven_.push_back(static_cast<std::uint32_t>(i));
  driven_stale_ = false;
}

void ParticleEdits::hold(std::uint32_t i, bool held) {
  Particles& p = sim_.world_.particles;
  require(i < p.size(), "hold: no particle " + std::to_string(i));
  require(p.kind[i] != Kind::fixed,
          "hold: particle " + std::to_string(i) + " is a fixed wall particle");
  // A held grain has no pairs with other held grains in the neighbour list (the list pairs a
  // grain with a free one), so a released one needs a new list before the next force stage:
  // otherwise it would fall into a held neighbour unseen until its drift forced a rebuild, and
  // be shot out by the overlap it had reached by then.
  if (!held && p.kind[i] == Kind::moved) sim_.list_stale_ = true;
  p.set_held(i, held);
  sim_.features_stale_ = true;
  sim_.forces_.list_changed(); // a held grain moves by displace_held: its entries are candidates
  sim_.driven_stale_ = true;
}

void ParticleEdits::set_material(std::uint32_t i, std::size_t m) {
  World& w = sim_.world_;
  require(i < w.particles.size(), "set_material: no particle " + std::to_string(i));
  require(m < w.materials.size(), "set_material: material index " + std::to_string(m) +
                                      " out of range; allowed: 0 to " +
                                      std::to_string(w.materials.size() - 1));
  w.particles.material[i] = static_cast<std::uint16_t>(m);
  sim_.features_stale_ = true; // one material may be two now
}

void ParticleEdits::displace_held(std::uint32_t i, Vec2 d) {
  Particles& p = sim_.world_.particles;
  if (i >= p.size() || p.kind[i] != Kind::moved)
    throw std::logic_error("displace_held: particle " + std::to_string(i) + " is not held");
  p.position[i] += d;
}

Footprint Simulation::footprint() const {
  const Particles& p = world_.particles;
  const NeighbourList& l = list_;
  Footprint f;
  p.for_each_state_field([&](const auto& v) { f.particles += capacity_bytes(v); });
  p.for_each_integrator_field([&](const auto& v) { f.integrator += capacity_bytes(v); });
  f.list = capacity_bytes(l.row_offset) + capacity_bytes(l.neighbour) + capacity_bytes(l.image) +
           capacity_bytes(l.block_first_slot) + capacity_bytes(l.deferred_offset) +
           capacity_bytes(l.deferred_slot) + capacity_bytes(l.late) + capacity_bytes(l.entry_row) +
           capacity_bytes(l.wall_offset) + capacity_bytes(l.wall_segment) +
           capacity_bytes(l.reference) + capacity_bytes(l.segment_reference);
  f.history = capacity_bytes(l.history) + capacity_bytes(l.wall_history) +
              capacity_bytes(l.rolling) + capacity_bytes(l.wall_rolling);
  f.candidates = forces_.candidate_bytes();
  f.other = capacity_bytes(world_.walls) + capacity_bytes(driven_) + forces_.footprint_bytes();
  return f;
}

void Simulation::run(std::uint64_t steps, const std::function<void(const Simulation&)>& observer,
                     std::uint64_t every) {
  // Between two steps of this loop nothing looks at the state, so a step's correction and the
  // next one's prediction are one pass (advance), except after the last step, a step the
  // observer or the escape check sees, and before a step that renumbers (it orders the
  // particles by the corrected positions).
  const bool box =
      config_.escape_hi.x > config_.escape_lo.x && config_.escape_hi.y > config_.escape_lo.y;
  for (std::uint64_t s = 0; s < steps; ++s) {
    const std::uint64_t next = steps_ + 1;
    advance(s + 1 < steps && !(observer && every > 0 && next % every == 0) &&
            !(config_.sort_interval > 0 && next % config_.sort_interval == 0) &&
            !(box && next % 16 == 0));
    if (observer && every > 0 && steps_ % every == 0) observer(*this);
  }
}

} // namespace talus
