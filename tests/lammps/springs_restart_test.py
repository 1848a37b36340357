#!/usr/bin/python3
"""A Cundall-Strack run resumed from a restart file continues the run that wrote it: the springs
of the grains' contacts (fix granthesis/history of the pair style) and of their contacts with a
rising floor (fix granthesis/wall's own), the floor's position and its work all come back
(springs500.in: 600 steps, the restart file, 400 more). On 1 rank the resumed run is the same to
the bit; on 2 ranks it differs by the rounding of sums taken in another order.

Usage: springs_restart_test.py TALUS_LMP WORK_DIR"""
import os
import re
import subprocess
import sys

from mpi_runs import HERE, largest_difference, read_dump, require_mpirun, run_deck

# as ranks_test.py: the sums' order differs between rank counts, so rounding, amplified by the
# contacts over 400 steps, and nothing more
BOUND = 1e-12  # m and m/s
# the floor's work over 1000 steps is a few mJ: rounding leaves its first 11 digits alone
WORK_BOUND = 1e-14  # J


def run(lmp, work, ranks, phase, name):
    out = os.path.join(work, f"{name}.dump")
    printed = run_deck(lmp, "springs500.in", ranks,
                       {"phase": phase, "out": out,
                        "restart": os.path.join(work, "springs500.restart")})
    found = re.search(r"^WORK (\S+)$", printed, re.MULTILINE)
    if not found:
        sys.exit(f"{name}: no WORK line in what the run printed:\n{printed}")
    return printed, float(found.group(1)), read_dump(out)


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    require_mpirun()
    os.makedirs(work, exist_ok=True)
    failures = []
    _, work_split, rows_split = run(lmp, work, 1, "split", "split")
    printed, work_resumed, rows_resumed = run(lmp, work, 1, "resume", "resumed")
    for fix_id in ("GRANTHESIS_HISTORY", "floor_HISTORY"):
        if f"fix style: granthesis/history, fix ID: {fix_id}" not in printed:
            failures.append(f"the springs of {fix_id} were not taken from the restart file")
    if "Unused restart file" in printed:
        failures.append("part of the restart file was not used")
    print(f"the floor's work: {work_split!r} J written, {work_resumed!r} J resumed")
    if work_resumed != work_split:
        failures.append("the resumed floor's work differs")
    if rows_resumed != rows_split:
        failures.append("the resumed run does not continue the run that wrote the restart file: "
                        f"largest difference {largest_difference(rows_resumed, rows_split, range(4)):.3g}")
    _, work_two, rows_two = run(lmp, work, 2, "resume", "resumed-2")
    difference = largest_difference(rows_two, rows_split, range(4))
    print(f"resumed on 2 ranks: largest difference {difference:.3g}, "
          f"work {work_two - work_split:.3g} J from the run that wrote the file")
    if difference > BOUND or abs(work_two - work_split) > WORK_BOUND:
        failures.append("the run resumed on 2 ranks differs beyond the bound")
    # the fix defined again with other segments than the run that wrote the file: refused
    refused = subprocess.run(
        [lmp, "-in", os.path.join(HERE, "springs500.in"), "-log", "none", "-var", "phase",
         "resume", "-var", "out", os.path.join(work, "never.dump"), "-var", "restart",
         os.path.join(work, "springs500.restart"), "-var", "more_walls",
         "segment 0 0.3 0.1 0.3 type 1"], capture_output=True, text=True, timeout=600)
    said = refused.stdout + refused.stderr
    if refused.returncode == 0 or "had 1 segment(s) in the run that wrote" not in said:
        failures.append(f"other segments than the restart file's were not refused:\n{said}")
    for f in failures:
        print("FAILED:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
