"""Analyses of a run folder, as `talus analyze` makes them, returned as numbers."""
import glob
import json
import os

import numpy as np

from . import _talus


def analyze(folder, what, *, frames="all", start=None, bins=0, cell=0.0, axis="y",
            kernel="gaussian", width=0.0, map=False):
    """Runs one analysis of a run folder (thermo, forces, profiles, tracks, segregation, frost,
    contacts, repose, fields, janssen, jamming, rheology, chute) as `talus analyze FOLDER WHAT` does,
    with its options (start is --from; axis, kernel, width and map are the fields'), writing
    FOLDER/analysis, and returns
    {"title", "summary", "numbers": {label: text}, "charts": [paths], "data": {name: the JSON
    of key numbers it wrote}}."""
    folder = os.fspath(folder)
    out = os.path.join(folder, "analysis")
    before = {p: os.path.getmtime(p) for p in glob.glob(os.path.join(out, "*.json"))}
    if axis not in ("x", "y"):
        raise ValueError(f"axis {axis!r}; allowed: x, y")
    r = _talus.analyze(folder, what, frames, -1.0 if start is None else float(start), int(bins),
                       float(cell), axis, kernel, float(width), bool(map))
    data = {}
    for p in sorted(glob.glob(os.path.join(out, "*.json"))):
        if p not in before or os.path.getmtime(p) != before[p]:
            with open(p) as f:
                data[os.path.splitext(os.path.basename(p))[0]] = json.load(f)
    return {
        "title": r["title"],
        "summary": r["summary"],
        "numbers": dict(r["numbers"]),
        "charts": [str(c) for c in r["charts"]],
        "data": data,
    }


def read_table(path):
    """A CSV file of a run folder (thermo.csv, track.csv, ...) as {column: numpy array}."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if rows.size == 0:
        return {h: np.empty(0) for h in header}
    return {h: rows[:, k] for k, h in enumerate(header)}
