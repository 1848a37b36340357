#!/usr/bin/python3
"""pair_style granthesis in 3d keeps vectors per contact (the Cundall-Strack springs and the
rolling angles: fix granthesis/history with three numbers per contact), and so does fix
granthesis/wall for its plates (a lid closing in, whose place and work a restart file keeps
too): a run resumed from a
restart file continues the run that wrote it to the bit on 1 rank, and the run on 2 ranks (the
atoms and their springs moving between ranks) differs from it by rounding alone
(springs3d.in: 500 spheres falling onto a frozen bed, 600 steps, the restart file, 400 more).
It fails with springs that carry one number of three across ranks and restart files (checked).

Usage: springs3d_test.py TALUS_LMP WORK_DIR"""
import os
import sys

from mpi_runs import require_mpirun, run_deck

# the sums' order differs between rank counts: rounding, amplified by the contacts over 1000
# steps, and nothing more (a spring lost or sent wrong moves a grain by far more)
BOUND = 1e-12  # m, m/s and rad/s x m


def read(path):
    """{id: [x, y, z, vx, vy, vz, wx r, wy r, wz r]} (spins times 5 mm: one scale)."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id x y z vx vy vz omegax omegay omegaz") + 1
    rows = {}
    for line in lines[start:]:
        w = line.split()
        rows[int(w[0])] = [float(x) for x in w[1:7]] + [0.005 * float(x) for x in w[7:10]]
    return rows


PERIOD = 0.099  # m: the box along x and y, where a run may hold an atom on either side


def largest(a, b):
    """The largest difference of two dumps, positions along x and y by the nearest image."""
    if a.keys() != b.keys():
        sys.exit("the runs have other atoms")

    def gap(k, x, y):
        d = x - y
        return abs(d - PERIOD * round(d / PERIOD)) if k < 2 else abs(d)

    return max(max(gap(k, x, y) for k, (x, y) in enumerate(zip(a[i], b[i]))) for i in a)


def run(lmp, work, ranks, phase, name):
    out = os.path.join(work, f"{name}.dump")
    printed = run_deck(lmp, "springs3d.in", ranks,
                       {"phase": phase, "out": out,
                        "restart": os.path.join(work, "springs3d.restart")})
    return printed, read(out)


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    require_mpirun()
    os.makedirs(work, exist_ok=True)
    failures = []
    printed, whole = run(lmp, work, 1, "whole", "whole")
    last = [l.split() for l in printed.splitlines() if l.split()[:1] == ["1000"]]
    if not last or not float(last[-1][2]) > 0.0:
        failures.append("the lid did not touch the spheres (f_lid[4] at step 1000: "
                        f"{last[-1][2] if last else 'no thermo row'})")
    _, split = run(lmp, work, 1, "split", "split")
    printed, resumed = run(lmp, work, 1, "resume", "resumed")
    for fix_id in ("GRANTHESIS_HISTORY", "GRANTHESIS_ROLLING", "lid_HISTORY", "lid_ROLLING"):
        if f"fix style: granthesis/history, fix ID: {fix_id}" not in printed:
            failures.append(f"the vectors of {fix_id} were not taken from the restart file")
    # not checked: a LAMMPS run split in two is not the whole run, for pair granthesis in 2d as in
    # 3d, since the second run's setup evaluates the springs' forces once more with their step's
    # stretch (the spring kept is not advanced, the force taken is)
    print(f"split run against the whole one: largest difference {largest(split, whole):.3g}")
    if resumed != split:
        failures.append("the resumed run does not continue the run that wrote the restart file: "
                        f"largest difference {largest(resumed, split):.3g}")
    _, two = run(lmp, work, 2, "whole", "whole-2")
    difference = largest(two, whole)
    print(f"2 ranks against 1: largest difference {difference:.3g} (bound {BOUND:g})")
    if difference > BOUND:
        failures.append("the run on 2 ranks differs beyond rounding")
    for f in failures:
        print("FAILED:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
