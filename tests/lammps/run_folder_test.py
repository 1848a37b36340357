#!/usr/bin/python3
"""validation/run_folder.py and measures.py: a LAMMPS run made into a talus run folder holds the
native engine's contacts, and the measures are right on shapes with known answers.

    run_folder_test.py TALUS TALUS_LMP SOURCE_DIR WORK_DIR

The 1000 falling disks of inputs/validation/settling_1000 run in native velocity Verlet with
LAMMPS' damper velocity and in LAMMPS with granthesis, whose trajectories agree to rounding over
the case (docs/validation.md), in a box of wall particles and in one of wall segments (fix
granthesis/wall). At every common snapshot the converted LAMMPS folder must then hold the same
contacts (pairs by id, and grains with a segment) with the same normal forces, to the 9 digits
the native .vtp files print (relative 1e-7: a force is k times an overlap of about 1e-3 radii,
which rounding moves by far less), the same coordination, and `talus analyze` must read it.
"""
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(sys.argv[3], "validation"))
import numpy as np  # noqa: E402

from measures import coordination, disk_area_in_box, packing_fraction  # noqa: E402
from run_folder import (add_analysis_dumps, data_array, lammps_run_folder,  # noqa: E402
                        pvd_entries)

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(command, cwd=None):
    done = subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")


def contacts(folder, name):
    path = os.path.join(folder, name)
    with open(path) as f:
        xml = f.read()
    pairs = zip(data_array(xml, "particle", path).astype(int),
                data_array(xml, "partner", path).astype(int),
                data_array(xml, "normal_force", path))
    return {(min(a, b), max(a, b)): f for a, b, f in pairs}


def shapes():
    """The measures on shapes with known areas."""
    r = np.array([1.0])
    # midpoint rule over 1024 chords: the error of a circle's area is below 2e-5 relative
    whole = disk_area_in_box(np.array([0.0]), np.array([0.0]), r, -2, -2, 2, 2)[0]
    check(abs(whole / math.pi - 1) < 2e-5, f"a whole disk: {whole / math.pi:.6f} pi")
    half = disk_area_in_box(np.array([0.0]), np.array([0.0]), r, 0, -2, 2, 2)[0]
    check(abs(half / (math.pi / 2) - 1) < 2e-5, f"half a disk: {half / (math.pi / 2):.6f} pi/2")
    quarter = disk_area_in_box(np.array([0.0]), np.array([0.0]), r, 0, 0, 2, 2)[0]
    check(abs(quarter / (math.pi / 4) - 1) < 2e-5,
          f"a quarter: {quarter / (math.pi / 4):.6f} pi/4")
    # touching disks on a triangular lattice fill pi / (2 sqrt 3) of the plane; a region of
    # whole cells (2 x sqrt 3 radii each) holds exactly that share, in every strip of it
    xs, ys = np.meshgrid(np.arange(-2, 24) * 2.0, np.arange(-2, 24) * math.sqrt(3))
    xs = xs + (np.arange(-2, 24)[:, None] % 2)  # every other row shifted by a radius
    frame = {"x": xs.ravel(), "y": ys.ravel(), "radius": np.ones(xs.size),
             "kind": np.zeros(xs.size, dtype=int)}
    phi, error, _ = packing_fraction([(0.0, frame)], [0, 0, 40, 20 * math.sqrt(3)], 4, [0, 1])
    exact = math.pi / (2 * math.sqrt(3))
    check(abs(phi / exact - 1) < 2e-5 and error < 1e-4 * exact,
          f"triangular lattice: {phi:.6f} +- {error:.1e} against {exact:.6f}")


def engines(talus, lmp, source, work, walls):
    scenario = os.path.join(source, "inputs", "validation", "settling_1000", "scenario.toml")
    verlet = ["--set", "simulation.integrator=verlet", "--set",
              "simulation.verlet_velocity=half_step", "--set", "output.snapshot_interval=0.02",
              "--set", f"geometry.walls={walls}"]
    native = os.path.join(work, f"native-{walls}")
    run([talus, "run", scenario, "--out", native, "--quiet", "--threads", "1"] + verlet)
    with open(os.path.join(native, "run.json")) as f:
        dt = json.load(f)["timestep"]
    deck = os.path.join(work, f"lammps-{walls}")
    run([talus, "export", "lammps", scenario, deck, "--quiet"] + verlet)
    add_analysis_dumps(os.path.join(deck, "in.settling_1000"))
    run([lmp, "-in", "in.settling_1000", "-var", "analysis_every", str(round(0.02 / dt)),
         "-log", "log.lammps", "-screen", "none"], cwd=deck)
    folder = lammps_run_folder(deck, native, dt, os.path.join(work, f"lammps-run-{walls}"))
    ours = {round(t / dt): name for t, name in pvd_entries(os.path.join(native, "contacts.pvd"))}
    compared, most, on_walls = 0, 0, 0
    for t, name in pvd_entries(os.path.join(folder, "contacts.pvd")):
        if round(t / dt) not in ours:
            continue
        a, b = contacts(native, ours[round(t / dt)]), contacts(folder, name)
        # the native engine lists touching pairs whose force is 0 (a damper pulling); both
        # lists must agree on every pair that carries a force
        a = {k: v for k, v in a.items() if v > 0}
        b = {k: v for k, v in b.items() if v > 0}
        same = a.keys() == b.keys() and all(abs(a[k] - b[k]) <= 1e-7 * a[k] for k in a)
        check(same, f"{walls}, t = {t:.4f} s: {len(a)} native contacts, {len(b)} LAMMPS, "
              "the same pairs and forces" if same else f"{walls}: different pairs or forces")
        compared += 1
        most = max(most, len(a))
        on_walls = max(on_walls, sum(1 for pair in b if pair[0] < 0))
    check(compared >= 4 and most > 100, f"{walls}: {compared} snapshots compared, up to {most} "
          "contacts")
    if walls == "segments":  # segment contacts (partner < 0) come from fix granthesis/wall
        check(on_walls > 10, f"segments: up to {on_walls} contacts with the wall segments")
    # with segments, the grains on the floor and against the sides too: their wall contacts count
    region = [0.02, 0.01, 0.18, 0.09] if walls == "particles" else [0.0, 0.0, 0.2, 0.09]
    window = [0.09, 0.11]
    za, zb = coordination(native, region, 4, window), coordination(folder, region, 4, window)
    check(abs(za[0] - zb[0]) < 1e-12,
          f"{walls}: coordination of the bed: {za[0]:.4f} and {zb[0]:.4f}")
    done = subprocess.run([talus, "analyze", folder, "forces", "--frames", "last"],
                          capture_output=True, text=True)
    check(done.returncode == 0 and os.path.exists(os.path.join(folder, "analysis",
                                                               "forces.json")),
          f"{walls}: talus analyze reads the LAMMPS run folder")


def main():
    talus, lmp, source, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    shapes()
    for walls in ("particles", "segments"):
        engines(talus, lmp, source, work, walls)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
