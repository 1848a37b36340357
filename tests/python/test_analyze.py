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
