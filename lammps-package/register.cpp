#include "register.hpp"

#include "force.h"
#include "lammps.h"
#include "pair_granthesis.h"

namespace {

LAMMPS_NS::Pair* create_pair_granthesis(LAMMPS_NS::LAMMPS* lmp) {
  return new talus::lammps::PairGranthesis(lmp);
}

} // namespace

extern "C" void talus_lammps_register(void* lmp) {
  auto* instance = static_cast<LAMMPS_NS::LAMMPS*>(lmp);
  (*instance->force->pair_map)["granthesis"] = &create_pair_granthesis;
}
