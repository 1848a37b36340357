#include "cli/run/run_loop.hpp"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/core.h>

#include "cli/pictures/pictures.hpp"
#include "cli/run/run_folder.hpp"
#include "cli/run/scenario_edits.hpp"
#include "io/checkpoint.hpp"
#include "run/progress.hpp"
#include "run/records.hpp"
#include "run/run.hpp"
#include "run/scenario_change.hpp"
#include "scenario/contact_pairs.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/stages.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

volatile std::sig_atomic_t stop_requested = 0;
void on_signal(int) {
  stop_requested = 1;
}

} // namespace

void catch_stop_signals() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool stop_signal() {
  return stop_requested != 0;
}

void scenario_pictures(const Scenario& s, const fs::path& dir, const run::RunBook& book,
                       bool quiet) {
  for (const std::string& p : s.output.pictures) {
    const PictureRequest r = parse_picture_request(p);
    render_run(dir, r, "last", 1200, dir / "pictures");
    if (!quiet)
      fmt::print(
          "picture: {}\n",
          (dir / "pictures" / fmt::format("{}_{:06d}.png", picture_stem(r), book.snapshots - 1))
              .string());
  }
  if (s.output.movie) {
    const std::size_t n = make_movie(dir, {s.output.movie_color, false, false}, 10.0, 1200);
    if (!quiet) fmt::print("movie: {} ({} frames)\n", (dir / "movie.mp4").string(), n);
  }
}

namespace {

// Runs to the end (or a stop) in dir, answering SIGINT and SIGTERM with a checkpoint. `set`: the
// changes this session makes as it starts (talus resume --set, --duration), from `source`.
int go(const Scenario& s, Simulation sim, run::RunBook book, const RunFolder& folder,
       const RunOptions& o, bool fresh, std::vector<std::string> set = {},
       std::string source = {}) {
  const fs::path& dir = folder.path();
  run::RunControl control;
  control.folder_gone = [&folder] { return folder.gone(); };
  control.stop_at = o.stop_at;
  control.quiet = o.quiet;
  const std::string scenario_file = (dir / "scenario.toml").string();
  control.scenario_with = [scenario_file](const std::vector<std::string>& changes) {
    return load_scenario_file(scenario_file, changes);
  };
  control.set_now = std::move(set);
  control.set_now_source = std::move(source);
  control.stop_requested = [] { return stop_requested != 0; };
  control.end_pictures = [&](const run::RunBook& b) { scenario_pictures(s, dir, b, o.quiet); };
  run::Run r(s, std::move(sim), std::move(book), dir, std::move(control), fresh);
  catch_stop_signals(); // a signal caught while settling stays caught
  switch (r.go()) {
  case run::RunOutcome::completed:
    return exit_completed;
  case run::RunOutcome::stopped_at:
    return exit_stopped;
  case run::RunOutcome::interrupted:
  case run::RunOutcome::paused: // go() without a pause step never pauses
    break;
  }
  fmt::print(stderr,
             "talus: interrupted at t = {:.6g} s; checkpoint written. Continue with: "
             "talus resume {}\n",
             r.simulation().time(), dir.string());
  return exit_interrupted;
}

// A run stopped before its first checkpoint (killed while settling, say) has nothing to
// continue from: it starts again from its scenario.toml, which holds the whole resolved
// scenario, so a requeue that resumes after each kill always gets somewhere. --set and
// --duration apply from its start.
// --set of a key a run cannot change is refused, naming the keys that can.
void refuse_unchangeable(const std::vector<std::string>& set) {
  for (const std::string& x : set)
    if (!changeable_during_run(change_key(x)))
      throw InvalidArgument("--set " + x + ": '" + change_key(x) +
                            "' cannot change during a run; allowed: " + changeable_keys_text());
}

// What this session changes from its resume point: the edits of scenario.toml, then --set and
// --duration, with their source for changes.csv and the run's new whole length (-1: as it was).
struct SessionChanges {
  std::vector<std::string> set;
  std::string source;
  double duration = -1.0;
};

SessionChanges session_changes(std::vector<std::string> edits, const RunOptions& o) {
  refuse_unchangeable(o.set);
  SessionChanges c{std::move(edits), {}, o.duration};
  if (!c.set.empty()) c.source = "scenario.toml edited";
  for (const std::string& x : c.set)
    if (change_key(x) == "simulation.duration" && c.duration < 0.0)
      c.duration = std::stod(x.substr(x.find('=') + 1));
  c.set.insert(c.set.end(), o.set.begin(), o.set.end());
  std::string resume_words = o.set.empty() ? "" : "resume --set";
  if (o.duration >= 0.0) {
    resume_words += resume_words.empty() ? "resume --duration" : " --duration";
    c.set.push_back(fmt::format("simulation.duration={}", o.duration));
  }
  if (!resume_words.empty()) c.source += (c.source.empty() ? "" : ", ") + resume_words;
  return c;
}

int start_again(const std::string& text, const std::string& scenario_file, RunFolder& folder,
                const RunOptions& o) {
  refuse_unchangeable(o.set);
  std::vector<std::string> set = o.set;
  if (o.duration >= 0.0) set.push_back(fmt::format("simulation.duration={}", o.duration));
  const Scenario s = load_scenario(text, scenario_file, set);
  if (!o.quiet)
    fmt::print("'{}' was stopped before its first checkpoint (while settling, say): starting it "
               "again from its scenario.toml\n",
               folder.path().string());
  folder.start_afresh(s);
  return settle_and_start(s, std::move(folder), o, scenario_file);
}

} // namespace

