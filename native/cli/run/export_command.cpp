// `talus export lammps SCENARIO DIR`: a native scenario as a LAMMPS case for the talus package.
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/run/run_folder.hpp"
#include "cli/run/scenario_source.hpp"
#include "io/lammps_export.hpp"
#include "io/lammps_export3.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/build3.hpp"

namespace talus::cli {

namespace {

// The command line as the user typed it, for the deck's header.
std::string command_line(const std::string& scenario, const std::string& dir,
                         const std::vector<std::string>& set) {
  std::string out = "talus export lammps " + scenario + " " + dir;
  for (const std::string& s : set) out.append(" --set ").append(s);
  return out;
}

// A run or sweep folder's marks: an export never writes among them.
bool holds_a_run(const std::filesystem::path& d) {
  for (const char* mark :
       {".lock", "checkpoint.bin", "checkpoint.prev.bin", "run.json", "sweep.json", "snapshots"})
    if (std::filesystem::exists(d / mark)) return true;
  return false;
}

// The folder must be new or empty, as talus run --out wants it; with --replace it may hold a
// previous export, never a run's or a sweep's files (a run folder's scenario.toml is its record).
void check_export_folder(const std::string& dir, bool replace) {
  namespace fs = std::filesystem;
  const fs::path d(dir);
  if (!fs::exists(d)) return;
  if (!fs::is_directory(d))
    throw InvalidArgument("'" + dir + "' is a file, not a folder; choose another folder");
  if (fs::is_empty(d)) return;
  if (holds_a_run(d)) {
    std::string holder;
    if (in_use(d, holder))
      throw InvalidArgument(
          "'" + dir + "' is in use by " +
          (holder.empty() ? std::string("another process") : "process " + holder) +
          " (a run or a sweep); choose another folder");
    throw InvalidArgument("'" + dir +
                          "' holds a run or a sweep (its checkpoint, run.json, lock or snapshots), "
                          "whose files an export would overwrite; choose another folder");
  }
  if (!replace)
    throw InvalidArgument("'" + dir +
                          "' already exists and is not empty; choose another folder, or give "
                          "--replace to write over a previous export there");
}

// A 3D scenario's case: its spheres where the builder puts them (no settling).
void export_3d(const Scenario3& s, const std::string& source, const std::string& dir, bool replace,
               const std::string& command, bool quiet) {
  check_export_folder(dir, replace);
  LammpsCase c;
  std::size_t atoms = 0;
  try {
    check_lammps_export(s);
    const BuiltScenario3 built = build_scenario3(s);
    atoms = built.scene.spheres.size();
    c = export_lammps(s, built, command);
  } catch (const ScenarioError& e) {
    throw ScenarioError(source + ": " + e.what());
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(source + ": " + e.what());
  }
  write_lammps_case(c, dir);
  if (!quiet)
    fmt::print("talus export lammps: {0}/in.{1}, data.{1}, masses.{1} and scenario.toml (the "
               "native twin) ({2} spheres, 3D); run it in {0} with talus-lmp -in in.{1}\n",
               dir, c.name, atoms);
}

} // namespace

void add_export_command(CLI::App& app) {
  struct Options {
    std::string scenario, dir;
    std::vector<std::string> set;
    bool quiet = false;
    bool replace = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("export", "write a scenario for another engine");
  cmd->require_subcommand(1);
  CLI::App* lammps = cmd->add_subcommand(
      "lammps", "a LAMMPS data file, masses and input deck (pair_style granthesis) of a scenario "
                "after its packing, in DIR; refused, with the reason, for what LAMMPS cannot "
                "express (the freezing front, rigid materials, lever arms at the radius)");
  lammps->add_option("scenario", o->scenario, "scenario file or built-in name")->required();
  lammps->add_option("dir", o->dir, "the folder for in.NAME, data.NAME and masses.NAME")
      ->required();
  lammps->add_option("--set", o->set, "override a key, e.g. --set geometry.walls=particles");
  lammps->add_flag("--quiet", o->quiet, "no progress output");
  lammps->add_flag("--replace", o->replace,
                   "DIR may hold a previous export, whose files are written over (never a run "
                   "or a sweep folder)");
  lammps->callback([o] {
    const ScenarioText text = scenario_text(o->scenario);
    if (scenario_dimension(text, o->set) == 3)
      return export_3d(load_scenario3(text.text, text.file, o->set), o->scenario, o->dir,
                       o->replace, command_line(o->scenario, o->dir, o->set), o->quiet);
    const Scenario s = load_scenario(text.text, text.file, o->set);
    check_export_folder(o->dir, o->replace); // before the settling, which can take minutes
    try {
      check_lammps_export(s);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(o->scenario + ": " + e.what());
    }
    BuiltScenario built;
    try {
      double next = 0.0; // a line per 0.1 s of settling
      built = build_scenario(s, [&](double t, double ke) {
        if (o->quiet || t < next) return;
        fmt::print("  settling: t = {:.4f} s, E_kin = {:.4e} J\n", t, ke);
        next = t + 0.1;
      });
    } catch (const ScenarioError& e) {
      throw ScenarioError(o->scenario + ": " + e.what());
    }
    LammpsCase c;
    try {
      c = export_lammps(s, built, command_line(o->scenario, o->dir, o->set));
    } catch (const InvalidArgument& e) { // a wall particle moved by two drivers
      throw InvalidArgument(o->scenario + ": " + e.what());
    }
    if (!built.settled)
      fmt::print(stderr,
                 "talus export lammps: warning: {} did not settle within "
                 "packing.settle_max_time ({} s); the case starts from where it got\n",
                 s.name, s.packing.settle_max_time);
    check_export_folder(o->dir, o->replace); // a run may have started there meanwhile
    write_lammps_case(c, o->dir);
    if (!o->quiet)
      fmt::print(
          "talus export lammps: {0}/in.{1}, data.{1}, masses.{1} and scenario.toml (the native "
          "twin) ({2} atoms); run it in {0} with talus-lmp -in in.{1}\n",
          o->dir, c.name, built.world.particles.size());
  });
}

} // namespace talus::cli
