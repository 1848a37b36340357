#!/usr/bin/python3
"""pair_style granthesis gives the same trajectories of a 500-disk packing (packing500.in, 1000
steps) with newton pair on and off and on 1, 2 and 4 MPI ranks, within a stated bound: the pair
forces are the same terms, summed in another order (by rank, ghosts and newton), so the runs differ
by rounding, which the contacts amplify over 1000 steps.

Usage: ranks_test.py TALUS_LMP WORK_DIR"""
import os
import shutil
import subprocess
import sys

# Rounding in a sum of a few forces is about 1e-16 of them; 1000 steps of a dense packing amplify
# it, but must leave it far below anything physical: a picometre against 5 mm grains, a
# picometre per second against speeds of 5 cm/s.
POSITION_BOUND = 1e-12  # m
VELOCITY_BOUND = 1e-12  # m/s


def run(lmp, work, ranks, newton):
    out = os.path.join(work, f"packing500-{ranks}-{newton}.dump")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "packing500.in")
    command = ["mpirun", "--oversubscribe", "-np", str(ranks), lmp, "-in", deck, "-var",
               "newton", newton, "-var", "out", out, "-log", "none", "-screen", "none"]
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
    rows = {}
    with open(out) as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id x y vx vy omegaz") + 1
    for line in lines[start:]:
        words = line.split()
        rows[int(words[0])] = [float(w) for w in words[1:]]
    return rows


def main():
    lmp, work = sys.argv[1], sys.argv[2]
    if shutil.which("mpirun") is None:
        print("mpirun not found (Debian package openmpi-bin): skipped")
        sys.exit(77)
    os.makedirs(work, exist_ok=True)
    reference = run(lmp, work, 1, "on")
    if len(reference) != 500:
        sys.exit(f"expected 500 atoms, read {len(reference)}")
    failed = False
    for ranks, newton in [(1, "off"), (2, "on"), (2, "off"), (4, "on")]:
        rows = run(lmp, work, ranks, newton)
        if rows.keys() != reference.keys():
            sys.exit(f"{ranks} ranks, newton {newton}: other atoms than the reference")
        dx = max(max(abs(rows[i][k] - reference[i][k]) for k in (0, 1)) for i in reference)
        dv = max(max(abs(rows[i][k] - reference[i][k]) for k in (2, 3)) for i in reference)
        ok = dx <= POSITION_BOUND and dv <= VELOCITY_BOUND
        failed |= not ok
        print(f"{ranks} rank(s), newton {newton}: largest difference from 1 rank, newton on: "
              f"position {dx:.3g} m, velocity {dv:.3g} m/s {'ok' if ok else 'BEYOND THE BOUND'}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
