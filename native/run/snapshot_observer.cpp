// The snapshots: VTK files and their ParaView collections, and the thesis' run.out blocks.
#include "io/thesis_format.hpp"
#include "run/observers.hpp"
#include "run/records.hpp"

namespace talus::run {

SnapshotObserver::SnapshotObserver(RunContext& c)
    : every_(steps_of(c.scenario.output.snapshot_interval, c.sim.config().timestep)) {}

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
  if (every_ && k % every_ >= (every_ + 1) / 2) {
    end_step_ = k;
    write(c);
  }
}

void SnapshotObserver::cut_back(RunContext& c) {
  end_step_ = 0; // an end snapshot, if written, was after the checkpoint
  write_collections(c);
}

void SnapshotObserver::write(RunContext& c) {
  write_snapshot_files(c.files.dir(), c.sim, c.book.snapshots++, c.scenario.output.contacts);
  write_collections(c);
  if (thesis_out_) *thesis_out_ << thesis_out_block(c.sim);
}

void SnapshotObserver::write_collections(RunContext& c) const {
  write_collections_of(c.files.dir(), c.book.snapshots, every_, end_step_, c.sim.config().timestep,
                       !c.sim.world().walls.empty());
}

} // namespace talus::run
