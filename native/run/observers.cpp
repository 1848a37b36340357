#include "run/observers.hpp"

#include <algorithm>
#include <cmath>

namespace talus::run {

std::uint64_t steps_of(double interval, double dt) {
  if (interval <= 0.0) return 0;
  // a count beyond any run (an interval of years) is cut to one no run reaches, since converting
  // a larger number to an integer is undefined
  return std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::clamp(std::round(interval / dt), 0.0, 1e18)));
}

Every every_of(const RunContext& c, double interval) {
  return {c.sim.clock_step(), steps_of(interval, c.sim.config().timestep)};
}

std::vector<std::unique_ptr<Observer>> observers_for(RunContext& c, RunProgress& progress,
                                                     SnapshotObserver*& snapshots) {
  std::vector<std::unique_ptr<Observer>> list;
  const OutputSection& out = c.scenario.output;
  if (out.contacts) list.push_back(std::make_unique<ContactOutput>(c));
  LedgerObserver* ledger = nullptr;
  if (out.energy_ledger) {
    auto l = std::make_unique<LedgerObserver>(c);
    ledger = l.get();
    list.push_back(std::move(l));
  }
  if (!c.book.tracked.empty()) list.push_back(std::make_unique<TrackObserver>(c));
  list.push_back(std::make_unique<ThermoObserver>(c, ledger));
  list.push_back(std::make_unique<ProgressObserver>(c, progress));
  if (c.scenario.frost.model == "uniform") list.push_back(std::make_unique<UniformFreezeEvent>(c));
  if (c.scenario.frost.model == "front") list.push_back(std::make_unique<FreezingFrontEvent>(c));
  if (!c.scenario.stages.empty()) list.push_back(std::make_unique<StageEvent>(c));
  auto s = std::make_unique<SnapshotObserver>(c);
  snapshots = s.get();
  list.push_back(std::move(s));
  return list;
}

} // namespace talus::run
