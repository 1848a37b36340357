#!/usr/bin/python3
"""Cross-check in 3D: the same spheres in the native 3D engine and in LAMMPS, sphere by sphere.

    /usr/bin/python3 validation/crosscheck3d.py [--case settling3d] [--quick] [--mutation]
        [--build build] [--out DIR]

The case is a folder of inputs/validation: settling3d (the default), spheres on a lattice in a
box of plates fall and settle, or shaken3d, spheres fall onto a vibrating floor while one side
closes in and another turns (scenario.toml), with its bounds and their reasons in
tolerances.toml. It runs in

- the native 3D engine (`talus run`, velocity Verlet with LAMMPS' damper velocity), whose
  snapshots hold every sphere's state as the shortest text that reads back to the same double;
- LAMMPS with pair_style granthesis and fix granthesis/wall planes, from the deck `talus export
  lammps` writes of the same scenario, on 1 rank and on 2 (the spheres, their springs and the
  plates' springs moving between ranks), dumping at the snapshots' steps.

At every common time the largest difference of a position, in mean radii, between native and
LAMMPS on 1 rank and between 1 and 2 ranks must stay within the case's rounding bound up to its
time; the last snapshot's kinetic energy, coordination and bed height are printed side by side.
--quick runs the case with the changes its tolerances.toml lists under [quick] (settling3d: the
first part of the fall with fewer spheres), the default test suite's;
--mutation also runs LAMMPS from a deck with the friction changed in the fourth digit, which
must fail the comparison (a rule that can fail). Exit status 1 if a comparison fails.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tomllib
import xml.etree.ElementTree as ET

import numpy as np

from run_folder import data_array, dump_blocks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")


def run(command, cwd=None):
    done = subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stdout[-3000:]}"
                 f"\n{done.stderr[-3000:]}")
    return done.stdout


def vtp_state(path):
    """{id: (x, y, z, vx, vy, vz)} of a native snapshot (ids as LAMMPS', from 1)."""
    with open(path) as f:
        xml = f.read()
    ids = data_array(xml, "id", path).astype(int) + 1
    x = data_array(xml, "position", path).reshape(-1, 3)
    v = data_array(xml, "velocity", path).reshape(-1, 3)
    return {i: np.concatenate([x[k], v[k]]) for k, i in enumerate(ids)}


def native_snapshots(folder):
    """[(time, state)] of a native 3D run folder, from its particles.pvd."""
    entries = ET.parse(os.path.join(folder, "particles.pvd")).getroot().find("Collection")
    return [(float(e.get("timestep")), vtp_state(os.path.join(folder, e.get("file"))))
            for e in entries]


def dump_frames(path, dt):
    """[(time, state)] of a LAMMPS dump of id, type, radius, mass, x y z, vx vy vz, spins."""
    frames = []
    for step, columns, rows in dump_blocks(path):
        at = [columns.index(c) for c in ("x", "y", "z", "vx", "vy", "vz")]
        ids = rows[:, columns.index("id")].astype(int)
        frames.append((step * dt, {i: rows[k, at] for k, i in enumerate(ids)}))
    return frames


def largest_difference(a, b, radius):
    """The largest difference of a position component between two states, in mean radii."""
    if a.keys() != b.keys():
        return float("inf")
    return max(np.max(np.abs(a[i][:3] - b[i][:3])) for i in a) / radius


def compare(name, first, second, dt, radius, bound, until, must_fail=False):
    """Prints the largest difference at the common times up to `until` (s); returns whether it
    held the bound (or, with must_fail, whether it did not)."""
    others = {round(t / dt): s for t, s in second}
    worst = 0.0
    for t, state in first:
        other = others.get(round(t / dt))
        if other is not None and t <= until:
            worst = max(worst, largest_difference(state, other, radius))
    ok = (worst <= bound) != must_fail
    print(f"{'ok  ' if ok else 'FAIL'} {name}: largest position difference up to {until:g} s: "
          f"{worst:.3g} mean radii (bound {bound:g}{', must be exceeded' if must_fail else ''})")
    return ok


def lammps(build, deck_dir, work, ranks, mutate=False):
    """Runs the exported deck in a copy of its folder; returns the dump's frames."""
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(deck_dir, work)
    deck = next(f for f in os.listdir(work) if f.startswith("in."))
    if mutate:  # the friction in its fourth digit: a wrong law that rounding cannot hide
        path = os.path.join(work, deck)
        text = open(path).read()
        if "friction 0.40000000000000002" not in text:
            sys.exit(f"{path}: no friction 0.4 to change: the case's material changed?")
        open(path, "w").write(text.replace("friction 0.40000000000000002", "friction 0.4001"))
    launcher = os.path.join(build, "lammps-package", "talus-lmp")
    command = [launcher, "-in", deck, "-log", "log.lammps"]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "--oversubscribe"] + command
    run(command, cwd=work)
    dt = float(next(l.split()[1] for l in open(os.path.join(work, deck))
                    if l.startswith("timestep")))
    dump = next(f for f in os.listdir(work) if f.startswith("dump."))
    return dt, dump_frames(os.path.join(work, dump), dt)


