"""The statistics of a long case, measured the same way in a native run folder and in a LAMMPS
run made into one (run_folder.py), each as a value, its one-standard-error uncertainty and the
degrees of freedom behind that (the pass rule compares two by Welch's t: welch, t_bound).

A case's tolerances.toml lists them as [[measures]] tables:

- `analysis` + `value` (+ `error`, + `error_dof`): run `talus analyze DIR ANALYSIS [options]` and
  read a number of its JSON, "forces.json:beta", with its error "forces.json:beta_error" and the
  degrees of freedom behind that (blocks - 1 for an error from blocks; infinite if not given);
- `analysis` + `series`: a column of its CSV, "segregation.csv:index", averaged over `window`
  with the standard error of `blocks` block averages;
- `analysis = "frost"` + `cycle` K + `quantity`: from `talus analyze DIR frost`, which samples
  the bed at rest before each freeze, sample K's "stone_height" (the stones' mean centre height
  above the bed's bottom, m) or "sorting_index" ((mean stone height - mean fine height) / bed
  height); one number per run, so its error is the seeds' scatter;
- `packing`: the area fraction of the free grains in `region` = [x0, y0, x1, y1], averaged over
  the snapshots in `window`, with the standard error over `strips` equal vertical strips of the
  region (a static packing's snapshots are not independent; its strips nearly are).
"""
import csv
import functools
import json
import math
import os
import subprocess

import numpy as np
from scipy import stats

from run_folder import data_array, pvd_entries, read_frames


def welch(a, b):
    """Welch's t of two estimates (value, standard error, degrees of freedom) and its degrees of
    freedom by the Welch-Satterthwaite rule (an error of 0, or infinite degrees of freedom,
    adds nothing to the sum of the fourth powers)."""
    var = a[1] ** 2 + b[1] ** 2
    t = abs(a[0] - b[0]) / max(math.sqrt(var), 1e-300)
    fourth = sum(e ** 4 / dof for _, e, dof in (a, b) if e > 0.0 and math.isfinite(dof))
    return t, (var * var / fourth if fourth > 0.0 else math.inf)


def t_bound(z_max, dof):
    """The |t| of Student's distribution with `dof` degrees of freedom that is exceeded as
    rarely as a normal |z| of z_max (two-sided): the pass rule "within z_max errors" with the
    false-alarm rate it states, however few the blocks or seeds behind the errors."""
    if math.isinf(dof):
        return float(z_max)
    return float(stats.t.isf(stats.norm.sf(z_max), dof))


def combined(estimates):
    """The mean of several runs' estimates (value, error, dof) and its error: the larger of the
    runs' own errors combined and their scatter (the standard error of the mean), with the
    degrees of freedom of the one taken (Welch-Satterthwaite for the combined own errors,
    runs - 1 for the scatter)."""
    v = np.array([e[0] for e in estimates], dtype=float)
    n = len(v)
    own = math.sqrt(sum(e[1] ** 2 for e in estimates)) / n
    fourth = sum(e[1] ** 4 / e[2] for e in estimates if e[1] > 0.0 and math.isfinite(e[2]))
    own_dof = (own * n) ** 4 / fourth if fourth > 0.0 else math.inf
    scatter = float(v.std(ddof=1) / math.sqrt(n)) if n > 1 else 0.0
    if scatter > own:
        return float(v.mean()), scatter, float(n - 1)
    return float(v.mean()), own, own_dof


def block_mean(t, x, lo, hi, blocks):
    """The mean of x over t in [lo, hi], its standard error from `blocks` block averages
    (blocks long against the correlation time keep the error honest), and its degrees of
    freedom, blocks - 1."""
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    x = x[(t >= lo) & (t <= hi) & np.isfinite(x)]
    if len(x) < blocks:
        raise ValueError(f"{len(x)} samples in [{lo}, {hi}] s, fewer than {blocks} blocks")
    means = np.array([b.mean() for b in np.array_split(x, blocks)])
    return float(means.mean()), float(means.std(ddof=1) / np.sqrt(blocks)), float(blocks - 1)


def disk_area_in_box(cx, cy, r, x0, y0, x1, y1, samples=1024):
    """Areas of the disks (arrays cx, cy, r) inside [x0, x1] x [y0, y1]: the chord's part inside
    [y0, y1] integrated over x by the midpoint rule (the square-root ends of the chord make the
    error fall as samples^-1.5: below 2e-5 of the area at 1024 samples, far below a packing's
    strip-to-strip scatter)."""
    u = (np.arange(samples) + 0.5) / samples * 2.0 - 1.0  # across the disk, in radii
    x = cx[:, None] + r[:, None] * u[None, :]
    h = r[:, None] * np.sqrt(1.0 - u * u)[None, :]
    inside = np.clip(np.minimum(cy[:, None] + h, y1) - np.maximum(cy[:, None] - h, y0), 0, None)
    inside[(x < x0) | (x > x1)] = 0.0
    return inside.sum(axis=1) * (2.0 * r / samples)


def in_window(t, window):
    return window[0] - 1e-9 <= t <= window[1] + 1e-9


def strip_mean(per_strip, where):
    """The mean over the strips of the rows' average (one row of strips per snapshot), its
    standard error over the strips, and its degrees of freedom, strips - 1."""
    if not per_strip:
        raise ValueError(f"{where}: no snapshot in the window")
    v = np.mean(per_strip, axis=0)
    return float(v.mean()), float(v.std(ddof=1) / np.sqrt(len(v))), float(len(v) - 1)


