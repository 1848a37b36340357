#!/usr/bin/python3
"""A small parameter study: the packing fraction and the coordination number of a bed poured and
settled in a box, against the grains' friction coefficient, gathered into a numpy table and a
matplotlib chart. Friction lets a bed come to rest looser (random loose packing).

    PYTHONPATH=build/python examples/python/friction_study.py [--grains 300] [--out study]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import talus  # noqa: E402


def bed(friction, grains):
    """A box of grains poured and settled as the scenario is built, then left 0.05 s."""
    return {
        "name": f"bed_mu_{friction:g}",
        "simulation": {"duration": 0.05},
        "materials": [{"name": "grain", "density": 2650.0, "normal_stiffness": 1.0e5,
                       "restitution": 0.3, "friction": friction}],
        "particles": {"count": grains, "material": "grain", "shape": "sphere",
                      "size": {"distribution": "uniform", "mean_radius": 0.003, "spread": 0.0006}},
        "packing": {"method": "sedimentation", "settle_energy": 1.0e-6},
        "geometry": {"builder": "box", "width": 0.12, "height": 0.3},
        "output": {"thermo_interval": 0.01, "snapshot_interval": 0.0},
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--grains", type=int, default=300)
    p.add_argument("--friction", type=float, nargs="+", default=[0.0, 0.1, 0.2, 0.4, 0.7, 1.0])
    p.add_argument("--out", default="friction_study", help="folder for the table and the chart")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)

    rows = []
    for mu in a.friction:
        with talus.Simulation(bed(mu, a.grains)) as sim:
            sim.run()
            # the bed's own packing fraction: thermo.csv's, over the region the grains were
            # poured into, counts the empty space above the bed too; measure below its top
            x = sim.positions
            r = sim.radii
            free = sim.kinds == 0
            top = (x[free, 1] + r[free]).max()
            bottom_half = free & (x[:, 1] < 0.5 * top)
            area = np.pi * (r[bottom_half] ** 2).sum()
            phi = area / (0.12 * 0.5 * top)
            rows.append((mu, phi, sim.thermo()["coordination"]))
            print(f"mu = {mu:4.2f}: packing fraction {phi:.3f}, coordination "
                  f"{rows[-1][2]:.2f}")
    table = np.array(rows)
    np.savetxt(os.path.join(a.out, "friction_study.csv"), table, delimiter=",",
               header="friction,packing_fraction,coordination", comments="")

    fig, ax = plt.subplots(1, 2, figsize=(8, 3.2))
    ax[0].plot(table[:, 0], table[:, 1], "o-")
    ax[0].set(xlabel="friction coefficient", ylabel="packing fraction (lower half)")
    ax[1].plot(table[:, 0], table[:, 2], "s-", color="C1")
    ax[1].set(xlabel="friction coefficient", ylabel="coordination number")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "friction_study.png"), dpi=120)
    print(f"table and chart in {a.out}/")
    return table


if __name__ == "__main__":
    main()
