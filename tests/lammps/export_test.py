"""The LAMMPS cases of the thesis' experiments (inputs/*/lammps, written by talus export lammps):

- `talus export lammps` writes the committed collisions case again, file for file;
- every committed case runs in talus-lmp; the masses LAMMPS uses are the native engine's, bit for
  bit; the wall particles move as the native scenario's driver says (vibration, the press' lid,
  the drum's turn), to rounding; fixed wall particles stay;
- the collisions case, run to its end, gives the native engine's rebounds and the closed form
  (restitution 1) to within the integrators' error;
- in the cases with gravity, the grains move.

Usage: export_test.py TALUS TALUS_LMP SOURCE_DIR WORK_DIR"""
import math
import os
import shutil
import subprocess
import sys
import tomllib

TALUS, LMP, SOURCE, WORK = sys.argv[1:5]
CASES = ["collisions", "hourglass", "silo_shake", "force_network", "drum", "frost_heave"]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def case_dir(name):
    return os.path.join(SOURCE, "inputs", name, "lammps")


def run_case(name, steps, every):
    """Runs a copy of the committed case for `steps` steps with a dump every `every`; returns the
    copy's folder."""
    folder = os.path.join(WORK, name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(case_dir(name), folder)
    command = [LMP, "-in", f"in.{name}", "-var", "steps", str(steps), "-var", "snapshot_every",
               str(every), "-log", "log.lammps", "-screen", "none"]
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        with open(os.path.join(folder, "log.lammps")) as f:
            sys.exit(f"{name}: {' '.join(command)} failed:\n{f.read()[-3000:]}\n{done.stderr}")
    return folder


def read_frames(path):
    """[(step, {id: {column: value}})] of a LAMMPS text dump."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        step = int(lines[k + 1])
        count = int(lines[k + 3])
        columns = lines[k + 8].split()[2:]
        atoms = {}
        for line in lines[k + 9:k + 9 + count]:
            values = line.split()
            atoms[int(values[0])] = {c: float(v) for c, v in zip(columns, values)}
        frames.append((step, atoms))
        k += 9 + count
    return frames


def deck_words(folder, name):
    with open(os.path.join(folder, f"in.{name}")) as f:
        return [line.split() for line in f if line.strip() and not line.startswith("#")]


def group_types(words, group):
    for w in words:
        if w[:2] == ["group", group]:
            return {int(t) for t in w[3:]}
    return set()


def timestep(words):
    return next(float(w[1]) for w in words if w[0] == "timestep")


def native_motion(name, scenario):
    """The native driver's displacement of a wall particle from its start at time t, and whether
    the motion is a turn about a centre (drum)."""
    if name == "silo_shake":
        d = scenario["drivers"][0]
        w = 2 * math.pi * d["frequency"]
        n = math.hypot(*d["direction"])
        return lambda p, t: [d["amplitude"] * math.sin(w * t + d["phase"]) * c / n
                             for c in d["direction"]]
    if name == "force_network":
        v = scenario["geometry"]["lid_speed"]
        return lambda p, t: [0.0, -v * t]
    if name == "drum":
        g = scenario["geometry"]
        c, omega = (g["radius"], g["radius"]), g["angular_velocity"]

        def turned(p, t):
            a = omega * t
            x, y = p[0] - c[0], p[1] - c[1]
            return [c[0] + x * math.cos(a) - y * math.sin(a) - p[0],
                    c[1] + x * math.sin(a) + y * math.cos(a) - p[1]]
        return turned
    return None


def check_case(name):
    folder = run_case(name, 200, 100)
    words = deck_words(folder, name)
    frames = read_frames(os.path.join(folder, f"dump.{name}.lammpstrj"))
    check([s for s, _ in frames] == [0, 100, 200], f"{name}: runs 200 steps, dumps 0, 100, 200")
    first, last = frames[0][1], frames[-1][1]
    with open(os.path.join(folder, f"masses.{name}")) as f:
        masses = {int(w[2]): float(w[4]) for w in (l.split() for l in f) if w[:1] == ["set"]}
    check(all(first[i]["mass"] == m for i, m in masses.items()) and len(masses) == len(first),
          f"{name}: LAMMPS' masses are the native engine's, bit for bit ({len(masses)} atoms)")
    with open(os.path.join(folder, "scenario.toml"), "rb") as f:
        scenario = tomllib.load(f)
    fixed = group_types(words, "fixed_walls")
    if fixed:
        still = all(last[i]["x"] == first[i]["x"] and last[i]["y"] == first[i]["y"]
                    for i in first if int(first[i]["type"]) in fixed)
        check(still, f"{name}: the fixed wall particles stay")
    motion = native_motion(name, scenario)
    driven = group_types(words, "drive1")
    if motion and driven:
        t = 200 * timestep(words)
        scale = max(abs(first[i]["x"]) + abs(first[i]["y"]) for i in first)
        worst = 0.0
        for i, a in first.items():
            if int(a["type"]) not in driven:
                continue
            d = motion((a["x"], a["y"]), t)
            worst = max(worst, abs(last[i]["x"] - a["x"] - d[0]), abs(last[i]["y"] - a["y"] - d[1]))
        # fix move adds the displacement to the start in doubles: a few ulp of the coordinates
        check(worst <= 1e-14 * scale,
              f"{name}: the wall particles move as the native driver (largest difference "
              f"{worst:.2e} m, bound {1e-14 * scale:.1e} m)")
    if not any(w[:2] == ["fix", "gravity"] for w in words):
        return  # grains at rest and apart (the press' loose packing) wait for the lid
    grains = group_types(words, "grains")
    moved = any(last[i]["x"] != first[i]["x"] or last[i]["y"] != first[i]["y"]
                for i in first if int(first[i]["type"]) in grains)
    check(moved, f"{name}: the grains move")


def check_export_reproduces_collisions():
    out = os.path.join(WORK, "exported-collisions")
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([TALUS, "export", "lammps", "inputs/collisions/scenario.toml", out, "--quiet"],
                   cwd=SOURCE, check=True, timeout=300)
    for f in sorted(os.listdir(case_dir("collisions"))):
        with open(os.path.join(case_dir("collisions"), f)) as a, open(os.path.join(out, f)) as b:
            # the header names the folder it was written to
            same = [l for l in a if not l.startswith("# Written by:")] == \
                   [l for l in b if not l.startswith("# Written by:")]
        check(same, f"talus export lammps writes inputs/collisions/lammps/{f} again")


def native_final_velocities(folder):
    """The native engine's velocities at the end of the case's twin scenario, by LAMMPS id."""
    run = os.path.join(WORK, "native-collisions")
    shutil.rmtree(run, ignore_errors=True)
    subprocess.run([TALUS, "run", os.path.join(folder, "scenario.toml"), "--out", run, "--quiet"],
                   check=True, timeout=300)
    with open(os.path.join(run, "track.csv")) as f:
        header = f.readline().strip().split(",")
        rows = [dict(zip(header, line.strip().split(","))) for line in f]
    last_time = max(float(r["time"]) for r in rows)
    return {int(r["id"]) + 1: (float(r["vx"]), float(r["vy"]))
            for r in rows if float(r["time"]) == last_time}


def check_collisions_physics():
    steps = next(int(w[3]) for w in deck_words(case_dir("collisions"), "collisions")
                 if w[:3] == ["variable", "steps", "index"])
    folder = run_case("collisions", steps, steps)
    last = read_frames(os.path.join(folder, "dump.collisions.lammpstrj"))[-1][1]
    # restitution 1, no friction: the head-on pair (ids 1, 2) leaves at its approach speed
    e = (last[2]["vx"] - last[1]["vx"]) / 0.02
    check(abs(e - 1.0) < 1e-4,
          f"collisions: the head-on restitution in LAMMPS is {e:.7f} (closed form 1; velocity "
          f"Verlet at dt = t_c/50 is within 1e-4)")
    native = native_final_velocities(folder)
    worst = max(max(abs(last[i]["vx"] - native[i][0]), abs(last[i]["vy"] - native[i][1]))
                for i in last)
    # LAMMPS' velocity Verlet against the native Gear at dt = t_c/50: each is within 1e-4 of the
    # exact rebound (the restitution above; tests/physics for Gear); the track has 9 digits
    check(worst < 1e-4 * 0.01,
          f"collisions: LAMMPS' rebound velocities are the native engine's to {worst:.2e} m/s "
          f"(bound 1e-6 m/s, 1e-4 of the speed)")


os.makedirs(WORK, exist_ok=True)
check_export_reproduces_collisions()
for name in CASES:
    check_case(name)
check_collisions_physics()
if failures:
    sys.exit(f"{len(failures)} failed")
