#include "register.hpp"

#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair_granthesis.h"
#ifndef TALUS_HOST_LIGGGHTS
#include "fix_contact_history.h"
#include "fix_frost_heave.h"
#include "fix_granthesis_wall.h"
#endif

namespace {

LAMMPS_NS::Pair* create_pair_granthesis(LAMMPS_NS::LAMMPS* lmp) {
  return new talus::lammps::PairGranthesis(lmp);
}

#ifndef TALUS_HOST_LIGGGHTS
LAMMPS_NS::Fix* create_fix_frost_heave(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new talus::lammps::FixFrostHeave(lmp, narg, arg);
}
LAMMPS_NS::Fix* create_fix_contact_history(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new talus::lammps::FixContactHistory(lmp, narg, arg);
}
LAMMPS_NS::Fix* create_fix_granthesis_wall(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new talus::lammps::FixGranthesisWall(lmp, narg, arg);
}
#endif

} // namespace

extern "C" void talus_lammps_register(void* lmp) {
  auto* instance = static_cast<LAMMPS_NS::LAMMPS*>(lmp);
  (*instance->force->pair_map)["granthesis"] = &create_pair_granthesis;
#ifndef TALUS_HOST_LIGGGHTS // the LIGGGHTS adapter carries the pair style only
  (*instance->modify->fix_map)["frost/heave"] = &create_fix_frost_heave;
  (*instance->modify->fix_map)["granthesis/history"] = &create_fix_contact_history;
  (*instance->modify->fix_map)["granthesis/wall"] = &create_fix_granthesis_wall;
#endif
}
