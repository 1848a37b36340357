#include "run/run.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <thread>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "render/snapshot_png.hpp"
#include "run/observers.hpp"
#include "run/records.hpp"
#include "run/scenario_change.hpp"
#include "scenario/build_checks.hpp"
#include "scenario/file/toml_reader.hpp"

namespace fs = std::filesystem;

namespace talus::run {

namespace {

constexpr const char* changes_header = "time,step,source,change\n";

// output.checkpoint_interval: a checkpoint now and then, after the other observers have looked.
class CheckpointEvent final : public Observer {
public:
  CheckpointEvent(RunContext& c, Run& run)
      : every_(every_of(c, c.scenario.output.checkpoint_interval)), run_(run) {}
  std::uint64_t next_look(std::uint64_t step) const override { return every_.next(step); }
  void look(RunContext&) override { run_.checkpoint(); }

private:
  Every every_;
  Run& run_;
};

} // namespace

Run::Run(const Scenario& s, Simulation sim, RunBook book, fs::path dir, RunControl o, bool fresh)
    : s_(s), sim_(std::move(sim)), book_(std::move(book)), o_(std::move(o)),
      files_(std::move(dir), fresh),
      progress_(o_.quiet, s.simulation.duration, s.output.thermo_interval, sim_.config().timestep),
      threads_(sim_.max_threads()), c_{s_, sim_, book_, files_} {
  c_.quiet = o_.quiet;
  c_.progress_on_terminal = progress_.on_terminal();
  set_length();
  c_.session_wall = [this] { return wall_now() - session_wall_before_; };
  c_.change = [this](const std::vector<std::string>& set, const std::string& source) {
    change(set, source);
  };
  checkpointed_ = !book_.file_bytes.empty(); // resumed: from a checkpoint
  checkpointed_snapshots_ = book_.snapshots;
  make_observers();
}

// The run's length in steps, and where this session stops, from the scenario as it stands.
void Run::set_length() {
  c_.total_steps = sim_.step_at(s_.simulation.duration);
  c_.stop_step =
      o_.stop_at >= 0.0 ? std::min(c_.total_steps, sim_.step_at(o_.stop_at)) : c_.total_steps;
  progress_.set_duration(s_.simulation.duration);
}

// After a change: the events and observers of the changed scenario, from their saved state.
void Run::refresh_observers() {
  make_observers();
  for (auto& o : observers_) o->open(c_);
  due_.clear();
  for (const auto& o : observers_) due_.push_back(o->next_look(sim_.step_count()));
  observers_stale_ = false;
}

void Run::make_observers() {
  for (const auto& o : observers_) o->save(book_);
  observers_ = observers_for(c_, progress_, snapshots_);
  observers_.push_back(std::make_unique<CheckpointEvent>(c_, *this));
}

Run::~Run() = default;

RunOutcome Run::go(std::uint64_t pause) {
  try {
    if (!opened_) open();
    return steps(pause);
  } catch (const WriteError& e) {
    stop_on_write_failure(e);
  } catch (const InstabilityError&) {
    // the last checkpoint stays as it was; the rate is this session's, to where it went unstable
    write_run_json(wall_now(), sim_.step_count() - c_.first_step, "unstable");
    throw;
  } catch (const std::bad_alloc&) {
    out_of_memory();
  }
}

// The process could not get memory (a limit, or other processes' use): say what was kept.
void Run::out_of_memory() const {
  const std::string dir = files_.dir().string();
  const std::string expected = readable_bytes(memory_estimate(sim_.world().particles.size()));
  if (!checkpointed_)
    throw std::runtime_error(fmt::format(
        "out of memory at t = {:.6g} s, before the run's first checkpoint, so nothing was kept "
        "to resume; with more memory (about {} are expected), or fewer particles, start it again "
        "with: talus run {}/scenario.toml --out {}",
        sim_.time(), expected, dir, dir));
  throw std::runtime_error(fmt::format(
      "out of memory at t = {:.6g} s; the last checkpoint is kept: with more memory (about {} "
      "are expected), continue with: talus resume {}",
      sim_.time(), expected, dir));
}

void Run::open() {
  session_start_ = std::chrono::steady_clock::now();
  session_wall_before_ = book_.wall_seconds;
  c_.first_step = sim_.step_count();
  opened_ = true;
  for (auto& o : observers_) o->open(c_);
  if (files_.fresh()) start();
  if (!o_.set_now.empty()) {
    change(o_.set_now, o_.set_now_source);
    refresh_observers();
  }
}

void Run::start() {
  for (auto& o : observers_) o->start(c_);
  checkpoint_at(0.0); // a run killed before its first interval continues from here
}

RunOutcome Run::steps(std::uint64_t pause) {
  pause_ = pause;
  // a run killed after its last checkpoint, while drawing its pictures, has its end recorded
  const bool finished_before = !book_.ended.empty();
  std::string ended = finished_before ? book_.ended : "duration";
  if (finished_before && !o_.quiet)
    fmt::print("the run had ended ({}); completing its pictures and run.json\n", ended);
  due_.clear();
  for (const auto& o : observers_) due_.push_back(o->next_look(sim_.step_count()));
  while (!finished_before && sim_.step_count() < c_.stop_step) {
    if (sim_.step_count() >= pause) return RunOutcome::paused;
    run_stretch(steps_to_next_look());
    follow_renumbering();
    look_after_step();
    if (!c_.end.empty()) {
      ended = c_.end;
      break;
    }
    if (o_.stop_requested && o_.stop_requested()) {
      checkpoint_at(wall_now());
      progress_.finish();
      write_run_json(wall_now(), sim_.step_count() - c_.first_step, "signal");
      return RunOutcome::interrupted;
    }
  }
  if (!finished_before) {
    if (sim_.step_count() < c_.total_steps && ended == "duration") ended = "stop_at";
    if (ended != "stop_at") finish(ended);
    checkpoint_at(wall_now());
  }
  progress_.finish();
  if (ended != "stop_at" && s_.output.picture)
    write_snapshot_png(sim_, (files_.dir() / "final.png").string(), 1200, SnapshotColour::speed);
  if (ended != "stop_at" && o_.end_pictures) o_.end_pictures(book_);
  write_run_json(wall_now(), sim_.step_count() - c_.first_step, ended);
  if (!o_.quiet)
    fmt::print("{} at t = {} s after {} steps; run folder {}\n",
               ended == "stop_at" ? "stopped (--stop-at)" : "finished",
               progress_.time_text(sim_.time()), sim_.step_count(), files_.dir().string());
  return ended == "stop_at" ? RunOutcome::stopped_at : RunOutcome::completed;
}

// The steps on the threads the chooser gives, timed for it; a change of its choice is said.
void Run::run_stretch(std::uint64_t steps) {
  sim_.use_threads(threads_.threads());
  const auto start = std::chrono::steady_clock::now();
  sim_.run(steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (threads_.took(seconds, steps, wall_now()) && !o_.quiet && !c_.progress_on_terminal)
    fmt::print("threads: {} from t = {:.6g} s ({:.3g} us a step on {}, {:.3g} on 1: the machine "
               "is {})\n",
               threads_.threads(), sim_.time(), 1e6 * threads_.time_all(), sim_.max_threads(),
               1e6 * threads_.time_one(), threads_.threads() == 1 ? "busy" : "free again");
}

// Steps to the next one after which an observer looks, at most 1000 so that a stop request is
// answered soon. Simulation::run does the steps in between with one pass over memory less each
// (the correction of one and the prediction of the next together).
std::uint64_t Run::steps_to_next_look() const {
  const std::uint64_t k = sim_.step_count();
  std::uint64_t next = std::min({c_.stop_step, k + 1000, std::max(pause_, k + 1)});
  for (const std::uint64_t d : due_) next = std::min(next, d);
  // a renumbering the run's own indices follow
  next = std::min(next, next_multiple(k, sim_.config().sort_interval));
  return next - k;
}

void Run::check_folder() const {
  if (!o_.folder_gone) return;
  if (const std::string why = o_.folder_gone(); !why.empty())
    throw FolderGone(fmt::format("{} at t = {:.6g} s; the run stops and writes nothing more, so "
                                 "that no other run's files are written into",
                                 why, sim_.time()));
}

void Run::look_after_step() {
  check_folder();
  const std::uint64_t k = sim_.step_count();
  for (std::size_t i = 0; i < observers_.size(); ++i) {
    if (due_[i] != k) continue;
    observers_[i]->look(c_);
    due_[i] = observers_[i]->next_look(k);
    if (!c_.end.empty()) return; // an event ended the run: the end's records follow
  }
  if (observers_stale_) refresh_observers();
}

void Run::change(const std::vector<std::string>& set, const std::string& source) {
  if (!o_.scenario_with)
    throw ScenarioError("this run cannot be changed as it goes (" + source + ")");
  std::vector<std::string> all = book_.overrides();
  all.insert(all.end(), set.begin(), set.end());
  Scenario next = o_.scenario_with(all);
  WorldChange done;
  done.energy_before = energies(sim_).total();
  done.wall_index = apply_scenario_change(sim_, s_, next, book_);
  // the engine starts again from its state, with its count of renumberings from 0: the run's
  // indices are the state's, nothing to follow
  renumberings_seen_ = sim_.renumberings();
  for (auto& o : observers_) o->changed(c_, done);
  book_.changes.push_back({sim_.step_count(), sim_.time(), source, set});
  files_.open("changes.csv", changes_header); // a change of nothing is listed too: the header
  for (const std::string& x : set) log_change(source, x);
  s_ = std::move(next);
  set_length();
  observers_stale_ = true;
}

void Run::log_change(const std::string& source, const std::string& change) {
  std::ostream& log = files_.open("changes.csv", changes_header);
  const auto quoted = [](std::string text) { // a CSV field: its quotes doubled
    for (std::size_t at = text.find('"'); at != std::string::npos; at = text.find('"', at + 2))
      text.insert(at, 1, '"');
    return '"' + text + '"';
  };
  log << fmt::format("{:.9g},{},{},{}\n", sim_.time(), sim_.step_count(), quoted(source),
                     quoted(change));
}

// The engine renumbers the particles now and then (simulation.sort_every): the run's own
// particle indices (tracked grains, wall groups) follow.
void Run::follow_renumbering() {
  if (sim_.renumberings() == renumberings_seen_) return;
  renumberings_seen_ = sim_.renumberings();
  const std::vector<std::uint32_t>& to = sim_.new_indices();
  for (std::uint32_t& i : book_.tracked) i = to[i];
  for (auto& [name, g] : book_.groups)
    for (std::uint32_t& i : g.particles) i = to[i];
}

// The end's state is always recorded, though an interval may not divide the duration; the
// checkpoint that follows says the run ended, so a resume never records it twice.
void Run::finish(const std::string& why) {
  book_.ended = why;
  for (auto& o : observers_) o->finish(c_);
}

void Run::checkpoint() {
  checkpoint_at(wall_now());
}

void Run::stop_here() {
  if (!opened_ || ended()) return;
  checkpoint_at(wall_now());
  progress_.finish();
  write_run_json(wall_now(), sim_.step_count() - c_.first_step, "stop_at");
}

void Run::checkpoint_at(double wall) {
  check_folder();
  files_.flush();
  book_.file_bytes = files_.sizes();
  book_.wall_seconds = wall;
  for (const auto& o : observers_) o->save(book_);
  const Checkpoint c{sim_.state(), sim_.config(), book_.encode()};
  const fs::path latest = files_.dir() / "checkpoint.bin";
  const fs::path previous = files_.dir() / "checkpoint.prev.bin";
  if (fs::exists(latest)) fs::rename(latest, previous);
  write_file_atomically(latest.string(), encode_checkpoint(c));
  checkpointed_ = true;
  checkpointed_snapshots_ = book_.snapshots;
}

// A write failed (a full disk, a file size limit): every output is cut back to what the last
// checkpoint holds, so the folder reads as the run stopped there and resume continues it.
void Run::stop_on_write_failure(const WriteError& e) {
  files_.close();
  if (e.error() == ENOENT) stop_on_deleted_file(e);
  check_folder(); // a folder deleted under the run is the true cause, and nothing is cut back
  const fs::path& dir = files_.dir();
  if (!checkpointed_) // nothing to continue from: the command that starts it again
    throw std::runtime_error(std::string(e.what()) +
                             ", before the run's first checkpoint; make room, then start it "
                             "again with: talus run " +
                             (dir / "scenario.toml").string() + " --out " + dir.string());
  std::error_code ignored;
  cut_back_outputs(dir, book_.file_bytes, checkpointed_snapshots_, ignored);
  book_.snapshots = checkpointed_snapshots_;
  try { // the collections and run.json need a little room too; the checkpoint is what counts
    snapshots_->cut_back(c_);
    write_run_json(book_.wall_seconds, 0, "write_error");
  } catch (const WriteError&) {
  }
  throw std::runtime_error(std::string(e.what()) +
                           "; the outputs are cut back to the last checkpoint, which is kept; "
                           "make room, then: talus resume " +
                           dir.string());
}

// A file the run had just written, or the folder it goes in, vanished: something is deleting
// the run folder, and may not yet have reached the lock by which the folder is known. Room is not
// the cause and cutting back would write into the folder, so the run waits a moment for the
// deletion to show, then stops, writing nothing more.
void Run::stop_on_deleted_file(const WriteError& e) {
  for (int tries = 0; tries < 200; ++tries) {
    check_folder();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  throw FolderGone(fmt::format("files of the run folder '{}' were deleted under the running run "
                               "({}) at t = {:.6g} s; the run stops and writes nothing more",
                               files_.dir().string(), e.what(), sim_.time()));
}

void Run::write_run_json(double wall, std::uint64_t steps_done, const std::string& ended) {
  check_folder();
  write_file_atomically(
      (files_.dir() / "run.json").string(),
      run_json(s_, sim_, book_, wall, wall - session_wall_before_, steps_done, ended));
}

double Run::wall_now() const {
  return session_wall_before_ +
         std::chrono::duration<double>(std::chrono::steady_clock::now() - session_start_).count();
}

} // namespace talus::run
