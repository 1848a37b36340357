"""Every example of examples/python runs, small, and gives what it is for."""
import os
import subprocess
import sys

import pytest

from conftest import REPO

EXAMPLES = REPO / "examples" / "python"


def run(name, *args, cwd=None):
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *args], capture_output=True,
                          text=True, timeout=600, cwd=cwd)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_angle_of_repose():
    out = run("angle_of_repose.py", "--grains", "60", "--step", "5", "--hold", "0.1")
    # round grains without rolling resistance: a low angle, as the built-in tilted_box finds
    angle = float(out.split("tilt of ")[1].split()[0])
    assert 5 <= angle <= 40


def test_lid_pressure():
    out = run("lid_pressure.py", "--grains", "80", "--hold", "0.15")
    deviation = float(out.split("(")[-1].split("%")[0])
    assert abs(deviation) < 1.0  # the controller holds the force within 1 % of the target


def test_friction_study(tmp_path):
    out = run("friction_study.py", "--grains", "80", "--friction", "0.0", "0.5",
              "--out", str(tmp_path))
    assert (tmp_path / "friction_study.png").stat().st_size > 0
    rows = (tmp_path / "friction_study.csv").read_text().splitlines()
    assert rows[0] == "friction,packing_fraction,coordination" and len(rows) == 3
    assert "packing fraction" in out


def test_two_disks_in_both_engines():
    library = os.environ.get("TALUS_LAMMPS_LIBRARY")
    if not library:
        pytest.skip("built without the LAMMPS package (TALUS_LAMMPS off)")
    out = run("two_disks_lammps.py", "--library", library)
    difference = float(out.split("largest difference: ")[1].split()[0])
    # the same law's code and LAMMPS' velocity Verlet: equal to rounding
    assert difference < 1e-12
