#include "cli/run/scenario_source.hpp"

#include <filesystem>

#include "cli/builtin_scenarios.hpp"
#include "io/checkpoint.hpp"
#include "io/thesis_format.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/file/shared_sections.hpp"
#include "scenario/file/toml_reader.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

ScenarioText scenario_text(const std::string& what) {
  // a folder (say, the run folder of a built-in scenario, named after it) is never a scenario
  if (fs::is_regular_file(what)) {
    if (fs::path(what).extension() == ".in") {
      const ThesisFile f = read_thesis_in(read_file(what), what);
      return {to_toml(scenario_from_thesis(f, fs::path(what).stem().string())),
              what + " (converted)"};
    }
    return {read_file(what), what};
  }
  std::string names, best;
  std::size_t best_d = 1000;
  for (const auto& b : builtin_scenarios()) {
    if (b.name == what)
      return {std::string(b.text), "inputs/" + std::string(b.name) + "/scenario.toml"};
    names += (names.empty() ? "" : ", ") + std::string(b.name);
    if (const auto d = edit_distance(what, b.name); d < best_d) best_d = d, best = b.name;
  }
  std::string msg = "'" + what + "' is neither a file nor a built-in scenario";
  if (fs::is_directory(what))
    msg = "'" + what + "' is a folder, not a scenario file (a run folder continues with talus " +
          "resume; its scenario is " + (fs::path(what) / "scenario.toml").string() + ")";
  if (best_d <= 3) msg += "; did you mean '" + best + "'?";
  throw InvalidArgument(msg + " (built-in: " + names + ")");
}

int scenario_dimension(const ScenarioText& t, const std::vector<std::string>& overrides) {
  return talus::scenario_dimension(parse_with_overrides(t.text, t.file, overrides), t.file);
}

Scenario resolve_scenario(const std::string& what, const std::vector<std::string>& overrides) {
  const ScenarioText t = scenario_text(what);
  return load_scenario(t.text, t.file, overrides);
}

ResolvedScenario resolve_any_scenario(const std::string& what,
                                      const std::vector<std::string>& overrides) {
  const ScenarioText t = scenario_text(what);
  if (scenario_dimension(t, overrides) == 3) {
    const Scenario3 s = load_scenario3(t.text, t.file, overrides);
    return {to_toml(s), s.name, s.simulation.seed, 3};
  }
  const Scenario s = load_scenario(t.text, t.file, overrides);
  return {to_toml(s), s.name, s.simulation.seed, 2};
}

} // namespace talus::cli
