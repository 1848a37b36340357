# The charts of `talus analyze`, drawn with matplotlib (Debian's python3-matplotlib, Agg backend:
# no display needed). Compiled into talus; run as: python3 plots.py KIND CSV PNG [JSON].
import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

kind, source, target = sys.argv[1], sys.argv[2], sys.argv[3]
extra = json.load(open(sys.argv[4])) if len(sys.argv) > 4 else {}
rows = list(csv.DictReader(open(source)))


def col(key, rs=None):
    return [float(r[key]) for r in (rows if rs is None else rs)]


def by_id(rs):
    out = {}
    for r in rs:
        out.setdefault(r["id"], []).append(r)
    return out


if kind == "thermo":
    t = col("time")
    ledger = "energy_imbalance" in rows[0]  # output.energy_ledger
    fig, axes = plt.subplots(3 if ledger else 2, 1, figsize=(8, 10 if ledger else 7), sharex=True)
    a, b = axes[0], axes[-1]
    # a 3D run's thermo.csv names the kinetic energies kinetic and rotational
    three = "kinetic_translational" not in rows[0]
    for key, label in [("kinetic" if three else "kinetic_translational", "kinetic, translation"),
                       ("rotational" if three else "kinetic_rotational", "kinetic, rotation"),
                       ("elastic", "elastic"), ("total", "total")]:
        a.plot(t, col(key), label=label)
    a.set_ylabel("energy [J]")
    a.set_yscale("symlog", linthresh=1e-9)
    a.legend(fontsize=8)
    if ledger:  # where the energy went: E + dissipated - wall work stays at its start
        c = axes[1]
        start = float(rows[0]["total"])
        for key, label in [("dissipated_damper", "dissipated by the normal dampers"),
                           ("dissipated_friction", "dissipated by friction"),
                           ("wall_work", "work of the driven walls")]:
            c.plot(t, col(key), label=label)
        c.plot(t, [x - start for x in col("total")], label="total energy - its start")
        c.plot(t, col("energy_imbalance"), "k--", label="imbalance (the integration's error)")
        c.set_ylabel("energy [J]")
        c.legend(fontsize=8)
    # each quantity on its own axis: Z runs to 3 or more, the packing fraction below 1
    b.plot(t, col("coordination"), color="C0", label="coordination number Z")
    b.set_xlabel("time [s]")
    b.set_ylabel("coordination number Z [-]", color="C0")
    b2 = b.twinx()
    # 3D: the stress region's, with output.stress
    packing = next((k for k in ("packing_fraction", "region_packing_fraction") if k in rows[0]), None)
    if packing:
        b2.plot(t, col(packing), color="C1", label="packing fraction")
        b2.set_ylabel("packing fraction [-]", color="C1")
    else:
        b2.set_axis_off()
    lines = b.get_lines() + b2.get_lines()
    b.legend(lines, [l.get_label() for l in lines], fontsize=8)
elif kind == "forces":
    used = [r for r in rows if int(r["count"]) > 0]
    fig, a = plt.subplots(figsize=(7, 5))
    a.semilogy(col("f_over_mean", used), col("probability_density", used), "o", ms=4,
               label=f"{extra['contacts']} contacts")
    if extra["fit_bins"] >= 3:
        xs = [extra["fit_from"], extra["fit_to"]]
        c = extra["intercept"]
        a.semilogy(xs, [math.exp(c - extra["beta"] * v) for v in xs], "-",
                   label=f"exp(-beta f/<f>), beta = {extra['beta']:.2f} +- "
                         f"{extra['beta_error']:.2f}")
    a.set_xlabel("f / <f> [-]")
    a.set_ylabel("P(f / <f>) [-]")
    a.legend()
elif kind == "profiles":
    used = [r for r in rows if int(r["samples"]) > 0]
    x = col("x", used)
    fig, a = plt.subplots(figsize=(8, 5))
    a.plot(x, col("speed", used), "o-", label="|v|")
    a.plot(x, col("vx", used), "s-", label="v_x")
    a.plot(x, col("vy", used), "^-", label="v_y")
    a.axhline(0.0, color="grey", lw=0.5)
    a.set_xlabel("x [m]")
    a.set_ylabel("mean velocity [m/s]")
    a.set_title(f"band {extra['band'][0]:.3g} m <= y < {extra['band'][1]:.3g} m, "
                f"{extra['snapshots']} snapshots")
    a.legend()
