#!/usr/bin/python3
"""The cross-check can fail: each small error of validation/crosscheck.py's MUTATIONS, put into
one engine on a quick case, must make its comparison of native Verlet (half step) with LAMMPS
fail (1e-6 relative in a stiffness or a mass, 1e-6 radii in a wall's place, the lever arm at the
radius, the predicted damper velocity); on a case that also runs LAMMPS' own pair_style granular,
that comparison must fail too.

Usage: mutation_test.py BUILD OUT"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# each mutation on a case where what it changes acts: contacts with a stiffness (both laws), a
# head-on impact's masses, the segment walls of a settling box, an oblique impact's friction
# torque and dampers
CASES = [("coefficient", "two_disks_linear_oblique"), ("coefficient", "two_disks_hertz_oblique"),
         ("mass", "two_disks_linear_headon"), ("wall", "walls_hertz_mindlin"),
         ("lever_arm", "two_disks_linear_oblique"),
         ("damper_velocity", "two_disks_linear_oblique"),
         ("mass", "two_disks_granular_oblique")]
ROW = "native Verlet (half_step) against LAMMPS granthesis, 1 rank"
# and, where the case runs LAMMPS' own pair_style granular, its comparison too
GRANULAR_ROW = ("native Verlet (half_step, lever_arm = granular) against LAMMPS pair_style "
                "granular, fix wall/gran")


def main():
    build, out = (os.path.abspath(p) for p in sys.argv[1:3])
    if not os.path.exists(os.path.join(build, "lammps-package", "talus-lmp")):
        print("talus-lmp not built: skipped")
        sys.exit(77)
    missed = []
    for mutation, case in CASES:
        done = subprocess.run(
            ["/usr/bin/python3", os.path.join(ROOT, "validation", "crosscheck.py"), case,
             "--mutate", mutation, "--build", build,
             "--out", os.path.join(out, f"{mutation}-{case}")],
            capture_output=True, text=True, timeout=600)
        printed = done.stdout + done.stderr
        rows = [ROW] + ([GRANULAR_ROW] if "granular" in case else [])
        found = [re.search(rf"^FAIL {re.escape(case)}: {re.escape(row)}: largest (\S+) radii",
                           printed, flags=re.M) for row in rows]
        if done.returncode == 1 and all(found):
            which = "comparisons fail" if len(rows) > 1 else "comparison fails"
            print(f"ok: {mutation} on {case}: the {which}, largest difference "
                  f"{', '.join(f.group(1) for f in found)} mean radii")
        else:
            missed.append(f"{mutation} on {case}")
            print(f"MISSED: {mutation} on {case} (exit {done.returncode}):\n{printed[-3000:]}")
    if missed:
        sys.exit(f"the cross-check did not fail on: {', '.join(missed)}")


if __name__ == "__main__":
    main()