@functools.lru_cache(maxsize=8)
def frames_of(folder):
    """A run folder's frames, read once however many measures look at them."""
    return read_frames(folder)


def packing_fraction(frames, region, strips, window):
    """The free grains' area fraction in `region`, per strip, averaged over the frames in
    `window`: the mean over the strips and its standard error."""
    x0, y0, x1, y1 = region
    edges = np.linspace(x0, x1, strips + 1)
    per_strip = []
    for t, f in frames:
        if not in_window(t, window):
            continue
        free = f["kind"] == 0
        cx, cy, r = f["x"][free], f["y"][free], f["radius"][free]
        per_strip.append([disk_area_in_box(cx, cy, r, a, y0, b, y1).sum() / ((b - a) * (y1 - y0))
                          for a, b in zip(edges[:-1], edges[1:])])
    return strip_mean(per_strip, f"packing fraction over {window} s")


def coordination(folder, region, strips, window):
    """Contacts per free grain (walls included) of the grains whose centres lie in `region`,
    per strip, from the snapshots' contacts in `window`: the mean over the strips and its
    standard error (a static packing's snapshots are one sample, as for packing_fraction)."""
    x0, y0, x1, y1 = region
    edges = np.linspace(x0, x1, strips + 1)
    per_strip = []
    for (t, f), (_, name) in zip(frames_of(folder),
                                 pvd_entries(os.path.join(folder, "contacts.pvd"))):
        if not in_window(t, window):
            continue
        path = os.path.join(folder, name)
        with open(path) as c:
            xml = c.read()
        touching = data_array(xml, "overlap", path) > 0.0
        ends = np.concatenate([data_array(xml, "particle", path)[touching],
                               data_array(xml, "partner", path)[touching]]).astype(int)
        ids, counts = np.unique(ends[ends >= 0], return_counts=True)
        count = dict(zip(ids, counts))
        z = np.array([count.get(i, 0) for i in f["id"]])
        inside = (f["kind"] == 0) & (f["y"] >= y0) & (f["y"] <= y1)
        per_strip.append([z[inside & (f["x"] >= a) & (f["x"] < b)].mean()
                          for a, b in zip(edges[:-1], edges[1:])])
    return strip_mean(per_strip, f"{folder}: coordination over {window} s")


def analyze(talus, folder, analysis, options):
    """Runs `talus analyze` once per (folder, analysis, options)."""
    done = os.path.join(folder, "analysis", f".{analysis}{'_'.join(options)}.done")
    if not os.path.exists(done):
        result = subprocess.run([talus, "analyze", folder, analysis, *options],
                                capture_output=True, text=True)
        if result.returncode != 0:
            raise RuntimeError(f"talus analyze {folder} {analysis} failed:\n{result.stderr}")
        open(done, "w").close()


def read_column(path, column):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows or column not in rows[0]:
        raise ValueError(f"{path}: no column '{column}'")
    time = np.array([float(r["time"]) for r in rows])
    value = np.array([float(r[column]) if r[column] not in ("", "nan") else np.nan
                      for r in rows])
    return time, value


def measure(spec, folder, talus):
    """(value, standard error, degrees of freedom) of one [[measures]] table in one run folder
    (an exact sample, or a fit's error from its counts: infinite degrees of freedom)."""
    if "packing" in spec:
        p = spec["packing"]
        return packing_fraction(frames_of(folder), p["region"], p["strips"], spec["window"])
    if "coordination" in spec:
        p = spec["coordination"]
        return coordination(folder, p["region"], p["strips"], spec["window"])
    options = list(spec.get("options", []))
    analyze(talus, folder, spec["analysis"], options)
    out = os.path.join(folder, "analysis")
    if "cycle" in spec:
        return frost_sample(out, spec["quantity"], spec["cycle"]), 0.0, math.inf
    if "series" in spec:
        name, column = spec["series"].split(":")
        t, x = read_column(os.path.join(out, name), column)
        return block_mean(t, x, spec["window"][0], spec["window"][1], spec["blocks"])
    name, key = spec["value"].split(":")
    with open(os.path.join(out, name)) as f:
        value = json.load(f)[key]
    error = 0.0
    if "error" in spec:
        name, key = spec["error"].split(":")
        with open(os.path.join(out, name)) as f:
            error = json.load(f)[key]
    # an error from blocks of one run has blocks - 1 degrees of freedom (error_dof); a fit's
    # from its counts, or an exact sample, infinitely many
    return float(value), float(error), float(spec.get("error_dof", math.inf))


def frost_sample(out, quantity, cycle):
    """One number of `talus analyze DIR frost`'s sample `cycle` (analysis/frost.csv, .json)."""
    if quantity == "sorting_index":
        with open(os.path.join(out, "frost.json")) as f:
            index = json.load(f)["sorting_index"]
        if cycle >= len(index):
            raise ValueError(f"{out}: {len(index)} frost samples, no sample {cycle}")
        return float(index[cycle])
    if quantity != "stone_height":
        raise ValueError(f"frost quantity '{quantity}': allowed: stone_height, sorting_index")
    with open(os.path.join(out, "frost.csv")) as f:
        heights = [float(r["height"]) for r in csv.DictReader(f)
                   if r["role"] == "stone" and int(r["cycle"]) == cycle]
    if not heights:
        raise ValueError(f"{out}/frost.csv: no stone at sample {cycle}")
    return float(np.mean(heights))