elif kind == "discharge":
    t, n = col("time"), col("grains_below")
    fig, a = plt.subplots(figsize=(8, 5))
    a.plot(t, n, "o", ms=3, label="grains below the orifice")
    rate = extra.get("rate")
    if rate is not None:
        t0, t1, c = extra["window_from"], extra["window_to"], extra["intercept"]
        a.axvspan(t0, t1, color="tab:orange", alpha=0.12,
                  label=f"{extra['window']} window, {t0:.3g} to {t1:.3g} s")
        a.plot([t0, t1], [c + rate * t0, c + rate * t1], "-", color="tab:orange", lw=2,
               label=f"fit: {rate:.4g}" + ("" if extra["rate_error"] is None else
                                           f" ± {extra['rate_error']:.2g}") + " grains/s")
        a.set_title(f"{extra['passed']} grains through; {extra['end']} at the end")
    else:
        a.set_title(f"no rate: {extra.get('why_no_rate')}")
    a.set_xlabel("time [s]")
    a.set_ylabel("grains [-]")
    a.legend()
elif kind == "speed_map":
    import numpy as np
    nx, ny = extra["nx"], extra["ny"]
    v = np.full((ny, nx), np.nan)
    counts = sorted(int(r["samples"]) for r in rows if int(r["samples"]) > 0)
    least = max(3, 0.05 * counts[len(counts) // 2]) if counts else 1  # rarely visited: blank
    for r in rows:
        if int(r["samples"]) >= least:
            v[int(r["row"]), int(r["column"])] = float(r["mean_speed"])
    lo, hi, cell = extra["region"][:2], extra["region"][2:], extra["cell"]
    fig, a = plt.subplots(figsize=(7, 7 * min(2.0, max(0.4, ny / nx))))
    # a logarithmic scale: slow creep and stagnant zones stay visible beside free fall
    from matplotlib.colors import LogNorm
    top = np.nanmax(v) if np.isfinite(v).any() else 1.0
    top = top if top > 0 else 1.0
    m = a.imshow(np.clip(v, top * 1e-3, None), origin="lower", cmap="viridis",
                 interpolation="nearest", norm=LogNorm(vmin=top * 1e-3, vmax=top),
                 extent=[lo[0], lo[0] + nx * cell, lo[1], lo[1] + ny * cell])
    fig.colorbar(m, ax=a, label="mean |v| [m/s]")
    a.set_xlabel("x [m]")
    a.set_ylabel("y [m]")
    a.set_title(f"mean speed over {extra['snapshots']} snapshots (blank: rarely visited)")
elif kind == "tracks":
    tracks = by_id(rows)
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True,
                             layout="constrained" if len(tracks) > 10 else None)
    many = len(tracks) > 10  # a legend that long would cover the panels: a colour scale instead
    cmap = plt.get_cmap("viridis")
    ids = sorted(int(pid) for pid in tracks)
    norm = plt.Normalize(ids[0], max(ids[-1], ids[0] + 1))
    for k, (pid, rs) in enumerate(tracks.items()):
        t = col("time", rs)
        colour = cmap(norm(int(pid))) if many else f"C{k % 10}"
        # unwrapped positions: no sawtooth where a grain crosses a periodic boundary
        for a, key in zip(axes.flat, ["xu", "yu", "vx", "vy"]):
            a.plot(t, col(key, rs), label=f"id {pid}", color=colour, lw=0.6 if many else 1.5)
    for a, label in zip(axes.flat, ["x (unwrapped) [m]", "y (unwrapped) [m]", "v_x [m/s]",
                                    "v_y [m/s]"]):
        a.set_ylabel(label)
    axes[1][0].set_xlabel("time [s]")
    axes[1][1].set_xlabel("time [s]")
    if many:
        m = plt.cm.ScalarMappable(cmap=cmap, norm=norm)
        fig.colorbar(m, ax=axes, label=f"particle id ({len(ids)} tracked)")
    else:
        axes[0][0].legend(fontsize=7)
elif kind == "segregation":
    t = col("time")
    ledger = "energy_imbalance" in rows[0]  # output.energy_ledger
    fig, axes = plt.subplots(3 if ledger else 2, 1, figsize=(8, 10 if ledger else 7), sharex=True)
    a, b = axes[0], axes[-1]
    for k in range(extra["largest"]):
        a.plot(t, col(f"largest_{k}_height"), label=f"largest grain #{k + 1}")
    a.plot(t, col("bed_height"), "k--", label="bed height")
    a.set_ylabel("height above the bed's bottom [m]")
    a.legend(fontsize=8)
    b.plot(t, col("index"), label="segregation index")
    b.axhline(0.0, color="grey", lw=0.5)
    b.set_xlabel("time [s]")
    b.set_ylabel("(<h_large> - <h_small>) / H [-]")
    b.legend(fontsize=8)
elif kind == "repose":
    fig, a = plt.subplots(figsize=(8, 4.5))
    a.plot(col("x"), col("surface"), "k.-", lw=0.8, label="free surface (highest grain top)")
    for side in ("left", "right"):
        f = extra[side]
        if f["measured"]:
            used = [r for r in rows if r["flank"] == side]
            xs = col("x", used)
            a.plot(xs, [f["slope"] * x + f["intercept"] for x in xs], lw=2,
                   label=f"{side} flank: {f['angle_deg']:.1f} deg")
    a.axhline(extra["base"], color="grey", lw=0.5)
    a.set_aspect("equal", adjustable="datalim")
    a.set_xlabel("x [m]")
    a.set_ylabel("height [m]")
    a.set_title(f"angle of repose {extra['angle_deg']:.1f} deg" if extra["angle_deg"] is not None
                else "angle of repose not measured")
    a.legend(fontsize=8)
elif kind == "convection":
    used = [r for r in rows if int(r["samples"]) > 0]
    fig, a = plt.subplots(figsize=(8, 4.5))
    a.bar(col("x", used), col("drift", used), width=0.8 * extra["bin_width"])
    a.axhline(0.0, color="grey", lw=0.5)
    a.set_xlabel("x [m]")
    a.set_ylabel("mean vertical drift of small grains [m/s]")
elif kind == "frost":
    fig, (a, b, c) = plt.subplots(3, 1, figsize=(8, 10))
    for pid, rs in by_id(rows).items():
        style = "o-" if rs[0]["role"] == "stone" else ".:"
        label = (f"stone {pid}, R = {1e3 * float(rs[0]['radius']):.2f} mm"
                 if rs[0]["role"] == "stone" else None)
        a.plot(col("cycle", rs), col("height", rs), style, label=label)
    a.set_ylabel("height above the bed's bottom [m]")
    a.legend(fontsize=8, title="dotted: tracer fines")
    cycles = sorted({int(r["cycle"]) for r in rows})
    a.set_xlabel("freeze-thaw cycle [-]")
    b.plot(extra["cycles"], extra["sorting_index"], "o-", label="sorting index")
    b.plot(extra["cycles"], extra["surface_cover"], "s-", label="surface stone cover")
    b.set_xlabel("freeze-thaw cycle [-]")
    b.set_ylabel("sorting index, cover [-]")
    b.legend(fontsize=8)
    st = extra["stones"]
    sc = c.scatter([1e3 * s["radius"] for s in st], [1e3 * s["rise_per_cycle"] for s in st],
                   c=[1e3 * s["start_depth"] for s in st], cmap="viridis")
    fig.colorbar(sc, ax=c, label="top depth at the start [mm]")
    c.axhline(0.0, color="grey", lw=0.5)
    c.set_xlabel("stone radius [mm]")
    c.set_ylabel("rise per cycle [mm]")
elif kind == "fields":
    axis = extra["axis"]
    y = col(axis)
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(13, 4.5), sharey=True)
    a.plot(col("density"), y)
    a.set_xlabel("density [kg/m^2]")
    a.set_ylabel(f"{axis} [m]")
    b.plot(col("velocity_x"), y, label="v_x")
    b.plot(col("velocity_y"), y, label="v_y")
    b.set_xlabel("velocity [m/s]")
    b.legend(fontsize=8)
    for comp, label in [("xx", "sigma_xx"), ("yy", "sigma_yy"), ("xy", "sigma_xy")]:
        c.plot([p + q for p, q in zip(col("contact_" + comp), col("kinetic_" + comp))], y,
               label=label)
    c.set_xlabel("stress, contact + kinetic [N/m]")
    c.legend(fontsize=8)
    fig.suptitle(f"{extra['kernel']} kernel, width {extra['width']:.3g} m, "
                 f"{extra['frames']} snapshots")
