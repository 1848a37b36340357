// The snapshots: VTK files and their ParaView collections, and the thesis' run.out blocks.
#include "io/thesis_format.hpp"
#include "run/observers.hpp"
#include "run/records.hpp"

namespace talus::run {

SnapshotObserver::SnapshotObserver(RunContext& c)
    : every_(every_of(c, c.scenario.output.snapshot_interval)) {
  // a book of a talus that kept no times: its snapshots were on the grid from t = 0
  std::vector<double>& times = c.book.snapshot_times;
  for (std::uint64_t k = times.size(); k < c.book.snapshots; ++k)
    times.push_back(static_cast<double>(k * every_.steps) * c.sim.config().timestep);
}

void SnapshotObserver::open(RunContext& c) {
  if (c.scenario.output.thesis_out) thesis_out_ = &c.files.open("run.out");
}

void SnapshotObserver::start(RunContext& c) {
  if (thesis_out_) *thesis_out_ << thesis_out_header(c.sim, c.scenario.simulation.duration);
  write(c);
}

void SnapshotObserver::finish(RunContext& c) {
  // a snapshot less than half an interval before the end stands for it: no near-twin frames
  const std::uint64_t k = c.sim.step_count();
  if (every_.steps && every_.past(k) >= (every_.steps + 1) / 2) {
    write(c);
  }
}

void SnapshotObserver::cut_back(RunContext& c) {
  write_collections(c);
}

void SnapshotObserver::write(RunContext& c) {
  std::vector<double>& times = c.book.snapshot_times;
  times.resize(c.book.snapshots); // those after a checkpoint the outputs were cut back to go
  times.push_back(c.sim.time());
  write_snapshot_files(c.files.dir(), c.sim, c.book.snapshots++, c.scenario.output.contacts,
                       c.scenario.output.stress);
  write_collections(c);
  if (thesis_out_) *thesis_out_ << thesis_out_block(c.sim);
}

void SnapshotObserver::write_collections(RunContext& c) const {
  std::vector<double> times = c.book.snapshot_times;
  times.resize(c.book.snapshots);
  write_collections_of(c.files.dir(), times, !c.sim.world().walls.empty());
}

} // namespace talus::run
