"""Small errors that are still errors, put into one engine of the cross-check on purpose
(`validation/crosscheck.py --mutate KIND`): its comparison of native Verlet (half step) with
LAMMPS must fail each (tests/validation/mutation_test.py), so that a pass means something. Two
are not small (`friction`, `shear_remap`): a chaotic case's statistics must fail on a change of
its physics (docs/validation.md shows the chute's and the sheared cell's).
"""
import os
import re
import sys

MUTATIONS = {
    "coefficient": "LAMMPS: every pair_coeff's normal_stiffness and young times 1 + 1e-6",
    "mass": "LAMMPS: every atom's mass times 1 + 1e-6",
    "wall": "LAMMPS: every wall segment moved by 1e-6 mean radii in x and in y",
    "lever_arm": "native: the lever arms at the radius, not at the contact point",
    "damper_velocity": "native: the dampers given the predicted velocity, not the half step's",
    # not small: a long case's statistics must see a change of the physics, not of rounding
    "friction": "LAMMPS: every pair_coeff's friction times 0.75 (for a flow's statistics)",
    "shear_remap": "LAMMPS: the sheared cell's fix deform remaps the atoms' positions (remap x), "
                   "not the velocities of those that cross the tilted box (remap v)",
}
NATIVE_MUTATIONS = {"lever_arm": ["simulation.lever_arm=radius"],
                    "damper_velocity": ["simulation.verlet_velocity=predicted"]}
MUTATION_FACTOR = 1.0 + 1e-6


def scale_numbers(text, pattern, change):
    """`text` with the number after each match of `pattern` (a regex whose last group is the
    number) changed by `change`, and how many were changed."""
    count = 0

    def one(m):
        nonlocal count
        count += 1
        return m.group(0)[:m.start(m.lastindex) - m.start(0)] + repr(change(float(m.group(
            m.lastindex))))

    return re.sub(pattern, one, text, flags=re.M), count


def mutate_deck(folder, deck_name, kind, radius):
    """Puts mutation `kind` (MUTATIONS) into the LAMMPS deck in `folder`, or exits if the deck
    has nothing it applies to (a mutation that changes nothing would pass for the wrong
    reason)."""
    def grow(x):
        return x * MUTATION_FACTOR

    def shift(x):
        return x + 1e-6 * radius

    # the file, the lines to change, and (the regex whose last group is a number, its change)
    name, chosen, edits = {
        "mass": ("masses", lambda line: line.startswith("set atom"), [(r"(mass )(\S+)", grow)]),
        # every key of a pair_coeff line (keys and values alternate: none precedes a value)
        "coefficient": ("in", lambda line: line.startswith("pair_coeff"),
                        [(r"(?<=\s)((?:normal_stiffness|young) )(\S+)", grow)]),
        "friction": ("in", lambda line: line.startswith("pair_coeff"),
                     [(r"(?<=\s)(friction )(\S+)", lambda x: 0.75 * x)]),
        # a text change: (the regex, its replacement)
        "shear_remap": ("in", lambda line: line.startswith("fix cell all deform 1 xy erate"),
                        [(r"remap v$", "remap x")]),
        "wall": ("in", lambda line: line.lstrip().startswith("segment "),
                 [(r"^(\s*segment " + r"\S+ " * k + r")(\S+)", shift) for k in range(4)]),
    }[kind]
    path = os.path.join(folder, f"{name}.{deck_name}")
    if not os.path.exists(path):
        sys.exit(f"mutation {kind}: no {path}")
    with open(path) as f:
        lines = f.read().splitlines(keepends=True)
    count = 0
    for k, line in enumerate(lines):
        if chosen(line):
            for pattern, change in edits:
                line, n = (re.subn(pattern, change, line.rstrip("\n")) if isinstance(change, str)
                           else scale_numbers(line, pattern, change))
                if isinstance(change, str):
                    line += "\n"
                count += n
            lines[k] = line
    if count == 0:
        sys.exit(f"mutation {kind}: nothing in {path} to change")
    with open(path, "w") as f:
        f.writelines(lines)
