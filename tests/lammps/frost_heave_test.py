#!/usr/bin/python3
"""fix frost/heave does the same on 1 and 2 MPI ranks, and a run resumed from a restart file
continues as the run that wrote it: the same heaves at the same steps and times, and the same
trajectories (frost500.in, 1000 steps with about six heaves).

Usage: frost_heave_test.py TALUS_LMP WORK_DIR"""
import os
import re
import sys

from mpi_runs import largest_difference, read_dump, require_mpirun, run_deck

# as ranks_test.py: the sums' order differs between rank counts, so rounding, amplified by the
# contacts over 1000 steps, and nothing more
BOUND = 1e-12  # m and m/s


def run(lmp, work, ranks, phase, name):
    out = os.path.join(work, f"{name}.dump")
    printed = run_deck(lmp, "frost500.in", ranks,
                       {"phase": phase, "out": out,
                        "restart": os.path.join(work, "frost500.restart")})
    heaves = [(int(s), float(t))
              for t, s in re.findall(r"heave \d+ at t = (\S+) s \(step (\d+)\)", printed)]
    return heaves, read_dump(out)


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    require_mpirun()
    os.makedirs(work, exist_ok=True)
    failures = []
    one, rows_one = run(lmp, work, 1, "whole", "whole-1")
    two, rows_two = run(lmp, work, 2, "whole", "whole-2")
    if len(one) < 3:
        failures.append(f"expected several heaves in 1000 steps, got {len(one)}")
    difference = largest_difference(rows_one, rows_two, range(4))
    print(f"heaves (step, time) {one} on 1 rank, {two} on 2; largest difference {difference:.3g}")
    if one != two or difference > BOUND:
        failures.append("1 and 2 ranks differ")
    split, rows_split = run(lmp, work, 1, "split", "split")
    resumed, rows_resumed = run(lmp, work, 1, "resume", "resumed")
    resumed_two, rows_resumed_two = run(lmp, work, 2, "resume", "resumed-2")
    # (step, time): a resumed run's time goes on from the restart file's, not from 0
    after = [h for h in split if h[0] > 600]
    print(f"heaves after the restart: {after} written, {resumed} resumed, {resumed_two} on 2 ranks")
    if resumed != after or resumed_two != after:
        failures.append("the resumed run heaves at other steps")
    if rows_resumed != rows_split:
        failures.append("the resumed run does not continue the run that wrote the restart")
    if largest_difference(rows_resumed_two, rows_split, range(4)) > BOUND:
        failures.append("the resumed run on 2 ranks differs beyond the bound")
    for f in failures:
        print("FAILED:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
