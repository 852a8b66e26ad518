#!/usr/bin/python3
"""tools/reflection_analysis.py separates incident and reflected waves it is given: synthetic
gauge records (linear waves, frequencies on the records' Fourier bins, so the separation is
exact to round-off) of a regular wave reflected with Kr = 0.15, an irregular sea reflected with
Kr = 0.3, and no reflection; and it refuses gauges at one position.
Usage: reflection_analysis_test.py <repo-root>"""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

root = sys.argv[1]
tool = os.path.join(root, "tools", "reflection_analysis.py")
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(root, "tools"))
from reflection_analysis import wave_number  # noqa: E402

depth, xs = 0.5, [2.0, 2.25, 2.6]
dt, n = 0.02, 1500  # 30 s: frequencies on multiples of 1/30 Hz are on the Fourier bins
t = np.arange(n) * dt


def record(components, kr):
    """Elevations at the gauges: each component (f, a, phase) incident, and reflected with
    amplitude kr * a and its own phase (the reflector's lag)."""
    recs = []
    for x in xs:
        eta = np.zeros(n)
        for f, a, ph in components:
            w = 2 * math.pi * f
            k = wave_number(w, depth)
            eta += a * np.cos(k * x - w * t + ph)
            eta += kr * a * np.cos(-k * x - w * t + 2.1 * ph + 0.7)
        recs.append(eta)
    return recs


def run(recs, kr_expected, hm0_expected, tol, tmp, name, extra=()):
    path = os.path.join(tmp, name + ".csv")
    with open(path, "w") as f:
        f.write("time [s],g1 [m],g2 [m],g3 [m]\n")
        for i in range(n):
            f.write(f"{t[i]:.6f},{recs[0][i]:.12e},{recs[1][i]:.12e},{recs[2][i]:.12e}\n")
    out = os.path.join(tmp, name + ".json")
    subprocess.run([sys.executable, tool, path, "--gauges", "g1,g2,g3", "--x",
                    ",".join(map(str, xs)), "--depth", str(depth), "--json", out, *extra],
                   check=True)
    r = json.load(open(out))
    kr = r["reflection_coefficient"]
    assert abs(kr - kr_expected) <= tol, f"{name}: Kr {kr} against {kr_expected}"
    hm0 = r["incident_hm0_m"]
    assert abs(hm0 - hm0_expected) <= 1e-6 * hm0_expected, f"{name}: Hm0 {hm0} vs {hm0_expected}"


with tempfile.TemporaryDirectory() as tmp:
    # Regular wave, T = 1.2 s (25 periods in the record), H = 0.04 m.
    regular = [(25 / 30, 0.02, 0.4)]
    run(record(regular, 0.15), 0.15, 4 * math.sqrt(0.02**2 / 2), 1e-6, tmp, "regular")
    run(record(regular, 0.0), 0.0, 4 * math.sqrt(0.02**2 / 2), 1e-6, tmp, "none")
    # An irregular sea: 40 components from 0.4 to 1.7 Hz, random amplitudes and phases.
    rng = np.random.default_rng(5)
    sea = [(m / 30, float(rng.uniform(0.002, 0.01)), float(rng.uniform(0, 2 * math.pi)))
           for m in range(12, 52)]
    hm0 = 4 * math.sqrt(sum(a * a / 2 for _, a, _ in sea))
    run(record(sea, 0.3), 0.3, hm0, 1e-6, tmp, "irregular", ("--band", "0.35,1.75"))
    # Three gauges at one position cannot separate anything: refused with a message.
    p = subprocess.run([sys.executable, tool, os.path.join(tmp, "regular.csv"), "--gauges",
                        "g1,g2,g3", "--x", "2,2,2", "--depth", "0.5"], capture_output=True,
                       text=True)
    assert p.returncode != 0 and "different positions" in p.stderr, p.stderr
print("PASS: reflection analysis")