elif kind == "fields3":
    axis = extra["axis"]
    y = col(axis)
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(13, 4.5), sharey=True)
    a.plot(col("density"), y)
    a.set_xlabel("density [kg/m^3]")
    a.set_ylabel(f"{axis} [m]")
    # the velocity where there is mass to carry it (beyond the grains it is noise over noise)
    dense = [d > 0.01 * max(col("density")) for d in col("density")]
    for v in "xyz":
        b.plot([u if ok else float("nan") for u, ok in zip(col("velocity_" + v), dense)], y,
               label="v_" + v)
    b.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
    b.set_xlabel("velocity [m/s]")
    b.legend(fontsize=8)
    # the shear stress in the plane of the axis and x (or y, along x)
    shear = "xy" if axis in "xy" else "xz"
    for comp in ["xx", "yy", "zz", shear]:
        c.plot([p + q for p, q in zip(col("contact_" + comp), col("kinetic_" + comp))], y,
               label="sigma_" + comp)
    c.set_xlabel("stress, contact + kinetic [Pa]")
    c.legend(fontsize=8)
    fig.suptitle(f"spheres, {extra['kernel']} kernel, width {extra['width']:.3g} m, "
                 f"{extra['frames']} snapshots")
elif kind == "janssen":
    fig, a = plt.subplots(figsize=(8, 4.5))
    depth = col("depth")
    a.plot(depth, col("wall_normal_stress"), "o", ms=4, label="wall normal stress")
    a.plot(depth, col("wall_shear_stress"), "s", ms=3, mfc="none", label="wall friction")
    if extra["measured"]:
        a.plot(depth, [float(r["fit"]) for r in rows], "k-", lw=1.5,
               label=f"fit: sigma_inf = {extra['saturation']:.3g} N/m, "
                     f"lambda = {extra['length']:.3g} m")
        a.axhline(extra["predicted_saturation"], color="grey", ls="--", lw=1,
                  label=f"rho_b g W / (2 mu), mu = {extra['mobilised_friction']:.2f}")
    unfit = [r for r in rows if r["fitted"] == "0"]
    if unfit:
        a.axvspan(min(col("depth", unfit)) - 0.5 * extra["bin"], max(depth) + 0.5 * extra["bin"],
                  color="grey", alpha=0.15, label="left out (the floor's corners)")
    a.set_xlabel("depth below the free surface [m]")
    a.set_ylabel("stress on the side walls [N/m]")
    a.legend(fontsize=8)
