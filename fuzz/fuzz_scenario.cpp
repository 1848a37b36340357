// libFuzzer target: the scenario loader and builder must reject any text cleanly (ScenarioError
// or InvalidArgument; InstabilityError where settling the packing goes unstable), never crash,
// hang or trip a sanitizer.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    talus::Scenario s = talus::load_scenario(text, "fuzz.toml");
    // keep builds small and fast: the fuzzer explores the loader, not sedimentation
    if (s.particles.count > 200 || s.particles.list.size() > 200) return 0;
    s.packing.settle_max_time = std::min(s.packing.settle_max_time, 0.001);
    talus::build_scenario(s);
  } catch (const talus::InvalidArgument&) {
  } catch (const talus::InstabilityError&) { // a scene that settles unstably is told so
  }
  return 0;
}
