#!/usr/bin/python3
"""A lid held at a pressure by a controller written in Python: a bed settles under gravity in the
grain press, the lid comes down onto it, and a proportional controller sets the lid's speed from
the force the grains put on it, every few steps, until that force holds at the target.

In 2D a stress is a force per unit length (N/m): the target force on the lid is the pressure
times the press' width.

    PYTHONPATH=build/python examples/python/lid_pressure.py [--pressure 20] [--grains 200]
"""
import argparse

import numpy as np

import talus

K_N = 1.0e5  # N/m: the grains' normal stiffness


def press(grains):
    """Spheres moving in a plane, settled in a press 0.1 m wide, its lid starting a little above
    the room the grains need to be poured in (a packing fraction of a half)."""
    r, width = 0.0025, 0.1
    height = grains * 3.14159 * r**2 / (0.5 * width) + 0.005
    return {
        "name": "pressure_controlled_press",
        "simulation": {"duration": 1000.0},
        "materials": [{"name": "grain", "density": 2650.0, "normal_stiffness": K_N,
                       "restitution": 0.5, "friction": 0.4}],
        "particles": {"count": grains, "material": "grain", "shape": "sphere",
                      "size": {"distribution": "uniform", "mean_radius": r,
                               "spread": 0.0005}},
        "packing": {"method": "sedimentation", "settle_energy": 1.0e-6},
        "geometry": {"builder": "grain_press", "width": width, "height": height,
                     "lid_speed": 0.1},
        "output": {"thermo_interval": 0.01, "snapshot_interval": 0.0},
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pressure", type=float, default=20.0, help="N/m on the lid")
    p.add_argument("--grains", type=int, default=200)
    p.add_argument("--hold", type=float, default=0.3, help="s of control after the lid touches")
    p.add_argument("--every", type=int, default=100, help="steps between the controller's looks")
    p.add_argument("--out", default=None, help="the run folder (default: a temporary one)")
    a = p.parse_args()

    with talus.Simulation(press(a.grains), a.out) as sim:
        lid = sim.groups()["lid"]["segments"]
        w = sim.walls()
        width = float(np.ptp(np.concatenate([w["a"][lid, 0], w["b"][lid, 0]])))
        target = a.pressure * width  # N
        # Speed per newton short of the target. The bed under the lid is a spring of about the
        # grains' stiffness k_n, so the force closes its gap at a rate k_n x gain; a fifth of it
        # per look keeps the loop well inside its stability limit (2).
        gain = 0.2 / (K_N * sim.timestep * a.every)
        approach = 0.1  # m/s until the lid touches
        history = []

        def control(s):
            f = s.thermo()["wall_forces"]["lid"][1]  # the grains push the lid up: f > 0
            speed = approach if f == 0.0 else float(np.clip(gain * (target - f), -0.1, 0.1))
            s.change({"geometry.lid_speed": speed}, source="pressure controller")
            history.append((s.time, f))
            return False

        # down until the lid touches, then held for `hold` s
        sim.run(duration=2.0, every=a.every, callback=lambda s: control(s) or history[-1][1] > 0)
        touched = sim.time
        sim.run(duration=a.hold, every=a.every, callback=control)
        t, f = np.array(history).T
        late = t > touched + 0.5 * a.hold
        mean, spread = f[late].mean(), f[late].std()
        print(f"lid touched at t = {touched:.3f} s; target {target:.4g} N ({a.pressure:g} N/m over "
              f"{width:.3g} m); over the last half: {mean:.4g} N +- {spread:.2g} N "
              f"({100 * (mean / target - 1):+.2f} %)")
        return target, mean, spread


if __name__ == "__main__":
    main()
