#!/usr/bin/python3
"""PNG plots of a netsph run folder (what `netsph plot DIR` and the end of `netsph run` call).

Reads the folder's summary.json, series.csv, probes/*_mean.csv and the nets' VTK series, and
writes into DIR/plots/:
  forces_<group>.png        drag (Fx) and lift (Fz) of each force group over time, the
                            averaging window shaded, its mean drawn; Cd on a second axis
                            (a standalone net run: forces_<net>.png, the current's force)
  net_<net>.png             a net's largest deflection and twine tension over time
  net_<net>_shape.png       the net seen from the side (x-z) at five moments of the run, or at
                            the times given as a second argument ("0.5,1,2.5")
  probe_<name>.png          line probes: mean u_x / U along the line (the paper's Figures 13,
                            19, 24); plane probes: contours of the mean speed (Figures 17, 18,
                            22, 23), with the nets' final knots drawn in
  gauges.png                wave gauges: the surface elevation at each gauge over time, with
                            the target wave ([waves]) and the summary's window shaded
  time_step.png             dt and the fluid particle count over time
Every axis carries its unit; colour maps are perceptually uniform (viridis, cividis).
Run with Debian's Python (/usr/bin/python3): it needs python3-matplotlib and python3-numpy.
"""
import csv
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    """Columns of a netsph CSV by name (the unit in brackets stripped), as float arrays."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}, {}
    names, units = [], {}
    for h in rows[0]:
        m = re.match(r"^(.*?)(?: \[(.*)\])?$", h)
        names.append(m.group(1))
        units[m.group(1)] = m.group(2) or ""
    data = {n: [] for n in names}
    for r in rows[1:]:
        for n, v in zip(names, r):
            data[n].append(float(v) if v not in ("", "nan") else math.nan)
    return {n: np.array(v) for n, v in data.items()}, units


def read_vtk_points(path):
    """The POINTS of a legacy ASCII VTK polydata file written by netsph, and its LINES."""
    with open(path) as f:
        tokens = f.read().split()
    i = tokens.index("POINTS")
    n = int(tokens[i + 1])
    pts = np.array(tokens[i + 3:i + 3 + 3 * n], dtype=float).reshape(n, 3)
    lines = []
    if "LINES" in tokens:
        j = tokens.index("LINES")
        count = int(tokens[j + 1])
        k = j + 3
        for _ in range(count):
            m = int(tokens[k])
            lines.append([int(t) for t in tokens[k + 1:k + 1 + m]])
            k += 1 + m
    return pts, lines


def save(fig, folder, name):
    path = os.path.join(folder, name)
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_forces(series, summary, case, out):
    written = []
    for g in summary.get("bodies", []):
        name = g["group"]
        if name + "_Fx" not in series:
            continue
        t = series["time"]
        fig, ax = plt.subplots(figsize=(8, 4.5))
        ax.plot(t, series[name + "_Fx"], color="#1f4e79", lw=1, label="drag $F_x$")
        ax.plot(t, series[name + "_Fz"], color="#c0504d", lw=1, label="lift $F_z$")
        t0, t1 = g.get("window_s", [t[0], t[-1]])
        ax.axvspan(t0, t1, color="0.85", zorder=0, label="averaging window")
        if "force_N" in g:
            ax.hlines(g["force_N"][0], t0, t1, colors="k", linestyles="--",
                      label=f"mean drag {g['force_N'][0]:.4g} N")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("force [N]" if summary["model"]["dimensions"] == 3 else "force [N/m]")
        if name + "_Cd" in series and g.get("reference_velocity_m_s"):
            ax2 = ax.twinx()
            ax2.plot(t, series[name + "_Cd"], color="0.4", lw=0.6, alpha=0.6)
            ax2.set_ylabel("Cd [-] (grey)")
            lo, hi = ax.get_ylim()
            scale = 0.5 * 1000 * g["reference_velocity_m_s"] ** 2 * g["reference_area"]
            ax2.set_ylim(lo / scale, hi / scale)
        ax.set_title(f"{case}: fluid force on '{name}'")
        ax.legend(loc="best", fontsize=8)
        written.append(save(fig, out, f"forces_{name}.png"))
    return written


def plot_time_step(series, case, out):
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(series["time"][1:], series["dt"][1:], color="#1f4e79", lw=1)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("dt [s]")
    ax2 = ax.twinx()
    ax2.plot(series["time"], series["fluid_particles"], color="#c0504d", lw=1)
    ax2.set_ylabel("fluid particles [-] (red)")
    ax.set_title(f"{case}: time step and particle count")
    return [save(fig, out, "time_step.png")]


def plot_net_series(series, summary, case, out):
    written = []
    for n in summary.get("nets", []):
        name = n["name"]
        if name + "_deflection" not in series:
            continue
        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(series["time"], series[name + "_deflection"], color="#1f4e79", lw=1)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("largest deflection along the normal [m]")
        ax2 = ax.twinx()
        ax2.plot(series["time"], series[name + "_max_tension"], color="#c0504d", lw=0.8)
        ax2.set_ylabel("largest twine tension [N] (red)")
        ax.set_title(f"{case}: net '{name}'")
        written.append(save(fig, out, f"net_{name}.png"))
    return written


def plot_standalone_forces(series, summary, case, out):
    """A standalone net run: the current's force on each net over time, the window shaded."""
    written = []
    t0, t1 = summary.get("force_window_s", [None, None])
    for n in summary.get("nets", []):
        name = n["name"]
        if name + "_Fx" not in series:
            continue
        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(series["time"], series[name + "_Fx"], color="#1f4e79", lw=1, label="drag (Fx)")
        ax.plot(series["time"], series[name + "_Fz"], color="#9bbb59", lw=0.8, label="lift (Fz)")
        if t0 is not None:
            ax.axvspan(t0, t1, color="0.9", zorder=0, label="averaging window")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("force of the current on the net [N]")
        ax.set_title(f"{case}: net '{name}' (standalone, screen or Morison model)")
        ax.legend(loc="best", fontsize=8)
        written.append(save(fig, out, f"forces_{name}.png"))
    return written


