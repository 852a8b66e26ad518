#!/usr/bin/python3
"""tools/harmonic_analysis.py separates what it is given: synthetic gauge records along a flume
of a first harmonic (incident, and reflected with Kr = 0.05), a bound second harmonic (2k) and
a free one (k2 from the dispersion relation at 2 omega) of known amplitudes, sampled at
jittered times as a run's gauges are; the amplitudes come back to the interpolation's error.
With no free harmonic, the free amplitude comes back below 1% of the bound one. A wave
travelling in -x against a current (its wave number from (omega - k U)^2 = g k tanh kh, solved
here by fixed-point iteration) comes back with its wavelength. A paddle that sends back 30% of
a reflected wave (the incident wave changes by 0.3 of the reflected one between a window
before the reflection and one after) has that reflection coefficient (--before). Gauges at
fewer than three positions are refused.
Usage: harmonic_analysis_test.py <repo-root>"""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

root = sys.argv[1]
tool = os.path.join(root, "tools", "harmonic_analysis.py")
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(root, "tools"))
from reflection_analysis import wave_number  # noqa: E402

depth, period = 0.5, 1.946
omega = 2 * math.pi / period
k, k2 = wave_number(omega, depth), wave_number(2 * omega, depth)
xs = [3.93 + 0.68 * i for i in range(9)]
rng = np.random.default_rng(7)
# A sample every 0.05 s, each late by up to 3e-4 s (a time step), over four periods.
t = 16 + np.arange(0, 4 * period, 0.05) + rng.uniform(0, 3e-4, int(math.ceil(4 * period / 0.05)))


def records(a1, kr, bound, free):
    recs = []
    for x in xs:
        th = k * x - omega * t + 0.3
        eta = a1 * np.cos(th) + kr * a1 * np.cos(-k * x - omega * t + 1.1)
        eta += bound * np.cos(2 * th) + free * np.cos(k2 * x - 2 * omega * t + 2.0)
        recs.append(eta + 0.002)  # a set-up the fit's mean takes
    return recs


def run(recs, tmp, name, extra=()):
    path = os.path.join(tmp, name + ".csv")
    names = [f"g{i + 1}" for i in range(len(xs))]
    with open(path, "w") as f:
        f.write("time [s]," + ",".join(f"{n} [m],{n}_target [m]" for n in names) + "\n")
        for i in range(len(t)):
            f.write(f"{t[i]:.9f}," + ",".join(f"{r[i]:.12e},0" for r in recs) + "\n")
    out = os.path.join(tmp, name + ".json")
    subprocess.run([sys.executable, tool, path, "--period", str(period), "--depth", str(depth),
                    "--x", ",".join(map(str, xs)), "--json", out, *extra], check=True)
    return json.load(open(out))


with tempfile.TemporaryDirectory() as tmp:
    # Linear interpolation of 39 samples a period: error (pi 0.05 / T)^2 / 2 = 0.3% of the first
    # harmonic, 1.3% of the second's own amplitude at most, less on average over the window.
    r = run(records(0.039, 0.05, 0.0054, 0.0031), tmp, "beating")
    assert abs(r["incident_height_m"] - 0.078) < 0.003 * 0.078, r["incident_height_m"]
    assert abs(r["reflection_coefficient"] - 0.05) < 0.003, r["reflection_coefficient"]
    assert abs(r["bound_second_harmonic_m"] - 0.0054) < 0.015 * 0.0054, r
    assert abs(r["free_second_harmonic_m"] - 0.0031) < 0.015 * 0.0031 + 0.003 * 0.0054, r
    r = run(records(0.039, 0.0, 0.0054, 0.0), tmp, "bound_only")
    assert r["free_over_bound"] < 0.01, r["free_over_bound"]
    # Against a current of 0.2 m/s, travelling in -x: k = (omega - k U)^2 / (g tanh kh).
    u = -0.2
    kc = k
    for _ in range(500):
        kc = (omega - kc * u) ** 2 / (9.81 * math.tanh(kc * depth))
    assert abs((omega - kc * u) ** 2 - 9.81 * kc * math.tanh(kc * depth)) < 1e-12
    recs = [0.02 * np.cos(-kc * x - omega * t + 0.5) for x in xs]
    r = run(recs, tmp, "opposing", ("--current", str(u)))
    assert abs(r["measured_wavelength_m"] - 2 * math.pi / kc) < 1e-4 * 2 * math.pi / kc, r
    assert abs(r["wavelength_ratio"] - 1) < 1e-4, r["wavelength_ratio"]
    assert abs(r["incident_height_m"] - 0.04) < 0.003 * 0.04, r["incident_height_m"]
    # The paddle's reflection: before t = 10 s the incident wave alone; after it, the far end's
    # reflection R and 0.3 R sent back by the paddle, with a phase of its own.
    tt = np.arange(0, 24, 0.05)
    xr = [1.0, 1.3, 1.7, 2.1, 2.5]
    path = os.path.join(tmp, "paddle.csv")
    with open(path, "w") as f:
        f.write("time [s]," + ",".join(f"g{i + 1} [m]" for i in range(len(xr))) + "\n")
        for ti in tt:
            row = []
            for x in xr:
                eta = 0.03 * math.cos(k * x - omega * ti + 0.2)
                if ti >= 10:
                    eta += 0.025 * math.cos(-k * x - omega * ti + 1.3)
                    eta += 0.3 * 0.025 * math.cos(k * x - omega * ti + 2.6)
                row.append(f"{eta:.12e}")
            f.write(f"{ti:.6f}," + ",".join(row) + "\n")
    out = os.path.join(tmp, "paddle.json")
    subprocess.run([sys.executable, tool, path, "--period", str(period), "--depth", str(depth),
                    "--x", ",".join(map(str, xr)), "--from", "12", "--to", str(12 + 5 * period),
                    "--before", f"1,{1 + 4 * period}", "--json", out], check=True)
    r = json.load(open(out))
    assert abs(r["paddle_reflection_coefficient"] - 0.3) < 0.01, r["paddle_reflection_coefficient"]
    assert abs(r["paddle_incident_height_before_m"] - 0.06) < 0.001, r
    # Three gauges at one position cannot separate anything: refused with a message.
    p = subprocess.run([sys.executable, tool, os.path.join(tmp, "beating.csv"), "--period",
                        str(period), "--depth", str(depth), "--gauges", "g1,g2,g3", "--x",
                        "2,2,2"], capture_output=True, text=True)
    assert p.returncode != 0 and "different positions" in p.stderr, p.stderr
print("PASS: harmonic analysis")