def summary_line(name, state, radii):
    z = np.array([s[2] for s in state.values()])
    v2 = np.array([np.dot(s[3:], s[3:]) for s in state.values()])
    return f"  {name}: mean height {np.mean(z):.6g} m, top {np.max(z + radii):.6g} m, " \
           f"mean v^2 {np.mean(v2):.6g} m^2/s^2"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default="settling3d", choices=["settling3d", "shaken3d"])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--mutation", action="store_true")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", help="default: validation/results/crosscheck3d/CASE")
    args = parser.parse_args()
    case = os.path.join(ROOT, "inputs", "validation", args.case)
    args.out = args.out or os.path.join(ROOT, "validation", "results", "crosscheck3d", args.case)
    if shutil.which("mpirun") is None:
        print("mpirun is not installed: skipping")
        sys.exit(77)
    with open(os.path.join(case, "tolerances.toml"), "rb") as f:
        bounds = tomllib.load(f)["quick" if args.quick else "full"]
    talus = os.path.join(args.build, "native", "talus")
    scenario = os.path.join(case, "scenario.toml")
    sets = sum([["--set", s] for s in bounds.get("set", [])], [])
    os.makedirs(args.out, exist_ok=True)
    native_dir, deck_dir = os.path.join(args.out, "native"), os.path.join(args.out, "deck")
    shutil.rmtree(native_dir, ignore_errors=True)
    run([talus, "run", scenario, "--out", native_dir, "--quiet"] + sets)
    run([talus, "export", "lammps", scenario, deck_dir, "--quiet", "--replace"] + sets)
    native = native_snapshots(native_dir)
    first = os.path.join(native_dir, "snapshots", "spheres_000000.vtp")
    with open(first) as f:
        radii = data_array(f.read(), "radius", first)
    radius = float(np.mean(radii))
    dt, one = lammps(args.build, deck_dir, os.path.join(args.out, "lammps-1"), 1)
    _, two = lammps(args.build, deck_dir, os.path.join(args.out, "lammps-2"), 2)
    print(f"{args.case}{' (quick)' if args.quick else ''}: {len(radii)} spheres, dt = {dt:.6g} s, "
          f"{len(native)} snapshots")
    results = [
        compare("native (half step) against LAMMPS granthesis, 1 rank", native, one, dt, radius,
                bounds["rounding"], bounds["rounding_until"]),
        compare("LAMMPS on 2 ranks against 1", two, one, dt, radius, bounds["ranks"],
                bounds["ranks_until"]),
    ]
    steps = {round(t / dt): s for t, s in one}
    t_last, last = max((t, s) for t, s in native if round(t / dt) in steps)
    print(f"at the last common time, {t_last:.6g} s:")
    print(summary_line("native    ", last, radii))
    print(summary_line("LAMMPS    ", steps[round(t_last / dt)], radii))
    if args.mutation:
        _, wrong = lammps(args.build, deck_dir, os.path.join(args.out, "lammps-mutated"), 1,
                          mutate=True)
        results.append(compare("native against LAMMPS with the friction 0.4001", native, wrong,
                               dt, radius, bounds["rounding"], bounds["rounding_until"],
                               must_fail=True))
    sys.exit(0 if all(results) else 1)


if __name__ == "__main__":
    main()
