// A resume continues only a run whose folder still holds what its checkpoint vouches for: the
// run's own checkpoint (not one copied from another run) and every output at least as long as it
// was then. Anything else falls back to the previous checkpoint or is refused, never padded.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/core.h>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "support/builtin_scenario.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::builtin;
using testing::fresh_dir;
using testing::resume_quietly;
using testing::run_quietly;

std::string resume_error(const fs::path& dir) {
  try {
    resume_quietly(dir);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "(resumed)";
}

Scenario collisions(const std::string& seed = "1") {
  return builtin("collisions", {"simulation.duration=0.02", "output.checkpoint_interval=0.004",
                                "output.thermo_interval=0.0005", "simulation.seed=" + seed});
}

// The bytes of thermo.csv each checkpoint vouches for.
std::uint64_t vouched(const fs::path& dir, const char* checkpoint) {
  const Checkpoint c =
      decode_checkpoint(read_file((dir / checkpoint).string()), (dir / checkpoint).string());
  return run::RunBook::decode(c.run_data).file_bytes.at("thermo.csv");
}

// thermo.csv's tail lost (a crash after the checkpoint reached the disk and before the file's
// tail did): the previous checkpoint, which it still covers, is taken, and the run ends as one
// never stopped; cut below both, the resume is refused and the file left as it was.
TEST(ResumeOutputs, AFileShorterThanItsCheckpointIsNeverPadded) {
  const fs::path whole = fresh_dir("outputs_whole"), dir = fresh_dir("outputs_short");
  ASSERT_EQ(run_quietly(collisions(), whole), cli::exit_completed);
  ASSERT_EQ(run_quietly(collisions(), dir, 0.01), cli::exit_stopped);
  const std::uint64_t last = vouched(dir, "checkpoint.bin");
  const std::uint64_t previous = vouched(dir, "checkpoint.prev.bin");
  ASSERT_LT(previous + 10, last);
  const fs::path copy = fresh_dir("outputs_shorter");
  fs::copy(dir, copy, fs::copy_options::recursive);

  fs::resize_file(dir / "thermo.csv", last - 5);
  ASSERT_EQ(resume_quietly(dir), cli::exit_completed);
  EXPECT_EQ(read_file((whole / "thermo.csv").string()), read_file((dir / "thermo.csv").string()));

  fs::resize_file(copy / "thermo.csv", previous - 5);
  const std::string why = resume_error(copy);
  EXPECT_NE(why.find("thermo.csv holds " + std::to_string(previous - 5) + " bytes, fewer than"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("talus run " + (copy / "scenario.toml").string()), std::string::npos) << why;
  EXPECT_EQ(fs::file_size(copy / "thermo.csv"), previous - 5);
  fs::remove(copy / "snapshots" / "particles_000001.vtp");
  fs::resize_file(copy / "thermo.csv", last);
  EXPECT_NE(resume_error(copy).find("particles_000001.vtp is missing"), std::string::npos);
  for (const fs::path& d : {whole, dir, copy}) fs::remove_all(d);
}

// Checkpoints copied from another run (of another seed) into a run folder are refused, naming
// both runs; the folder's own checkpoints, put back, resume.
TEST(ResumeOutputs, ACheckpointOfAnotherRunIsRefusedNamingBoth) {
  const fs::path mine = fresh_dir("foreign_mine"), other = fresh_dir("foreign_other");
  const fs::path kept = fresh_dir("foreign_kept");
  ASSERT_EQ(run_quietly(collisions("1"), mine, 0.01), cli::exit_stopped);
  ASSERT_EQ(run_quietly(collisions("5"), other, 0.01), cli::exit_stopped);
  fs::create_directories(kept);
  for (const char* f : {"checkpoint.bin", "checkpoint.prev.bin"}) {
    fs::copy_file(mine / f, kept / f);
    fs::copy_file(other / f, mine / f, fs::copy_options::overwrite_existing);
  }
  const std::string why = resume_error(mine);
  const auto id_of = [](const fs::path& d) {
    return fmt::format("{:016x}", run::run_id_in(read_file((d / "scenario.toml").string())));
  };
  EXPECT_NE(why.find(fmt::format("belongs to another run ({}", id_of(other))), std::string::npos)
      << why;
  EXPECT_NE(why.find(fmt::format("({})", id_of(mine))), std::string::npos) << why;
  for (const char* f : {"checkpoint.bin", "checkpoint.prev.bin"})
    fs::copy_file(kept / f, mine / f, fs::copy_options::overwrite_existing);
  EXPECT_EQ(resume_quietly(mine), cli::exit_completed);
  for (const fs::path& d : {mine, other, kept}) fs::remove_all(d);
}

} // namespace
} // namespace talus
