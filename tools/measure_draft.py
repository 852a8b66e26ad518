#!/usr/bin/python3
"""Measures the draft of a floating or fixed box from a netsph run, against Archimedes.

Usage: measure_draft.py OUTDIR --size SX SY SZ --dp DP [--density RHO_BODY]
                        [--dims 3] [--body 0] [--rho 1000] [--window T0 T1]
                        [--margin 0.03] [--tank XMIN XMAX [YMIN YMAX]]

The draft is the free surface minus the bottom of the box. The bottom comes from the body's
centre in OUTDIR/bodies.csv (the box is taken as upright: the floating-box cases only
heave); the free surface from each snapshot in OUTDIR/snapshots: on a dp grid in the
horizontal plane, the highest fluid particle of each column plus dp/2, averaged over the
columns at least MARGIN outside the box's footprint and inside the tank (TANK, default the
extent of the fluid). Vertical is z, as in netsph's 2D (x-z) and 3D cases. Archimedes'
draft of an upright box of uniform section is (RHO_BODY / RHO) SZ.

Prints the mean draft over the window (default: from a third of the run to its end), the
surface's range, the body's mean vertical fluid force against Archimedes' force at the
measured draft (RHO g SX SY draft; 2D: per metre: the buoyancy of a fixed box), and with
RHO_BODY (a floating box) the Archimedes draft, the error and the force against the weight
(equilibrium check). Run it with Debian's /usr/bin/python3.
"""
import argparse
import glob
import os
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"error: {e} (run with /usr/bin/python3; apt-get install python3-h5py)")
    sys.exit(1)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_results import read_csv  # noqa: E402  (netsph's CSV reader, units stripped)

FLUID = 0  # ParticleKind::Fluid


def read_bodies(path, body):
    """Times, centre (x, y, z) and vertical fluid force of one body, from bodies.csv."""
    data, _ = read_csv(path)
    rows = data["body"] == body
    centre = np.stack([data[c][rows] for c in ("x", "y", "z")], axis=1)
    return data["time"][rows], centre, data["Fz"][rows]


def surface_level(h5, horiz, dp, centre, half, margin, tank):
    """Mean free-surface height in the columns outside the footprint, or None if none."""
    pos = h5["position"][...]
    fluid = pos[h5["kind"][...] == FLUID]
    xy = fluid[:, horiz]
    if tank is None:
        lo, hi = xy.min(axis=0) - dp / 2, xy.max(axis=0) + dp / 2
    else:
        lo, hi = np.array(tank[0::2]), np.array(tank[1::2])
    ncell = np.maximum(np.ceil((hi - lo) / dp).astype(np.int64), 1)
    cells = np.clip(np.floor((xy - lo) / dp).astype(np.int64), 0, ncell - 1)
    flat = np.ravel_multi_index(tuple(cells.T), tuple(ncell))
    top = np.full(int(np.prod(ncell)), -np.inf)
    np.maximum.at(top, flat, fluid[:, 2])
    # Column centres; keep those MARGIN outside the footprint and MARGIN inside the tank.
    axes = [lo[k] + (np.arange(ncell[k]) + 0.5) * dp for k in range(len(horiz))]
    grid = np.meshgrid(*axes, indexing="ij")
    outside = np.zeros(grid[0].shape, dtype=bool)
    inside = np.ones(grid[0].shape, dtype=bool)
    for k in range(len(horiz)):
        outside |= np.abs(grid[k] - centre[k]) > half[k] + margin
        inside &= (grid[k] > lo[k] + margin) & (grid[k] < hi[k] - margin)
    use = (outside & inside).ravel() & np.isfinite(top)
    if not use.any():
        return None
    return float(np.mean(top[use])) + dp / 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", help="the run's output folder")
    ap.add_argument("--size", type=float, nargs=3, required=True, metavar=("SX", "SY", "SZ"),
                    help="box size [m] (2D: SY is ignored)")
    ap.add_argument("--density", type=float, help="body density [kg/m^3] (a floating box)")
    ap.add_argument("--dp", type=float, required=True, help="the run's particle spacing [m]")
    ap.add_argument("--dims", type=int, choices=(2, 3), default=3, help="2D (x-z) or 3D run")
    ap.add_argument("--body", type=int, default=0, help="body index in bodies.csv")
    ap.add_argument("--rho", type=float, default=1000.0, help="water density [kg/m^3]")
    ap.add_argument("--window", type=float, nargs=2, metavar=("T0", "T1"),
                    help="averaging window [s] (default: last two thirds of the run)")
    ap.add_argument("--margin", type=float, default=0.03, help="[m] from box and tank walls")
    ap.add_argument("--tank", type=float, nargs="+", help="xmin xmax [ymin ymax] of the water")
    ap.add_argument("--gravity", type=float, default=9.81, help="[m/s^2]")
    a = ap.parse_args()

    bodies_csv = os.path.join(a.outdir, "bodies.csv")
    if not os.path.isfile(bodies_csv):
        sys.exit(f"error: {bodies_csv} not found (is {a.outdir} a netsph run with a body?)")
    t, centre, fz = read_bodies(bodies_csv, a.body)
    if t.size == 0:
        sys.exit(f"error: no rows for body {a.body} in {a.outdir}/bodies.csv")
    t0, t1 = a.window if a.window else (t[-1] / 3, t[-1])
    horiz = [0] if a.dims == 2 else [0, 1]
    if a.tank is not None and len(a.tank) != 2 * len(horiz):
        sys.exit(f"error: --tank takes {2 * len(horiz)} values in {a.dims}D, got {len(a.tank)}")
    half = [a.size[k] / 2 for k in horiz]
    section = a.size[0] * (a.size[1] if a.dims == 3 else 1.0)  # 2D: per metre

    drafts, levels = [], []
    for path in sorted(glob.glob(os.path.join(a.outdir, "snapshots", "particles_*.h5"))):
        with h5py.File(path, "r") as h5:
            time = float(h5.attrs["time"])
            if time < t0 or time > t1:
                continue
            k = min(int(np.searchsorted(t, time)), t.size - 1)
            level = surface_level(h5, horiz, a.dp, centre[k, horiz], half, a.margin, a.tank)
        if level is None:
            sys.exit("error: no free-surface column outside the footprint; lower --margin")
        levels.append(level)
        drafts.append(level - (centre[k, 2] - a.size[2] / 2))
    if not drafts:
        sys.exit(f"error: no snapshot in the window [{t0}, {t1}] s")
    sel = (t >= t0) & (t <= t1)
    draft = float(np.mean(drafts))
    force = float(np.mean(fz[sel]))
    buoyancy = a.rho * a.gravity * section * draft
    print(f"window {t0:.3g}-{t1:.3g} s, {len(drafts)} snapshots")
    print(f"mean draft {draft:.4f} m (range {min(drafts):.4f}-{max(drafts):.4f} m; "
          f"surface {min(levels):.4f}-{max(levels):.4f} m)")
    print(f"mean vertical fluid force {force:.2f} N, rho g A draft {buoyancy:.2f} N: "
          f"ratio {force / buoyancy:.3f} (2D: per metre)")
    if a.density is not None:
        # An upright box of uniform section floats with draft (rho_body / rho) SZ (Archimedes).
        archimedes = a.density / a.rho * a.size[2]
        weight = a.density * section * a.size[2] * a.gravity
        print(f"Archimedes draft {archimedes:.4f} m: error {100 * (draft / archimedes - 1):+.1f}%; "
              f"force / weight {force / weight:.3f}")


if __name__ == "__main__":
    main()
