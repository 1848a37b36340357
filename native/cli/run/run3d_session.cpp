#include "cli/run/run3d_session.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/core.h>
#include <fmt/format.h>

#include "analysis/stress3.hpp"
#include "cli/run/thermo3.hpp"
#include "io/checkpoint3.hpp"
#include "io/vtk.hpp"
#include "io/vtk_spheres.hpp"
#include "run/progress.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/file/stages.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// The contacts' file of the spheres' snapshot `spheres` (snapshots/spheres_NNNNNN.vtp): the book
// keeps the spheres' and plates' names, and the contacts' follow from them.
std::string contacts_name(const std::string& spheres) {
  std::string name = spheres;
  const auto at = name.rfind("spheres_");
  return at == std::string::npos ? name : name.replace(at, 7, "contacts");
}

// The collections of the snapshots the book lists.
void write_collections3(const fs::path& dir, const Book3& book) {
  std::vector<std::pair<double, std::string>> contacts;
  for (const auto& [t, name] : book.spheres) contacts.emplace_back(t, contacts_name(name));
  write_file_atomically((dir / "particles.pvd").string(), pvd_collection(book.spheres));
  write_file_atomically((dir / "walls.pvd").string(), pvd_collection(book.plates));
  write_file_atomically((dir / "contacts.pvd").string(), pvd_collection(contacts));
}

// A snapshot of the spheres, one of the plates and one of the contacts, listed in the book and
// their collections. With output.stress, each sphere's stress too.
void write_snapshot(const fs::path& dir, const Simulation3& sim, double reach, bool stress,
                    Book3& book) {
  const std::string k = fmt::format("{:06d}", book.spheres.size());
  const std::string s = "snapshots/spheres_" + k + ".vtp", p = "snapshots/plates_" + k + ".vtp";
  std::vector<Tensor3> stresses;
  if (stress) stresses = sphere_stresses(sim);
  write_file_atomically((dir / s).string(), vtp_spheres(sim.scene(), stresses));
  write_file_atomically((dir / p).string(), vtp_plates(sim.scene(), reach));
  write_file_atomically((dir / contacts_name(s)).string(), vtp_contacts3(sim));
  book.spheres.emplace_back(sim.time(), s);
  book.plates.emplace_back(sim.time(), p);
  write_collections3(dir, book);
}

std::string run_json(const Scenario3& s, const Simulation3& sim, double collision_time, double wall,
                     std::uint64_t steps_done, const std::string& ended) {
  const std::size_t n = sim.scene().spheres.size();
  const double rate = wall > 0 ? static_cast<double>(steps_done * n) / wall : 0.0;
  return fmt::format(
      "{{\n  \"talus_version\": \"{}\",\n  \"scenario\": \"{}\",\n  \"dimension\": 3,\n"
      "  \"seed\": {},\n  \"particles\": {},\n  \"plates\": {},\n  \"steps\": {},\n"
      "  \"time\": {:.9g},\n  \"timestep\": {:.9g},\n  \"collision_time\": {:.9g},\n"
      "  \"integrator\": \"{}\",\n  \"threads\": {},\n  \"step\": \"{}\",\n"
      "  \"wall_seconds\": {:.6f},\n"
      "  \"particle_steps_per_second\": {:.6g},\n  \"ended_by\": \"{}\"\n}}\n",
      TALUS_VERSION, s.name, s.simulation.seed, n, sim.scene().plates.size(), sim.step_count(),
      sim.time(), sim.settings().timestep, collision_time, to_string(sim.settings().integrator),
      sim.threads(), sim.step_description(), wall, rate, ended);
}

void checkpoint(const fs::path& dir, const Simulation3& sim, Book3& book, std::ofstream& thermo,
                const Thermo3& columns) {
  thermo.flush();
  book.ledger_state = columns.save();
  book.thermo_bytes = fs::file_size(dir / "thermo.csv");
  write_file_atomically((dir / "checkpoint.bin").string(),
                        encode_checkpoint3({sim.state(), sim.settings(), book.encode()}));
}

