"""What the LAMMPS package's MPI tests share: a deck of this folder run in talus-lmp under
mpirun, and the final dump it writes read back by atom id."""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def require_mpirun():
    """Exits with ctest's skip status where Open MPI's mpirun is missing."""
    if shutil.which("mpirun") is None:
        print("mpirun not found (Debian package openmpi-bin): skipped")
        sys.exit(77)


def run_deck(lmp, deck, ranks, variables):
    """Runs deck (a file of this folder) on `ranks` ranks with -var NAME VALUE for each item of
    `variables`; returns what it printed, or exits with it if the run failed."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    command = ["mpirun", "--oversubscribe", "-np", str(ranks), lmp, "-in",
               os.path.join(HERE, deck), "-log", "none"]
    for name, value in variables.items():
        command += ["-var", name, value]
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
    return done.stdout


def read_dump(path):
    """{id: [x, y, vx, vy]} from a dump of `id x y vx vy omegaz`."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id x y vx vy omegaz") + 1
    return {int(l.split()[0]): [float(w) for w in l.split()[1:5]] for l in lines[start:]}


def largest_difference(a, b, columns):
    """The largest |a - b| over the atoms and the given columns (indices into read_dump's rows)."""
    if a.keys() != b.keys():
        sys.exit("the runs have other atoms")
    return max(max(abs(a[i][k] - b[i][k]) for k in columns) for i in a)
