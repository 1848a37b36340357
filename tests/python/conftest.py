"""The Python module's tests: run by ctest (tests/CMakeLists.txt), which puts the build's python/
folder on PYTHONPATH and names the talus program in TALUS_PROGRAM."""
import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def talus_program():
    p = os.environ.get("TALUS_PROGRAM", str(REPO / "build" / "native" / "talus"))
    if not os.path.exists(p):
        pytest.fail(f"the talus program is not at {p} (set TALUS_PROGRAM)")
    return p


# A small, quick scenario: 40 grains poured into a box, no settling.
SMALL = {
    "name": "small_box",
    "simulation": {"duration": 0.05, "threads": 1},
    "materials": [{"name": "grain", "density": 2650.0, "normal_stiffness": 1.0e5,
                   "restitution": 0.5, "friction": 0.5}],
    "particles": {"count": 40, "material": "grain",
                  "size": {"distribution": "uniform", "mean_radius": 0.003, "spread": 0.0005}},
    "packing": {"method": "random"},
    "geometry": {"builder": "box", "width": 0.06, "height": 0.08},
    "output": {"thermo_interval": 0.005, "snapshot_interval": 0.025},
}
