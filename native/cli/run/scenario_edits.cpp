#include "cli/run/scenario_edits.hpp"

#include <fmt/core.h>

#include "io/checkpoint.hpp"
#include "scenario/file/differences.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/stages.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

fs::path started_copy(const fs::path& dir) {
  return dir / ".scenario.started.toml";
}

std::vector<std::string> scenario_edits(const fs::path& dir, const std::string& edited,
                                        const run::RunBook& book, std::string& started) {
  const std::string file = (dir / "scenario.toml").string();
  const std::string how = fmt::format(
      "a run goes on with the scenario it started with; undo the edit, and change the run from "
      "its resume point with talus resume {} --set KEY=VALUE (or --duration T)",
      dir.string());
  std::error_code e;
  if (fs::exists(started_copy(dir), e)) started = read_file(started_copy(dir).string());
  if (started.empty() || fnv1a_hash(started) != book.scenario_hash)
    throw InvalidArgument("'" + file +
                          "' was edited after the run started, and the copy of it as it started "
                          "is missing, so what changed cannot be told; " +
                          how);
  // the files alone: a key a stage or a resume changed since is edited as much as any other
  const std::vector<KeyDifference> d =
      scenario_differences(load_scenario(started, file), load_scenario(edited, file));
  std::vector<std::string> changes, refused;
  for (const KeyDifference& k : d) {
    if (k.value && (k.key == "simulation.duration" || changeable_during_run(k.key)))
      changes.push_back(k.key + "=" + *k.value);
    else
      refused.push_back(k.value ? k.key : k.key + " (removed)");
  }
  if (!refused.empty()) {
    std::string keys;
    for (const std::string& k : refused) keys += (keys.empty() ? "" : ", ") + k;
    throw InvalidArgument("'" + file + "' was edited after the run started in keys that cannot " +
                          "change during a run: " + keys + "; " + how +
                          "; the keys that can: " + changeable_keys_text());
  }
  return changes;
}

} // namespace talus::cli
