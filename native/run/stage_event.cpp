// The stages of an experiment run in stages ([[stages]], StageSection).
#include <cmath>

#include <fmt/core.h>

#include "frost/uniform_freeze.hpp"
#include "run/observers.hpp"
#include "run/records.hpp"

namespace talus::run {

namespace {

// The step at which the stage under way reaches `duration`, rounded up: counted from its start
// while the timestep is the one it started with, else from when the timestep changed.
std::uint64_t end_of(const RunContext& c, double duration) {
  const std::uint64_t start = c.book.stage_start;
  if (c.sim.clock_step() <= start)
    return start + std::max<std::uint64_t>(1, steps_until(duration, c.sim.config().timestep));
  return c.sim.step_at(c.book.stage_start_time + duration);
}

} // namespace

StageEvent::StageEvent(RunContext& c)
    : thermo_every_(every_of(c, c.scenario.output.thermo_interval)), c_(&c) {
  if (std::isnan(c.book.stage_start_time)) // a book of a talus whose timestep never changed
    c.book.stage_start_time = static_cast<double>(c.book.stage_start) * c.sim.config().timestep;
}

std::uint64_t StageEvent::next_look(std::uint64_t step) const {
  const std::vector<StageSection>& stages = c_->scenario.stages;
  const std::size_t k = c_->book.stage;
  if (k >= stages.size()) return never;
  std::uint64_t next = never;
  // the last stage lasts to the run's end
  if (k + 1 < stages.size()) next = std::max(step + 1, end_of(*c_, stages[k].duration));
  if (stages[k].until != "none") next = std::min(next, thermo_every_.next(step));
  return next;
}

void StageEvent::open(RunContext& c) {
  log_ = &c.files.open("stages.csv");
}

void StageEvent::start(RunContext&) {
  *log_ << "stage,name,start_time,end_time,ended_by\n";
}

bool StageEvent::condition_holds(const RunContext& c) const {
  const StageSection& st = c.scenario.stages[c.book.stage];
  if (st.until == "settled")
    return c.last_kinetic < c.scenario.packing.settle_energy * rest_energy_scale(c.sim);
  if (st.until == "kinetic_below") return c.last_kinetic < st.kinetic;
  if (st.until == "kinetic_above") return c.last_kinetic > st.kinetic;
  if (st.until == "grains_below") {
    const Particles& p = c.sim.world().particles;
    std::size_t below = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_free(i) && p.position[i].y < st.height) ++below;
    return below >= st.count;
  }
  const DriverTargets& g = c.book.groups.at(st.group); // the build checked that it is there
  if (st.until == "wall_force_above") return norm(group_force(c.sim, g)) > st.force;
  if (st.until == "wall_position_below") return group_height(c.sim, g) < st.position;
  if (st.until == "wall_position_above") return group_height(c.sim, g) > st.position;
  return false;
}

void StageEvent::look(RunContext& c) {
  const std::vector<StageSection>& stages = c.scenario.stages;
  const std::size_t k = c.book.stage;
  if (k >= stages.size()) return;
  const std::uint64_t step = c.sim.step_count();
  if (stages[k].until != "none" && thermo_every_.on(step) && condition_holds(c))
    return end_stage(c, stages[k].until.c_str());
  if (k + 1 < stages.size() && step >= end_of(c, stages[k].duration)) end_stage(c, "duration");
}

void StageEvent::end_stage(RunContext& c, const char* why) {
  const std::vector<StageSection>& stages = c.scenario.stages;
  const std::size_t k = c.book.stage;
  write_row(c, why);
  c.book.stage = k + 1;
  c.book.stage_start = c.sim.step_count();
  c.book.stage_start_time = c.sim.time();
  if (!c.quiet && !c.progress_on_terminal)
    fmt::print("stage {} ({}) ended ({}) at t = {:.6g} s\n", k, stages[k].name, why, c.sim.time());
  // the last stage's end, or a condition that ends the experiment, ends the run
  if (k + 1 == stages.size() || (std::string_view(why) != "duration" && stages[k].then == "end")) {
    c.book.stage = stages.size();
    c.end = "stages";
    return;
  }
  const StageSection& next = stages[k + 1];
  // copied: the change replaces the scenario this refers to
  const std::vector<std::string> set = next.set;
  c.change(set, fmt::format("stage {} ({})", k + 1, next.name));
}

void StageEvent::finish(RunContext& c) {
  const std::size_t k = c.book.stage;
  if (k >= c.scenario.stages.size()) return; // its last row is written
  write_row(c, c.book.ended.c_str());
}

void StageEvent::write_row(const RunContext& c, const char* why) {
  const std::size_t k = c.book.stage;
  *log_ << fmt::format("{},{},{:.9g},{:.9g},{}\n", k, c.scenario.stages[k].name,
                       c.book.stage_start_time, c.sim.time(), why);
}

} // namespace talus::run
