"""LAMMPS' own granular styles in place of granthesis: implementations independent of src/talus,
for the cases whose tolerances ask for them (validation/crosscheck.py). Each takes the case's
exported deck and writes its pair lines (and, for `granular`, its walls) in that style's terms,
with the native conventions pinned where the two differ (docs/validation.md):

- `gran/hooke` with `limit_damping`: the linear law with the capped viscous friction, for one
  material whose dampers are rates (gran/hooke has one gamma_n for every pair), against the
  native engine with its lever arms at the radius, gran/hooke's convention;
- `granular`: `hertz/material` with `damping viscoelastic`, `tangential mindlin_rescale/force`
  and `limit_damping` for the pairs, `fix wall/gran granular` with the same for a box's
  axis-aligned segments, for equal grains of one material with a given viscoelastic constant A
  and no tangential dashpot.
"""
import os
import re
import sys


def gran_hooke_lines(case, scenario):
    """LAMMPS' gran/hooke line for the case's one material, which must give its dampers as rates
    (gran/hooke takes one gamma_n for every pair; a restitution is derived per pair)."""
    materials = scenario["materials"]
    m = materials[0]
    if len(materials) != 1 or "normal_damping_rate" not in m or "restitution" in m:
        sys.exit(f"{case}: gran_hooke needs one material with normal_damping_rate (gran/hooke "
                 "has one gamma_n for every pair)")
    law = scenario["simulation"]
    if (law.get("normal_law"), law.get("tangential_law")) != ("linear", "coulomb"):
        sys.exit(f"{case}: gran_hooke needs normal_law = linear and tangential_law = coulomb, "
                 "the laws gran/hooke has")
    # Kn Kt gamma_n gamma_t xmu dampflag: Kt unused without history; limit_damping: never
    # attractive, as the native law
    return (f"pair_style gran/hooke {m['normal_stiffness']!r} NULL "
            f"{m['normal_damping_rate']!r} {m['tangential_damping']!r} {m['friction']!r} 1 "
            "limit_damping\npair_coeff * *\n")


def equal_mass(case, masses_path):
    """The one mass of every atom of the deck's masses file (kg), or exits if they differ."""
    with open(masses_path) as f:
        masses = {float(m) for m in re.findall(r"^set atom \d+ mass (\S+)", f.read(), re.M)}
    if len(masses) != 1:
        sys.exit(f"{case}: granular needs equal grains (damping viscoelastic's eta_n0 holds for "
                 f"one m_eff per pair of types); {masses_path} has {len(masses)} masses")
    return masses.pop()


def granular_model(m, eta_n0, young=None):
    """The model words of pair_coeff and fix wall/gran granular for material m: Hertz of E
    (`young`, or the material's) and nu with the viscoelastic eta_n0, Mindlin's spring from E
    and nu (NULL), no tangential dashpot (x_gamma,t = 0), the friction; never attractive."""
    young = m["young"] if young is None else young
    return (f"hertz/material {young!r} {eta_n0!r} {m.get('poisson', 0.3)!r} tangential "
            f"mindlin_rescale/force NULL 0.0 {m['friction']!r} damping viscoelastic "
            "limit_damping")


def granular_lines(case, scenario, masses_path):
    """pair_style granular's lines for the case. The native viscoelastic force 3/2 A rho
    sqrt(xi) dxi/dt, rho = 4/3 E* sqrt(R*), is granular's eta_n0 a m_eff v_n with a =
    sqrt(R* xi) when eta_n0 = 2 A E* / m_eff: m_eff = m/2 between two equal grains, m against a
    wall. The native mindlin law (incremental force under a growing stiffness, the stretch kept
    under a falling one, the spring alone held in the Coulomb cone) is mindlin_rescale/force
    when no tangential dashpot is there to be capped with it."""
    materials = scenario["materials"]
    law = scenario["simulation"]
    m = materials[0]
    problems = []
    if len(materials) != 1:
        problems.append("one material")
    if (law.get("normal_law"), law.get("tangential_law")) != ("hertz", "mindlin"):
        problems.append("normal_law = hertz and tangential_law = mindlin")
    if m.get("hertz_damping", -1.0) < 0.0:
        problems.append("a given hertz_damping (the A of every contact)")
    if m.get("tangential_damping", 0.0) != 0.0 or m.get("rolling_friction", 0.0) != 0.0:
        problems.append("tangential_damping = 0 and no rolling_friction")
    if problems:
        sys.exit(f"{case}: granular needs {', '.join(problems)}")
    mass = equal_mass(case, masses_path)
    nu = m.get("poisson", 0.3)
    e_star = m["young"] / (2.0 * (1.0 - nu * nu))
    pair = (f"pair_style granular\npair_coeff * * "
            f"{granular_model(m, 2.0 * m['hertz_damping'] * e_star / (0.5 * mass))}\n")
    # fix wall/gran takes E* = E / (2 (1 - nu)) where pair_style granular (and the native wall
    # of the grains' own material) take E / (2 (1 - nu^2)): its E is given as E / (1 + nu)
    wall = granular_model(m, 2.0 * m["hertz_damping"] * e_star / mass, m["young"] / (1.0 + nu))
    return pair, wall


def wall_planes(case, segments, wall):
    """fix wall/gran granular lines for a box's segments (AX AY BX BY): each is a plane x = c or
    y = c; the planes bound the box as its segments do."""
    planes = {"x": set(), "y": set()}
    for ax, ay, bx, by in segments:
        if ax == bx:
            planes["x"].add(ax)
        elif ay == by:
            planes["y"].add(ay)
        else:
            sys.exit(f"{case}: granular's walls are planes: segment ({ax}, {ay})-({bx}, {by}) is "
                     "neither vertical nor horizontal")
    lines = []
    for axis, at in planes.items():
        if len(at) > 2:
            sys.exit(f"{case}: {len(at)} walls across {axis}: a box has two")
        if at:
            lo, hi = min(at), max(at)
            bounds = f"{lo!r} {hi!r}" if len(at) == 2 else f"{lo!r} NULL"
            lines.append(f"fix walls_{axis} grains wall/gran granular {wall} {axis}plane "
                         f"{bounds}\n")
    return "".join(lines)


def rewrite_deck(path, pair, wall=None):
    """The deck at `path` with its pair lines replaced by `pair` and, given `wall` (granular's
    model words), its fix granthesis/wall by wall/gran planes; the lines that read the fix's
    contacts (the coordination, the walls' work) then count the pairs only."""
    with open(path) as f:
        text = f.read()
    case = os.path.basename(path)
    lines = re.sub(r"&\n", " ", text).splitlines(keepends=True)  # continuations joined
    out = []
    for line in lines:
        if line.startswith(("pair_style", "pair_coeff")):
            if line.startswith("pair_style"):
                out.append(pair)
            continue
        if wall is not None and "granthesis/wall" in line:
            numbers = re.findall(r"segment (\S+) (\S+) (\S+) (\S+) type", line)
            out.append(wall_planes(case, [tuple(map(float, s)) for s in numbers], wall))
            continue
        if wall is not None and line.startswith("fix_modify walls"):
            continue
        if wall is not None:  # the reduction of the pairs' contacts alone is a scalar
            line = re.sub(r" f_walls(\[\d+\])?", "", line)
            line = line.replace("c_contact_parts[1]+c_contact_parts[2]", "c_contact_parts")
        out.append(line)
    with open(path, "w") as f:
        f.writelines(out)
