#include "cli/run_loop.hpp"

#include "cli/run_folder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include <fmt/core.h>

#include "analysis/contact_events.hpp"
#include "analysis/energy_ledger.hpp"
#include "analysis/observables.hpp"
#include "cli/pictures.hpp"
#include "cli/run_progress.hpp"
#include "cli/run_records.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "io/thesis_format.hpp"
#include "render/snapshot_png.hpp"
#include "scenario/contact_pairs.hpp"
#include "scenario/frost_setup.hpp"
#include "scenario/load.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

volatile std::sig_atomic_t stop_requested = 0;
void on_signal(int) {
  stop_requested = 1;
}

// A count of steps, from a time in steps (rounded as the caller chose). A count beyond any run
// (an interval of years, or a scenario.toml edited before a resume) is cut to one no run reaches,
// since converting a larger number to an integer is undefined.
std::uint64_t step_count(double steps) {
  return static_cast<std::uint64_t>(std::clamp(steps, 0.0, 1e18));
}

std::uint64_t every(double interval, double dt) {
  if (interval <= 0.0) return 0;
  return std::max<std::uint64_t>(1, step_count(std::round(interval / dt)));
}

class Run {
public:
  Run(const Scenario& s, Simulation sim, RunBook book, fs::path dir, const RunOptions& o)
      : s_(s), sim_(std::move(sim)), book_(std::move(book)), dir_(std::move(dir)), o_(o),
        progress_(o.quiet, s.simulation.duration, s.output.thermo_interval,
                  sim_.config().timestep) {
    const double dt = sim_.config().timestep;
    total_ = step_count(std::ceil(s.simulation.duration / dt - 1e-9));
    stop_ =
        o.stop_at >= 0.0 ? std::min(total_, step_count(std::ceil(o.stop_at / dt - 1e-9))) : total_;
    thermo_every_ = every(s.output.thermo_interval, dt);
    snapshot_every_ = every(s.output.snapshot_interval, dt);
    track_every_ = std::max<std::uint64_t>(1, every(s.output.track_interval, dt));
    checkpoint_every_ = every(s.output.checkpoint_interval, dt);
    checkpointed_ = !book_.file_bytes.empty(); // resumed: from a checkpoint
    checkpointed_snapshots_ = book_.snapshots;
    if (s.frost.model == "front") {
      front_.emplace(front_parameters(s, sim_.world().particles, book_.bounds));
      if (!book_.front_state.empty())
        front_->load(book_.front_state, sim_.world().particles.size());
      const double phase = std::min(s.frost.freeze_time, s.frost.thaw_time);
      front_every_ = std::max<std::uint64_t>(1, step_count(std::floor(phase / 1000.0 / dt)));
    }
    if (s.output.contacts) {
      contact_log_.emplace();
      if (!book_.contact_state.empty()) contact_log_->load(book_.contact_state);
      contact_log_->remember(sim_);
    }
    if (s.output.energy_ledger) {
      ledger_.emplace();
      if (!book_.ledger_state.empty()) ledger_->load(book_.ledger_state);
    }
  }

  void open_files(bool fresh) {
    const auto mode = fresh ? std::ios::out | std::ios::trunc : std::ios::out | std::ios::app;
    thermo_.open(dir_ / "thermo.csv", mode);
    if (!book_.tracked.empty()) track_.open(dir_ / "track.csv", mode);
    if (s_.output.thesis_out) out_.open(dir_ / "run.out", mode);
    if (s_.frost.model != "none") frost_.open(dir_ / "frost.csv", mode);
    if (contact_log_) events_.open(dir_ / "contact_events.csv", mode);
    if (!thermo_) throw WriteError("cannot write " + (dir_ / "thermo.csv").string());
    if (!fresh) return;
    if (ledger_) ledger_->start(sim_);
    thermo_ << thermo_header(book_, ledger_.has_value());
    if (track_.is_open()) track_ << "time,id,x,y,angle,vx,vy,omega\n";
    if (frost_.is_open()) frost_ << "cycle,time,event\n";
    if (events_.is_open()) events_ << contact_events_header();
    observe_contacts();
    if (out_.is_open()) out_ << thesis_out_header(sim_, s_.simulation.duration);
    record_thermo();
    record_track();
    write_snapshot();
    if (out_.is_open()) out_ << thesis_out_block(sim_);
    checkpoint(0.0); // a run killed before its first interval continues from here
  }