elif kind == "jamming":
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.5))
    p, phi, z = col("pressure"), col("packing_fraction"), col("coordination")
    a.plot(p, phi, "o", label="at rest after each stage")
    if extra["measured"]:
        ps = [0.0] + sorted(p)
        a.plot(ps, [extra["phi_j"] + q / extra["bulk"] for q in ps], "k-", lw=1,
               label=f"phi_J + p / B, phi_J = {extra['phi_j']:.4f}")
    a.axhline(0.842, color="grey", ls="--", lw=1, label="O'Hern et al. 2003: 0.842")
    a.set_xlabel("pressure of the stress region [N/m]")
    a.set_ylabel("packing fraction of the stress region [-]")
    a.legend(fontsize=8)
    if extra["measured"]:
        dphi = [max(q - extra["phi_j"], 0.0) for q in phi]
        b.errorbar(dphi, z, yerr=col("coordination_spread"), fmt="o", label="load-bearing Z")
        xs = sorted(dphi)
        b.plot(xs, [extra["z_j"] + extra["z_slope"] * math.sqrt(x) for x in xs], "k-", lw=1,
               label=f"Z_J + A sqrt(phi - phi_J), Z_J = {extra['z_j']:.2f}")
        b.set_xlabel("phi - phi_J [-]")
    else:
        b.plot(phi, z, "o")
        b.set_xlabel("packing fraction [-]")
    b.axhline(4.0, color="grey", ls="--", lw=1, label="isostatic: 4")
    b.set_ylabel("coordination, rattlers out [-]")
    b.legend(fontsize=8)
