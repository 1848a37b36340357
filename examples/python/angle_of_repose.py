#!/usr/bin/python3
"""The angle of repose, measured by a protocol written in Python: a bed settled in a box, then
gravity turned a little at a time (the box stays put) until the bed avalanches.

The built-in tilted_box does the same with fixed stages of 5 degrees; here the tilt step, the
hold and the avalanche test are Python's. Round grains without rolling resistance avalanche at a
small angle (docs/experiments.md).

    PYTHONPATH=build/python examples/python/angle_of_repose.py [--grains 300] [--step 1]
"""
import argparse
import math

import talus


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--grains", type=int, default=300)
    p.add_argument("--step", type=float, default=1.0, help="degrees of tilt at a time")
    p.add_argument("--hold", type=float, default=0.2, help="s at each tilt")
    p.add_argument("--kinetic", type=float, default=2.0e-4,
                   help="J: the kinetic energy of an avalanche (not a creep into place)")
    p.add_argument("--out", default=None, help="the run folder (default: a temporary one)")
    a = p.parse_args()

    # our own protocol replaces the built-in stages; the run is as long as the tilting takes
    sc = talus.scenario("tilted_box", set={"stages": [], "particles.count": a.grains,
                                           "simulation.duration": 1000.0,
                                           "output.snapshot_interval": 0.0,
                                           "output.pictures": []})
    g = 9.81
    with talus.Simulation(sc, a.out) as sim:
        sim.run(duration=0.1)  # the bed was settled as it was built; let it come fully to rest
        angle = 0.0
        while angle < 60.0:
            angle += a.step
            t = math.radians(angle)
            sim.change({"simulation.gravity": [g * math.sin(t), -g * math.cos(t)]},
                       source=f"tilt {angle:g} deg")
            sim.run(duration=a.hold, every=200,
                    callback=lambda s: s.thermo()["kinetic"] > a.kinetic)
            if sim.thermo()["kinetic"] > a.kinetic:
                print(f"avalanche at a tilt of {angle:g} degrees (t = {sim.time:.3f} s)")
                return angle
        print("no avalanche up to 60 degrees")
        return None


if __name__ == "__main__":
    main()
