// The upstream plugin entry point, for a LAMMPS built with the PLUGIN package: `plugin load
// talusplugin.so`, or the folder in LAMMPS_PLUGIN_PATH. Debian's LAMMPS has no PLUGIN package and
// ships no lammpsplugin.h, so CMake compiles this file only where that header is found (see
// README.md, "Running it").
#include "fix_contact_history.h"
#include "fix_frost_heave.h"
#include "fix_segment_walls.h"
#include "lammpsplugin.h"
#include "pair_granthesis.h"
#include "version.h"

namespace {

void* create_pair_granthesis(void* lmp) {
  // as the base class: the loader casts the pointer back to a Pair*
  return static_cast<LAMMPS_NS::Pair*>(
      new talus::lammps::PairGranthesis(static_cast<LAMMPS_NS::LAMMPS*>(lmp)));
}

void* create_fix_frost_heave(void* lmp, int narg, char** arg) {
  return static_cast<LAMMPS_NS::Fix*>(
      new talus::lammps::FixFrostHeave(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg));
}

void* create_fix_contact_history(void* lmp, int narg, char** arg) {
  return static_cast<LAMMPS_NS::Fix*>(
      new talus::lammps::FixContactHistory(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg));
}

void* create_fix_segment_walls(void* lmp, int narg, char** arg) {
  return static_cast<LAMMPS_NS::Fix*>(
      new talus::lammps::FixSegmentWalls(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg));
}

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
  plugin.name = "frost/heave";
  plugin.info = "the thesis' freeze-thaw heave";
  plugin.creator.v2 = &create_fix_frost_heave;
  register_plugin(&plugin, lmp);

  plugin.name = "granthesis/history";
  plugin.info = "the tangential springs of granthesis' contacts (made by the styles)";
  plugin.creator.v2 = &create_fix_contact_history;
  register_plugin(&plugin, lmp);

  plugin.name = "granthesis/wall";
  plugin.info = "straight wall segments with granthesis' laws";
  plugin.creator.v2 = &create_fix_segment_walls;
  register_plugin(&plugin, lmp);
}
