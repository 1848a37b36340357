#!/usr/bin/python3
"""Elastic oblique impacts in LAMMPS' own pair_style granular, for each of its Mindlin springs:
the normalised angle of reflection psi2 against that of incidence psi1 (Maw, Barber & Fawcett
1976), beside the theory that tests/physics/test_oblique_impact_theory.cpp computes and the
table in docs/validation.md ("Oblique elastic impacts").

Two equal spheres (R = 1 mm, E = 1e8 Pa, nu = 0.3, mu = 0.3, density 2700 kg/m^3) meet head on
in y at 0.1 m/s each, sliding past each other in x; the contact's mid-plane stays fixed, so each
sphere meets it as a sphere meets a rigid half-space, with chi = (1 - nu) / (2 - nu) * 3.5. No
damping, t_c / 200, LAMMPS' 3D velocity Verlet.

    /usr/bin/python3 validation/oblique_lammps.py [--out FILE.csv]
"""
import argparse
import csv
import math
import sys

try:
    from lammps import lammps
except ImportError:
    sys.exit("oblique_lammps.py: needs LAMMPS' Python module (apt-get install python3-lammps)")

RADIUS, YOUNG, POISSON, MU, DENSITY, SPEED = 1e-3, 1e8, 0.3, 0.3, 2700.0, 1e-4
KAPPA = 2.0 * (1.0 - POISSON) / (2.0 - POISSON)  # k_t / k_n of Mindlin's no-slip spring
CHI = (1.0 - POISSON) / (2.0 - POISSON) * 3.5
SPRINGS = ("mindlin", "mindlin/force", "mindlin_rescale", "mindlin_rescale/force")


def contact_time():
    """Hertz' collision time of the pair (Landau & Lifshitz): 2.868 (m*^2 / (R* E*^2 v))^(1/5)."""
    mass = DENSITY * 4.0 / 3.0 * math.pi * RADIUS ** 3
    e_star = YOUNG / (2.0 * (1.0 - POISSON ** 2))
    return 2.868 * ((mass / 2) ** 2 / (RADIUS / 2 * e_star ** 2 * 2 * SPEED)) ** 0.2


def slip(lmp):
    """The contact point's velocity of sphere 2 against sphere 1 along x (the contact normal is
    y, sphere 2 above): v2x - v1x + R (w1z + w2z)."""
    v = lmp.numpy.extract_atom("v")
    w = lmp.numpy.extract_atom("omega")
    return v[1][0] - v[0][0] + RADIUS * (w[0][2] + w[1][2])


def psi2(spring, psi1):
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    u0 = psi1 * MU * 2.0 * SPEED / KAPPA  # the approach speed is 2 SPEED
    lmp.commands_string(f"""
        units si
        atom_style sphere
        atom_modify map array
        boundary f f f
        comm_modify vel yes
        region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
        create_box 1 box
        create_atoms 1 single 0 0 0
        create_atoms 1 single 0 {2.0 * RADIUS * 1.0001!r} 0
        set type 1 diameter {2.0 * RADIUS!r}
        set type 1 density {DENSITY!r}
        velocity all set 0 0 0
        set atom 1 vx {-u0 / 2.0!r} vy {SPEED!r}
        set atom 2 vx {u0 / 2.0!r} vy {-SPEED!r}
        pair_style granular
        pair_coeff * * hertz/material {YOUNG!r} 0.0 {POISSON!r} tangential {spring} NULL 0.0 {MU!r}
        neighbor {RADIUS!r} bin
        fix integrate all nve/sphere
        timestep {contact_time() / 200.0!r}
    """)
    for _ in range(2000):  # until the spheres have parted and move apart
        lmp.command("run 1 pre no post no")
        x, v = lmp.numpy.extract_atom("x"), lmp.numpy.extract_atom("v")
        if x[1][1] - x[0][1] > 2.0 * RADIUS and v[1][1] > v[0][1]:
            break
    else:
        sys.exit(f"oblique_lammps.py: {spring} at psi1 = {psi1}: the spheres never parted")
    out = KAPPA * slip(lmp) / (MU * 2.0 * SPEED)
    lmp.close()
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", help="also write the table here (CSV)")
    args = parser.parse_args()
    grid = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 4.0 * CHI - 1.0, 4.0 * CHI]
    rows = [[psi1] + [psi2(s, psi1) for s in SPRINGS] for psi1 in grid]
    print(f"chi = {CHI:.4f}; gross sliding: psi2 = psi1 - 4 chi for psi1 >= 4 chi - 1 = "
          f"{4 * CHI - 1:.4f}")
    print("psi1    " + "  ".join(f"{s:>22}" for s in SPRINGS))
    for r in rows:
        print(f"{r[0]:6.3f}  " + "  ".join(f"{v:22.4f}" for v in r[1:]))
    if args.out:
        with open(args.out, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["psi1"] + list(SPRINGS))
            w.writerows(rows)


if __name__ == "__main__":
    main()