elif kind == "fields_map":
    nx, ny = extra["nx"], extra["ny"]
    xs, ys = col("x"), col("y")
    extent = [min(xs) - 0.5 * extra["cell_x"], max(xs) + 0.5 * extra["cell_x"],
              min(ys) - 0.5 * extra["cell_y"], max(ys) + 0.5 * extra["cell_y"]]

    def grid(values):
        return [values[row * nx:(row + 1) * nx] for row in range(ny)]

    speed = [math.hypot(u, v) for u, v in zip(col("velocity_x"), col("velocity_y"))]
    pressure = [0.5 * (a + b + c + d) for a, b, c, d in
                zip(col("contact_xx"), col("contact_yy"), col("kinetic_xx"), col("kinetic_yy"))]
    fig, panels = plt.subplots(1, 3, figsize=(14, 4.8))
    for a, values, label in zip(panels, [col("density"), speed, pressure],
                                ["density [kg/m^2]", "speed [m/s]", "pressure [N/m]"]):
        im = a.imshow(grid(values), origin="lower", extent=extent, aspect="equal")
        fig.colorbar(im, ax=a, label=label, shrink=0.8)
        a.set_xlabel("x [m]")
    panels[0].set_ylabel("y [m]")
    fig.suptitle(f"{extra['kernel']} kernel, width {extra['width']:.3g} m, "
                 f"{extra['frames']} snapshots")
elif kind == "contacts":
    ended = [r for r in rows if r["touching"] == "0"]
    fig, (a, b, c) = plt.subplots(3, 1, figsize=(8, 11))
    for walls, label, marker in [(False, "grain-grain", "o"), (True, "grain-wall", "s")]:
        rs = [r for r in ended if (int(r["wall"]) >= 0) == walls]
        if not rs:
            continue
        impacts = [r for r in rs if float(r["impact_speed"]) > 0 and float(r["rebound_speed"]) > 0]
        a.hist(col("duration", rs), bins=40, alpha=0.6, label=f"{label}, {len(rs)} contacts")
        if impacts:
            v = col("impact_speed", impacts)
            b.plot(v, col("peak_normal_force", impacts), marker, ms=3, ls="", label=label)
            c.plot(v, [float(r["rebound_speed"]) / float(r["impact_speed"]) for r in impacts],
                   marker, ms=3, ls="", label=label)
            if max(v) > 10 * min(v):  # speeds over decades: log axes
                b.set_xscale("log")
                b.set_yscale("log")
                c.set_xscale("log")
    a.set_xlabel("contact duration [s]")
    a.set_ylabel("contacts [-]")
    a.legend(fontsize=8)
    b.set_xlabel("impact speed [m/s]")
    b.set_ylabel("peak normal force [N]")
    c.set_xlabel("impact speed [m/s]")
    c.set_ylabel("restitution: rebound / impact speed [-]")
    for ax in (b, c):
        if ax.has_data():
            ax.legend(fontsize=8)
elif kind == "sweep":
    axes, result = extra["axes"], extra["result"]

    def number(v):
        try:
            return float(v)
        except ValueError:
            return None

    xs = [r[axes[0]] if axes else "" for r in rows]
    numeric = all(number(x) is not None for x in xs)
    order = sorted(set(xs), key=number) if numeric else list(dict.fromkeys(xs))
    series = {}
    for r in rows:
        label = ", ".join(f"{k}={r[k]}" for k in axes[1:])
        series.setdefault(label, []).append(r)
    fig, a = plt.subplots(figsize=(8, 5))
    for label, rs in series.items():
        rs = [r for r in rs if r["mean"] != ""]
        x = [number(r[axes[0]]) if numeric else order.index(r[axes[0]]) for r in rs]
        y = [float(r["mean"]) for r in rs]
        e = [float(r["sd"]) if r["sd"] != "" else 0.0 for r in rs]
        a.errorbar(x, y, yerr=e, fmt="o-", capsize=3, label=label or None)
    if not numeric:
        a.set_xticks(range(len(order)), order)
    a.set_xlabel(axes[0] if axes else "")
    a.set_ylabel(result)
    a.set_title(f"{result}: mean and standard deviation over {extra['seeds']} seed(s)")
    if len(series) > 1:
        a.legend(fontsize=8)