  // Opens the outputs (fresh: a new run) and steps to the end.
  int loop(bool fresh) {
    try {
      open_files(fresh);
      return loop_steps();
    } catch (const WriteError& e) {
      stop_on_write_failure(e);
    } catch (const InstabilityError&) {
      write_run_json(book_.wall_seconds, 0, "unstable"); // the last checkpoint stays as it was
      throw;
    }
  }

  int loop_steps() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    stop_requested = 0;
    const auto start = std::chrono::steady_clock::now();
    session_wall_before_ = book_.wall_seconds;
    const std::uint64_t first_step = sim_.step_count();
    const auto wall_now = [&] {
      return session_wall_before_ +
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // a run killed after its last checkpoint, while drawing its pictures, has its end recorded
    const bool finished_before = !book_.ended.empty();
    std::string ended = finished_before ? book_.ended : "duration";
    if (finished_before && !o_.quiet)
      fmt::print("the run had ended ({}); completing its pictures and run.json\n", ended);
    while (!finished_before && sim_.step_count() < stop_) {
      sim_.run(steps_to_next_look());
      follow_renumbering();
      const std::uint64_t k = sim_.step_count();
      observe_contacts();
      if (ledger_) ledger_->observe(sim_);
      if (!book_.tracked.empty() && k % track_every_ == 0) record_track();
      if (k % thermo_every_ == 0) {
        record_thermo();
        progress_.report(sim_.time(), k, total_, stop_, wall_now() - session_wall_before_,
                         k - first_step, last_kinetic_);
        if (frost_cycles_done()) {
          ended = "cycles";
          break;
        }
      }
      if (front_ && front_->phase() != FrostFront::Phase::idle && k % front_every_ == 0)
        advance_front();
      if (snapshot_every_ && k % snapshot_every_ == 0) {
        write_snapshot();
        if (out_.is_open()) out_ << thesis_out_block(sim_);
      }
      if (checkpoint_every_ && k % checkpoint_every_ == 0) checkpoint(wall_now());
      if (stop_requested) return stop_on_signal(wall_now(), first_step);
    }
    if (!finished_before) {
      if (sim_.step_count() < total_ && ended == "duration") ended = "stop_at";
      if (ended != "stop_at") record_end(ended);
      checkpoint(wall_now());
    }
    progress_.finish();
    if (ended != "stop_at" && s_.output.picture) {
      write_snapshot_png(sim_, (dir_ / "final.png").string(), 1200, SnapshotColour::speed);
    }
    if (ended != "stop_at") scenario_pictures();
    write_run_json(wall_now(), sim_.step_count() - first_step, ended);
    if (!o_.quiet)
      fmt::print("{} at t = {} s after {} steps; run folder {}\n",
                 ended == "stop_at" ? "stopped (--stop-at)" : "finished",
                 progress_.time_text(sim_.time()), sim_.step_count(), dir_.string());
    return ended == "stop_at" ? exit_stopped : exit_completed;
  }

private:
  // The frost models at a thermo row: the uniform rule freezes when the grains are at rest; the
  // front model starts a freeze then. True when the run has had its frost.cycles.
  bool frost_cycles_done() {
    const auto done = [&] { return s_.frost.cycles > 0 && book_.freezes >= s_.frost.cycles; };
    if (s_.frost.model == "uniform" && freeze() && done()) return true;
    if (front_ && front_->phase() == FrostFront::Phase::idle && at_rest()) {
      if (done()) {
        log_frost("end");
        return true;
      }
      front_->start_freeze(sim_);
      ++book_.freezes;
      log_frost("freeze");
    }
    return false;
  }

  // The front model's freeze or thaw front moves on; it logs when a phase ends.
  void advance_front() {
    if (!front_->advance(sim_)) return;
    if (front_->phase() == FrostFront::Phase::thawing) {
      log_frost("thaw");
    } else {
      book_.last_freeze = sim_.time(); // the next cycle waits min_interval after the thaw
      log_frost("thawed");
    }
  }

  // SIGINT or SIGTERM: a checkpoint, then the command that continues the run.
  int stop_on_signal(double wall, std::uint64_t first_step) {
    checkpoint(wall);
    progress_.finish();
    fmt::print(stderr,
               "talus: interrupted at t = {:.6g} s; checkpoint written. Continue with: "
               "talus resume {}\n",
               sim_.time(), dir_.string());
    write_run_json(wall, sim_.step_count() - first_step, "signal");
    return exit_interrupted;
  }

