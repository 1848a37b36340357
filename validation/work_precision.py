#!/usr/bin/python3
"""Work-precision: the error each integrator buys at each timestep, and what it costs.

    /usr/bin/python3 validation/work_precision.py [PROBLEM ...] [--quick] [--build build]
                                                  [--out validation/results/work_precision]

For each reference problem and each integrator (native Gear, native velocity Verlet, and LAMMPS'
velocity Verlet with pair_style granthesis where talus-lmp is built), over timesteps from t_c/5
to t_c/1000 (t_c: the problem's collision time, the automatic timestep's unit), it measures the
error against the reference and the cost (CPU seconds per simulated second, and per
particle-step), and draws a log-log work-precision chart per problem with a table beside it
(index.html, opening offline; results.json). Problems:

- hertz_impact: two disks, viscoelastic Hertz with a given damping A; restitution, peak force
  and duration against an accurate solution of the contact's ODE (RK4 at t_c / 200000);
- linear_impact: the same with the linear spring-dashpot, against the same ODE, which is the
  closed form's (docs/model.md);
- oblique_impact: two disks meeting off-centre, linear law and the capped viscous friction:
  tangential restitution of the contact point and the rebound spin, against native Gear at
  t_c / 20000 (no closed form: the line of centres turns while they touch);
- settling_1000: 1000 disks falling into a box (inputs/validation/settling_1000) for 0.03 s:
  RMS position error (mean radii) and total-energy error at the end against the same integrator
  at the finest timestep / 64, with the fitted convergence order.

Each impact runs with its touch at four places within a step (a dashpot's force starts at the
touch, an error of first order in dt that depends on where the touch falls); an error is the
largest of the four. --quick runs fewer timesteps and leaves out settling_1000. The timestep
that each integrator needs for a restitution error of 1e-2, 1e-3 and 1e-4 (interpolated in
log-log) is printed and tabled. The exit status is 1 when a check fails (check()): an engine
whose error does not fall with the timestep, a reference off its closed form, or the linear
law's error off the estimate `talus run` prints.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crosscheck import ENV  # noqa: E402  (the same environment for mpirun as root)
from impact_reference import (DENSITY, HERTZ_A, LINEAR_E, LINEAR_K, OFFSET,  # noqa: E402
                              POISSON, RADIUS, SPEED, YOUNG, collision_time, contact_ode,
                              linear_damping_ratio)
from trajectories import read_dump, read_track  # noqa: E402  (the same readers)
from work_precision_report import by_engine, page, summarise  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FACTORS = [5, 10, 20, 50, 100, 200, 500, 1000]
QUICK_FACTORS = [5, 20, 100, 500]
SETTLING_FACTORS = [5, 10, 20, 50, 100, 200]


def impact_scenario(law, oblique, delay=0.0):
    """Two equal disks approaching along x at +-SPEED, 2 mm of gap (and what they close in
    `delay` s more); oblique: offset in y."""
    gap = 0.001 + SPEED * delay  # each disk's part
    damping = (f"hertz_damping = {HERTZ_A}" if law == "hertz" else
               f"normal_stiffness = {LINEAR_K}\nrestitution = {LINEAR_E}")
    friction = "friction = 0.3\ntangential_damping = 2000.0" if oblique else "friction = 0.0"
    y = OFFSET if oblique else 0.0
    # the touch after 2 ms, the separation 1.2 ms later (Hertz; linear: 0.9 ms); one snapshot at
    # the start and one at the end (LAMMPS' deck dumps at snapshots)
    return f"""name = "{law}_{'oblique' if oblique else 'impact'}"
