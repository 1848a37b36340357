#!/usr/bin/python3
"""Cross-check: the same case in the native engine and in LAMMPS, trajectories diffed.

    /usr/bin/python3 validation/crosscheck.py [CASE ...] [--quick] [--build build] [--out DIR]

A case is a folder of inputs/validation/ with the native scenario.toml (or the name of one),
tolerances.toml (the bound of each comparison, with its reason) and lammps/, the deck `talus
export lammps` writes of it (`--write-decks` writes it again; every run checks that it is still
the deck export writes). Each case runs in:

- the native engine with velocity Verlet and LAMMPS' damper velocity (verlet_velocity =
  half_step), with that and a skin of a mean radius (other lists, so other summation orders),
  with velocity Verlet and the native default (predicted), and with Gear;
- LAMMPS with pair_style granthesis (talus-lmp), on 1 rank and on 2, from the deck that
  `talus export lammps` writes of the same scenario;
- where tolerances.toml says `gran_hooke = true` or `granular = true`, LAMMPS' own gran/hooke or
  pair_style granular (with fix wall/gran) in place of granthesis, independent of src/talus
  (validation/independent.py), against the native engine with their conventions.

Every grain is tracked at full precision in both (track.csv, the LAMMPS dump); the trajectories
are compared by id at the common times: the largest and the RMS position difference, in mean
radii, against time. While native Verlet (half step) and LAMMPS agree to rounding, their thermo
rows must count the same contacts, and the uniform frost rule must freeze at the same steps.

Long cases are also compared by their statistics, each with its standard error: [statistics]
(thermo columns, block averages over a window) and [[measures]] (validation/measures.py: the
packing fraction, the coordination, and any number `talus analyze` gives, P(f/<f>)'s tail and the
segregation index among them), taken by the same code from the native snapshots and from the
LAMMPS run made into a talus run folder (validation/run_folder.py), over the case's seed and
those of [analysis] seeds: native Verlet (half step) must pass Welch's t test against LAMMPS
(measures.t_bound); native Gear is reported. A comparison with no bound is a measurement.

The summary (index.html, opening offline) and charts go to --out; a line per comparison is
printed as it goes; the exit status is 1 if any comparison fails its bound (docs/validation.md).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time
import tomllib

import numpy as np

from crosscheck_report import difference_chart, force_chart, statistics_chart, summary
from independent import gran_hooke_lines, granular_lines, rewrite_deck
from mutations import MUTATIONS, NATIVE_MUTATIONS, mutate_deck
from measures import block_mean, combined, measure, t_bound, welch
from run_folder import add_analysis_dumps, first_frame, frost_heaves, lammps_run_folder
from trajectories import differences, read_dump, read_lammps_thermo, read_track

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = os.path.join(ROOT, "inputs", "validation")
# the cases the default test suite runs (seconds each on 2 cores)
QUICK = {"two_disks_linear_headon", "two_disks_linear_oblique", "two_disks_hertz_headon",
         "two_disks_hertz_oblique", "two_disks_hooke_oblique", "collisions", "settling_1000",
         "walls_hertz_mindlin", "drum_linear_cundall", "two_disks_granular_oblique"}
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")


def mark(passed):
    """The printed mark of a row: a check that passed or failed, or a measurement reported with
    no bound to hold (passed is None), which can neither pass nor fail."""
    return {True: "ok  ", False: "FAIL", None: "info"}[passed]


def run(command, cwd=None):
    """Runs a command; returns its wall time, or exits with what it printed."""
    start = time.monotonic()
    done = subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stdout[-3000:]}"
                 f"\n{done.stderr[-3000:]}")
    return time.monotonic() - start


class Case:
    def __init__(self, name, out, build, mutation=None):
        self.name, self.folder = name, os.path.join(CASES, name)
        self.mutation = mutation  # a key of MUTATIONS, or None
        self.out = os.path.join(out, name)
        self.talus = os.path.join(build, "native", "talus")
        self.lmp = os.path.join(build, "lammps-package", "talus-lmp")
        with open(os.path.join(self.folder, "tolerances.toml"), "rb") as f:
            self.tolerances = tomllib.load(f)
        # the scenario: the case's own, or one it names (a built-in experiment's)
        self.scenario_file = os.path.normpath(os.path.join(
            self.folder, self.tolerances.get("scenario", "scenario.toml")))
        with open(self.scenario_file, "rb") as f:
            self.scenario = tomllib.load(f)
        self.chaotic = self.tolerances["trajectory"].get("chaotic", False)
        # the exported deck's files are named after the scenario, not the case
        self.deck_name = self.scenario["name"]
        # settings of the case on top of its scenario, in every run and in the deck
        self.sets = self.tolerances.get("sets", [])
        # how often every grain is compared: the scenario's track interval, or the case's own
        # (a long case tracked at the scenario's would write millions of rows)
        self.track_interval = self.tolerances["trajectory"].get(
            "track_interval", self.scenario["output"]["track_interval"])
        # (comparison, value, bound, passed, note); passed None: a measurement, no check
        self.rows = []
        self.speeds = {}  # engine: wall seconds per particle-step
        self.lammps_logs = {}  # ranks: log.lammps
        self.native_thermo = {}  # label: thermo.csv
        self.native_folders = {}  # label: run folder
        self.stats = []  # (quantity, (native value, error), (LAMMPS value, error))
        # the snapshots the [[measures]] are taken from, at this interval in both engines
        self.analysis = self.tolerances.get("analysis")

    def native(self, label, sets):
        folder = os.path.join(self.out, label)
        shutil.rmtree(folder, ignore_errors=True)
        command = [self.talus, "run", self.scenario_file, "--out", folder,
                   "--quiet", "--threads", "1", "--set", "track.select=all", "--set",
                   f"output.track_interval={self.track_interval!r}"]
        for s in self.sets + sets:
            command += ["--set", s]
        wall = run(command)
        self.native_thermo[label] = os.path.join(folder, "thermo.csv")
        self.native_folders[label] = folder
        return read_track(os.path.join(folder, "track.csv")), wall, folder

    def export(self, name, sets, deck=None):
        """The deck `talus export lammps` writes of the case (with `sets`), for velocity Verlet
        with the half-step damper velocity, LAMMPS' scheme, into the case's results (or `deck`).
        Paths in the command are relative to the repository, as the deck's header repeats it."""
        deck = deck or os.path.join(self.out, name)
        shutil.rmtree(deck, ignore_errors=True)
        command = [os.path.relpath(self.talus, ROOT), "export", "lammps",
                   os.path.relpath(self.scenario_file, ROOT), os.path.relpath(deck, ROOT),
                   "--quiet", "--set", "simulation.integrator=verlet", "--set",
                   "simulation.verlet_velocity=half_step"]
        for s in self.sets + sets:
            command += ["--set", s]
        run(command, cwd=ROOT)
        return deck

    def write_deck(self):
        """The case's deck, committed beside its tolerances (inputs/validation/CASE/lammps)."""
        deck = self.export("lammps", [], os.path.join(self.folder, "lammps"))
        print(f"wrote {os.path.relpath(deck, ROOT)}")

    def compare_deck(self, deck):
        """The deck committed with the case must be the one `talus export lammps` writes now,
        file for file (but the header's line naming where it was written), so that it is what
        the cross-check ran."""
        committed = os.path.join(self.folder, "lammps")

        def text(folder, name):
            with open(os.path.join(folder, name)) as f:
                return [line for line in f if not line.startswith("# Written by: ")]

        names = sorted(os.listdir(deck))
        if not os.path.isdir(committed):
            differ = ["no deck committed"]
        elif sorted(os.listdir(committed)) != names:
            differ = [f"files {sorted(os.listdir(committed))} against {names}"]
        else:
            differ = [n for n in names if text(committed, n) != text(deck, n)]
        passed = not differ
        note = ("the same files" if passed else f"differs: {', '.join(differ)}; write it again "
                f"with validation/crosscheck.py --write-decks {self.name}")
        self.rows.append((f"inputs/validation/{self.name}/lammps is talus export's deck now",
                          float(len(differ)), 0.0, passed, note))
        print(f"{mark(passed)} {self.name}: committed LAMMPS deck: {note}")

    def lammps(self, ranks, deck_dir, every, name=None):
        folder = os.path.join(self.out, name or f"lammps-{ranks}")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(deck_dir, folder)
        if self.mutation in MUTATIONS and self.mutation not in NATIVE_MUTATIONS:
            mutate_deck(folder, self.deck_name, self.mutation, self.radius)
        command = ["mpirun", "--oversubscribe", "-np", str(ranks), self.lmp, "-in",
                   f"in.{self.deck_name}", "-var", "snapshot_every", str(every), "-log",
                   "log.lammps", "-screen", "none"]
        if ranks == 1 and self.analysis:
            # the snapshots for the [[measures]]: the grains and their contacts
            add_analysis_dumps(os.path.join(folder, f"in.{self.deck_name}"))
            command += ["-var", "analysis_every",
                        str(max(1, round(self.analysis["snapshot_interval"] / self.dt)))]
        wall = run(command, cwd=folder)
        if name is None:
            self.lammps_logs[ranks] = os.path.join(folder, "log.lammps")
        return read_dump(os.path.join(folder, f"dump.{self.deck_name}.lammpstrj"), self.dt), wall

    def compare(self, what, a, b, bound_key, kind):
        t, largest, rms = differences(a, b, self.dt, self.radius)
        bound = self.tolerances["trajectory"][bound_key]
        worst = float(largest.max()) if len(largest) else float("nan")
        if self.chaotic:
            # many grains: rounding grows exponentially; the pass rule is how long the engines
            # stay within the bound, and the report says when they part by 1% of a radius
            apart = t[largest > bound]
            since = float(apart[0]) if len(apart) else float(t[-1])
            need = self.tolerances["trajectory"].get(f"{kind}_until", 0.0)
            # no time to hold the bound until: what is measured is reported, not checked
            passed = since >= need if need > 0.0 else None
            over = t[largest > 0.01]
            held = f"needed: {need:g} s" if need > 0.0 else "reported, no window to check"
            note = (f"within {bound:g} radii until t = {since:.4g} s ({held}); "
                    + (f"0.01 radii at t = {over[0]:.4g} s" if len(over) else
                       "below 0.01 radii throughout"))
        else:
            passed = bool(len(largest)) and worst <= bound
            note = f"over {len(t)} times to t = {t[-1]:.4g} s" if len(t) else "no common times"
        self.rows.append((what, worst, bound, passed, note))
        print(f"{mark(passed)} {self.name}: {what}: largest {worst:.3e} radii, "
              f"RMS at the end {rms[-1] if len(rms) else float('nan'):.3e} (bound {bound:g}; "
              f"{note})")
        return t, largest

    def run_all(self, ranks):
        os.makedirs(self.out, exist_ok=True)
        snapshots = ([f"output.snapshot_interval={self.analysis['snapshot_interval']!r}"]
                     if self.analysis else [])
        half, wall_h, folder = self.native("native-verlet-half_step",
                                           ["simulation.integrator=verlet",
                                            "simulation.verlet_velocity=half_step"] + snapshots
                                           + NATIVE_MUTATIONS.get(self.mutation, []))
        with open(os.path.join(folder, "run.json")) as f:
            info = json.load(f)
        self.dt, steps, n = info["timestep"], info["steps"], info["particles"]
        # the unit of the position differences: the free grains' mean radius, at the start
        first = first_frame(folder)
        self.radius = float(np.mean(first["radius"][first["kind"] == 0]))
        predicted, wall_p, _ = self.native("native-verlet-predicted",
                                           ["simulation.integrator=verlet",
                                            "simulation.verlet_velocity=predicted"])
        gear, wall_g, _ = self.native("native-gear", ["simulation.integrator=gear"] + snapshots)
        deck = self.export("deck", [])
        self.compare_deck(deck)
        every = max(1, round(self.track_interval / self.dt))
        curves = {}
        lmp1, wall_l1 = self.lammps(1, deck, every)
        curves["Verlet (half step) - LAMMPS"] = self.compare(
            "native Verlet (half_step) against LAMMPS granthesis, 1 rank", half, lmp1,
            "rounding", "rounding")
        self.compare_coordination(*curves["Verlet (half step) - LAMMPS"])
        if self.scenario.get("frost", {}).get("model") == "uniform":
            self.compare_freezes(*curves["Verlet (half step) - LAMMPS"])
        if ranks > 1:
            lmp2, _ = self.lammps(ranks, deck, every)
            curves[f"LAMMPS 1 - {ranks} ranks"] = self.compare(
                f"LAMMPS on 1 rank against {ranks}", lmp1, lmp2, "rounding", "rounding")
        curves["Verlet: predicted - half step"] = self.compare(
            "native Verlet, predicted against half_step damper velocity", predicted, half,
            "integrators", "integrators")
        curves["Gear - Verlet"] = self.compare("native Gear against Verlet (half_step)", gear,
                                               half, "integrators", "integrators")
        # another skin gives other lists, rebuilt at other steps, so the forces on a grain are
        # summed in another order: rounding, as LAMMPS against the native engine
        skin, _, _ = self.native("native-verlet-half_step-skin",
                                 ["simulation.integrator=verlet",
                                  "simulation.verlet_velocity=half_step",
                                  f"simulation.skin={self.radius!r}"])
        curves["Verlet: skin of a mean radius - automatic"] = self.compare(
            "native Verlet (half_step), a skin of a mean radius against the automatic one", skin,
            half, "rounding", "rounding")
        for style, key in (("gran/hooke", "gran_hooke"), ("granular", "granular")):
            if self.tolerances["trajectory"].get(key, False):
                curves.update(self.independent(deck, every, half, style))
        if "statistics" in self.tolerances:
            self.statistics()
        if "measures" in self.tolerances:
            self.measures()
        if self.stats:
            statistics_chart(self.out, self.stats)
        for engine, wall in (("native Verlet", wall_h), ("native Gear", wall_g),
                             ("LAMMPS granthesis", wall_l1)):
            self.speeds[engine] = wall / max(1, steps * n)
        difference_chart(self.name, self.out, curves)
        return all(r[3] is not False for r in self.rows)

    def rounding_until(self, t, largest):
        """The first time the trajectories differ by more than the rounding bound (or never)."""
        apart = t[largest > self.tolerances["trajectory"]["rounding"]]
        return float(apart[0]) if len(apart) else float("inf")

    def compare_coordination(self, t, largest):
        """While native Verlet (half step) and LAMMPS agree to rounding, their thermo rows must
        count the same contacts: the coordination (walls included) at every common time, to the
        digits the native thermo.csv prints (6 decimals)."""
        until = self.rounding_until(t, largest)
        native = np.genfromtxt(self.native_thermo["native-verlet-half_step"], delimiter=",",
                               names=True)
        lammps = read_lammps_thermo(self.lammps_logs[1])
        # c_coordination, or v_coordination where wall segments add their contacts
        column = lammps.get("c_coordination", lammps.get("v_coordination"))
        at = {round(x / self.dt): z for x, z in zip(lammps["Time"], column)}
        # at a freeze's step the native row is the bed before the heave, LAMMPS' (thermo comes
        # after fix frost/heave's end_of_step) the bed after it
        heaves = {round(x / self.dt) for _, x in frost_heaves(self.lammps_logs[1])}
        pairs = [(z, at[round(x / self.dt)]) for x, z in
                 zip(np.atleast_1d(native["time"]), np.atleast_1d(native["coordination"]))
                 if x < until and round(x / self.dt) in at and round(x / self.dt) not in heaves]
        worst = max((abs(a - b) for a, b in pairs), default=float("nan"))
        passed = bool(pairs) and worst <= 1e-6
        note = (f"{len(pairs)} thermo rows to t = {min(until, float(t[-1])):.4g} s; largest "
                f"coordination {max((a for a, _ in pairs), default=0.0):.4g}")
        self.rows.append(("coordination, native Verlet (half_step) against LAMMPS thermo", worst,
                          1e-6, passed, note))
        print(f"{mark(passed)} {self.name}: coordination against LAMMPS' thermo: "
              f"largest difference {worst:.3g} (bound 1e-06; {note})")

    def compare_freezes(self, t, largest):
        """The uniform frost rule's freezes: while native Verlet (half step) and LAMMPS agree to
        rounding, fix frost/heave must heave at the steps the native engine froze (the times
        as both write them, 9 digits); after that the two are reported."""
        until = self.rounding_until(t, largest)
        with open(os.path.join(self.native_folders["native-verlet-half_step"], "frost.csv")) as f:
            native = [float(line.split(",")[1]) for line in f.readlines()[1:]
                      if line.strip().endswith(",freeze")]
        lammps = [x for _, x in frost_heaves(self.lammps_logs[1])]
        early = [(a, b) for a, b in zip(native, lammps) if min(a, b) < until]
        worst = max((abs(a - b) for a, b in early), default=float("nan"))
        passed = bool(early) and worst <= 1e-9 * max(native[-1], 1e-300)
        note = (f"{len(early)} freezes before the trajectories part (t = "
                f"{min(until, float(t[-1])):.4g} s); in the whole run native {len(native)} at "
                f"{', '.join(f'{x:.4g}' for x in native)} s, LAMMPS {len(lammps)} at "
                f"{', '.join(f'{x:.4g}' for x in lammps)} s")
        self.rows.append(("freeze times, native Verlet (half_step) against LAMMPS fix frost/heave",
                          worst, 1e-9 * max(native[-1], 1e-300), passed, note))
        print(f"{mark(passed)} {self.name}: freeze times against fix frost/heave: "
              f"largest difference {worst:.3g} s ({note})")

    def independent(self, deck, every, half, style):
        """The case in LAMMPS' own `style` (validation/independent.py): the exported deck
        rewritten for it, against native Verlet (half step) with that style's conventions; for
        gran/hooke, whose lever arms are at the radius, also with the native default."""
        name = style.replace("/", "-")
        rewritten = os.path.join(self.out, f"deck-{name}")
        shutil.rmtree(rewritten, ignore_errors=True)
        shutil.copytree(deck, rewritten)
        # the mutations that outlive the rewriting (the masses, the walls' places: a plane goes
        # where its segment went), so that this comparison is shown to fail too
        if self.mutation in ("mass", "wall"):
            mutate_deck(rewritten, self.deck_name, self.mutation, self.radius)
        path = os.path.join(rewritten, f"in.{self.deck_name}")
        if style == "gran/hooke":
            rewrite_deck(path, gran_hooke_lines(self.name, self.scenario))
        else:
            rewrite_deck(path, *granular_lines(self.name, self.scenario, os.path.join(
                rewritten, f"masses.{self.deck_name}")))
        folder = os.path.join(self.out, f"lammps-{name}")
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(rewritten, folder)
        run([self.lmp, "-in", f"in.{self.deck_name}", "-var", "snapshot_every", str(every), "-log",
             "log.lammps", "-screen", "none"], cwd=folder)
        lmp = read_dump(os.path.join(folder, f"dump.{self.deck_name}.lammpstrj"), self.dt)
        if style == "granular":  # its spins' velocity at the radius, its torques at R - xi/2
            native, _, _ = self.native("native-verlet-half_step-granular",
                                       ["simulation.integrator=verlet",
                                        "simulation.verlet_velocity=half_step",
                                        "simulation.lever_arm=granular"])
            return {"Verlet (lever arms granular) - granular": self.compare(
                "native Verlet (half_step, lever_arm = granular) against LAMMPS pair_style "
                "granular, fix wall/gran", native, lmp, "independent", "independent")}
        radius, _, _ = self.native("native-verlet-half_step-radius",
                                   ["simulation.integrator=verlet",
                                    "simulation.verlet_velocity=half_step",
                                    "simulation.lever_arm=radius"])
        return {
            "Verlet (lever arm R) - gran/hooke": self.compare(
                "native Verlet (half_step, lever_arm = radius) against LAMMPS gran/hooke",
                radius, lmp, "independent", "independent"),
            "Verlet (lever arm R - xi/2) - gran/hooke": self.compare(
                "native Verlet (half_step, lever_arm = contact_point) against LAMMPS gran/hooke",
                half, lmp, "conventions", "conventions"),
        }

    def z_rows(self, quantity, values, spec, where):
        """The rows of one statistic, each value (mean, standard error, degrees of freedom):
        native Verlet (half step), LAMMPS' scheme, against LAMMPS must pass Welch's t test at the
        false-alarm rate of a normal |z| of z_max (measures.t_bound: with few blocks or seeds
        the bound on t grows as Student's t says); native Gear against LAMMPS is reported
        (Gear's dampers see another velocity, which can shift a dissipative statistic: a
        settled packing's), and passes or fails only where the case sets gear_z_max."""
        lammps = values["LAMMPS"]
        self.stats.append((quantity, values))
        for label, bound_key in (("native Verlet (half_step)", "z_max"),
                                 ("native Gear", "gear_z_max")):
            a = values[label]
            t, dof = welch(a, lammps)
            z_max = spec.get(bound_key)
            bound = None if z_max is None else t_bound(z_max, dof)
            passed = None if bound is None else bool(t <= bound)
            rule = ("reported, no bound" if bound is None else
                    f"bound {bound:.3g}: Student's t at the two-sided rate of z = {z_max:g}")
            note = (f"{label} {a[0]:.4g} +- {a[1]:.2g}, LAMMPS {lammps[0]:.4g} +- "
                    f"{lammps[1]:.2g}{where}; Welch's t with {dof:.3g} degrees of freedom; "
                    f"{rule}")
            self.rows.append((f"{quantity}: Welch's t, {label} against LAMMPS", t,
                              float("nan") if bound is None else bound, passed, note))
            print(f"{mark(passed)} {self.name}: {quantity}: {label} against LAMMPS: t = {t:.2f} "
                  f"({note})")

    def statistics(self):
        """Time averages of thermo columns over the case's window, each with its standard error
        from block averages, of the native engine and LAMMPS (z_rows)."""
        spec = self.tolerances["statistics"]
        lo, hi = spec["window"]
        lammps = read_lammps_thermo(self.lammps_logs[1])
        where = f" over t in [{lo:g}, {hi:g}] s, {spec['blocks']} blocks"
        for quantity, column in spec["quantities"].items():
            values = {"LAMMPS": block_mean(lammps["Time"], lammps[column], lo, hi,
                                           spec["blocks"])}
            for label, run_label in (("native Verlet (half_step)", "native-verlet-half_step"),
                                     ("native Gear", "native-gear")):
                native = np.genfromtxt(self.native_thermo[run_label], delimiter=",", names=True)
                values[label] = block_mean(native["time"], native[quantity], lo, hi,
                                           spec["blocks"])
            self.z_rows(quantity, values, spec, where)

    def seed_runs(self, seed):
        """The run folders of the case with another seed: native Verlet (half step), native
        Gear, LAMMPS on 1 rank (made into a talus run folder)."""
        sets = [f"simulation.seed={seed}",
                f"output.snapshot_interval={self.analysis['snapshot_interval']!r}"]
        _, _, half = self.native(f"seed-{seed}/native-verlet-half_step",
                                 ["simulation.integrator=verlet",
                                  "simulation.verlet_velocity=half_step"] + sets)
        _, _, gear = self.native(f"seed-{seed}/native-gear", ["simulation.integrator=gear"] + sets)
        deck = self.export(f"seed-{seed}/deck", sets[:1])
        every = max(1, round(self.track_interval / self.dt))
        self.lammps(1, deck, every, name=f"seed-{seed}/lammps-1")
        lammps = lammps_run_folder(os.path.join(self.out, f"seed-{seed}", "lammps-1"), half,
                                   self.dt, os.path.join(self.out, f"seed-{seed}", "lammps-1-run"))
        return {"native Verlet (half_step)": half, "native Gear": gear, "LAMMPS": lammps}

    def measures(self):
        """The [[measures]] of tolerances.toml (validation/measures.py), taken by the same code
        from the native runs' snapshots and from the LAMMPS run's, made into a talus run folder,
        for the case's seed and each of [analysis] seeds; compared by z_rows. Over several seeds
        a value is the mean of the seeds' and its error the larger of two estimates: the seeds'
        own errors combined, and their scatter (the standard error of the mean)."""
        half = self.native_folders["native-verlet-half_step"]
        runs = [{"native Verlet (half_step)": half,
                 "native Gear": self.native_folders["native-gear"],
                 "LAMMPS": lammps_run_folder(os.path.join(self.out, "lammps-1"), half, self.dt,
                                             os.path.join(self.out, "lammps-1-run"))}]
        seeds = self.analysis.get("seeds", [])
        for seed in seeds:
            runs.append(self.seed_runs(seed))
        count = f", {len(runs)} seeds" if seeds else ""
        for spec in self.tolerances["measures"]:
            values = {label: combined([measure(spec, r[label], self.talus) for r in runs])
                      for label in runs[0]}
            where = (f" over t in [{spec['window'][0]:g}, {spec['window'][1]:g}] s"
                     if "window" in spec else "") + count
            self.z_rows(spec["name"], values, spec, where)
        if any(spec.get("analysis") == "forces" for spec in self.tolerances["measures"]):
            force_chart(self.name, self.out, runs[0])


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="*", help="case folders of inputs/validation (all if none)")
    parser.add_argument("--quick", action="store_true",
                        help="the quick cases only (those of the default test suite)")
    parser.add_argument("--ranks", type=int, default=2, help="LAMMPS' second run's ranks")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build folder")
    parser.add_argument("--out", default=os.path.join(ROOT, "validation", "results"))
    parser.add_argument("--mutate", choices=sorted(MUTATIONS),
                        help="put a small error into one engine, which the cross-check must "
                        "find: " + "; ".join(f"{k}: {v}" for k, v in MUTATIONS.items()))
    parser.add_argument("--write-decks", action="store_true",
                        help="write each case's LAMMPS deck into inputs/validation/CASE/lammps "
                        "(the committed deck every run checks) and run nothing")
    args = parser.parse_args()
    names = args.cases or sorted(os.listdir(CASES))
    if args.quick:
        names = [n for n in names if n in QUICK]
    unknown = [n for n in names if not os.path.isdir(os.path.join(CASES, n))]
    if unknown:
        sys.exit(f"no case {', '.join(unknown)} in {CASES}; cases: {', '.join(sorted(os.listdir(CASES)))}")
    if args.write_decks:
        for name in names:
            Case(name, args.out, args.build).write_deck()
        sys.exit(0)
    if shutil.which("mpirun") is None:
        print("mpirun not found (Debian package openmpi-bin): skipped")
        sys.exit(77)
    for tool in ("native/talus", "lammps-package/talus-lmp"):
        if not os.path.exists(os.path.join(args.build, tool)):
            print(f"{os.path.join(args.build, tool)} not built (the LAMMPS package needs Debian's "
                  "lammps and liblammps-dev): skipped")
            sys.exit(77)
    os.makedirs(args.out, exist_ok=True)
    cases, good = [], True
    for name in names:
        c = Case(name, args.out, args.build, args.mutate)
        good = c.run_all(args.ranks) and good
        cases.append(c)
    summary(cases, args.out)
    print(f"summary: {os.path.join(args.out, 'index.html')}")
    sys.exit(0 if good else 1)


if __name__ == "__main__":
    main()