// talus resume --duration T: the run goes on to T s, T beyond where it stands, and its
// scenario.toml says so (the length alone changes: the steps up to the old end are the same).
// Without it, a run that has reached its end is refused, saying how to lengthen it.
void lengthen(Scenario3& s, const Checkpoint3& c, double duration, const fs::path& dir) {
  const double dt = c.settings.timestep;
  if (duration < 0.0) {
    if (c.state.steps >= steps_until(s.simulation.duration, dt))
      throw InvalidArgument(fmt::format("the run in '{}' has ended at t = {:.9g} s, its "
                                        "simulation.duration; run it on to T s with: talus "
                                        "resume {} --duration T",
                                        dir.string(), c.state.time, dir.string()));
    return;
  }
  if (!(duration > c.state.time))
    throw InvalidArgument(fmt::format("a duration of {:g} s: the run is at t = {:.9g} s already; "
                                      "allowed: a longer whole length",
                                      duration, c.state.time));
  s.simulation.duration = duration;
  write_file_atomically((dir / "scenario.toml").string(), to_toml(s));
}

// The keys `talus resume --set` changes in a 3D run: its outputs' intervals, which leave the
// physics and so the run's bits as they were.
constexpr std::array<const char*, 3> changeable3{
    "output.thermo_interval", "output.snapshot_interval", "output.checkpoint_interval"};

void refuse_unchangeable3(const std::vector<std::string>& set) {
  for (const std::string& x : set) {
    const std::string key = change_key(x);
    if (std::ranges::find(changeable3, key) != changeable3.end()) continue;
    throw InvalidArgument(fmt::format("--set {}: a 3D run changes only its outputs' intervals "
                                      "as it goes on, for now; allowed: {} (--duration "
                                      "lengthens it)",
                                      x, fmt::join(changeable3, ", ")));
  }
}

} // namespace

std::string Book3::encode() const {
  std::string out = fmt::format("talus 3D run book\n{:.17g} {}\n{}\n", collision_time, thermo_bytes,
                                spheres.size());
  for (std::size_t k = 0; k < spheres.size(); ++k)
    out += fmt::format("{:.17g} {} {}\n", spheres[k].first, spheres[k].second, plates[k].second);
  if (!ledger_state.empty())
    out += fmt::format("ledger {}\n{:.17g}\n", ledger_state.size(), fmt::join(ledger_state, " "));
  return out;
}

Book3 Book3::decode(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string title;
  std::getline(in, title);
  Book3 b;
  std::size_t count = 0;
  if (title != "talus 3D run book" || !(in >> b.collision_time >> b.thermo_bytes >> count))
    throw CheckpointError(source + ": its run book is not a 3D run's");
  for (std::size_t k = 0; k < count; ++k) {
    double t = 0.0;
    std::string s, p;
    if (!(in >> t >> s >> p)) throw CheckpointError(source + ": its run book is cut short");
    b.spheres.emplace_back(t, s);
    b.plates.emplace_back(t, p);
  }
  std::string word;
  if (!(in >> word)) return b;
  if (word != "ledger" || !(in >> count) || count > 64) // a ledger holds a dozen numbers
    throw CheckpointError(source + ": its run book has '" + word + "' after the snapshots");
  b.ledger_state.resize(count);
  for (double& v : b.ledger_state)
    if (!(in >> v)) throw CheckpointError(source + ": its run book's ledger is cut short");
  return b;
}