def net_snapshots(folder, name):
    """(time, file) of a net's VTK series, in time order."""
    path = os.path.join(folder, name + ".vtk.series")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        files = json.load(f)["files"]
    return [(e["time"], os.path.join(folder, e["name"])) for e in files]


def plot_net_shapes(folder, summary, case, out, times=None):
    written = []
    for n in summary.get("nets", []):
        snaps = net_snapshots(folder, n["name"])
        if not snaps:
            continue
        if times:  # the snapshots nearest the times asked for
            picks = sorted({min(range(len(snaps)), key=lambda i: abs(snaps[i][0] - t))
                            for t in times})
        else:  # five moments spread over the run
            picks = sorted({round(i * (len(snaps) - 1) / 4) for i in range(5)})
        cmap = plt.get_cmap("viridis")
        fig, ax = plt.subplots(figsize=(6, 6))
        for k, i in enumerate(picks):
            t, path = snaps[i]
            pts, lines = read_vtk_points(path)
            color = cmap(k / max(1, len(picks) - 1))
            for line in lines:
                ax.plot(pts[line, 0], pts[line, 2], color=color, lw=0.8, alpha=0.7)
            ax.plot(pts[:, 0], pts[:, 2], "o", color=color, ms=3, label=f"t = {t:.2f} s")
        ax.set_xlabel("x (along the current) [m]")
        ax.set_ylabel("z (up) [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(f"{case}: net '{n['name']}' from the side")
        ax.legend(fontsize=8)
        written.append(save(fig, out, f"net_{n['name']}_shape.png"))
    return written


def final_knots(folder, summary):
    knots = []
    for n in summary.get("nets", []):
        snaps = net_snapshots(folder, n["name"])
        if snaps:
            knots.append(read_vtk_points(snaps[-1][1])[0])
    return knots


def plot_probes(folder, summary, case, out):
    written = []
    inflow = None
    for p in summary.get("probes", []):
        inflow = inflow or p.get("reference_velocity_m_s")
    knots = final_knots(folder, summary)
    for p in summary.get("probes", []):
        path = os.path.join(folder, p["mean_file"])
        if not os.path.exists(path) or p["type"] == "point":
            continue
        d, _ = read_csv(path)
        ok = d["coverage"] >= 0.5
        if p["type"] == "line":
            fig, ax = plt.subplots(figsize=(8, 4))
            x = d["x"] if np.ptp(d["x"]) > 0 else d["s"]
            xlabel = "x [m]" if np.ptp(d["x"]) > 0 else "distance along the line [m]"
            u = np.where(ok, d["ux"], np.nan)
            if inflow:
                ax.plot(x, u / inflow, color="#1f4e79", lw=1.2)
                ax.axhline(1.0, color="0.6", lw=0.8, ls="--")
                ax.set_ylabel("mean $u_x$ / U [-]")
            else:
                ax.plot(x, u, color="#1f4e79", lw=1.2)
                ax.set_ylabel("mean $u_x$ [m/s]")
            ax.set_xlabel(xlabel)
            ax.set_title(f"{case}: probe '{p['name']}' (time mean)")
            written.append(save(fig, out, f"probe_{p['name']}.png"))
            continue
        # A plane: the two coordinates that vary.
        axes = [c for c in ("x", "y", "z") if np.ptp(d[c]) > 0]
        if len(axes) != 2:
            continue
        a, b = axes
        ua, ub = np.unique(d[a]), np.unique(d[b])
        speed = np.where(ok, d["speed"], np.nan)
        grid = np.full((len(ub), len(ua)), np.nan)
        ia = np.searchsorted(ua, d[a])
        ib = np.searchsorted(ub, d[b])
        grid[ib, ia] = speed
        fig, ax = plt.subplots(figsize=(8, 8 * np.ptp(ub) / max(np.ptp(ua), 1e-9) + 1.2))
        levels = 24
        cs = ax.contourf(ua, ub, grid, levels=levels, cmap="viridis")
        fig.colorbar(cs, ax=ax, label="mean speed [m/s]", shrink=0.8)
        index = {"x": 0, "y": 1, "z": 2}
        flat = [c for c in ("x", "y", "z") if c not in axes][0]
        level = d[flat][0]
        for pts in knots:
            near = np.abs(pts[:, index[flat]] - level) < 0.6 * max(np.ptp(ua), np.ptp(ub))
            ax.plot(pts[near, index[a]], pts[near, index[b]], "s", color="white", ms=3,
                    mec="k", mew=0.4)
        ax.set_xlabel(f"{a} [m]")
        ax.set_ylabel(f"{b} [m]")
        ax.set_aspect("equal")
        ax.set_title(f"{case}: probe '{p['name']}' at {flat} = {level:.3g} m (time mean)")
        written.append(save(fig, out, f"probe_{p['name']}.png"))
    return written


def plot_gauges(folder, summary, case, out):
    gauges = summary.get("gauges", [])
    path = os.path.join(folder, "gauges.csv")
    if not gauges or not os.path.exists(path):
        return []
    d, _ = read_csv(path)
    t = d["time"]
    fig, axes = plt.subplots(len(gauges), 1, figsize=(10, 1.9 * len(gauges) + 0.8), sharex=True,
                             squeeze=False)
    for ax, g in zip(axes[:, 0], gauges):
        name = g["name"]
        window = g.get("window_s")
        if window:
            ax.axvspan(window[0], window[1], color="0.92", lw=0)
        if f"{name}_target" in d:
            ax.plot(t, d[f"{name}_target"], color="0.45", lw=1.0, ls="--", label="target")
        ax.plot(t, d[name], color="#1f4e79", lw=1.1, label="measured")
        ratio = g.get("height_ratio")
        note = f", H / H_target = {ratio:.3f}" if ratio is not None else ""
        ax.set_title(f"gauge '{name}' at x = {g['x_m']:.3g} m{note}", fontsize=9, loc="left")
        ax.set_ylabel("η [m]")
        ax.axhline(0.0, color="0.7", lw=0.6)
    axes[0, 0].legend(loc="upper left", fontsize=8, ncol=2)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{case}: surface elevation (window of the summary shaded)")
    return [save(fig, out, "gauges.png")]


def main(argv):
    if len(argv) not in (2, 3):
        print("usage: plot_results.py RUN_FOLDER [TIMES]  (TIMES: net shapes at t1,t2,... s)",
              file=sys.stderr)
        return 2
    folder = argv[1]
    times = [float(t) for t in argv[2].split(",")] if len(argv) == 3 and argv[2] else None
    summary_path = os.path.join(folder, "summary.json")
    if not os.path.exists(summary_path):
        print(f"plot_results: {summary_path} not found: not a netsph run folder", file=sys.stderr)
        return 1
    with open(summary_path) as f:
        summary = json.load(f)
    case = summary.get("case", {}).get("name", os.path.basename(os.path.abspath(folder)))
    out = os.path.join(folder, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    series_path = os.path.join(folder, "series.csv")
    if "model" in summary and os.path.exists(series_path):
        series, _ = read_csv(series_path)
        written += plot_forces(series, summary, case, out)
        written += plot_net_series(series, summary, case, out)
        written += plot_time_step(series, case, out)
        written += plot_net_shapes(folder, summary, case, out, times)
        written += plot_probes(folder, summary, case, out)
        written += plot_gauges(folder, summary, case, out)
    elif summary.get("mode") == "standalone net" and os.path.exists(series_path):
        # A standalone net run (no fluid): nets in a current, no particles.
        series, _ = read_csv(series_path)
        written += plot_standalone_forces(series, summary, case, out)
        written += plot_net_series(series, summary, case, out)
        written += plot_net_shapes(folder, summary, case, out, times)
    if not written:
        print(f"plot_results: nothing to plot in {folder}", file=sys.stderr)
        return 1
    for w in written:
        print(w)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
