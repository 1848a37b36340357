"""A run driven from Python, looked at every few steps, is the run `talus run` makes: the same
files, byte for byte (the engine's results do not depend on where its steps are cut)."""
import filecmp
import os
import subprocess

import talus

# a staged built-in: settle, then gravity tilted by a stage (a change during the run)
SET = {"particles.count": 60, "simulation.duration": 0.3, "simulation.threads": 1}


def same_files(a, b, names):
    for n in names:
        assert filecmp.cmp(os.path.join(a, n), os.path.join(b, n), shallow=False), n


def test_python_and_the_command_line_write_the_same_run(tmp_path, talus_program):
    cli = tmp_path / "cli"
    args = [talus_program, "run", "tilted_box", "--out", str(cli)]
    for k, v in SET.items():
        args += ["--set", f"{k}={v}"]
    subprocess.run(args, check=True, capture_output=True)

    looked = []
    with talus.Simulation("tilted_box", tmp_path / "py", set=SET) as sim:
        sim.run(every=997, callback=lambda s: looked.append(s.positions.sum()))
        assert sim.ended
    assert len(looked) > 10
    py = tmp_path / "py"
    same_files(cli, py, ["thermo.csv", "stages.csv", "changes.csv", "particles.pvd"])
    snapshots = sorted(os.listdir(cli / "snapshots"))
    assert snapshots == sorted(os.listdir(py / "snapshots")) and len(snapshots) > 3
    same_files(cli / "snapshots", py / "snapshots", snapshots)
