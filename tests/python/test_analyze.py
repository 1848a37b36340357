"""talus.analyze: the analyses of talus analyze, returned as numbers."""
import pytest

import talus
from conftest import SMALL


def test_thermo_and_forces_return_their_numbers(tmp_path):
    with talus.Simulation(SMALL, tmp_path / "r") as sim:
        sim.run()
    r = talus.analyze(tmp_path / "r", "forces")
    assert r["title"] and r["numbers"]
    assert "forces" in r["data"]
    assert all(isinstance(k, str) for k in r["numbers"])
    t = talus.analyze(tmp_path / "r", "thermo")  # charts only
    assert t["title"] and t["charts"]


def test_an_unknown_analysis_names_the_allowed_ones(tmp_path):
    with talus.Simulation(SMALL, tmp_path / "r") as sim:
        sim.run(steps=10)
    with pytest.raises(ValueError, match="allowed: thermo, forces"):
        talus.analyze(tmp_path / "r", "force")


def test_fields_integrate_to_the_grains_mass(tmp_path):
    with talus.Simulation(SMALL, tmp_path / "r") as sim:
        sim.run()
    r = talus.analyze(tmp_path / "r", "fields", start=0.02)
    f = r["data"]["fields"]
    assert f["axis"] == "y" and f["kernel"] == "gaussian" and f["frames"] >= 2
    table = talus.read_table(tmp_path / "r" / "analysis" / "fields.csv")
    assert {"y", "density", "contact_yy", "kinetic_xy"} <= set(table)
    lucy = talus.analyze(tmp_path / "r", "fields", axis="x", kernel="lucy", width=0.006)
    assert lucy["data"]["fields"]["width"] == 0.006 and lucy["data"]["fields"]["axis"] == "x"
    with pytest.raises(ValueError, match="allowed: gaussian, lucy"):
        talus.analyze(tmp_path / "r", "fields", kernel="box")
    # the profile reaches four widths past the grains, beyond a Gaussian's tails: the mass to
    # the trapezoid rule's error over points a quarter width apart
    assert f["mass_integral"] == pytest.approx(f["mass"], rel=1e-4)
    # maps of the plane: cells as wide as the kernel, which reaches five widths
    m = talus.analyze(tmp_path / "r", "fields", start=0.02, map=True)["data"]["fields_map"]
    assert m["nx"] >= 2 and m["ny"] >= 2
    assert m["mass_integral"] == pytest.approx(f["mass"], rel=1e-4)