elif kind == "beverloo":
    d, axis = extra["d"], extra["orifice_axis"]
    others = [k for k in extra["axes"] if k != axis]
    fig, a = plt.subplots(figsize=(8, 5))
    for n, fit in enumerate(extra["fits"]):
        mine = [r for r in rows if [r[k] for k in others] == fit["values"]]
        rs = [r for r in mine if r["rate"] != ""]
        stuck = [float(r["D_over_d"]) for r in mine if r["rate"] == "" and r["end"] == "clogged"]
        if stuck:
            a.plot(stuck, [0.0] * len(stuck), "x", color=f"C{n}", ms=9, mew=2,
                   label=f"clogged ({len(stuck)} runs; no rate)")
        x, y = col("D_over_d", rs), col("rate", rs)
        e = [float(r["rate_error"]) if r["rate_error"] != "" else 0.0 for r in rs]
        colour = f"C{n}"
        a.errorbar(x, y, yerr=e, fmt="o", color=colour, capsize=3,
                   label=fit["label"] or "runs")
        if not x:
            continue
        for key, style in (("free", "-"), ("fixed", "--")):
            f = fit[key]
            if not f["ok"]:
                continue
            lo, hi = f["k"] + 1e-3, max(x) * 1.05
            u = [lo + (hi - lo) * i / 200 for i in range(201)]
            nlabel = f"n = {f['n']:.2f}" + (" (fixed)" if f["n_fixed"] else
                                           f" ± {f['n_error']:.2f}")
            a.plot(u, [f["A"] * (v - f["k"]) ** f["n"] for v in u], style, color=colour,
                   label=f"W = A (D/d - k)^n: k = {f['k']:.2f}, {nlabel}")
    a.set_xlim(left=0)
    a.set_ylim(bottom=0)
    a.set_xlabel("orifice width D / mean grain diameter d")
    a.set_ylabel("discharge rate W [grains/s]")
    a.set_title(f"Beverloo fits, d = {1e3 * d:.3g} mm")
    a.legend(fontsize=8)
elif kind == "rheology":
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.5), sharey=True)
    y = col("y")
    bulk = [float(r["y"]) for r in rows if r["bulk"] == "1"]
    for a, key, label in ((axes[0], "velocity_x", "v_x [m/s]"),
                          (axes[1], "packing_fraction", "packing fraction [-]"),
                          (axes[2], "friction", "|sigma_xy| / sigma_yy [-]")):
        rs = [r for r in rows if r[key] != ""]
        a.plot(col(key, rs), col("y", rs), "-")
        a.axhspan(min(bulk), max(bulk), color="grey", alpha=0.15, label="bulk measured")
        a.set_xlabel(label)
    axes[0].set_ylabel("height [m]")
    axes[2].axvline(extra["friction"], color="k", ls="--", lw=1,
                    label=f"mu = {extra['friction']:.3f}, I = {extra['inertial']:.3g}")
    axes[2].legend(fontsize=8)
    axes[0].legend(fontsize=8)
elif kind == "rheology_sweep":
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.5))
    rs = [r for r in rows if r["measured"] == "1"]
    i, ie = col("inertial", rs), col("inertial_error", rs)
    a.errorbar(i, col("friction", rs), xerr=ie, yerr=col("friction_error", rs), fmt="o",
               capsize=3, label="runs")
    b.errorbar(i, col("packing", rs), xerr=ie, yerr=col("packing_error", rs), fmt="o",
               capsize=3, label="runs")
    u = [max(i) * 1.1 * k / 200 for k in range(1, 201)] if i else []
    f = extra["mu_of_i"]
    if f["ok"]:
        a.plot(u, [f["mu_s"] + (f["mu_2"] - f["mu_s"]) / (f["i_0"] / v + 1) for v in u], "k-",
               lw=1, label=f"mu_s = {f['mu_s']:.3f}, mu_2 = {f['mu_2']:.3f}, "
                           f"I_0 = {f['i_0']:.3g}")
    f = extra["mu_line"]
    if f["ok"]:
        a.plot(u, [f["intercept"] + f["slope"] * v for v in u], "k--", lw=1,
               label=f"mu_1 + b I: mu_1 = {f['intercept']:.3f}, b = {f['slope']:.2f}")
    f = extra["phi_line"]
    if f["ok"]:
        b.plot(u, [f["intercept"] + f["slope"] * v for v in u], "k-", lw=1,
               label=f"phi_max - a I: phi_max = {f['intercept']:.3f}, a = {-f['slope']:.2f}")
    a.set_xlabel("inertial number I [-]")
    a.set_ylabel("friction coefficient mu [-]")
    b.set_xlabel("inertial number I [-]")
    b.set_ylabel("packing fraction phi [-]")
    a.legend(fontsize=8)
    b.legend(fontsize=8)
