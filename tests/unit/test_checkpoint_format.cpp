// The checkpoint file's envelope (version, checksum) and the checks on what a checksummed file may
// still hold: ids of laws and schemes, particle kinds and flags outside their lists.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <new>

#include "io/checkpoint.hpp"
#include "support/two_body.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

// The magic word, the version and the payload's size come before the payload; its checksum
// after it (docs/file-formats.md, "Checkpoints").
constexpr std::size_t head_bytes = 8 + 4 + 8;
constexpr std::size_t sum_bytes = 8;

// FNV-1a, 64 bits, as published (Fowler, Noll and Vo; IETF draft-eastlake-fnv): the offset basis
// 14695981039346656037 and the prime 1099511628211. `basis` is there for format 7's.
std::uint64_t reference_fnv1a(const std::string& s, std::uint64_t basis = 14695981039346656037ULL) {
  std::uint64_t h = basis;
  for (const unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

Checkpoint small_checkpoint() {
  World w = testing::two_grains(testing::elastic_material(), 0.01, 0.1);
  w.domain = {.lo = {-0.37, -0.41}, .hi = {0.53, 0.59}, .periodic_x = true};
  w.walls.push_back({.a = {-0.3, -0.2}, .b = {0.3, -0.2}}); // a floor below the grains
  SimulationConfig c;
  c.timestep = 1.0e-5;
  c.integrator = Integrator::verlet;
  Simulation sim(std::move(w), c);
  sim.run(10);
  return {sim.state(), sim.config(), "bookkeeping"};
}

std::string payload_of(const std::string& file) {
  return file.substr(head_bytes, file.size() - head_bytes - sum_bytes);
}

// The file a talus of format `version` wrote: the same envelope, this payload, that checksum.
std::string envelope(std::uint32_t version, const std::string& payload, std::uint64_t sum) {
  std::string out = "TALUSCKP";
  const std::uint64_t size = payload.size();
  out.append(reinterpret_cast<const char*>(&version), sizeof(version));
  out.append(reinterpret_cast<const char*>(&size), sizeof(size));
  out += payload;
  out.append(reinterpret_cast<const char*>(&sum), sizeof(sum));
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

// The published test vectors of FNV-1a 64 check the reference; the checkpoint's sum is then
// the reference's over the payload, bit for bit.
TEST(CheckpointFormat, TheChecksumIsFnv1a64OfThePayload) {
  EXPECT_EQ(reference_fnv1a(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(reference_fnv1a("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(reference_fnv1a("foobar"), 0x85944171f73967e8ULL);
  const std::string file = encode_checkpoint(small_checkpoint());
  std::uint64_t sum = 0;
  std::memcpy(&sum, file.data() + file.size() - sum_bytes, sum_bytes);
  EXPECT_EQ(sum, reference_fnv1a(payload_of(file)));
  std::uint32_t version = 0;
  std::memcpy(&version, file.data() + 8, sizeof(version));
  EXPECT_EQ(version, checkpoint_version);
}

// Format 7 is read with its own basis (one digit short of FNV-1a's; Resume.AFormat7Checkpoint*
// reads a real one): a format 7 file summed with format 8's basis is damaged, not of another
// version. Other versions are refused, naming what this talus reads.
TEST(CheckpointFormat, OtherVersionsAreRefusedNamingTheOnesRead) {
  const std::string payload = payload_of(encode_checkpoint(small_checkpoint()));
  EXPECT_NE(error_of([&] {
              decode_checkpoint(envelope(7, payload, reference_fnv1a(payload)), "x");
            }).find("checksum mismatch"),
            std::string::npos);
  for (const std::uint32_t version : {6u, checkpoint_version + 1}) {
    const std::string e = error_of(
        [&] { decode_checkpoint(envelope(version, payload, reference_fnv1a(payload)), "f"); });
    EXPECT_NE(e.find("version " + std::to_string(version) + "; this talus reads versions 7 to " +
                     std::to_string(checkpoint_version)),
              std::string::npos)
        << e;
  }
}

// `v` made again in its own memory after filling it with `fill`: its members are the defaults,
// its padding bytes `fill`.
template <class T> T& remade(T& v, unsigned char fill) {
  std::memset(static_cast<void*>(&v), fill, sizeof(T));
  return *::new (&v) T;
}

// The same state makes the same file: no padding byte, whose value is unspecified, is written.
// The structs with padding (the domain, a wall segment, the settings) are made twice with the
// same members, once in memory filled with zeros and once with 0xAB.
TEST(CheckpointFormat, TheSameStateGivesTheSameBytes) {
  const Checkpoint c = small_checkpoint();
  ASSERT_EQ(c.state.world.walls.size(), 1u);
  std::string files[2];
  for (const int fill : {0x00, 0xAB}) {
    Checkpoint k = c;
    const Domain& d0 = c.state.world.domain;
    Domain& d = remade(k.state.world.domain, static_cast<unsigned char>(fill));
    d.lo = d0.lo, d.hi = d0.hi, d.periodic_x = d0.periodic_x, d.periodic_y = d0.periodic_y;
    const Segment& s0 = c.state.world.walls[0];
    Segment& s = remade(k.state.world.walls[0], static_cast<unsigned char>(fill));
    s.a = s0.a, s.b = s0.b, s.material = s0.material, s.force = s0.force;
    SimulationConfig& config = remade(k.config, static_cast<unsigned char>(fill));
    config.timestep = c.config.timestep, config.integrator = c.config.integrator;
    files[fill ? 1 : 0] = encode_checkpoint(k);
  }
  EXPECT_EQ(files[0], files[1]);
  EXPECT_EQ(files[0], encode_checkpoint(c));
}

// A periodic flag is a bool, stored as one byte after the domain's corners; any other byte than
// 0 or 1 there is refused when read (reading it as a bool would be undefined behaviour).
TEST(CheckpointFormat, APeriodicFlagNeitherZeroNorOneIsRefused) {
  const Checkpoint c = small_checkpoint();
  std::string payload = payload_of(encode_checkpoint(c));
  const Domain& d = c.state.world.domain;
  std::string corners(4 * sizeof(double), '\0');
  std::memcpy(corners.data(), &d.lo, sizeof(Vec2));
  std::memcpy(corners.data() + sizeof(Vec2), &d.hi, sizeof(Vec2));
  const std::size_t at = payload.find(corners);
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(payload.find(corners, at + 1), std::string::npos);
  const std::size_t flag = at + corners.size(); // periodic_x, then periodic_y
  ASSERT_EQ(payload[flag], 1);
  ASSERT_EQ(payload[flag + 1], 0);
  for (const std::size_t k : {flag, flag + 1}) {
    std::string bad = payload;
    bad[k] = 2;
    const std::string e = error_of([&] { decode_checkpoint(seal_checkpoint(bad), "flag"); });
    EXPECT_NE(e.find("flag: corrupt checkpoint: a flag is neither 0 nor 1"), std::string::npos)
        << e;
  }
}

// A law, integrator or lever arm is stored as its id: one outside its list would quietly select
// another (the law table maps any id past the end to its last law). Restoring names the setting
// and the allowed values; so does a particle kind outside free, fixed and moved.
TEST(CheckpointFormat, IdsOutsideTheirListsAreRefusedOnRestore) {
  const Checkpoint c = small_checkpoint();
  EXPECT_NO_THROW(Simulation::restore(c.state, c.config));
  const std::vector<std::pair<std::string, std::function<void(SimulationConfig&)>>> settings{
      {"simulation.normal_law: id 2 is not a law; allowed: ",
       [](SimulationConfig& s) { s.normal_law = NormalLaw{2}; }},
      {"simulation.tangential_law: id 4 is not a law; allowed: coulomb, cundall_strack, mindlin, "
       "none",
       [](SimulationConfig& s) { s.tangential_law = TangentialLaw{4}; }},
      {"simulation.integrator: id 2 is not an integrator; allowed: gear, verlet",
       [](SimulationConfig& s) { s.integrator = static_cast<Integrator>(2); }},
      {"simulation.verlet_velocity: id 2 is not a choice; allowed: predicted, half_step",
       [](SimulationConfig& s) { s.verlet_velocity = static_cast<VerletVelocity>(2); }},
      {"simulation.lever_arm: id 7 is not a choice; allowed: contact_point, radius",
       [](SimulationConfig& s) { s.lever_arm = static_cast<LeverArm>(7); }}};
  for (const auto& [message, change] : settings) {
    SimulationConfig bad = c.config;
    change(bad);
    // what is stored is what comes back: the check is the restore's, not the reader's
    const Checkpoint read = decode_checkpoint(encode_checkpoint({c.state, bad, c.run_data}), "ids");
    const std::string e = error_of([&] { Simulation::restore(read.state, read.config); });
    EXPECT_NE(e.find(message), std::string::npos) << e;
  }
  SimulationState bad = c.state;
  bad.world.particles.kind[1] = static_cast<Kind>(3);
  const std::string e = error_of([&] { Simulation::restore(bad, c.config); });
  EXPECT_NE(e.find("particle 1: kind 3 is not one; allowed: 0 (free), 1 (fixed), 2 (moved)"),
            std::string::npos)
      << e;
}

// Settings a scenario's loader bounds are bounded again on restore (and for a Simulation made
// through the API): a checkpoint's, or a program's, are not read through the loader.
TEST(CheckpointFormat, SettingsOutOfRangeAreRefusedOnRestore) {
  const Checkpoint c = small_checkpoint();
  const std::vector<std::pair<std::string, std::function<void(SimulationConfig&)>>> settings{
      {"simulation.timestep = nan s; allowed: > 0",
       [](SimulationConfig& s) { s.timestep = std::nan(""); }},
      {"simulation.impact_speed = -1.000000 m/s; allowed: > 0",
       [](SimulationConfig& s) { s.impact_speed = -1.0; }},
      {"simulation.impact_speed = inf m/s; allowed: > 0",
       [](SimulationConfig& s) { s.impact_speed = HUGE_VAL; }}};
  for (const auto& [message, change] : settings) {
    SimulationConfig bad = c.config;
    change(bad);
    const std::string e = error_of([&] { Simulation::restore(c.state, bad); });
    EXPECT_NE(e.find(message), std::string::npos) << e;
  }
}

} // namespace
} // namespace talus
