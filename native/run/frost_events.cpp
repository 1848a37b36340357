// The frost models as events of a run: the thesis' uniform freeze and the freezing front. Both
// start a freeze at a thermo row once the grains are at rest (frost.kinetic_threshold) and
// frost.min_interval after the last, log to frost.csv, and end the run after frost.cycles.
#include <fmt/core.h>

#include "frost/uniform_freeze.hpp"
#include "run/observers.hpp"
#include "scenario/frost_setup.hpp"

namespace talus::run {

namespace {

bool at_rest(const RunContext& c) {
  const FrostSection& f = c.scenario.frost;
  return c.last_kinetic < f.kinetic_threshold * rest_energy_scale(c.sim) &&
         c.sim.time() - c.book.last_freeze >= f.min_interval;
}

bool cycles_done(const RunContext& c) {
  return c.scenario.frost.cycles > 0 && c.book.freezes >= c.scenario.frost.cycles;
}

void log_frost(RunContext& c, std::ostream& log, const char* event) {
  log << fmt::format("{},{:.9g},{}\n", c.book.freezes, c.sim.time(), event);
  if (!c.quiet && !c.progress_on_terminal)
    fmt::print("frost: {} {} at t = {:.6g} s\n", event, c.book.freezes, c.sim.time());
}

} // namespace

UniformFreezeEvent::UniformFreezeEvent(RunContext& c)
    : thermo_every_(every_of(c, c.scenario.output.thermo_interval)) {}

void UniformFreezeEvent::open(RunContext& c) {
  log_ = &c.files.open("frost.csv");
}

void UniformFreezeEvent::start(RunContext&) {
  *log_ << "cycle,time,event\n";
}

void UniformFreezeEvent::look(RunContext& c) {
  if (!at_rest(c)) return;
  freeze_uniformly(c.sim, c.book.bounds.lo.y, c.scenario.frost.heave_factor);
  ++c.book.freezes;
  c.book.last_freeze = c.sim.time();
  log_frost(c, *log_, "freeze");
  if (cycles_done(c)) c.end = "cycles";
}

FreezingFrontEvent::FreezingFrontEvent(RunContext& c)
    : thermo_every_(every_of(c, c.scenario.output.thermo_interval)),
      front_(front_parameters(c.scenario, c.sim.world().particles, c.book.bounds)) {
  if (!c.book.front_state.empty()) front_.load(c.book.front_state, c.sim.world().particles.size());
  // the fronts move a thousandth of the shorter phase at a time
  const double phase = std::min(c.scenario.frost.freeze_time, c.scenario.frost.thaw_time);
  front_every_ = {c.sim.clock_step(),
                  std::max<std::uint64_t>(
                      1, static_cast<std::uint64_t>(std::clamp(
                             std::floor(phase / 1000.0 / c.sim.config().timestep), 0.0, 1e18)))};
}

void FreezingFrontEvent::open(RunContext& c) {
  log_ = &c.files.open("frost.csv");
}

void FreezingFrontEvent::start(RunContext&) {
  *log_ << "cycle,time,event\n";
}

void FreezingFrontEvent::look(RunContext& c) {
  const std::uint64_t k = c.sim.step_count();
  if (thermo_every_.on(k) && front_.phase() == FrostFront::Phase::idle && at_rest(c)) {
    if (cycles_done(c)) {
      log_frost(c, *log_, "end");
      c.end = "cycles";
      return;
    }
    front_.start_freeze(c.sim);
    ++c.book.freezes;
    log_frost(c, *log_, "freeze");
  }
  if (front_.phase() == FrostFront::Phase::idle || !front_every_.on(k)) return;
  if (!front_.advance(c.sim)) return;
  if (front_.phase() == FrostFront::Phase::thawing) {
    log_frost(c, *log_, "thaw");
  } else {
    c.book.last_freeze = c.sim.time(); // the next cycle waits min_interval after the thaw
    log_frost(c, *log_, "thawed");
  }
}

} // namespace talus::run
