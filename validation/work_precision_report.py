"""What the work-precision runs say: the timestep each engine needs for an error, the fitted
order, the charts and index.html (validation/work_precision.py measures, this reports).
"""
import html
import math
import os

import numpy as np

TARGETS = [1e-2, 1e-3, 1e-4]
COLOURS = {"native gear": "tab:blue", "native verlet": "tab:orange", "LAMMPS verlet": "tab:green"}


def fitted_order(rows, metric):
    """The slope of log error against log dt over the runs whose error is above rounding."""
    pts = [(math.log(1.0 / r["factor"]), math.log(r[metric])) for r in rows if r[metric] > 1e-13]
    if len(pts) < 3:
        return float("nan")
    x, y = np.array(pts).T
    return float(np.polyfit(x, y, 1)[0])


def needed(rows, metric, target):
    """(t_c / dt, cost per simulated s) at which the error falls to `target`, interpolated in
    log-log between the last run above it and the first below; None when no run reaches it."""
    rows = sorted(rows, key=lambda r: r["factor"])
    for a, b in zip(rows, rows[1:]):
        if a[metric] > target >= b[metric] > 0.0:
            f = (math.log(target) - math.log(a[metric])) / (math.log(b[metric]) -
                                                              math.log(a[metric]))
            factor = math.exp(math.log(a["factor"]) + f * (math.log(b["factor"]) -
                                                          math.log(a["factor"])))
            cost = math.exp(math.log(a["cost_per_second"]) + f * (
                math.log(b["cost_per_second"]) - math.log(a["cost_per_second"])))
            return factor, cost
    if rows and rows[0][metric] <= target:
        return rows[0]["factor"], rows[0]["cost_per_second"]
    return None


def by_engine(problem):
    out = {}
    for r in problem.rows:
        out.setdefault(r["engine"], []).append(r)
    return out


def chart(problem, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(problem.metrics), figsize=(5 * len(problem.metrics), 4.2),
                             squeeze=False)
    for ax, metric in zip(axes[0], problem.metrics):
        engines = by_engine(problem)
        for engine, colour in COLOURS.items():
            if engine not in engines:
                continue
            rows = sorted(engines[engine], key=lambda r: r["factor"])
            pts = [(r["cost_per_second"], max(r[metric], 1e-16), r["factor"]) for r in rows
                   if not math.isnan(r[metric])]
            if not pts:
                continue
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", ms=4, label=engine,
                      color=colour)
            for c, e, f in pts:
                ax.annotate(f"{f:g}", (c, e), fontsize=6, xytext=(2, 2),
                            textcoords="offset points")
        ax.set_xlabel("cost [CPU s per simulated s]")
        ax.set_ylabel(f"relative error in {metric.replace('_', ' ')} [-]")
        ax.legend(fontsize=7, title="labels: t_c / dt", title_fontsize=7)
    fig.suptitle(problem.name)
    fig.tight_layout()
    path = os.path.join(out, f"{problem.name}.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def page(problems, out):
    import base64
    parts = ["<!doctype html><meta charset='utf-8'><title>talus work-precision</title>",
             "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
             "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}</style>",
             "<h1>Work-precision</h1><p>validation/work_precision.py: relative error against "
             "cost for each integrator; t_c is the collision time.</p>"]
    for p in problems:
        with open(chart(p, out), "rb") as f:
            img = base64.b64encode(f.read()).decode()
        parts.append(f"<h2>{html.escape(p.name)}</h2><img src='data:image/png;base64,{img}'>")
        head = "".join(f"<th>{html.escape(m)} error</th>" for m in p.metrics)
        parts.append(f"<table><tr><th>engine</th><th>t_c / dt</th>{head}<th>CPU s per "
                     "simulated s</th><th>s per particle-step</th></tr>")
        for r in sorted(p.rows, key=lambda r: (r["engine"], r["factor"])):
            cells = "".join(f"<td>{r[m]:.2e}</td>" for m in p.metrics)
            parts.append(f"<tr><td>{r['engine']}</td><td>{r['factor']:g}</td>{cells}"
                         f"<td>{r['cost_per_second']:.3g}</td>"
                         f"<td>{r['cost_per_particle_step']:.3g}</td></tr>")
        parts.append("</table>")
        parts.append(needed_table(p))
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write("\n".join(parts))


def needed_table(p):
    metric = p.metrics[0]
    rows = ["<p>The timestep each engine needs for a " + html.escape(metric.replace("_", " ")) +
            " error of ...</p><table><tr><th>engine</th>" +
            "".join(f"<th>{t:g}: t_c / dt (cost)</th>" for t in TARGETS) + "</tr>"]
    for engine, rs in by_engine(p).items():
        cells = []
        for t in TARGETS:
            n = needed(rs, metric, t)
            cells.append(f"<td>{n[0]:.0f} ({n[1]:.3g})</td>" if n else "<td>not reached</td>")
        rows.append(f"<tr><td>{engine}</td>{''.join(cells)}</tr>")
    if p.name == "settling_1000":
        for engine, rs in by_engine(p).items():
            rows.append(f"<tr><td>{engine}: fitted order, position / energy</td><td>"
                        f"{fitted_order(rs, 'position'):.2f} / {fitted_order(rs, 'energy'):.2f}"
                        "</td></tr>")
    return "".join(rows) + "</table>"


def summarise(problems):
    for p in problems:
        metric = p.metrics[0]
        for engine, rs in by_engine(p).items():
            found = []
            for t in TARGETS:
                n = needed(rs, metric, t)
                found.append(f"{t:g}: t_c/{n[0]:.0f} at {n[1]:.3g} CPU s/s" if n else
                             f"{t:g}: not reached")
            print(f"{p.name} {engine}: {metric} error " + "; ".join(found))
            if p.name == "settling_1000":
                print(f"{p.name} {engine}: fitted order {fitted_order(rs, 'position'):.2f} "
                      f"(position), {fitted_order(rs, 'energy'):.2f} (energy)")
