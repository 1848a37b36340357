// libFuzzer target: the thesis .in reader and its conversion to a scenario.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/thesis_format.hpp"
#include "scenario/file/load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const talus::ThesisFile f = talus::read_thesis_in(text, "fuzz.in");
    const talus::Scenario s = talus::scenario_from_thesis(f, "fuzz");
    talus::load_scenario(talus::to_toml(s), "fuzz.toml");
  } catch (const talus::InvalidArgument&) {
  }
  return 0;
}
