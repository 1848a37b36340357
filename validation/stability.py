#!/usr/bin/python3
"""Stability on hard cases: how large a timestep each integrator survives, and what it says.

    /usr/bin/python3 validation/stability.py [CASE ...] [--check | --long] [--build build]
                                             [--out validation/results/stability]

A case is a folder of inputs/hard/ (a native scenario). For each case and integrator (native
Gear, native velocity Verlet, and LAMMPS' Verlet with granthesis where `talus export lammps`
can write the case and talus-lmp is built) it finds by bisection the stability limit
dt_crit / t_c: the largest timestep (t_c: the run's collision time) at which the run ends
without the stability guard stopping it, without its energy growing by more than 1% of the
energy in play (energy_growth), and, where the case says so, without a grain passing through a
wall. The native runs keep the energy ledger (output.energy_ledger), whose guard stops a run at
that growth: the growth is that of its imbalance, the energy no damper, friction or wall
accounts for, so a driven case is measured as an undriven one; LAMMPS' is that of its total
energy less the work of its walls (fix granthesis/wall). It reports the energy behaviour at the automatic timestep (t_c / 50) and, beyond the
limit, what the guard said. The results go to OUT/results.json.

--long runs the cases at the automatic timestep only, the static pile for a million steps
(its default is 188000): the energy of resting contacts must not grow over a long run.

--check is the default suite's fast test: every case at the automatic timestep ends, its energy
does not grow by more than that 1%, and no grain passes through a wall; the exit status is 1 when
one does not.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crosscheck import ENV  # noqa: E402  (the same environment for mpirun as root)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = os.path.join(ROOT, "inputs", "hard")
GROWTH = 0.01  # the energy growth allowed (energy_growth), the native guard's limit
# Where a grain must stay: (grain id, coordinate, +1 or -1, value): the grain's coordinate stays
# on that side of the value at every tracked time (the case tracks its grains).
SIDES = {
    "thin_wall": [(0, "y", 1, 0.0), (1, "y", -1, 0.0), (2, "x", 1, 0.005)],
}
# What --long changes: the static pile for 1e6 steps at t_c / 50 (dt = 5.31e-6 s)
LONG = {"static_pile": ["simulation.duration=5.32"]}
# Runs that must stop at the automatic timestep, and the diagnosis they must give: Gear is
# unstable for the contacts the compression stiffens.
STOPS = {
    ("dense_compression", "gear"): "The contacts have stiffened",
}


def energy_growth(thermo):
    """With the energy ledger, its measure of growth, as the run's guard takes it: the largest
    rise of the imbalance above its lowest before, over the energy in play then (the largest
    kinetic plus elastic energy so far, plus the dissipated energy and the walls' work).
    Without one (LAMMPS), the rise of the total energy less the walls' work, over the largest
    kinetic plus elastic energy of the run: a run only loses what the walls do not put in."""
    d = np.atleast_1d(np.genfromtxt(thermo, delimiter=",", names=True))
    mechanical = d["kinetic_translational"] + d["kinetic_rotational"] + d["elastic"]
    if "energy_imbalance" not in d.dtype.names:
        scale = float(np.max(mechanical))
        rise = float(np.max(d["total"] - np.minimum.accumulate(d["total"])))
        return rise / scale if scale > 0 else 0.0
    imbalance = d["energy_imbalance"]
    lowest = np.minimum.accumulate(np.concatenate([[0.0], imbalance]))[:-1]
    in_play = (np.maximum.accumulate(mechanical) + np.abs(d["dissipated_damper"])
               + np.abs(d["dissipated_friction"]) + np.abs(d["wall_work"]))
    growth = np.where(in_play > 0, (imbalance - lowest) / np.where(in_play > 0, in_play, 1), 0)
    return float(np.max(growth))


def through_walls(case, folder):
    """What passed through a wall (SIDES), or ""."""
    if case not in SIDES:
        return ""
    d = np.atleast_1d(np.genfromtxt(os.path.join(folder, "track.csv"), delimiter=",",
                                    names=True))
    for grain, axis, side, value in SIDES[case]:
        crossed = side * (d[axis][d["id"] == grain] - value) <= 0
        if np.any(crossed):
            return (f"grain {grain} passed through the wall ({axis} = {value:g}; the guard "
                    f"let it be)")
    return ""


def lammps_through_walls(case, dump):
    """What passed through a wall (SIDES) in a LAMMPS dump of `id x y` (id = native id + 1), or
    ""."""
    if case not in SIDES:
        return ""
    with open(dump) as f:
        for line in f:
            if line.startswith("ITEM: ATOMS"):
                continue
            w = line.split()
            if len(w) != 3:
                continue
            grain = int(w[0]) - 1
            at = {"x": float(w[1]), "y": float(w[2])}
            for g, axis, side, value in SIDES[case]:
                if g == grain and side * (at[axis] - value) <= 0:
                    return (f"grain {grain} passed through the wall ({axis} = {value:g}; "
                            "LAMMPS has no guard)")
    return ""


class Runner:
    def __init__(self, build, out, long=False):
        self.long = long
        self.talus = os.path.join(build, "native", "talus")
        self.lmp = os.path.join(build, "lammps-package", "talus-lmp")
        self.out = out
        self.has_lammps = os.path.exists(self.lmp) and shutil.which("mpirun") is not None
        self.exported = set()  # the cases exported by this run (once each, at t_c / 50)

    def native(self, case, integrator, factor):
        """(stable, energy growth, the guard's words or what went wrong) of one run."""
        folder = os.path.join(self.out, "runs", f"{case}-{integrator}-{factor:g}")
        shutil.rmtree(folder, ignore_errors=True)
        done = subprocess.run(
            [self.talus, "run", os.path.join(CASES, case, "scenario.toml"), "--out", folder,
             "--quiet", "--threads", "1", "--set", f"simulation.integrator={integrator}",
             "--set", f"simulation.timestep_factor={factor}", "--set", "output.energy_ledger=true"]
            + [w for k in (LONG.get(case, []) if self.long else []) for w in ("--set", k)],
            env=ENV, capture_output=True, text=True)
        said = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""
        thermo = os.path.join(folder, "thermo.csv")
        growth = energy_growth(thermo) if os.path.exists(thermo) else float("nan")
        stable = done.returncode == 0 and growth <= GROWTH
        if done.returncode == 0 and not stable:
            said = f"the run ended with its energy grown by {growth:.2g} (the guard let it be)"
        passed = through_walls(case, folder) if done.returncode == 0 else ""
        if passed:
            stable, said = False, passed
        return stable, growth, said

    def lammps(self, case, factor):
        """The same in LAMMPS (no guard there: stable when it ends with finite, non-growing
        energy); None when the case cannot be exported. The case is exported once, at t_c / 50
        (its packing is settled by the native engine at that timestep), and run at t_c / factor
        for the same duration."""
        base = os.path.join(self.out, "runs", f"{case}-lammps-export")
        if case not in self.exported:
            self.exported.add(case)
            shutil.rmtree(base, ignore_errors=True)
            subprocess.run(
                [self.talus, "export", "lammps", os.path.join(CASES, case, "scenario.toml"), base,
                 "--quiet", "--set", "simulation.integrator=verlet",
                 "--set", "simulation.verlet_velocity=half_step",
                 "--set", "simulation.timestep_factor=50"],
                env=ENV, capture_output=True, text=True)
        if not os.path.exists(os.path.join(base, "scenario.toml")):
            return None
        folder = os.path.join(self.out, "runs", f"{case}-lammps-{factor:g}")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(base, folder)
        name = next(f[3:] for f in os.listdir(folder) if f.startswith("in."))
        deck_path = os.path.join(folder, f"in.{name}")
        with open(deck_path) as f:
            deck = f.read().splitlines()
        dt50 = float(next(l.split()[1] for l in deck if l.startswith("timestep ")))
        steps50 = int(next(l.split()[3] for l in deck if l.startswith("variable steps index")))
        dt = dt50 * 50.0 / factor
        scale = dt50 / dt
        steps = max(1, round(steps50 * scale))
        rewritten = []
        for line in deck:
            w = line.split()
            if line.startswith("timestep "):
                line = f"timestep {dt!r}"
            elif line.startswith("variable steps index"):
                line = f"variable steps index {steps}"
            elif w[:1] == ["thermo"] and len(w) == 2:
                # at least 2000 rows, as the native guard looks at every step: an energy that
                # grows within an impact and falls back is seen
                line = f"thermo {max(1, min(round(int(w[1]) * scale), steps // 2000))}"
            elif line.startswith("run ") and case in SIDES:  # where the grains are, every step
                rewritten += ["dump sides all custom 1 sides.lammpstrj id x y",
                              "dump_modify sides sort id format float %.17g"]
            rewritten.append(line)
        with open(deck_path, "w") as f:
            f.write("\n".join(rewritten) + "\n")
        run = subprocess.run([
            "mpirun", "-np", "1", self.lmp, "-in", f"in.{name}", "-log", "log.lammps",
            "-screen", "none"], cwd=folder, env=ENV, capture_output=True, text=True)
        with open(os.path.join(folder, "log.lammps")) as f:
            log = f.read().splitlines()
        said = next((l for l in log if l.startswith("ERROR")), "")
        # the thermo table: kinetic and rotational energy, pe (the elastic energy of the pairs
        # and of fix granthesis/wall), the grains' energy in gravity (f_gravity) and the work
        # the walls did on them (f_walls[1])
        start = max((k for k, l in enumerate(log) if l.split()[:2] == ["Step", "Time"]),
                    default=None)
        rows = []
        for line in log[start + 1:] if start is not None else []:
            try:
                rows.append([float(w) for w in line.split()])
            except ValueError:
                break
        table = np.array([r for r in rows if len(r) == len(log[start].split())])
        if run.returncode != 0 or not len(table) or not np.all(np.isfinite(table)):
            return False, float("nan"), said or "LAMMPS stopped, or a value went non-finite"
        names = log[start].split()
        at = {n: k for k, n in enumerate(names)}
        kinetic = table[:, at["c_grains_ke"]] + table[:, at["c_grains_rotation"]]
        mechanical = kinetic + table[:, at["PotEng"]]
        total = mechanical.copy()
        if "f_gravity" in at:
            total += table[:, at["f_gravity"]]
        if "f_walls[1]" in at:  # what the walls put in is no growth
            total -= table[:, at["f_walls[1]"]]
        scale = float(np.max(mechanical))
        growth = float(np.max(total - np.minimum.accumulate(total))) / scale if scale else 0.0
        passed = lammps_through_walls(case, os.path.join(folder, "sides.lammpstrj"))
        if passed:
            return False, growth, passed
        return growth <= GROWTH, growth, said


def limit(probe, lo=1.0, hi=50.0, steps=7):
    """The smallest factor t_c / dt in [lo, 800] at which probe(factor) is stable, by bisection
    in log from [lo, hi], widened 4 times at a time beyond hi (stability assumed monotone in dt);
    (factor, what the guard said just beyond it)."""
    if probe(lo)[0]:
        return lo, ""
    said = probe(lo)[2]
    while not probe(hi)[0]:
        if hi >= 800:
            return None, probe(hi)[2]
        lo, hi, said = hi, hi * 4, probe(hi)[2]
    for _ in range(steps):
        mid = (lo * hi) ** 0.5
        stable, _, words = probe(mid)
        if stable:
            hi = mid
        else:
            lo, said = mid, words
    return hi, said


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="*", help="folders of inputs/hard/ (default: all)")
    parser.add_argument("--check", action="store_true",
                        help="only: each case at the automatic timestep ends, energy not growing")
    parser.add_argument("--long", action="store_true",
                        help="only the automatic timestep, the static pile for 1e6 steps")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "validation", "results", "stability"))
    args = parser.parse_args()
    cases = args.cases or sorted(os.listdir(CASES))
    runner = Runner(os.path.abspath(args.build), os.path.abspath(args.out), args.long)
    if args.long:
        cases = args.cases or sorted(LONG)
    os.makedirs(runner.out, exist_ok=True)
    good, results = True, []
    for case in cases:
        if not os.path.exists(os.path.join(CASES, case, "scenario.toml")):
            sys.exit(f"no case '{case}' in {CASES}")
        row = {"case": case}
        for integrator in ("gear", "verlet"):
            stable, growth, said = runner.native(case, integrator, 50)
            row[f"{integrator}_default"] = {"stable": stable, "energy_growth": growth,
                                            "said": said}
            expected = STOPS.get((case, integrator))
            right = (not stable and expected in said) if expected else stable
            print(f"{'ok  ' if right else 'FAIL'} {case}: native {integrator} at t_c/50: "
                  + (f"stops as it must: {said}" if expected and right else
                     f"energy growth {growth:.2e}"
                     + (f"; {said}" if not stable else "")
                     + (f" (expected a stop saying '{expected}')" if expected else "")))
            good = good and right
            if args.check or args.long:
                continue
            factor, words = limit(lambda f: runner.native(case, integrator, f))
            row[f"{integrator}_limit"] = None if factor is None else 1.0 / factor
            row[f"{integrator}_beyond"] = words
            print(f"     {case}: native {integrator}: dt_crit / t_c = "
                  + ("below 1/800" if factor is None else f"{1.0 / factor:.3g}")
                  + (f"; beyond it: {words}" if words else ""))
        if not (args.check or args.long) and runner.has_lammps:
            if runner.lammps(case, 50) is None:
                row["lammps_limit"] = "not exportable"
                print(f"     {case}: LAMMPS: not exportable (talus export lammps refuses it)")
            else:
                factor, words = limit(lambda f: runner.lammps(case, f))
                row["lammps_limit"] = None if factor is None else 1.0 / factor
                print(f"     {case}: LAMMPS verlet: dt_crit / t_c = "
                      + ("below 1/800" if factor is None else f"{1.0 / factor:.3g}"))
        results.append(row)
    with open(os.path.join(runner.out, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    sys.exit(0 if good else 1)


if __name__ == "__main__":
    main()
