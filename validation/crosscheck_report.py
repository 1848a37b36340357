"""The cross-check's charts and its summary page (validation/crosscheck.py writes them)."""
import html
import os

import numpy as np


def force_chart(name, out, folders):
    """P(f/<f>) of the engines on one chart (talus analyze's forces.csv of each)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 4))
    for label, folder in folders.items():
        data = np.genfromtxt(os.path.join(folder, "analysis", "forces.csv"), delimiter=",",
                             names=True)
        data = data[data["count"] > 0]
        ax.semilogy(data["f_over_mean"], data["probability_density"], "o-", ms=3,
                    label=label)
    ax.set_xlabel("f / <f>")
    ax.set_ylabel("P(f / <f>)")
    ax.set_title(f"{name}: normal contact forces", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "force_distribution.png"), dpi=110)
    plt.close(fig)


def statistics_chart(out, stats):
    """The statistics of the engines side by side: each quantity's values with their errors."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(stats), figsize=(3.5 * len(stats), 3.5),
                             squeeze=False)
    for ax, (quantity, values) in zip(axes[0], stats):
        labels = list(values)
        ax.errorbar(range(len(labels)), [values[k][0] for k in labels],
                    yerr=[values[k][1] for k in labels], fmt="o", capsize=6)
        ax.set_xticks(range(len(labels)),
                      [k.replace("native ", "native\n") for k in labels], fontsize=8)
        ax.set_xlim(-0.5, len(labels) - 0.5)
        ax.set_title(quantity, fontsize=9, wrap=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "statistics.png"), dpi=110)
    plt.close(fig)


def difference_chart(name, out, curves):
    """The largest position difference against time, a curve per comparison."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for label, (t, largest) in curves.items():
        ax.semilogy(t, np.maximum(largest, 1e-18), label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("largest position difference (mean radii)")
    ax.set_title(name)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "position_difference.png"), dpi=110)
    plt.close(fig)


def summary(cases, out):
    """index.html: a row per comparison of every case, with its charts."""
    rows = []
    # a row with no bound (passed None) is a measurement: it is shown, and never as a pass
    verdict = {True: ("ok", "pass"), False: ("fail", "FAIL"), None: ("info", "measured")}
    for c in cases:
        for what, value, bound, passed, note in c.rows:
            rows.append(f"<tr><td>{html.escape(c.name)}</td><td>{html.escape(what)}</td>"
                        f"<td>{value:.3e}</td><td>{'reported' if bound != bound else f'{bound:g}'}</td><td>{html.escape(note)}</td>"
                        f"<td class={verdict[passed][0]}>{verdict[passed][1]}</td></tr>")
        speeds = ", ".join(f"{k}: {v * 1e9:.0f} ns" for k, v in c.speeds.items())
        rows.append(f"<tr><td colspan=6>{html.escape(c.name)}: wall time per particle-step "
                    f"(whole runs, start-up included): {html.escape(speeds)}<br>"
                    f"<img src='{html.escape(c.name)}/position_difference.png'>"
                    + (f"<img src='{html.escape(c.name)}/statistics.png'>" if c.stats else "")
                    + (f"<img src='{html.escape(c.name)}/force_distribution.png'>"
                       if os.path.exists(os.path.join(c.out, "force_distribution.png")) else "")
                    + "</td></tr>")
    page = ("<!doctype html><meta charset=utf-8><title>talus cross-check</title><style>"
            "body{font-family:sans-serif}td,th{padding:3px 8px;border-bottom:1px solid #ccc}"
            ".ok{color:green}.fail{color:red;font-weight:bold}.info{color:#555}</style>"
            "<h1>talus against LAMMPS: the cross-check</h1>"
            "<p>Position differences in mean radii; bounds from each case's tolerances.toml."
            "</p><table><tr><th>case</th><th>comparison</th><th>largest</th><th>bound</th>"
            "<th></th><th></th></tr>" + "".join(rows) + "</table>")
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page)