int run_session3(const Scenario3& s, Simulation3& sim, Book3& book, RunFolder& folder,
                 const RunOptions& o) {
  const fs::path& dir = folder.path();
  const double dt = sim.settings().timestep;
  const std::uint64_t total = steps_until(s.simulation.duration, dt);
  const std::uint64_t stop = o.stop_at >= 0.0 ? std::min(total, steps_until(o.stop_at, dt)) : total;
  const auto every = [&](double interval) {
    return interval > 0.0 ? std::max<std::uint64_t>(1, steps_until(interval, dt)) : 0;
  };
  const std::uint64_t thermo_every = every(s.output.thermo_interval),
                      snapshot_every = every(s.output.snapshot_interval),
                      checkpoint_every = every(s.output.checkpoint_interval);
  const double reach = norm(s.geometry.hi - s.geometry.lo);
  const bool fresh = book.spheres.empty() && book.thermo_bytes == 0;
  Thermo3 columns(s, book.ledger_state);
  std::ofstream thermo(dir / "thermo.csv", fresh ? std::ios::trunc : std::ios::app);
  if (fresh) {
    columns.start(sim);
    thermo << columns.header() << columns.row(sim, book.collision_time);
    if (snapshot_every > 0) write_snapshot(dir, sim, reach, s.output.stress, book);
  }
  run::RunProgress progress(o.quiet, s.simulation.duration, s.output.thermo_interval, dt);
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t first = sim.step_count();
  const auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const auto record = [&](const std::string& ended) {
    write_file_atomically((dir / "run.json").string(), run_json(s, sim, book.collision_time, wall(),
                                                                sim.step_count() - first, ended));
  };
  while (sim.step_count() < stop) {
    if (stop_signal()) {
      checkpoint(dir, sim, book, thermo, columns);
      progress.finish();
      fmt::print(stderr,
                 "talus: interrupted at t = {:.6g} s after a checkpoint; continue with: "
                 "talus resume {}\n",
                 sim.time(), dir.string());
      return exit_interrupted;
    }
    const std::uint64_t k = sim.step_count() + 1;
    try {
      sim.step();
      columns.look(sim);
      if (k % thermo_every == 0 || k == total) thermo << columns.row(sim, book.collision_time);
    } catch (const InstabilityError&) { // the last checkpoint and the outputs up to here stay
      thermo.close();
      record("unstable");
      throw;
    }
    if (snapshot_every > 0 && (k % snapshot_every == 0 || k == total))
      write_snapshot(dir, sim, reach, s.output.stress, book);
    if ((checkpoint_every > 0 && k % checkpoint_every == 0) || k == stop)
      checkpoint(dir, sim, book, thermo, columns);
    if (k % 256 == 0 || k == stop)
      progress.report(sim.time(), k, total, stop, wall(), k - first, sim.energies().kinetic);
  }
  progress.finish();
  if (stop < total) {
    if (!o.quiet)
      fmt::print("stopped at t = {:.6g} s after a checkpoint; continue with: talus resume {}\n",
                 sim.time(), dir.string());
    return exit_stopped;
  }
  thermo.close();
  record("duration");
  if (!o.quiet)
    fmt::print("finished at t = {:.6g} s after {} steps; run folder {}\n", sim.time(),
               sim.step_count(), dir.string());
  return exit_completed;
}

int resume_3d(RunFolder folder, const RunOptions& o) {
  refuse_unchangeable3(o.set);
  const fs::path& dir = folder.path();
  const std::string toml = (dir / "scenario.toml").string(),
                    bin = (dir / "checkpoint.bin").string();
  if (!fs::exists(bin))
    throw InvalidArgument("no checkpoint in '" + dir.string() + "': start it again with talus run");
  Scenario3 s = load_scenario3(read_file(toml), toml, o.set);
  Checkpoint3 c = decode_checkpoint3(read_file(bin), bin);
  Book3 book = Book3::decode(c.run_data, bin);
  // the outputs cut back to the checkpoint: thermo.csv's tail, the later snapshots
  if (fs::file_size(dir / "thermo.csv") < book.thermo_bytes)
    throw InvalidArgument((dir / "thermo.csv").string() + " is shorter than at the checkpoint");
  lengthen(s, c, o.duration, dir);
  // the run goes on with the outputs asked, and its scenario.toml says so
  if (!o.set.empty()) write_file_atomically(toml, to_toml(s));
  fs::resize_file(dir / "thermo.csv", book.thermo_bytes);
  for (const auto& e : fs::directory_iterator(dir / "snapshots")) {
    const std::string name = "snapshots/" + e.path().filename().string();
    bool kept = false;
    for (std::size_t k = 0; k < book.spheres.size(); ++k)
      kept = kept || name == book.spheres[k].second || name == book.plates[k].second ||
             name == contacts_name(book.spheres[k].second);
    if (!kept) fs::remove(e.path());
  }
  write_collections3(dir, book);
  fs::remove(dir / "run.json");
  if (o.threads >= 0) c.settings.threads = o.threads;
  Simulation3 sim = Simulation3::restore(std::move(c.state), c.settings);
  if (!o.quiet)
    fmt::print("talus resume {}: from t = {:.6g} s (step {})\n", dir.string(), sim.time(),
               sim.step_count());
  catch_stop_signals();
  return run_session3(s, sim, book, folder, o);
}

} // namespace talus::cli
