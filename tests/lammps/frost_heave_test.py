#!/usr/bin/python3
"""fix frost/heave does the same on 1 and 2 MPI ranks, and a run resumed from a restart file
continues as the run that wrote it: the same heaves at the same steps, and the same trajectories
(frost500.in, 1000 steps with about six heaves).

Usage: frost_heave_test.py TALUS_LMP WORK_DIR"""
import os
import re
import shutil
import subprocess
import sys

# as ranks_test.py: the sums' order differs between rank counts, so rounding, amplified by the
# contacts over 1000 steps, and nothing more
BOUND = 1e-12  # m and m/s


def run(lmp, work, ranks, phase, name):
    out = os.path.join(work, f"{name}.dump")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "frost500.in")
    command = ["mpirun", "--oversubscribe", "-np", str(ranks), lmp, "-in", deck,
               "-var", "phase", phase, "-var", "out", out,
               "-var", "restart", os.path.join(work, "frost500.restart"), "-log", "none"]
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
    heaves = [int(s) for s in re.findall(r"heave \d+ at t = \S+ s \(step (\d+)\)", done.stdout)]
    with open(out) as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id x y vx vy omegaz") + 1
    rows = {int(l.split()[0]): [float(w) for w in l.split()[1:5]] for l in lines[start:]}
    return heaves, rows


def largest_difference(a, b):
    if a.keys() != b.keys():
        sys.exit("the runs have other atoms")
    return max(max(abs(x - y) for x, y in zip(a[i], b[i])) for i in a)


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    if shutil.which("mpirun") is None:
        print("mpirun not found (Debian package openmpi-bin): skipped")
        sys.exit(77)
    os.makedirs(work, exist_ok=True)
    failures = []
    one, rows_one = run(lmp, work, 1, "whole", "whole-1")
    two, rows_two = run(lmp, work, 2, "whole", "whole-2")
    if len(one) < 3:
        failures.append(f"expected several heaves in 1000 steps, got {len(one)}")
    difference = largest_difference(rows_one, rows_two)
    print(f"heaves at steps {one} on 1 rank, {two} on 2; largest difference {difference:.3g}")
    if one != two or difference > BOUND:
        failures.append("1 and 2 ranks differ")
    split, rows_split = run(lmp, work, 1, "split", "split")
    resumed, rows_resumed = run(lmp, work, 1, "resume", "resumed")
    resumed_two, rows_resumed_two = run(lmp, work, 2, "resume", "resumed-2")
    after = [s for s in split if s > 600]
    print(f"heaves after the restart: {after} written, {resumed} resumed, {resumed_two} on 2 ranks")
    if resumed != after or resumed_two != after:
        failures.append("the resumed run heaves at other steps")
    if rows_resumed != rows_split:
        failures.append("the resumed run does not continue the run that wrote the restart")
    if largest_difference(rows_resumed_two, rows_split) > BOUND:
        failures.append("the resumed run on 2 ranks differs beyond the bound")
    for f in failures:
        print("FAILED:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