  // The end's state is always recorded, though an interval may not divide the duration; the
  // checkpoint that follows says the run ended, so a resume never records it twice.
  void record_end(const std::string& why) {
    const std::uint64_t k = sim_.step_count();
    if (k % thermo_every_ != 0) record_thermo();
    if (!book_.tracked.empty() && k % track_every_ != 0) record_track();
    // (a snapshot less than half an interval before the end stands for it: no near-twin frames)
    if (snapshot_every_ && k % snapshot_every_ >= (snapshot_every_ + 1) / 2) {
      end_snapshot_step_ = k;
      write_snapshot();
      if (out_.is_open()) out_ << thesis_out_block(sim_);
    }
    if (contact_log_) // the contacts still touching, once: the checkpoint after says it ended
      for (const ContactEvent& e : contact_log_->open_events()) events_ << contact_event_row(e);
    book_.ended = why;
  }

  // output.contacts: the contacts are looked at after every step, and those that ended are
  // written.
  void observe_contacts() {
    if (!contact_log_) return;
    for (const ContactEvent& e : contact_log_->observe(sim_)) events_ << contact_event_row(e);
  }

  // The pictures and the movie the scenario asks for (output.pictures, output.movie).
  void scenario_pictures() {
    for (const std::string& p : s_.output.pictures) {
      const PictureRequest r = parse_picture_request(p);
      render_run(dir_, r, "last", 1200, dir_ / "pictures");
      if (!o_.quiet)
        fmt::print(
            "picture: {}\n",
            (dir_ / "pictures" / fmt::format("{}_{:06d}.png", picture_stem(r), book_.snapshots - 1))
                .string());
    }
    if (s_.output.movie) {
      const std::size_t n = make_movie(dir_, {s_.output.movie_color, false, false}, 10.0, 1200);
      if (!o_.quiet) fmt::print("movie: {} ({} frames)\n", (dir_ / "movie.mp4").string(), n);
    }
  }

  void record_thermo() {
    const Energies e = energies(sim_);
    std::string row = thermo_columns(sim_, s_, book_, e);
    if (ledger_) {
      const LedgerRow l = ledger_->row(e);
      // energy from nowhere: an instability the overlap guard has not seen (yet)
      if (l.growth > ledger_growth_limit)
        throw InstabilityError(energy_growth_diagnosis(sim_, l, book_.collision_time));
      row += fmt::format(",{:.9e},{:.9e},{:.9e},{:.9e}", l.dissipated_damper, l.dissipated_friction,
                         l.wall_work, l.imbalance);
    }
    thermo_ << row << group_force_columns(sim_, book_) << "\n";
    last_kinetic_ = e.kinetic();
  }

  // Steps to the next one after which the loop looks at the state (a record, a snapshot, a
  // checkpoint, the frost model, a renumbering to follow: at most one per call), at most 1000 so
  // that a signal is answered soon. Simulation::run does the steps in between with one pass
  // over memory less each (the correction of one and the prediction of the next together).
  std::uint64_t steps_to_next_look() const {
    const std::uint64_t k = sim_.step_count();
    std::uint64_t next = std::min(stop_, k + 1000);
    const auto look_at_multiples_of = [&](std::uint64_t every) {
      if (every > 0) next = std::min(next, (k / every + 1) * every);
    };
    look_at_multiples_of(thermo_every_);
    look_at_multiples_of(snapshot_every_);
    look_at_multiples_of(checkpoint_every_);
    if (!book_.tracked.empty()) look_at_multiples_of(track_every_);
    if (front_) look_at_multiples_of(front_every_);
    look_at_multiples_of(sim_.config().sort_interval);
    if (contact_log_ || ledger_) look_at_multiples_of(1);
    return next - k;
  }

  // The engine renumbers the particles now and then (simulation.sort_every): the run's own
  // particle indices (tracked grains, wall groups) follow.
  void follow_renumbering() {
    if (sim_.renumberings() == renumberings_seen_) return;
    renumberings_seen_ = sim_.renumberings();
    const std::vector<std::uint32_t>& to = sim_.new_indices();
    for (std::uint32_t& i : book_.tracked) i = to[i];
    for (auto& [name, g] : book_.groups)
      for (std::uint32_t& i : g.particles) i = to[i];
  }

  void record_track() { track_ << track_rows(sim_, book_.tracked); }

  void write_snapshot() {
    write_snapshot_files(dir_, sim_, book_.snapshots++, s_.output.contacts);
    write_collections();
  }

