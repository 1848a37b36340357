"""A simulation driven from Python: stepping, callbacks, the state as arrays, changes, stops."""
import os

import numpy as np
import pytest

import talus
from conftest import SMALL


@pytest.fixture
def sim():
    s = talus.Simulation(SMALL)
    yield s
    s.close()


def test_run_by_steps_and_by_duration(sim):
    assert sim.run(steps=100) == "paused"
    assert sim.step == 100
    dt = sim.timestep
    sim.run(duration=50 * dt)
    assert sim.step == 150
    assert sim.time == pytest.approx(150 * dt, rel=1e-12)


def test_the_callback_runs_every_n_steps_and_can_stop(sim):
    seen = []
    sim.run(steps=1000, every=250, callback=lambda s: seen.append(s.step))
    assert seen == [250, 500, 750, 1000]
    seen.clear()

    def stop_at_1500(s):
        seen.append(s.step)
        return s.step >= 1500

    assert sim.run(steps=10000, every=250, callback=stop_at_1500) == "paused"
    assert seen == [1250, 1500] and sim.step == 1500


def test_running_to_the_end_completes_and_a_longer_run_goes_on(sim):
    assert sim.run() == "completed"
    assert sim.ended and sim.time == pytest.approx(0.05, abs=sim.timestep)
    # the run's new end is where the stretch ends: it ends there again
    assert sim.run(duration=0.01) == "completed"
    assert sim.duration == pytest.approx(sim.time, abs=sim.timestep) and sim.ended
    assert sim.time == pytest.approx(0.06, abs=2 * sim.timestep)
    with open(os.path.join(sim.folder, "changes.csv")) as f:
        assert "simulation.duration" in f.read()


def test_arrays_have_the_documented_shapes_and_types(sim):
    sim.run(steps=2000)
    p = sim.particles()
    n = len(p["radius"])
    assert n == 40
    for k in ("position", "velocity", "force", "image"):
        assert p[k].shape == (n, 2)
    for k in ("angle", "spin", "torque", "radius", "mass", "inertia", "material", "kind", "id"):
        assert p[k].shape == (n,)
    assert p["kind"].dtype == np.uint8 and p["id"].dtype == np.uint32
    assert sorted(p["id"]) == list(range(n))
    assert np.all(p["mass"] > 0)
    assert sim.positions.shape == (n, 2) and sim.spins.shape == (n,)
    w = sim.walls()
    assert w["a"].shape == (4, 2) and w["material"].shape == (4,)
    c = sim.contacts()
    k = len(c["i"])
    assert c["force"].shape == (k, 2) and c["overlap"].shape == (k,)
    assert np.all(c["overlap"] > 0)
    walls = c["wall"] >= 0
    assert np.all(c["j"][walls] == -1) and np.all(c["j"][~walls] >= 0)


def test_arrays_are_copies(sim):
    x = sim.positions
    x[:] = 0.0
    assert np.any(sim.positions != 0.0)


def test_thermo_now_and_the_table(sim):
    sim.run(duration=0.02)
    t = sim.thermo()
    assert t["kinetic"] == pytest.approx(t["kinetic_translational"] + t["kinetic_rotational"])
    assert set(t["wall_forces"]) == set(sim.groups())
    table = sim.thermo_table()
    assert table["time"][-1] == pytest.approx(0.02, abs=sim.timestep)
    assert len(table["time"]) == 5  # t = 0, 0.005, ..., 0.02


def test_changes_are_checked_and_recorded(sim):
    sim.change({"simulation.gravity": [0.0, -1.0]})
    with pytest.raises(talus.ScenarioError, match="cannot change during a run; allowed"):
        sim.change({"particles.count": 5})
    with pytest.raises(talus.ScenarioError, match=r"simulation\.gravity"):
        sim.change({"simulation.gravity": [0.0, "down"]})
    sim.flush()
    with open(os.path.join(sim.folder, "changes.csv")) as f:
        rows = f.read().splitlines()
    assert len(rows) == 2 and "simulation.gravity=[0.0, -1.0]" in rows[1]


def test_gravity_changed_from_python_acts(sim):
    sim.run(steps=10)
    sim.change({"simulation.gravity": [0.0, 0.0]})
    v0 = sim.velocities
    sim.run(steps=100)
    # no contact yet (the grains start apart): without gravity the grains keep their speed, but
    # for what Gear's corrector takes a few steps to forget of the old acceleration
    fall = 9.81 * 100 * sim.timestep
    assert np.abs(sim.velocities - v0).max() < 0.1 * fall


def test_a_named_folder_is_resumed_where_close_left_it(tmp_path):
    out = tmp_path / "run"
    a = talus.Simulation(SMALL, out)
    a.run(steps=700)
    x = a.positions
    a.close()
    with pytest.raises(RuntimeError, match="closed"):
        a.time
    b = talus.resume(out)
    assert b.step == 700 and np.array_equal(b.positions, x)
    b.run()
    assert b.ended
    b.close()


def test_a_temporary_folder_goes_with_its_simulation():
    s = talus.Simulation(SMALL)
    folder = s.folder
    assert os.path.isdir(folder)
    s.close()
    assert not os.path.exists(folder)
    with talus.Simulation(SMALL) as t:
        folder = t.folder
    assert not os.path.exists(folder)


def test_a_folder_with_a_run_is_refused(tmp_path):
    with talus.Simulation(SMALL, tmp_path / "r"):
        with pytest.raises(ValueError, match="holds a run|in use|locked"):
            talus.Simulation(SMALL, tmp_path / "r")


def test_bad_arguments_say_what_is_allowed(sim):
    with pytest.raises(ValueError, match="duration or steps, not both"):
        sim.run(duration=0.1, steps=10)
    with pytest.raises(ValueError, match="allowed: a whole number of steps"):
        sim.run(steps=10, every=0)
    with pytest.raises(ValueError, match="needs every"):
        sim.run(steps=10, callback=print)
    with pytest.raises(ValueError, match="allowed: 0"):
        talus.Simulation(SMALL, threads=-2)


def test_ctrl_c_checkpoints_and_raises(tmp_path):
    import signal
    import threading

    long = dict(SMALL, simulation=dict(SMALL["simulation"], duration=100.0))
    sim = talus.Simulation(long, tmp_path / "r")
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.run()
    timer.join()
    stopped = sim.time
    assert 0 < stopped < 100.0
    sim.close()
    with talus.resume(tmp_path / "r") as again:
        assert again.time == stopped  # the checkpoint the interrupt wrote


def test_stages_and_the_scenario_as_it_stands(tmp_path):
    with talus.Simulation("tilted_box", set={"particles.count": 40, "simulation.duration": 0.2,
                                             "simulation.threads": 1}) as sim:
        assert sim.stage == 0
        sim.run()
        assert sim.stage >= 1  # settled, then tilted by the next stage
        assert "1.703489" in sim.scenario_toml  # the tilt stage's gravity
