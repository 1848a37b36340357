"""Grains added and removed from Python: checked, recorded, and carried by checkpoints."""
import filecmp
import os

import numpy as np
import pytest

import talus
from conftest import SMALL

# the small box with its energy ledger, long enough for the grains to settle
LEDGER = dict(SMALL, simulation=dict(SMALL["simulation"], duration=0.4),
              output=dict(SMALL["output"], energy_ledger=True))
ABOVE = [[0.01, 0.07], [0.03, 0.07], [0.05, 0.07]]  # above the settled bed, apart


def settled(out=None):
    sim = talus.Simulation(LEDGER, out)
    sim.run(duration=0.15)
    assert (sim.positions[:, 1] + sim.radii).max() < 0.06
    return sim


def test_added_grains_get_new_ids_fall_and_keep_the_books():
    with settled() as sim:
        ids = sim.add_grains(ABOVE, 0.002, velocities=[[0, -0.1]] * 3, material="grain")
        assert list(ids) == [40, 41, 42] and len(sim.ids) == 43
        p = sim.particles()
        new = np.isin(p["id"], ids)
        assert np.allclose(p["radius"][new], 0.002)
        # spheres of the material's density (the scenario's particles.shape)
        assert np.allclose(p["mass"][new], 4 / 3 * np.pi * 0.002**3 * 2650.0)
        sim.run(duration=0.15)
        assert (sim.positions[np.isin(sim.ids, ids), 1] < 0.06).all()  # they fell into the bed
        imbalance = sim.thermo_table()["energy_imbalance"]
        # the ledger counts the grains' energy as the change's: what stays is the integration's
        # own error, a small part of the energy dissipated so far
        t = sim.thermo_table()
        assert abs(imbalance[-1]) < 1e-3 * (t["dissipated_damper"][-1] + t["dissipated_friction"][-1])


def test_removed_grains_go_with_their_contacts():
    with settled() as sim:
        sim.remove_grains([0, 5])
        assert len(sim.ids) == 38 and not np.isin([0, 5], sim.ids).any()
        c = sim.contacts()
        assert c["i"].max() < 38 and c["j"].max() < 38
        sim.run(duration=0.05)
        sim.flush()
        with open(os.path.join(sim.folder, "changes.csv")) as f:
            assert '"remove 2 grains: ids 0 5"' in f.read()


def test_bad_grains_are_refused_and_change_nothing():
    with settled() as sim:
        with pytest.raises(talus.ScenarioError, match="overlaps particle id 7"):
            sim.add_grains([sim.positions[sim.ids == 7][0]], 0.002)
        with pytest.raises(talus.ScenarioError, match="overlaps the grain added before it"):
            sim.add_grains([[0.01, 0.07], [0.01, 0.0705]], 0.002)
        with pytest.raises(talus.ScenarioError, match="overlaps wall segment"):
            sim.add_grains([[0.0005, 0.07]], 0.002)
        with pytest.raises(talus.ScenarioError, match="outside the region"):
            sim.add_grains([[5.0, 0.07]], 0.002)
        with pytest.raises(talus.ScenarioError, match="allowed: a finite radius"):
            sim.add_grains([[0.03, 0.07]], -0.002)
        with pytest.raises(talus.ScenarioError, match="allowed: grain"):
            sim.add_grains([[0.03, 0.07]], 0.002, material="sand")
        with pytest.raises(talus.ScenarioError, match="no such grain"):
            sim.remove_grains([999])
        assert len(sim.ids) == 40


def test_a_run_with_edits_resumes_as_it_went_on(tmp_path):
    def edit(sim):
        sim.add_grains(ABOVE, 0.002)
        sim.run(steps=3000)
        sim.remove_grains([3])

    with settled(tmp_path / "whole") as sim:
        edit(sim)
        sim.run()
    with settled(tmp_path / "cut") as sim:
        edit(sim)
        sim.run(steps=5000)
        sim.checkpoint()
    with talus.resume(tmp_path / "cut") as sim:
        assert len(sim.ids) == 42
        sim.run()
    for name in ("thermo.csv", "changes.csv"):
        assert filecmp.cmp(tmp_path / "whole" / name, tmp_path / "cut" / name, shallow=False)
