// libFuzzer target: the scenario loader and builder must reject any text cleanly (ScenarioError
// or InvalidArgument), never crash, hang or trip a sanitizer.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenario/build.hpp"
#include "scenario/load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    talus::Scenario s = talus::load_scenario(text, "fuzz.toml");
    // keep builds small and fast: the fuzzer explores the loader, not sedimentation
    if (s.particles.count > 200 || s.particles.list.size() > 200) return 0;
    s.packing.settle_max_time = std::min(s.packing.settle_max_time, 0.001);
    talus::build_scenario(s);
  } catch (const talus::InvalidArgument&) {
  }
  return 0;
}