elif kind == "chute":
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.5), sharey=True)
    z = col("z")
    d = extra["diameter"]
    zd = [v / d for v in z]
    band = [float(r["z"]) / d for r in rows if r["fitted"] == "1"]
    a = axes[0]
    a.plot(col("velocity"), zd, "-", label="coarse-grained")
    rs = [r for r in rows if r["bagnold"] != ""]
    a.plot(col("bagnold", rs), [float(r["z"]) / d for r in rs], "k--", lw=1,
           label=f"Bagnold: v_b + c (h^1.5 - (h - z)^1.5), rms {extra['bagnold_rms']:.2g} m/s")
    a.set_xlabel("velocity down the slope [m/s]")
    a.set_ylabel("height above the base / d")
    for ax, key, label in ((axes[1], "packing_fraction", "packing fraction [-]"),
                           (axes[2], "friction",
                            extra.get("friction_of", "|sigma_xy| / sigma_yy") + " and I [-]")):
        rs = [r for r in rows if r[key] != ""]
        ax.plot(col(key, rs), [float(r["z"]) / d for r in rs], "-", label=key)
        ax.set_xlabel(label)
    rs = [r for r in rows if r["inertial"] != "" and r["fitted"] == "1"]
    axes[2].plot(col("inertial", rs), [float(r["z"]) / d for r in rs], "-", label="I")
    axes[2].axvline(extra["tan_angle"], color="k", ls="--", lw=1,
                    label=f"tan theta = {extra['tan_angle']:.3f}")
    axes[2].set_xlim(0, 0.8)
    for ax in axes:
        ax.axhspan(min(band), max(band), color="grey", alpha=0.12)
        ax.legend(fontsize=8)
elif kind == "chute_stop" and len(extra["slopes"]) > 1:
    # Pouliquen's phase diagram: each layer by its depth and slope, h_stop(theta) between
    fig, a = plt.subplots(figsize=(8, 4.5))
    for flag, style, label in (("1", "o", "flowing"), ("0", "x", "stopped")):
        rs = [r for r in rows if r["flowing"] == flag]
        a.plot(col("depth_over_d", rs), col("angle_deg", rs), style, ms=8, label=label)
    d = extra["diameter"]
    bands = [s for s in extra["slopes"] if s["bracketed"]]
    for k, s in enumerate(bands):
        a.plot([s["h_stop_lo"] / d, s["h_stop_hi"] / d], [s["angle_deg"]] * 2, "-", color="grey",
               lw=6, alpha=0.4, label="h_stop lies here" if k == 0 else None)
    a.set_xlabel("depth of the layer h / d")
    a.set_ylabel("slope at the end [degrees]")
    a.set_title("layers that stopped and layers that flowed")
    a.legend(fontsize=8)
elif kind == "chute_stop":
    fig, a = plt.subplots(figsize=(8, 4.5))
    for flag, style, label in (("1", "o", "flowing"), ("0", "x", "stopped")):
        rs = [r for r in rows if r["flowing"] == flag]
        a.plot(col("depth_over_d", rs), col("mean_velocity", rs), style, ms=8, label=label)
    if extra["bracketed"]:
        d = extra["diameter"]
        a.axvspan(extra["h_stop_lo"] / d, extra["h_stop_hi"] / d, color="grey", alpha=0.2,
                  label="h_stop lies here")
    a.set_xlabel("depth of the layer h / d")
    a.set_ylabel("mean velocity down the slope at the end [m/s]")
    a.set_title(f"layers at {extra['angle_deg']:.2f} degrees")
    a.legend(fontsize=8)
else:
    sys.exit(f"unknown chart {kind}")
if fig.get_layout_engine() is None:  # a figure with a colour bar lays itself out
    fig.tight_layout()
fig.savefig(target, dpi=110)
