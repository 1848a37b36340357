"""talus: discrete element simulation of granular media, driven from Python.

    import talus
    sim = talus.Simulation("hourglass", set={"particles.count": 300})
    sim.run(duration=0.2, every=1000, callback=lambda s: print(s.time, s.thermo()["kinetic"]))
    print(sim.positions.shape)

The engine is talus' native one; a run writes its folder as `talus run` does (docs/python.md).
"""
from ._talus import CheckpointError, InstabilityError, ScenarioError
from .analysis import analyze, read_table
from .scenario import Scenario, builtin_scenarios, changeable_keys, scenario
from .simulation import Simulation, resume

__all__ = [
    "Scenario",
    "Simulation",
    "ScenarioError",
    "InstabilityError",
    "CheckpointError",
    "analyze",
    "builtin_scenarios",
    "changeable_keys",
    "read_table",
    "resume",
    "scenario",
]
