"""A simulation driven from Python: the run `talus run` makes, stepped in pieces."""
import os
import shutil
import tempfile

import numpy as np

from . import _talus, toml_text
from ._talus import ScenarioError
from .analysis import read_table
from .scenario import scenario as make_scenario


class Simulation:
    """A run of a scenario in a run folder, as `talus run` writes it.

    scenario: a Scenario, a scenario file, a built-in name or a dict (see talus.scenario), with
    `set` changes. out: the run folder (it must not hold another run); None: a temporary folder,
    removed by close(). threads: None for the scenario's simulation.threads. quiet: False prints
    what the command line prints.

    The grains are placed (and settled, where the scenario asks) here; run() steps them.
    """

    def __init__(self, scenario, out=None, *, set=None, threads=None, quiet=True):
        sc = make_scenario(scenario, set)
        self._temporary = out is None
        folder = tempfile.mkdtemp(prefix="talus-") if out is None else os.fspath(out)
        try:
            self._session = _talus.Session(sc._native, folder, _threads(threads), quiet)
        except BaseException:
            if self._temporary:
                shutil.rmtree(folder, ignore_errors=True)
            raise
        self._folder = folder

    @classmethod
    def resume(cls, folder, *, threads=None, quiet=True):
        """Continues the run in `folder` from its last good checkpoint, as `talus resume` does."""
        self = cls.__new__(cls)
        self._temporary = False
        self._folder = os.fspath(folder)
        self._session = _talus.Session.resume(self._folder, _threads(threads), quiet)
        return self

    # -- running -------------------------------------------------------------------------------

    def run(self, duration=None, steps=None, *, every=None, callback=None):
        """Steps on for `duration` s or `steps` steps (neither: to the scenario's end), with the
        outputs, stages and events of the scenario on the way.

        every, callback: callback(sim) after every `every` steps (and at the end of the call); a
        callback that returns True stops the call there. A stretch beyond the scenario's
        simulation.duration lengthens the run to its end (recorded in changes.csv, as talus
        resume --duration does): the run ends there, with its end's records, unless a later
        call lengthens it again. The engine runs without the GIL.

        Returns "paused" (the stretch is done, the run goes on), or "completed" (the run ended:
        its duration, or a stage that ends it).
        """
        s = self._live()
        if duration is not None and steps is not None:
            raise ValueError("run(): give duration or steps, not both")
        if every is not None and (int(every) != every or every < 1):
            raise ValueError(f"run(): every = {every!r}; allowed: a whole number of steps >= 1")
        if callback is not None and every is None:
            raise ValueError("run(): a callback needs every=N (steps between calls)")
        if duration is not None:
            if not duration >= 0:
                raise ValueError(f"run(): duration = {duration!r} s; allowed: a time >= 0 s")
            end = s.time + duration
            if end > s.duration:
                s.extend_to(end)
            target = s.step_at(end)
        elif steps is not None:
            if int(steps) != steps or steps < 0:
                raise ValueError(f"run(): steps = {steps!r}; allowed: a whole number >= 0")
            target = s.step + int(steps)
            if s.step_at(s.duration) < target:
                s.extend_to(s.time + int(steps) * s.timestep)
        else:
            target = s.step_at(s.duration)
        outcome = "paused"
        while True:
            stop = target if every is None else min(target, s.step + int(every))
            outcome = s.go(stop)
            if callback is not None and callback(self) is True:
                break
            if outcome != "paused" or s.step >= target:
                break
        return "completed" if s.ended else "paused"

    def change(self, changes, source="python"):
        """Changes the run from this step on: {"dotted.key": value} (or "key=value" strings), as a
        stage's set or `talus resume --set` change it, checked as the scenario loader checks it and
        recorded in changes.csv. talus.changeable_keys() lists the keys."""
        self._live().change(toml_text.assignments(changes), source)

    def add_grains(self, positions, radii, *, velocities=None, spins=None, material=None,
                   source="python"):
        """Adds free grains between steps: positions (k, 2) m, radii (k,) m, velocities (k, 2)
        m/s and spins (k,) rad/s (default 0), of one material (a name or an index; default the
        scenario's first). Their mass and inertia follow from the scenario's particles.shape and
        the material's density. Checked as a scenario's grains are (no overlap with a grain or a
        wall; inside the region grains may be in): a ScenarioError leaves the run as it was.
        Recorded in changes.csv. Returns the new grains' ids."""
        s = self._live()
        x = np.asarray(positions, dtype=float).reshape(-1, 2)
        k = len(x)
        r = np.broadcast_to(np.asarray(radii, dtype=float), (k,))
        v = np.zeros((k, 2)) if velocities is None else np.asarray(velocities, float).reshape(k, 2)
        w = np.zeros(k) if spins is None else np.broadcast_to(np.asarray(spins, float), (k,))
        names = s.material_names()
        if material is None:
            m = 0
        elif isinstance(material, str):
            if material not in names:
                raise ScenarioError(f"material '{material}' of the grains to add; allowed: "
                                    + ", ".join(names))
            m = names.index(material)
        else:
            m = int(material)
            if not 0 <= m < len(names):
                raise ScenarioError(f"material {material} of the grains to add; allowed: 0 to "
                                    f"{len(names) - 1} ({', '.join(names)})")
        return np.array(s.add_grains(x.tolist(), r.tolist(), v.tolist(), w.tolist(), m, source),
                        dtype=np.uint32)

    def remove_grains(self, ids, source="python"):
        """Removes the free grains with these ids (sim.ids gives them) between steps; their
        contacts end. Refused, naming the id, for an unknown id, a wall particle or a tracked
        grain. Recorded in changes.csv."""
        self._live().remove_grains([int(i) for i in np.atleast_1d(ids)], source)

    def checkpoint(self):
        """Writes a checkpoint now (talus.resume(folder) continues from the last one)."""
        self._live().checkpoint()

    def flush(self):
        """Writes what the outputs hold in memory to the run folder's files (thermo.csv,
        changes.csv, ...), so that they can be read now."""
        self._live().flush()

    def close(self):
        """Ends this session: a run stopped before its end is checkpointed so that
        talus.resume (or talus resume) continues it; a temporary folder is removed."""
        s = getattr(self, "_session", None)
        if s is None:
            return
        try:
            if not self._temporary:
                s.stop_here()
        finally:
            self._session = None
            if self._temporary:
                shutil.rmtree(self._folder, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        # a temporary folder never outlives its simulation; a named one keeps its last checkpoint
        if getattr(self, "_temporary", False) and getattr(self, "_session", None) is not None:
            self._session = None
            shutil.rmtree(self._folder, ignore_errors=True)

    # -- what it is ----------------------------------------------------------------------------

    @property
    def folder(self):
        """The run folder (scenario.toml, thermo.csv, snapshots/, checkpoints)."""
        return self._folder

    @property
    def time(self):
        """s of simulated time."""
        return self._live().time

    @property
    def step(self):
        return self._live().step

    @property
    def timestep(self):
        """s: the timestep in force."""
        return self._live().timestep

    @property
    def duration(self):
        """s: the run's whole length now."""
        return self._live().duration

    @property
    def ended(self):
        return self._live().ended

    @property
    def stage(self):
        """The index of the stage under way ([[stages]]; their count once past them)."""
        return self._live().stage

    @property
    def scenario_toml(self):
        """The run's scenario as it stands now (with every change), as TOML."""
        return self._live().scenario_toml()

    # -- the state, as numpy arrays (copies) ---------------------------------------------------

    def particles(self):
        """Every particle field: position, velocity, force, image (N, 2); angle, spin, torque,
        radius, mass, inertia, material, kind (0 free, 1 fixed, 2 moved), id (N,)."""
        return self._live().particles()

    positions = property(lambda self: self._field("position"), doc="m, (N, 2)")
    velocities = property(lambda self: self._field("velocity"), doc="m/s, (N, 2)")
    forces = property(lambda self: self._field("force"), doc="N, (N, 2)")
    angles = property(lambda self: self._field("angle"), doc="rad, (N,)")
    spins = property(lambda self: self._field("spin"), doc="rad/s, (N,)")
    torques = property(lambda self: self._field("torque"), doc="N m, (N,)")
    radii = property(lambda self: self._field("radius"), doc="m, (N,)")
    masses = property(lambda self: self._field("mass"), doc="kg, (N,)")
    kinds = property(lambda self: self._field("kind"), doc="(N,): 0 free, 1 fixed, 2 moved")
    materials = property(lambda self: self._field("material"),
                         doc="(N,): index into the scenario's materials")
    ids = property(lambda self: self._field("id"),
                   doc="(N,): identities (indices change as the engine renumbers)")

    def _field(self, name):
        return self._live().particle_field(name)

    def walls(self):
        """The wall segments: a, b, velocity, force (M, 2); angular_velocity, material (M,)."""
        return self._live().walls()

    def contacts(self):
        """Every touching contact: i, j (-1 for a wall), wall (-1 for a pair), overlap,
        overlap_rate, normal_force, tangential_force (K,); point, branch (centre of i to that of
        j, or to the wall's contact point), force (on i) (K, 2)."""
        return self._live().contacts()

    def groups(self):
        """The wall groups: {name: {"particles": indices, "segments": indices}}."""
        return self._live().groups()

    def thermo(self):
        """The thermo quantities now: energies (J), momentum, coordination, contacts, and the
        force on each wall group (N)."""
        return self._live().measures()

    def thermo_table(self, name="thermo.csv"):
        """A table of the run folder (thermo.csv: every row so far, with the energy ledger's
        columns when output.energy_ledger is on) as {column: numpy array}."""
        self._live().flush()
        return read_table(os.path.join(self._folder, name))

    def _live(self):
        s = getattr(self, "_session", None)
        if s is None:
            raise RuntimeError(f"this simulation was closed (its folder: {self._folder})")
        return s

    def __repr__(self):
        s = getattr(self, "_session", None)
        if s is None:
            return f"<talus.Simulation (closed), {self._folder}>"
        return f"<talus.Simulation t = {s.time:.6g} s, step {s.step}, {self._folder}>"


def resume(folder, *, threads=None, quiet=True):
    """Continues the run in `folder` from its last good checkpoint."""
    return Simulation.resume(folder, threads=threads, quiet=quiet)


def _threads(threads):
    if threads is None:
        return -1
    if int(threads) != threads or threads < 0:
        raise ValueError(f"threads = {threads!r}; allowed: 0 (all cores) or a count >= 1")
    return int(threads)
