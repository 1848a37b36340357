#!/usr/bin/python3
"""The cost of looking from Python: the dense2d system (a 100 x 100 lattice of disks, 8.5 to
9.5 mm across, falling onto a floor, periodic in x; inputs/dense2d/README.md) stepped by the
talus package with no callback, and with a callback every N steps that does nothing, reads the
thermo quantities, or copies the positions. Rounds are taken in turns, so that a noisy machine
slows each way alike, each round in another order; the medians are compared.

    PYTHONPATH=build/python bench/python_callback.py [--side 100] [--steps 2000] [--every 100]

Appends the figures to bench/results/python_callback.csv (docs/performance.md).
"""
import argparse
import datetime
import os
import platform
import statistics
import time

import numpy as np

import talus

HERE = os.path.dirname(os.path.abspath(__file__))


def dense2d(side, seed=12345):
    rng = np.random.default_rng(seed)
    spacing = 0.01
    grains = [{"position": [(i + 0.5) * spacing, (j + 0.5) * spacing],
               "radius": float(rng.uniform(0.00425, 0.00475))}
              for j in range(side) for i in range(side)]
    width = side * spacing
    return {
        "name": f"dense2d_{side}",
        "simulation": {"duration": 1000.0, "integrator": "verlet", "timestep": 1.0e-5,
                       "normal_law": "linear", "tangential_law": "cundall_strack"},
        "materials": [{"name": "grain", "density": 1000.0, "normal_stiffness": 1.0e5,
                       "tangential_stiffness_ratio": 2.0 / 7.0, "normal_damping_rate": 100.0,
                       "tangential_damping": 50.0, "friction": 0.5}],
        "particles": {"shape": "sphere", "list": grains},
        "geometry": {"builder": "none", "periodic": "x", "box": [0.0, -0.01, width, 2 * width],
                     "segments": [{"a": [0.0, 0.0], "b": [width, 0.0]}]},
        "output": {"thermo_interval": 10.0, "snapshot_interval": 0.0,
                   "checkpoint_interval": 0.0},
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--side", type=int, default=100, help="grains along each side of the lattice")
    p.add_argument("--steps", type=int, default=2000, help="steps timed per round and way")
    p.add_argument("--every", type=int, default=100, help="steps between callbacks")
    p.add_argument("--rounds", type=int, default=8)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--fall", type=float, default=1.0,
                   help="s of falling and settling before the timing")
    a = p.parse_args()

    ways = {
        "no callback": None,
        "callback: nothing": lambda s: None,
        "callback: thermo()": lambda s: s.thermo(),
        "callback: positions": lambda s: s.positions,
    }
    times = {w: [] for w in ways}
    with talus.Simulation(dense2d(a.side), threads=a.threads) as sim:
        n = len(sim.radii)
        sim.run(duration=a.fall)  # contacts formed: a bed, as dense2d times it
        names = list(ways)
        for r in range(a.rounds):
            # each round in another order: a bed still compacting makes later steps dearer
            for way in names[r % len(names):] + names[:r % len(names)]:
                f = ways[way]
                t0 = time.perf_counter()
                if f is None:
                    sim.run(steps=a.steps)
                else:
                    sim.run(steps=a.steps, every=a.every, callback=f)
                times[way].append(time.perf_counter() - t0)
        contacts = sim.thermo()["contacts"] / n

    base = statistics.median(times["no callback"])
    rows = []
    print(f"{n} grains, {contacts:.2f} contacts per grain, {a.steps} steps a round, "
          f"{a.rounds} rounds, {a.threads} thread(s), a callback every {a.every} steps")
    for way, ts in times.items():
        m = statistics.median(ts)
        ns = 1e9 * m / (a.steps * n)
        overhead = 100.0 * (m / base - 1.0)
        print(f"  {way:22s} {ns:7.2f} ns per particle-step, {overhead:+6.2f} %")
        rows.append((way, ns, overhead))
    out = os.path.join(HERE, "results", "python_callback.csv")
    new = not os.path.exists(out)
    with open(out, "a") as f:
        if new:
            f.write("date,machine,n,steps,rounds,threads,every,way,ns_per_particle_step,"
                    "overhead_percent\n")
        stamp = datetime.datetime.now().isoformat(timespec="seconds")
        for way, ns, overhead in rows:
            f.write(f"{stamp},{platform.processor() or platform.machine()},{n},{a.steps},"
                    f"{a.rounds},{a.threads},{a.every},{way},{ns:.3f},{overhead:.2f}\n")
    print(f"appended to {out}")


if __name__ == "__main__":
    main()
