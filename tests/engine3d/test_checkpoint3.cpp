// 3D checkpoints (io/checkpoint3.hpp): a run saved, read back and continued is the run that went
// on without stopping, to the bit (springs and rolling springs, list, plates on their drivers,
// periodic images), with velocity Verlet and with Gear (its derivatives); a damaged or foreign
// file is refused with what is wrong.
#include <gtest/gtest.h>

#include <cstring>

#include "engine3d/simulation3.hpp"
#include "io/checkpoint3.hpp"
#include "support/shaken_bed3.hpp"

namespace talus {
namespace {

using testing::shaken_bed3;

bool same(const std::vector<Vec3>& u, const std::vector<Vec3>& v) {
  return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(Vec3)) == 0;
}

class Checkpoint3Integrators : public ::testing::TestWithParam<Integrator> {};

TEST_P(Checkpoint3Integrators, AResumedRunIsTheWholeRunToTheBit) {
  Simulation3 whole = shaken_bed3(GetParam()), first = shaken_bed3(GetParam());
  whole.run(12000);
  first.run(6000);
  const std::string bytes =
      encode_checkpoint3({first.state(), first.settings(), "the run's own notes"});
  const Checkpoint3 c = decode_checkpoint3(bytes, "test");
  EXPECT_EQ(c.run_data, "the run's own notes");
  EXPECT_EQ(c.settings.sort_interval, 1000u);
  EXPECT_EQ(encode_checkpoint3(c), bytes); // every field read back as written
  Simulation3 second = Simulation3::restore(c.state, c.settings);
  second.run(6000);
  const Spheres &a = whole.scene().spheres, &b = second.scene().spheres;
  EXPECT_TRUE(same(a.position, b.position));
  EXPECT_TRUE(same(a.velocity, b.velocity));
  EXPECT_TRUE(same(a.angular_velocity, b.angular_velocity));
  EXPECT_TRUE(same(whole.list().spring, second.list().spring));
  EXPECT_TRUE(same(whole.list().rolling, second.list().rolling));
  EXPECT_TRUE(same(whole.list().plate_rolling, second.list().plate_rolling));
  EXPECT_FALSE(whole.list().rolling.empty());
  EXPECT_TRUE(a.image == b.image);
  EXPECT_EQ(whole.time(), second.time());
  EXPECT_EQ(whole.scene().plates[0].centre.z, second.scene().plates[0].centre.z);
  EXPECT_GT(whole.contact_count(), 100u);
  bool crossed = false; // and the run did what it is meant to test
  for (const Image3& i : a.image) crossed = crossed || i[0] != 0;
  EXPECT_TRUE(crossed) << "no sphere crossed the periodic side";
}

INSTANTIATE_TEST_SUITE_P(Checkpoint3, Checkpoint3Integrators,
                         ::testing::Values(Integrator::verlet, Integrator::gear),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(Checkpoint3, ADamagedOrForeignFileIsRefused) {
  Simulation3 s = shaken_bed3(Integrator::verlet);
  s.run(10);
  const std::string bytes = encode_checkpoint3({s.state(), s.settings(), ""});
  const auto refusal = [](const std::string& b) {
    try {
      decode_checkpoint3(b, "f.bin");
    } catch (const CheckpointError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x10);
  EXPECT_NE(refusal(flipped).find("checksum mismatch"), std::string::npos);
  EXPECT_NE(refusal(bytes.substr(0, bytes.size() - 9)).find("size mismatch"), std::string::npos);
  EXPECT_NE(refusal("TALUSCKP and the rest").find("not a talus 3D checkpoint"), std::string::npos);
  std::string newer = bytes;
  newer[8] = 9; // the version
  EXPECT_NE(refusal(newer).find("format version 9"), std::string::npos);
}

} // namespace
} // namespace talus
