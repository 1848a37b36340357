#!/usr/bin/python3
"""The package's shared library registers pair_style granthesis in python3-lammps with one line,
and a run there gives the same numbers as the same deck in talus-lmp (the same code and doubles).

Usage: python_register_test.py LIBTALUS_LAMMPS TALUS_LMP"""
import ctypes
import os
import re
import subprocess
import sys

try:
    from lammps import lammps
except ImportError:
    print("python3-lammps is not installed: skipped")
    sys.exit(77)

library, launcher = sys.argv[1], sys.argv[2]
deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "two_disks.in")

lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
ctypes.CDLL(library).talus_lammps_register(lmp.lmp)  # the documented registration
lmp.file(deck)
from_python = [lmp.extract_atom("v")[k][0] for k in range(2)]
lmp.close()

done = subprocess.run([launcher, "-in", deck, "-log", "none"], capture_output=True, text=True,
                      timeout=120)
match = re.search(r"VX1 (\S+) VX2 (\S+)", done.stdout)
if done.returncode != 0 or match is None:
    sys.exit(f"talus-lmp failed:\n{done.stdout}\n{done.stderr}")
from_launcher = [float(match.group(1)), float(match.group(2))]
print(f"python3-lammps: vx = {from_python}; talus-lmp: vx = {from_launcher}")
if from_python[0] >= 0.0 or from_python[1] <= 0.0:
    sys.exit("the disks did not bounce back")
if from_python != from_launcher:
    sys.exit("python3-lammps and talus-lmp differ")
