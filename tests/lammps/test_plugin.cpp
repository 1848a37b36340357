// The upstream plugin entry point (lammpsplugin_init in lammps-package/plugin.cpp), built against
// the test's own plugin host (plugin_host/) and loaded with dlopen as LAMMPS' `plugin load` does:
// the styles it registers run a deck exactly as the directly registered ones do.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <string>
#include <vector>

#include "fix.h"
#include "force.h"
#include "lammps_instance.hpp"
#include "modify.h"
#include "pair.h"
#include "plugin_host/lammpsplugin.h"

namespace talus::lammps_test {
namespace {

// What the plugin handed to the loader, and the loader's side of the calls: LAMMPS' maps hold
// functions of its own signatures, so the recorded factories are called through these.
std::vector<lammpsplugin_t> registered;
lammpsplugin_factory1* pair_factory = nullptr;
lammpsplugin_factory2* fix_factory = nullptr;

void record(lammpsplugin_t* plugin, void* /*lmp*/) {
  registered.push_back(*plugin);
}

LAMMPS_NS::Pair* make_pair(LAMMPS_NS::LAMMPS* lmp) {
  return static_cast<LAMMPS_NS::Pair*>(pair_factory(lmp));
}

LAMMPS_NS::Fix* make_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return static_cast<LAMMPS_NS::Fix*>(fix_factory(lmp, narg, arg));
}

const std::vector<std::string> deck{
    "dimension 2",
    "units si",
    "atom_style sphere",
    "atom_modify map array",
    "boundary f f p",
    "comm_modify vel yes",
    "region box block -1 1 -1 1 -0.01 0.01",
    "create_box 1 box",
    "create_atoms 1 single 0 0 0",
    "create_atoms 1 single 0.0019 0.0003 0",
    "set type 1 diameter 0.002",
    "set type 1 mass 1e-4",
    "set atom 1 vx 0.1 omega 0 0 5",
    "pair_style granthesis linear coulomb",
    "pair_coeff 1 1 normal_stiffness 1e4 restitution 0.5 friction 0.4 tangential_damping 200",
    "neighbor 0.001 bin",
    "fix move all nve/sphere disc",
    "fix heave all frost/heave epsilon 1e-30 factor 1.5 table 0",
    "fix 2d all enforce2d",
    "timestep 1e-6",
    "run 100"};

TEST(Plugin, LoadedStylesRunADeckAsTheRegisteredOnes) {
  void* handle = dlopen(TALUS_TEST_PLUGIN, RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(handle, nullptr) << dlerror();
  const auto init =
      reinterpret_cast<void (*)(void*, void*, void*)>(dlsym(handle, "lammpsplugin_init"));
  ASSERT_NE(init, nullptr) << dlerror();

  LammpsInstance loaded(false);
  registered.clear();
  init(loaded.lmp(), handle, reinterpret_cast<void*>(&record));
  ASSERT_EQ(registered.size(), 4u);
  std::vector<std::string> fixes;
  for (const lammpsplugin_t& p : registered) {
    EXPECT_STREQ(p.version, "test host");
    EXPECT_EQ(p.handle, handle);
    if (std::string(p.style) == "pair") {
      EXPECT_STREQ(p.name, "granthesis");
      pair_factory = p.creator.v1;
    } else {
      EXPECT_STREQ(p.style, "fix");
      fixes.emplace_back(p.name);
      if (fixes.back() == "frost/heave") fix_factory = p.creator.v2;
    }
  }
  EXPECT_EQ(fixes,
            (std::vector<std::string>{"frost/heave", "granthesis/history", "granthesis/wall"}));
  ASSERT_NE(pair_factory, nullptr);
  ASSERT_NE(fix_factory, nullptr);
  (*loaded.lmp()->force->pair_map)["granthesis"] = &make_pair;
  (*loaded.lmp()->modify->fix_map)["frost/heave"] = &make_fix;
  loaded.commands(deck);

  LammpsInstance direct;
  direct.commands(deck);
  for (const int tag : {1, 2})
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(loaded.position(tag)[k], direct.position(tag)[k]) << "atom " << tag;
      EXPECT_EQ(loaded.velocity(tag)[k], direct.velocity(tag)[k]) << "atom " << tag;
    }
  // the disks touched and pushed each other: the plugin's pair style acted
  EXPECT_NE(loaded.velocity(2)[0], 0.0);
}

} // namespace
} // namespace talus::lammps_test