std::pair<Simulation, run::RunBook> begin_run(const Scenario& s, BuiltScenario built,
                                              const RunFolder& folder, int threads) {
  run::RunBook book = run::RunBook::of(built);
  // the resolved scenario, now with the dampers derived for the built grains
  book.run_id = run::new_run_id();
  const std::string text = run::run_id_line(book.run_id) + to_toml(s) +
                           describe_contact_pairs(built.world, built.pairs, built.config);
  write_file_atomically((folder.path() / "scenario.toml").string(), text);
  write_file_atomically(started_copy(folder.path()).string(), text);
  book.scenario_hash = fnv1a_hash(text);
  SimulationConfig config = built.config;
  if (threads >= 0) config.threads = threads;
  return {Simulation(std::move(built.world), config), std::move(book)};
}

int start_run(const Scenario& s, BuiltScenario built, RunFolder folder, const RunOptions& o) {
  auto [sim, book] = begin_run(s, std::move(built), folder, o.threads);
  run::report_opening(sim, o.quiet);
  return go(s, std::move(sim), std::move(book), folder, o, true);
}

int start_run(const Scenario& s, BuiltScenario built, const std::string& dir, const RunOptions& o) {
  return start_run(s, std::move(built), RunFolder::create(dir, s), o);
}

std::pair<Checkpoint, run::RunBook> checkpoint_to_resume(const fs::path& d,
                                                         const std::string& text) {
  const std::string dir = d.string(), scenario_file = (d / "scenario.toml").string();
  std::vector<std::string> why;
  for (const char* name : {"checkpoint.bin", "checkpoint.prev.bin"}) {
    const fs::path p = d / name;
    if (!fs::exists(p)) continue;
    if (!why.empty()) fmt::print(stderr, "talus: {}; trying the previous checkpoint\n", why.back());
    Checkpoint c;
    try {
      c = decode_checkpoint(read_file(p.string()), p.string());
    } catch (const CheckpointError& e) {
      why.push_back(e.what());
      continue;
    }
    run::RunBook book = run::RunBook::decode(c.run_data);
    const std::uint64_t folder_run = run::run_id_in(text);
    if (book.run_id != 0 && folder_run != 0 && book.run_id != folder_run) {
      why.push_back(fmt::format("{} belongs to another run ({:016x}, {} particles at t = {:.6g} "
                                "s) than '{}' ({:016x}); a checkpoint continues only the run "
                                "that wrote it",
                                p.string(), book.run_id, c.state.world.particles.size(),
                                c.state.time, scenario_file, folder_run));
      continue;
    }
    if (const std::string short_of = run::outputs_short_of(d, book.file_bytes, book.snapshots);
        !short_of.empty()) {
      why.push_back(fmt::format("the outputs fall short of {} (t = {:.6g} s): {}", p.string(),
                                c.state.time, short_of));
      continue;
    }
    return {std::move(c), std::move(book)};
  }
  if (why.empty()) throw InvalidArgument("no checkpoint in '" + dir + "'");
  std::string all;
  for (const std::string& w : why) all += (all.empty() ? "" : "; ") + w;
  throw InvalidArgument("'" + dir + "' cannot be resumed: " + all +
                        ". Put back the run's own files, or start it again with: talus run " +
                        scenario_file + " --out NEW_FOLDER");
}

