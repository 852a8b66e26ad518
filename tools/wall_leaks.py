#!/usr/bin/python3
"""Counts, snapshot by snapshot, the fluid particles that have gone through a wall.

Usage: wall_leaks.py OUTDIR [CASE.toml]

A wall's box is its fluid side (docs/case-reference.md, [[wall]]): a fluid particle more than
dp/2 beyond one of the box's faces that carry wall particles, and within the box across that
face, has passed into or through the wall's layers. Particles leave the domain only once they
are past the domain's faces, so a leak shows here long before the run's count of lost
particles does (docs/VALIDATION.md, the Bi 2014 net at dp = 6 mm).

The case is the one OUTDIR/summary.json names (case.source), or, while the run is still going,
its log.txt; --set overrides are not applied to the walls, so give CASE.toml if one moved a
wall. Prints one line per snapshot: its time, and for
each wall face with leaked particles their count and how far the deepest is beyond the face.
Exits 1 when the last snapshot has any.

Run it with Debian's /usr/bin/python3, which has h5py (python3-h5py).
"""
import glob
import json
import os
import re
import sys
import tomllib

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"error: {e} (run with /usr/bin/python3; apt-get install python3-h5py)")
    sys.exit(2)

FACES = ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"]
FLUID = 0  # ParticleKind::Fluid


def walls_of(case_path, dims):
    with open(case_path, "rb") as f:
        case = tomllib.load(f)
    walls = []
    for k, w in enumerate(case.get("wall", [])):
        default = [f for f in FACES if dims == 3 or f[0] != "y"]
        walls.append((w.get("name", f"wall{k + 1}"), np.array(w["min"], float),
                      np.array(w["max"], float), w.get("faces", default)))
    return walls


def run_settings(out):
    """(dimensions, dp, case source) from summary.json, or while the run is still going (no
    summary yet) from the first lines of its log.txt."""
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        return summary["model"]["dimensions"], summary["model"]["dp_m"], summary["case"]["source"]
    except (OSError, KeyError, ValueError):
        pass
    dims = dp = source = None
    try:
        with open(os.path.join(out, "log.txt")) as f:
            for line in f:
                if m := re.search(r"run: case '.*' from (.+)$", line):
                    source = m.group(1).strip()
                if m := re.search(r"\] ([23])D, dp = ([0-9.eE+-]+) m", line):
                    dims, dp = int(m.group(1)), float(m.group(2))
                    break
    except OSError:
        pass
    return dims, dp, source


def leaks(pos, walls, dims, tol):
    """{(wall, face): (count, deepest m)} for the fluid positions pos."""
    found = {}
    for name, lo, hi, faces in walls:
        for face in faces:
            a = "xyz".index(face[0])
            beyond = (lo[a] - pos[:, a]) if face.endswith("min") else (pos[:, a] - hi[a])
            inside = beyond > tol
            for b in range(3):
                if b == a or (dims == 2 and b == 1):
                    continue
                inside &= (pos[:, b] >= lo[b] - tol) & (pos[:, b] <= hi[b] + tol)
            if inside.any():
                found[(name, face)] = (int(inside.sum()), float(beyond[inside].max()))
    return found


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    out = sys.argv[1]
    dims, dp, source = run_settings(out)
    if dims is None:
        print(f"error: neither {out}/summary.json nor a readable {out}/log.txt: not a run's folder?")
        return 2
    case_path = sys.argv[2] if len(sys.argv) == 3 else source
    if case_path.startswith("builtin:"):  # the shipped cases, cases/NAME.toml in this repository
        here = os.path.dirname(os.path.abspath(__file__))
        case_path = os.path.join(here, "..", "cases", case_path[len("builtin:"):] + ".toml")
    if not os.path.exists(case_path):
        print(f"error: case file {case_path} not found (give CASE.toml as the second argument)")
        return 2
    walls = walls_of(case_path, dims)
    if not walls:
        print(f"{case_path} has no [[wall]]: nothing to check")
        return 0
    files = sorted(glob.glob(os.path.join(out, "snapshots", "particles_*.h5")))
    if not files:
        print(f"error: no snapshots in {out}/snapshots")
        return 2
    found = {}
    for path in files:
        with h5py.File(path) as h:
            fluid = h["kind"][:] == FLUID
            pos = h["position"][:][fluid]
            time = float(h.attrs["time"])
        found = leaks(pos, walls, dims, 0.5 * dp)
        total = sum(c for c, _ in found.values())
        parts = [f"{w} {f}: {c} (deepest {d * 1000:.1f} mm)" for (w, f), (c, d) in found.items()]
        print(f"t = {time:8.4f} s  {total:6d} of {len(pos)} fluid particles through walls"
              + ("  " + "; ".join(parts) if parts else ""))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
