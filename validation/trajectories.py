"""Trajectories of the native engine and of LAMMPS, read at full precision and diffed by id.

read_track (a native track.csv) and read_dump (a LAMMPS dump) both give
{time: {id: (x, y, vx, vy, omega)}}, LAMMPS' ids; differences() compares two of them at their
common times. read_lammps_thermo reads the thermo table of a LAMMPS log (all its runs).
"""
import numpy as np

from run_folder import dump_blocks


def read_track(path):
    """{time: {id: (x, y, vx, vy, omega)}} from a native track.csv (ids as LAMMPS': +1)."""
    with open(path) as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    column = {n: k for k, n in enumerate(names)}
    time = data[:, column["time"]]
    ids = (data[:, column["id"]].astype(int) + 1).tolist()
    state = data[:, [column[n] for n in ("x", "y", "vx", "vy", "omega")]].tolist()
    # the rows come in frames of one time each
    cuts = [0, *(np.flatnonzero(np.diff(time)) + 1).tolist(), len(time)]
    frames = {}
    for start, end in zip(cuts, cuts[1:]):
        frames.setdefault(float(time[start]), {}).update(
            zip(ids[start:end], map(tuple, state[start:end])))
    return frames


def read_dump(path, dt):
    """The same from a LAMMPS dump of `id type radius mass x y vx vy omegaz`, keyed by time."""
    frames = {}
    for step, columns, rows in dump_blocks(path):
        at = [columns.index(c) for c in ("x", "y", "vx", "vy", "omegaz")]
        ids = rows[:, columns.index("id")].astype(int).tolist()
        frames[step * dt] = dict(zip(ids, map(tuple, rows[:, at].tolist())))
    return frames


def read_lammps_thermo(path):
    """The thermo table of a LAMMPS log, as a dict of arrays by column: every run's rows in
    order (a deck in stages runs once per stage), the row a run repeats from the one before
    left out. The runs must print the same columns."""
    with open(path) as f:
        lines = f.read().splitlines()
    names, rows = None, []
    for start, line in enumerate(lines):
        if line.split()[:2] != ["Step", "Time"]:
            continue
        if names is not None and line.split() != names:
            raise ValueError(f"{path}: runs with other thermo columns ({line.split()} after "
                             f"{names})")
        names = line.split()
        for row in lines[start + 1:]:
            words = row.split()
            if len(words) != len(names):
                break
            try:
                values = [float(w) for w in words]
            except ValueError:
                break
            if rows and values[0] <= rows[-1][0]:
                continue  # the run's first row: the step the one before ended on
            rows.append(values)
    table = np.array(rows)
    return {n: table[:, k] for k, n in enumerate(names)}


def align(a, b, dt):
    """The frames of a and b at common times (to within a hundredth of a step)."""
    keys_b = {round(t / dt): t for t in b}
    pairs = []
    for t in sorted(a):
        s = round(t / dt)
        if s in keys_b:
            pairs.append((s * dt, a[t], b[keys_b[s]]))
    return pairs


def differences(a, b, dt, radius):
    """Times, the largest and the RMS position difference (mean radii) of trajectories a and b."""
    times, largest, rms = [], [], []
    for t, fa, fb in align(a, b, dt):
        ids = sorted(set(fa) & set(fb))
        if not ids:
            continue
        d = np.array([np.hypot(fa[i][0] - fb[i][0], fa[i][1] - fb[i][1]) for i in ids]) / radius
        times.append(t)
        largest.append(d.max())
        rms.append(np.sqrt(np.mean(d * d)))
    return np.array(times), np.array(largest), np.array(rms)
