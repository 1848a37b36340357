#pragma once
// Seeded random streams: every random number in a run comes from a stream named by (seed, stream).
#include <cstdint>
#include <random>

namespace talus {

/// A reproducible generator. Two streams with the same seed but different stream numbers are
/// independent; the same (seed, stream) gives the same numbers on every platform.
class RandomStream {
public:
  RandomStream(std::uint64_t seed, std::uint64_t stream) : engine_(mix(seed, stream)) {}

  /// Uniform in [0, 1), from the top 53 bits (portable, unlike std::uniform_real_distribution).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
  static std::uint64_t mix(std::uint64_t seed, std::uint64_t stream) {
    // splitmix64 finaliser over the pair, so nearby seeds give unrelated streams.
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + stream + 0x632BE59BD9B4E019ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  std::mt19937_64 engine_;
};

} // namespace talus
