#include "io/lammps_stages.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "scenario/file/load.hpp"
#include "simulation/simulation.hpp"

namespace talus {

namespace {

std::string refused(const std::string& key, const std::string& why) {
  return "key '" + key + "': " + why + "; talus export lammps writes only what LAMMPS and the " +
         "talus package express exactly";
}

// The key of a stage's change "key=value".
std::string key_of(const std::string& change) {
  return change.substr(0, change.find('='));
}

// Whether `key` is a cell driver's strain_rate or shear_rate, which fix deform takes anew.
bool cell_rate_key(const Scenario& s, const std::string& key) {
  for (std::size_t k = 0; k < s.drivers.size(); ++k) {
    if (s.drivers[k].type != "cell") continue;
    const std::string d = "drivers." + std::to_string(k) + ".";
    if (key == d + "strain_rate" || key == d + "shear_rate") return true;
  }
  return false;
}

// The scenario as stage k runs it: its changes and every earlier stage's, in order.
Scenario at_stage(const Scenario& s, std::size_t k) {
  if (k == 0) return s;
  std::vector<std::string> sets;
  for (std::size_t j = 1; j <= k; ++j)
    sets.insert(sets.end(), s.stages[j].set.begin(), s.stages[j].set.end());
  return load_scenario(to_toml(s), s.name, sets);
}

// A copy: the scenario is often a stage's, a temporary.
std::optional<DriverSection> cell_of(const Scenario& s) {
  for (const DriverSection& d : s.drivers)
    if (d.type == "cell") return d;
  return std::nullopt;
}

std::optional<std::string> cell_refusal(const DriverSection& c, std::size_t stage) {
  if (c.shear_rate == 0.0 || (c.strain_rate.x == 0.0 && c.strain_rate.y == 0.0))
    return std::nullopt;
  return refused(stage == 0 ? "drivers" : "stages." + std::to_string(stage) + ".set",
                 "a cell that strains and shears at once: fix deform remaps the positions for a "
                 "strain (remap x) or the velocities across the tilted box for a shear (remap v), "
                 "not both; allowed: a stage that strains, then one that shears");
}

// fix deform for the cell: its true strain rates with the affine remap of every atom, or its
// shear as a tilt growing at shear_rate x L_y with the images' velocity (remap v).
std::string cell_fix(const DriverSection& c, bool periodic_x, bool periodic_y) {
  if (c.shear_rate != 0.0)
    return fmt::format("fix cell all deform 1 xy erate {} remap v\n", c.shear_rate);
  return fmt::format("fix cell all deform 1{}{} remap x\n",
                     periodic_x ? fmt::format(" x trate {}", c.strain_rate.x) : "",
                     periodic_y ? fmt::format(" y trate {}", c.strain_rate.y) : "");
}

} // namespace

std::optional<std::string> cell_and_stages_refusal(const Scenario& s) {
  for (std::size_t k = 0; k < s.stages.size(); ++k) {
    const StageSection& st = s.stages[k];
    const std::string at = "stages." + std::to_string(k);
    if (st.until != "none")
      return refused(at + ".until", "a stage that ends on a condition ('" + st.until +
                                        "'); LAMMPS runs each stage for its duration; allowed: "
                                        "none");
    for (const std::string& change : st.set)
      if (!cell_rate_key(s, key_of(change)))
        return refused(at + ".set", "a stage's change of '" + key_of(change) +
                                        "'; between LAMMPS runs the deck changes only the "
                                        "cell's fix deform; allowed: drivers.N.strain_rate, "
                                        "drivers.N.shear_rate of a cell driver");
  }
  for (std::size_t k = 0; k < std::max<std::size_t>(1, s.stages.size()); ++k)
    if (const auto c = cell_of(at_stage(s, k)))
      if (auto why = cell_refusal(*c, k)) return why;
  return std::nullopt;
}

bool shears_in_any_stage(const Scenario& s) {
  for (std::size_t k = 0; k < std::max<std::size_t>(1, s.stages.size()); ++k)
    if (const auto c = cell_of(at_stage(s, k)); c && c->shear_rate != 0.0) return true;
  return false;
}

std::string cell_and_runs(const Scenario& s, bool periodic_x, bool periodic_y, double dt,
                          std::uint64_t steps) {
  const auto first = cell_of(s);
  std::string out = first ? cell_fix(*first, periodic_x, periodic_y) : "";
  if (s.stages.size() < 2) return out + "run ${steps}\n";
  std::string previous = out;
  std::uint64_t done = 0;
  for (std::size_t k = 0; k < s.stages.size() && done < steps; ++k) {
    if (k > 0) {
      const auto c = cell_of(at_stage(s, k));
      const std::string fix = c ? cell_fix(*c, periodic_x, periodic_y) : "";
      if (fix != previous) out += "unfix cell\n" + fix;
      previous = fix;
    }
    const bool last = k + 1 == s.stages.size();
    const std::uint64_t length =
        last ? steps - done
             : std::min(steps - done,
                        std::max<std::uint64_t>(1, steps_until(s.stages[k].duration, dt)));
    out += fmt::format("# stage {} ({}): {} steps\nrun {}\n", k, s.stages[k].name, length, length);
    done += length;
  }
  return out;
}

} // namespace talus
