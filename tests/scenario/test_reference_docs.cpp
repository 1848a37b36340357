// docs/scenarios.md lists every key the loader accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli/builtin_scenarios.hpp"
#include "scenario/load.hpp"

namespace talus {
namespace {

TEST(ScenarioReference, DocsListEveryKey) {
  // the resolved form of each built-in scenario holds every key of every section it has;
  // loading it asks the readers for all of them
  for (const auto& b : cli::builtin_scenarios()) {
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

} // namespace
} // namespace talus
