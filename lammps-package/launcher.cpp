// talus-lmp: LAMMPS with the talus styles registered (built for LIGGGHTS: talus-liggghts, with
// the pair style). It takes the host program's command line (-in, -var, -log, -screen, ...) and
// runs under mpirun -np N as the host program does.
#include <cstdio>
#include <exception>

#include <mpi.h>

#include "input.h"
#include "lammps.h"
#include "register.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = 0;
  try {
    auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    talus_lammps_register(lmp);
    lmp->input->file();
    delete lmp;
  } catch (const std::exception& e) {
    // LAMMPS has printed the error (screen and log); its message again for a caller reading
    // stderr alone
    std::fprintf(stderr, "talus-lmp: %s\n", e.what());
    status = 1;
  }
  if (status != 0) MPI_Abort(MPI_COMM_WORLD, status);
  MPI_Finalize();
  return status;
}
