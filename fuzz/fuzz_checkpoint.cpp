// libFuzzer target: a checkpoint whose checksum holds but whose fields are anything must be
// refused (CheckpointError by the reader, InvalidArgument by Simulation::restore), never crash.
// The input is the payload: it is sealed with a valid header and checksum first, which mutated
// bytes would almost never carry, so that the fuzzer reaches the fields.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/checkpoint.hpp"
#include "talus/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string payload(reinterpret_cast<const char*>(data), size);
  try {
    talus::Checkpoint c = talus::decode_checkpoint(talus::seal_checkpoint(payload), "fuzz.ckpt");
    c.config.threads = 1;
    talus::Simulation::restore(std::move(c.state), c.config);
  } catch (const talus::CheckpointError&) {
  } catch (const talus::InvalidArgument&) {
  }
  return 0;
}
