#!/usr/bin/python3
"""pair_style granthesis gives the same trajectories of a 500-disk packing (packing500.in, 1000
steps) with newton pair on and off and on 1, 2 and 4 MPI ranks, within a stated bound: the pair
forces are the same terms, summed in another order (by rank, ghosts and newton), so the runs differ
by rounding, which the contacts amplify over 1000 steps. With Cundall-Strack springs (kept per
atom by fix granthesis/history, taken along when an atom changes rank; newton off) 2 and 4 ranks
give what 1 rank gives, within the same bound.

Usage: ranks_test.py TALUS_LMP WORK_DIR"""
import os
import sys

from mpi_runs import largest_difference, read_dump, require_mpirun, run_deck

# Rounding in a sum of a few forces is about 1e-16 of them; 1000 steps of a dense packing amplify
# it, but must leave it far below anything physical: a picometre against 5 mm grains, a
# picometre per second against speeds of 5 cm/s.
POSITION_BOUND = 1e-12  # m
VELOCITY_BOUND = 1e-12  # m/s


def run(lmp, work, ranks, newton, tangential="coulomb"):
    out = os.path.join(work, f"packing500-{tangential}-{ranks}-{newton}.dump")
    run_deck(lmp, "packing500.in", ranks,
             {"newton": newton, "out": out, "tangential": tangential})
    return read_dump(out)


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    require_mpirun()
    os.makedirs(work, exist_ok=True)
    reference = run(lmp, work, 1, "on")
    if len(reference) != 500:
        sys.exit(f"expected 500 atoms, read {len(reference)}")
    failed = False
    springs = run(lmp, work, 1, "off", "cundall_strack")
    # the springs change the motion: else the Cundall-Strack runs would test nothing new
    if largest_difference(springs, reference, (2, 3)) < 1e3 * VELOCITY_BOUND:
        sys.exit("cundall_strack moved the disks as coulomb did: the springs did not act")
    for ranks, newton, tangential, against in [
            (1, "off", "coulomb", reference), (2, "on", "coulomb", reference),
            (2, "off", "coulomb", reference), (4, "on", "coulomb", reference),
            (2, "off", "cundall_strack", springs), (4, "off", "cundall_strack", springs)]:
        rows = run(lmp, work, ranks, newton, tangential)
        dx = largest_difference(rows, against, (0, 1))
        dv = largest_difference(rows, against, (2, 3))
        ok = dx <= POSITION_BOUND and dv <= VELOCITY_BOUND
        failed |= not ok
        print(f"{tangential}, {ranks} rank(s), newton {newton}: largest difference from 1 rank, "
              f"newton {'on' if against is reference else 'off'}: position {dx:.3g} m, "
              f"velocity {dv:.3g} m/s {'ok' if ok else 'BEYOND THE BOUND'}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