  void write_collections() {
    write_collections_of(dir_, book_.snapshots, snapshot_every_, end_snapshot_step_,
                         sim_.config().timestep, !sim_.world().walls.empty());
  }

  // The grains are at rest and the last freeze (or thaw) is at least min_interval ago.
  bool at_rest() {
    double weight_scale = 0.0; // sum of m g R over the free grains (a frost may hold some)
    const Particles& p = sim_.world().particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_free(i)) weight_scale += p.mass[i] * norm(sim_.world().gravity) * p.radius[i];
    return last_kinetic_ < s_.frost.kinetic_threshold * weight_scale &&
           sim_.time() - book_.last_freeze >= s_.frost.min_interval;
  }

  void log_frost(const char* event) {
    frost_ << fmt::format("{},{:.9g},{}\n", book_.freezes, sim_.time(), event);
    if (!o_.quiet && !progress_.on_terminal())
      fmt::print("frost: {} {} at t = {:.6g} s\n", event, book_.freezes, sim_.time());
  }

  // The thesis' freeze (sec. 5.2): when the grains have come to rest, every free grain's height
  // above the floor is multiplied by the heave factor. Returns true when it froze.
  bool freeze() {
    if (!at_rest()) return false;
    Particles& p = sim_.edit_world().particles;
    const double floor = book_.bounds.lo.y;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_free(i)) p.position[i].y = floor + (p.position[i].y - floor) * s_.frost.heave_factor;
    ++book_.freezes;
    book_.last_freeze = sim_.time();
    log_frost("freeze");
    return true;
  }

  void checkpoint(double wall) {
    for (auto [f, name] : {std::pair{&thermo_, "thermo.csv"},
                           {&track_, "track.csv"},
                           {&out_, "run.out"},
                           {&frost_, "frost.csv"},
                           {&events_, "contact_events.csv"}}) {
      f->flush();
      if (f->is_open() && !*f) throw WriteError("cannot write " + (dir_ / name).string());
    }
    book_.file_bytes.clear();
    for (const char* name :
         {"thermo.csv", "track.csv", "run.out", "frost.csv", "contact_events.csv"})
      if (fs::exists(dir_ / name)) book_.file_bytes[name] = fs::file_size(dir_ / name);
    book_.wall_seconds = wall;
    if (front_) book_.front_state = front_->save();
    if (contact_log_) book_.contact_state = contact_log_->save();
    if (ledger_) book_.ledger_state = ledger_->save();
    Checkpoint c{sim_.state(), sim_.config(), book_.encode()};
    const fs::path latest = dir_ / "checkpoint.bin", previous = dir_ / "checkpoint.prev.bin";
    if (fs::exists(latest)) fs::rename(latest, previous);
    write_file_atomically(latest.string(), encode_checkpoint(c));
    checkpointed_ = true;
    checkpointed_snapshots_ = book_.snapshots;
  }

  // A write failed (a full disk, a file size limit): every output is cut back to what the last
  // checkpoint holds, so the folder reads as the run stopped there and resume continues it.
  [[noreturn]] void stop_on_write_failure(const WriteError& e) {
    for (std::ofstream* g : {&thermo_, &track_, &out_, &frost_, &events_}) g->close();
    std::error_code ignored;
    if (!checkpointed_) // nothing to continue from: the command that starts it again
      throw std::runtime_error(std::string(e.what()) +
                               " (disk full or a file size limit?) before the run's first "
                               "checkpoint; make room, then start it again with: talus run " +
                               (dir_ / "scenario.toml").string() + " --out " + dir_.string());
    cut_back_outputs(dir_, book_.file_bytes, checkpointed_snapshots_, ignored);
    book_.snapshots = checkpointed_snapshots_;
    end_snapshot_step_ = 0; // an end snapshot, if written, was after the checkpoint
    try { // the collections and run.json need a little room too; the checkpoint is what counts
      write_collections();
      write_run_json(book_.wall_seconds, 0, "write_error");
    } catch (const WriteError&) {
    }
    throw std::runtime_error(std::string(e.what()) +
                             " (disk full or a file size limit?); the outputs are cut back to the "
                             "last checkpoint, which is kept; make room, then: talus resume " +
                             dir_.string());
  }

  void write_run_json(double wall, std::uint64_t steps_done, const std::string& ended) {
    write_file_atomically(
        (dir_ / "run.json").string(),
        run_json(s_, sim_, book_, wall, wall - session_wall_before_, steps_done, ended));
  }

  const Scenario& s_;
  Simulation sim_;
  RunBook book_;
  fs::path dir_;
  RunOptions o_;
  std::uint64_t total_ = 0, stop_ = 0;
  std::uint64_t thermo_every_ = 1, snapshot_every_ = 0, track_every_ = 1, checkpoint_every_ = 0;
  std::uint64_t end_snapshot_step_ = 0; ///< the step of the end's snapshot, if it has one
  std::ofstream thermo_, track_, out_, frost_, events_;
  std::optional<FrostFront> front_;
  std::optional<ContactEventLog> contact_log_;
  std::optional<EnergyLedger> ledger_;
  std::uint64_t front_every_ = 1;
  std::uint64_t renumberings_seen_ = 0;
  double last_kinetic_ = 0.0;
  bool checkpointed_ = false;                ///< a checkpoint of this run exists
  std::uint64_t checkpointed_snapshots_ = 0; ///< the snapshots the last checkpoint counts
  RunProgress progress_;
  double session_wall_before_ = 0.0; ///< wall seconds of the sessions before this one
};