Resumption prepare_resume(const RunFolder& folder, const RunOptions& o) {
  const fs::path& d = folder.path();
  const std::string dir = d.string(), scenario_file = (d / "scenario.toml").string();
  const std::string text = read_file(scenario_file);
  auto [c, book] = checkpoint_to_resume(d, text);
  // an edit of scenario.toml: the keys a run may change, changed from here as --set does
  std::string started = text;
  std::vector<std::string> edits;
  if (book.scenario_hash != 0 && fnv1a_hash(text) != book.scenario_hash)
    edits = scenario_edits(d, text, book, started);
  // the run's scenario now: the file as it started with the changes made so far
  const Scenario s = load_scenario(started, scenario_file, book.overrides());
  auto [set, source, duration] = session_changes(std::move(edits), o);
  if (duration >= 0.0) {
    if (!(duration > c.state.time))
      throw InvalidArgument(fmt::format("a duration of {:g} s: the run is at t = {:.9g} s already; "
                                        "allowed: a longer whole length",
                                        duration, c.state.time));
    book.ended.clear(); // a finished run goes on
  } else if (!book.ended.empty() && !set.empty()) {
    throw InvalidArgument("the run in '" + dir + "' has ended (" + book.ended + "): " + source +
                          " changes it from there on; give --duration T too (or edit "
                          "simulation.duration), to run it on to T s");
  }
  if (!set.empty()) { // the values checked before anything is touched
    std::vector<std::string> all = book.overrides();
    all.insert(all.end(), set.begin(), set.end());
    const Scenario next = load_scenario(started, scenario_file, all);
    // and what they do to the engine (walls, the timestep), tried on a copy
    Simulation probe = Simulation::restore(c.state, c.config);
    run::RunBook probe_book = book;
    run::apply_scenario_change(probe, s, next, probe_book);
  }
  if (started != text) { // the edits are changes now (changes.csv); the file is as it started
    write_file_atomically(scenario_file, started);
    if (!o.quiet)
      fmt::print("{}: the edits are changes from t = {:.6g} s on (changes.csv); the file is put "
                 "back as the run started\n",
                 scenario_file, c.state.time);
  }
  std::error_code cut;
  run::cut_back_outputs(d, book.file_bytes, book.snapshots, cut);
  if (cut)
    throw WriteError("cannot cut the outputs of '" + dir +
                     "' back to its checkpoint: " + cut.message());
  SimulationConfig config = c.config;
  if (o.threads >= 0) config.threads = o.threads;
  return {s, Simulation::restore(std::move(c.state), config), std::move(book), std::move(set),
          std::move(source)};
}

int resume_run(const std::string& dir, const RunOptions& o) {
  const fs::path d(dir);
  if (!fs::exists(d / "scenario.toml") && !never_checkpointed(d))
    throw InvalidArgument("'" + dir + "' is not a talus run folder (no scenario.toml)");
  RunFolder folder = RunFolder::open(dir); // held until the run ends
  if (!fs::exists(d / "scenario.toml"))    // killed before it wrote even its scenario
    throw InvalidArgument("'" + dir + "' has no checkpoint: the run was stopped at its start; " +
                          "start it again with: talus run SCENARIO --out " + dir);
  const std::string scenario_file = (d / "scenario.toml").string();
  if (never_checkpointed(d)) return start_again(read_file(scenario_file), scenario_file, folder, o);
  Resumption r = prepare_resume(folder, o);
  run::report_opening(r.sim, o.quiet);
  if (!o.quiet)
    fmt::print("resuming {} at t = {:.6g} s (step {})\n", dir, r.sim.time(), r.sim.step_count());
  return go(r.scenario, std::move(r.sim), std::move(r.book), folder, o, false, std::move(r.set),
            std::move(r.source));
}

} // namespace talus::cli
