// libFuzzer target: the --set parser (load.cpp, apply_override). Each input is one or more
// KEY=VALUE lines applied to a built-in scenario as `talus run NAME --set LINE ...` would; the
// loader must refuse bad ones with a ScenarioError and never crash, hang or read out of bounds.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "scenario/file/load.hpp"

namespace {

// A scenario with every section the overrides can reach into: tables, arrays of tables, lists.
constexpr const char* base = R"(name = "fuzz"
[simulation]
duration = 0.01
[[materials]]
name = "grain"
[particles]
count = 10
[[particles.list]]
position = [0.0, 0.0]
radius = 0.001
[geometry]
builder = "box"
width = 0.1
height = 0.1
[[drivers]]
type = "vibrate"
amplitude = 0.001
frequency = 10.0
[output]
pictures = ["speed"]
)";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::string> overrides;
  for (std::string line; std::getline(in, line) && overrides.size() < 8;) overrides.push_back(line);
  try {
    const talus::Scenario s = talus::load_scenario(base, "fuzz.toml", overrides);
    talus::load_scenario(talus::to_toml(s), "fuzz.toml"); // the resolved text reads back
  } catch (const talus::InvalidArgument&) {
  }
  return 0;
}
