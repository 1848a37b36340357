// libFuzzer target: the checkpoint reader must detect any damage (CheckpointError), never crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/checkpoint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    talus::decode_checkpoint(bytes, "fuzz.ckpt");
  } catch (const talus::CheckpointError&) {
  }
  return 0;
}
