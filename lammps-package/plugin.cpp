// The upstream plugin entry point, for a LAMMPS built with the PLUGIN package: `plugin load
// talusplugin.so`, or the folder in LAMMPS_PLUGIN_PATH. Debian's LAMMPS has no PLUGIN package and
// ships no lammpsplugin.h, so CMake compiles this file only where that header is found (see
// README.md, "Running it").
#include "fix_contact_history.h"
#include "fix_frost_heave.h"
#include "fix_granthesis_wall.h"
#include "lammpsplugin.h"
#include "pair_granthesis.h"
#include "version.h"

namespace {

void* create_pair_granthesis(void* lmp) {
  // as the base class: the loader casts the pointer back to a Pair*
  return static_cast<LAMMPS_NS::Pair*>(
      new talus::lammps::PairGranthesis(static_cast<LAMMPS_NS::LAMMPS*>(lmp)));
}

// A fix style's creator, as the loader calls it: the fix as the base class.
template <class F> void* create_fix(void* lmp, int narg, char** arg) {
  return static_cast<LAMMPS_NS::Fix*>(new F(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg));
}

struct FixEntry {
  const char* name;
  const char* info;
  lammpsplugin_factory2* creator;
};

constexpr FixEntry fixes[] = {
    {"frost/heave", "the thesis' freeze-thaw heave", &create_fix<talus::lammps::FixFrostHeave>},
    {"granthesis/history", "the tangential springs of granthesis' contacts (made by the styles)",
     &create_fix<talus::lammps::FixContactHistory>},
    {"granthesis/wall", "straight wall segments with granthesis' laws",
     &create_fix<talus::lammps::FixGranthesisWall>},
};

} // namespace

extern "C" void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  const auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin{};
  plugin.version = LAMMPS_VERSION;
  plugin.author = "the talus developers";
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "granthesis";
  plugin.info = "the thesis' contact laws over src/talus";
  plugin.creator.v1 = &create_pair_granthesis;
  register_plugin(&plugin, lmp);

  plugin.style = "fix";
  for (const FixEntry& f : fixes) {
    plugin.name = f.name;
    plugin.info = f.info;
    plugin.creator.v2 = f.creator;
    register_plugin(&plugin, lmp);
  }
}