SimulationConfig with_threads(SimulationConfig c, const RunOptions& o) {
  if (o.threads >= 0) c.threads = o.threads;
  return c;
}

} // namespace

int start_run(const Scenario& s, BuiltScenario built, RunFolder folder, const RunOptions& o) {
  RunBook book;
  book.tracked = built.tracked;
  book.groups = built.groups;
  book.fill = built.fill;
  book.bounds = built.bounds;
  book.settle_time = built.settle_time;
  book.collision_time = built.collision_time;
  // the resolved scenario, now with the dampers derived for the built grains
  write_file_atomically((folder.path() / "scenario.toml").string(),
                        to_toml(s) + describe_contact_pairs(built.world, built.config));
  Simulation sim(std::move(built.world), with_threads(built.config, o));
  report_opening(sim, o.quiet);
  Run run(s, std::move(sim), std::move(book), folder.path(), o);
  return run.loop(true);
}

int start_run(const Scenario& s, BuiltScenario built, const std::string& dir, const RunOptions& o) {
  return start_run(s, std::move(built), RunFolder::create(dir, s), o);
}

int resume_run(const std::string& dir, const RunOptions& o) {
  const fs::path d(dir);
  if (!fs::exists(d / "scenario.toml") && !never_checkpointed(d))
    throw InvalidArgument("'" + dir + "' is not a talus run folder (no scenario.toml)");
  const RunFolder folder = RunFolder::open(dir); // held until the run ends
  if (!fs::exists(d / "scenario.toml"))          // killed before it wrote even its scenario
    throw InvalidArgument("'" + dir + "' has no checkpoint: the run was stopped at its start; " +
                          "start it again with: talus run SCENARIO --out " + dir);
  const Scenario s = load_scenario_file((d / "scenario.toml").string());
  std::optional<Checkpoint> c;
  for (const char* name : {"checkpoint.bin", "checkpoint.prev.bin"}) {
    const fs::path p = d / name;
    if (!fs::exists(p)) continue;
    try {
      c = decode_checkpoint(read_file(p.string()), p.string());
      break;
    } catch (const CheckpointError& e) {
      fmt::print(stderr, "talus: {}; trying the previous checkpoint\n", e.what());
    }
  }
  if (!c && never_checkpointed(d))
    throw InvalidArgument("'" + dir + "' has no checkpoint: the run was stopped before its first " +
                          "(while settling, say); start it again with: talus run " +
                          (d / "scenario.toml").string() + " --out " + dir);
  if (!c) throw InvalidArgument("no usable checkpoint in '" + dir + "'");
  RunBook book = RunBook::decode(c->run_data);
  std::error_code cut;
  cut_back_outputs(d, book.file_bytes, book.snapshots, cut);
  if (cut)
    throw WriteError("cannot cut the outputs of '" + dir +
                     "' back to its checkpoint: " + cut.message());
  Simulation sim = Simulation::restore(std::move(c->state), with_threads(c->config, o));
  report_opening(sim, o.quiet);
  if (!o.quiet)
    fmt::print("resuming {} at t = {:.6g} s (step {})\n", dir, sim.time(), sim.step_count());
  Run run(s, std::move(sim), std::move(book), d, o);
  return run.loop(false);
}

} // namespace talus::cli