[simulation]
duration = 0.006
timestep = "auto"
integrator = "verlet"
normal_law = "{law}"
tangential_law = "coulomb"
gravity = [0.0, 0.0]
impact_speed = {2 * SPEED}
[[materials]]
name = "grain"
density = {DENSITY}
young = {YOUNG}
poisson = {POISSON}
{damping}
{friction}
[particles]
shape = "disk"
[[particles.list]]
position = [{-RADIUS - gap!r}, 0.0]
radius = {RADIUS}
velocity = [{SPEED}, 0.0]
[[particles.list]]
position = [{RADIUS + gap!r}, {y}]
radius = {RADIUS}
velocity = [{-SPEED}, 0.0]
[geometry]
# periodic, so that the long runs that time each engine keep their grains (they meet again
# every 0.05 s; the measured impact is over long before that)
periodic = "xy"
box = [-0.025, -0.025, 0.025, 0.025]
[track]
select = "all"
[output]
contacts = true
thermo_interval = 0.001
snapshot_interval = 0.006
checkpoint_interval = 0.0
track_interval = 0.006
picture = false
"""


# ---- running the engines -------------------------------------------------------------------------

def attempt(command, cwd=None):
    """Runs a command; its wall time, or None when it failed (an unstable run, say)."""
    start = time.monotonic()
    done = subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True)
    return time.monotonic() - start if done.returncode == 0 else None


class Engines:
    def __init__(self, build, out):
        self.talus = os.path.join(build, "native", "talus")
        self.lmp = os.path.join(build, "lammps-package", "talus-lmp")
        self.out = out
        self.has_lammps = os.path.exists(self.lmp) and shutil.which("mpirun") is not None

    def native(self, scenario, label, integrator, factor, extra=()):
        """Runs the native engine; (run folder, CPU s per simulated s, per particle-step) or
        None when the run failed."""
        folder = os.path.join(self.out, "runs", f"{label}-{integrator}-{factor:g}")
        shutil.rmtree(folder, ignore_errors=True)
        command = [self.talus, "run", scenario, "--out", folder, "--quiet", "--threads", "1",
                   "--set", f"simulation.integrator={integrator}",
                   "--set", f"simulation.timestep_factor={factor}"]
        for s in extra:
            command += ["--set", s]
        if attempt(command) is None:
            return None
        with open(os.path.join(folder, "run.json")) as f:
            info = json.load(f)
        if info["ended_by"] != "duration":
            return None
        per_step = 1.0 / info["particle_steps_per_second"]
        return folder, info["wall_seconds"] / info["time"], per_step

    def lammps(self, scenario, label, factor, timed=True):
        """Runs LAMMPS with granthesis (velocity Verlet, its half-step damper velocity) on the
        deck `talus export lammps` writes; (the last dump frame, cost per simulated s, per
        particle-step) or None."""
        folder = os.path.join(self.out, "runs", f"{label}-lammps-{factor:g}")
        shutil.rmtree(folder, ignore_errors=True)
        if attempt([self.talus, "export", "lammps", scenario, folder, "--quiet",
                    "--set", "simulation.integrator=verlet",
                    "--set", "simulation.verlet_velocity=half_step",
                    "--set", f"simulation.timestep_factor={factor}"]) is None:
            return None
        name = next(f[3:] for f in os.listdir(folder) if f.startswith("in."))
        with open(os.path.join(folder, f"in.{name}")) as f:
            steps = int(re.search(r"^variable steps index (\d+)", f.read(), re.M).group(1))
        # the whole case, dumped at the start and the end only: the rebound is the last frame
        if self.lammps_loop(folder, name, steps) is None:
            return None
        with open(os.path.join(folder, "log.lammps")) as f:
            dt = float(re.search(r"^timestep\s+(\S+)", f.read(), re.M).group(1))
        frames = read_dump(os.path.join(folder, f"dump.{name}.lammpstrj"), dt)
        last = frames[max(frames)]
        if not timed:
            return last, math.nan, math.nan
        # the cost from 100000 steps at least, so that the loop's clock resolves it
        timing = self.lammps_loop(folder, name, max(steps, 100000))
        if timing is None:
            return None
        loop, steps, atoms = timing
        # LAMMPS ids are native ids + 1: the frame is keyed as read_track's
        return last, loop / (steps * dt), loop / (steps * atoms)

    def lammps_loop(self, folder, name, steps):
        """Runs the deck for `steps` on 1 rank; (loop seconds, steps, atoms) from its log."""
        if attempt(["mpirun", "-np", "1", self.lmp, "-in", f"in.{name}", "-var", "steps",
                    str(steps), "-var", "snapshot_every", str(steps), "-log", "log.lammps",
                    "-screen", "none"], cwd=folder) is None:
            return None
        with open(os.path.join(folder, "log.lammps")) as f:
            m = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) "
                           r"atoms", f.read())
        return float(m[-1][0]), int(m[-1][1]), int(m[-1][2])


# ---- the measurements ----------------------------------------------------------------------------

def last_frame(folder):
    """The last track.csv frame of a native run: {LAMMPS-style id: (x, y, vx, vy, omega)}."""
    frames = read_track(os.path.join(folder, "track.csv"))
    return frames[max(frames)]


def first_event(folder):
    """peak normal force and duration of the first row of contact_events.csv."""
    data = np.genfromtxt(os.path.join(folder, "contact_events.csv"), delimiter=",", names=True)
    row = np.atleast_1d(data)[0]
    return float(row["peak_normal_force"]), float(row["duration"])


def head_on_restitution(frame):
    return (frame[2][2] - frame[1][2]) / (2.0 * SPEED)


def oblique_numbers(frame):
    """Tangential restitution of the contact point, and disk 0's rebound spin (rad/s). The
    tangent is that of the line of centres at the touch (the straight approach's)."""
    dx = math.sqrt(4.0 * RADIUS**2 - OFFSET**2)
    n = np.array([dx, OFFSET]) / (2.0 * RADIUS)
    t = np.array([-n[1], n[0]])
    before = float(np.dot([-2.0 * SPEED, 0.0], t))
    v0, v1 = np.array(frame[1][2:4]), np.array(frame[2][2:4])
    after = float(np.dot(v1 - v0, t)) - RADIUS * (frame[1][4] + frame[2][4])
    return -after / before, frame[1][4]


def relative(x, ref):
    return abs(x - ref) / abs(ref) if ref else abs(x)


class Problem:
    """One reference problem: its scenario, the reference numbers, and a row per run."""

    def __init__(self, name, scenario, t_c, metrics):
        self.name, self.scenario, self.t_c, self.metrics = name, scenario, t_c, metrics
        # {"engine", "factor", "cost_per_second", "cost_per_particle_step", metric, ...}
        self.rows = []
        self.reference = {}

    def add(self, engine, factor, costs, values):
        """A row: each metric's largest relative error over `values` (one dict per run)."""
        if isinstance(values, dict):
            values = [values]
        row = {"engine": engine, "factor": factor, "cost_per_second": costs[0],
               "cost_per_particle_step": costs[1]}
        # (LAMMPS' rows have the rebound only: NaN for what its dump cannot tell)
        row.update({m: max(relative(v[m], self.reference[m]) for v in values)
                    if m in values[0] else math.nan for m in self.metrics})
        row.update({f"{m}_value": values[0].get(m, math.nan) for m in self.metrics})
        self.rows.append(row)
        print(f"{self.name}: {engine:14s} dt = t_c/{factor:<5g} " + ", ".join(
            f"{m} error {row[m]:.2e}" for m in self.metrics) +
            f"; {costs[0]:.3g} CPU s per simulated s")


PHASES = 4  # where in a step the touch falls: 0, 1/4, 1/2 and 3/4 of a step later


def phase_scenarios(problem, law, oblique, factor):
    """The problem's scenario with the touch delayed by 0, 1/4, ... of a step at this factor: a
    dashpot's force starts at the touch, and the error it makes depends on where that falls."""
    paths = []
    for j in range(PHASES):
        path = os.path.join(os.path.dirname(problem.scenario), f"{problem.name}-{factor}-{j}.toml")
        with open(path, "w") as f:
            f.write(impact_scenario(law, oblique, j / PHASES * problem.t_c / factor))
        paths.append(path)
    return paths


def impact(engines, problem, law, oblique, factors):
    """The impact problems: native Gear and Verlet, and LAMMPS where it is built; each error the
    largest over the phases of the touch."""
    for factor in factors:
        scenarios = phase_scenarios(problem, law, oblique, factor)
        for integrator in ("gear", "verlet"):
            runs = [engines.native(sc, f"{problem.name}-{j}", integrator, factor)
                    for j, sc in enumerate(scenarios)]
            if None in runs:
                print(f"{problem.name}: {integrator} at t_c/{factor}: unstable or failed")
                continue
            # the cost from a run without per-step outputs (contacts are looked at every step),
            # of 100000 steps at least, so that the wall clock resolves it: two disks cost the
            # loop's overhead per step, touching or not
            duration = max(0.006, 1e5 * problem.t_c / factor)
            cost = engines.native(problem.scenario, problem.name + "-cost", integrator, factor,
                                  ["output.contacts=false", "track.select=none",
                                   f"simulation.duration={duration}",
                                   f"output.snapshot_interval={duration}",
                                   f"output.thermo_interval={duration}"])
            problem.add(f"native {integrator}", factor, cost[1:] if cost else runs[0][1:],
                        [measure(r[0], oblique) for r in runs])
        if not engines.has_lammps:
            continue
        runs = [engines.lammps(sc, f"{problem.name}-{j}", factor, timed=j == 0)
                for j, sc in enumerate(scenarios)]
        if None in runs:
            print(f"{problem.name}: LAMMPS at t_c/{factor}: unstable or failed")
            continue
        values = [dict(zip(("tangential_restitution", "rebound_spin"), oblique_numbers(r[0])))
                  if oblique else {"restitution": head_on_restitution(r[0])} for r in runs]
        problem.add("LAMMPS verlet", factor, runs[0][1:], values)
    if not engines.has_lammps:
        print(f"{problem.name}: LAMMPS rows left out (talus-lmp or mpirun missing)")


def measure(folder, oblique):
    frame = last_frame(folder)
    if oblique:
        return dict(zip(("tangential_restitution", "rebound_spin"), oblique_numbers(frame)))
    peak, duration = first_event(folder)
    return {"restitution": head_on_restitution(frame), "peak_force": peak, "duration": duration}


def settling(engines, problem, factors):
    """1000 disks for 0.03 s: each integrator against itself at the finest timestep / 64."""
    # every run ends at the same time, a whole number of the coarsest timestep (the reference's
    # factor is a multiple of every factor), near 0.03 s
    probe = engines.native(problem.scenario, problem.name + "-probe", "verlet", 5,
                           ["simulation.duration=1e-4", "output.snapshot_interval=0"])
    with open(os.path.join(probe[0], "run.json")) as f:
        coarsest = json.load(f)["collision_time"] / min(factors)
    duration = round(0.03 / coarsest) * coarsest
    sets = [f"simulation.duration={duration!r}", "output.snapshot_interval=0",
            f"output.track_interval={duration!r}"]
    for integrator in ("gear", "verlet"):
        ref = engines.native(problem.scenario, problem.name + "-reference", integrator,
                             64 * max(factors), sets)
        ref_frame, ref_energy, ref_kinetic = settling_state(ref[0])
        for factor in factors:
            got = engines.native(problem.scenario, problem.name, integrator, factor, sets)
            if got is None:
                print(f"{problem.name}: {integrator} at t_c/{factor}: unstable or failed")
                continue
            frame, energy, _ = settling_state(got[0])
            ids = sorted(set(frame) & set(ref_frame))
            d = [math.hypot(frame[i][0] - ref_frame[i][0], frame[i][1] - ref_frame[i][1])
                 for i in ids]
            problem.reference = {"position": 0.0, "energy": 0.0}
            problem.add(f"native {integrator}", factor, got[1:],
                        {"position": math.sqrt(np.mean(np.square(d))) / 0.0025,
                         "energy": abs(energy - ref_energy) / ref_kinetic})


def settling_state(folder):
    """The last frame, the last total energy and translational kinetic energy (J)."""
    data = np.genfromtxt(os.path.join(folder, "thermo.csv"), delimiter=",", names=True)
    last = np.atleast_1d(data)[-1]
    return last_frame(folder), float(last["total"]), float(last["kinetic_translational"])


# ---- what the measurements say ------------------------------------------------------------------

def check(problems):
    """What must hold, or the measurement is wrong: the linear reference reaches the asked
    restitution (the closed form's, docs/model.md), the native engine's linear restitution
    error is within 1.3 times the onset model talus run prints, and every engine converges: its
    error in the first metric falls tenfold from the coarsest timestep to the finest, to below
    1e-2 there (not monotonically: a dashpot's force starts where the touch falls in a step, an
    error of first order in dt whose size goes with that phase)."""
    failures = []
    for p in problems:
        if p.name == "linear_impact" and abs(p.reference["restitution"] - LINEAR_E) > 1e-6:
            failures.append(f"linear_impact: the reference's restitution "
                            f"{p.reference['restitution']:.9f} is not the asked {LINEAR_E}")
        metric = p.metrics[0]
        if p.name == "linear_impact":  # the onset model `talus run` prints: pi zeta dt / t_c
            zeta = linear_damping_ratio(LINEAR_E)
            for r in p.rows:
                model = math.pi * zeta / r["factor"]
                if r["engine"].startswith("native") and r["factor"] >= 10 and not (
                        r["restitution"] <= 1.3 * model):
                    failures.append(f"linear_impact {r['engine']} at t_c/{r['factor']}: "
                                    f"restitution error {r['restitution']:.2e} above 1.3 x the "
                                    f"onset model's {model:.2e} (zeta = {zeta:.4f})")
        for engine, rs in by_engine(p).items():
            rs = sorted(rs, key=lambda r: r["factor"])
            if len(rs) < 2 or not rs[-1][metric] < min(rs[0][metric] / 10.0, 1e-2):
                failures.append(f"{p.name} {engine}: {metric} error does not converge "
                                f"({', '.join(f'{r[metric]:.2e}' for r in rs)})")
    for f in failures:
        print(f"FAIL {f}")
    return not failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("problems", nargs="*", help="hertz_impact, linear_impact, "
                        "oblique_impact, settling_1000 (default: all)")
    parser.add_argument("--quick", action="store_true", help="fewer timesteps, no settling")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "validation", "results",
                                                      "work_precision"))
    args = parser.parse_args()
    names = args.problems or (["hertz_impact", "linear_impact", "oblique_impact"] +
                              ([] if args.quick else ["settling_1000"]))
    allowed = {"hertz_impact", "linear_impact", "oblique_impact", "settling_1000"}
    if set(names) - allowed:
        sys.exit(f"unknown problem(s) {sorted(set(names) - allowed)}; allowed: {sorted(allowed)}")
    engines = Engines(os.path.abspath(args.build), os.path.abspath(args.out))
    if not os.path.exists(engines.talus):
        sys.exit(f"no {engines.talus}: build first (scripts/build.sh)")
    os.makedirs(os.path.join(engines.out, "scenarios"), exist_ok=True)
    factors = QUICK_FACTORS if args.quick else FACTORS
    problems = []
    for name in names:
        if name == "settling_1000":
            p = Problem(name, os.path.join(ROOT, "inputs", "validation", "settling_1000",
                                           "scenario.toml"), None, ["position", "energy"])
            settling(engines, p, SETTLING_FACTORS)
        else:
            law = "hertz" if name == "hertz_impact" else "linear"
            oblique = name == "oblique_impact"
            scenario = os.path.join(engines.out, "scenarios", f"{name}.toml")
            with open(scenario, "w") as f:
                f.write(impact_scenario(law, oblique))
            p = Problem(name, scenario, collision_time(law), ["tangential_restitution",
                        "rebound_spin"] if oblique else ["restitution", "peak_force",
                                                         "duration"])
            if oblique:
                got = engines.native(scenario, name + "-reference", "gear", 20000)
                p.reference = measure(got[0], True)
            else:
                e, peak, duration = contact_ode(law)
                p.reference = {"restitution": e, "peak_force": peak, "duration": duration}
                if law == "linear":  # the engine's collision time: the damped contact's
                    p.t_c = duration
            print(f"{name}: reference " + ", ".join(f"{k} = {v:.10g}"
                                                     for k, v in p.reference.items()))
            impact(engines, p, law, oblique, factors)
        problems.append(p)
    page(problems, engines.out)
    with open(os.path.join(engines.out, "results.json"), "w") as f:
        json.dump([{"problem": p.name, "reference": p.reference, "rows": p.rows}
                   for p in problems], f, indent=1)
    summarise(problems)
    print(f"report: {os.path.join(engines.out, 'index.html')}")
    sys.exit(0 if check(problems) else 1)


if __name__ == "__main__":
    main()
