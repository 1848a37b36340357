// docs/scenarios.md lists every key the loader accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "cli/builtin_scenarios.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/file/shared_sections.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

TEST(ScenarioReference, DocsListEveryKey) {
  // the resolved form of each built-in scenario holds every key of every section it has;
  // loading it asks the readers for all of them
  for (const auto& b : cli::builtin_scenarios()) {
    if (scenario_dimension(toml::parse(b.text), std::string(b.name)) == 3) {
      const Scenario3 s = load_scenario3(b.text, std::string(b.name));
      load_scenario3(to_toml(s), "resolved");
      continue;
    }
    const Scenario s = load_scenario(b.text, std::string(b.name));
    load_scenario(to_toml(s), "resolved");
  }
  std::ifstream in(std::string(TALUS_SOURCE_DIR) + "/docs/scenarios.md");
  ASSERT_TRUE(in) << "docs/scenarios.md missing";
  std::stringstream doc;
  doc << in.rdbuf();
  const auto& keys = TableReader::known_keys();
  EXPECT_GT(keys.size(), 60U);
  for (const std::string& key : keys)
    EXPECT_NE(doc.str().find("`" + key + "`"), std::string::npos) << key << " is not documented";
}

// the rows of the law keys name every law of the table (talus/law_table.hpp), in quotes
TEST(ScenarioReference, DocsNameEveryLaw) {
  std::ifstream in(std::string(TALUS_SOURCE_DIR) + "/docs/scenarios.md");
  ASSERT_TRUE(in) << "docs/scenarios.md missing";
  std::string line, normal_row, tangential_row;
  while (std::getline(in, line)) {
    if (line.starts_with("| `simulation.normal_law`")) normal_row = line;
    if (line.starts_with("| `simulation.tangential_law`")) tangential_row = line;
  }
  const auto quoted = [](std::string_view name) {
    std::string q(1, '"');
    q.append(name);
    q.push_back('"');
    return q;
  };
  for (std::string_view name : NormalLaws::names)
    EXPECT_NE(normal_row.find(quoted(name)), std::string::npos) << name;
  for (std::string_view name : TangentialLaws::names)
    EXPECT_NE(tangential_row.find(quoted(name)), std::string::npos) << name;
}

} // namespace
} // namespace talus
