#!/usr/bin/python3
"""Incident and reflected waves from three wave gauges (Mansard & Funke 1980).

In a flume, a wave gauge records the incident wave plus whatever the far end (an absorbing
beach, a damping zone, a wall) sends back. Mansard & Funke's method separates the two from
three gauges in a line along the flume: at each frequency f of the records' Fourier
transforms, gauge p at position x_p sees

    B_p = Z_I exp(-i k x_p) + Z_R exp(+i k x_p)            (k from the dispersion relation)

for the incident (travelling in +x) and reflected (in -x) complex amplitudes Z_I, Z_R: three
equations, two unknowns, solved by least squares (the third gauge makes the fit robust where
two gauges' spacing is near half a wavelength, where they cannot tell the two waves apart).
The reflection coefficient is Kr = sqrt(E_R / E_I), the energies summed over the frequency
band. Mansard, E.P.D. and Funke, E.R. (1980), "The measurement of incident and reflected
spectra using a least squares method", Proc. 17th Int. Conf. Coastal Engineering, 154-172.

Reads a CSV whose first column is time (s) and whose other columns are gauge elevations (m),
such as netsph's gauges.csv (`name [m]` headers). Usage:

  /usr/bin/python3 tools/reflection_analysis.py gauges.csv --gauges g1,g2,g3 \\
      --x 2.0,2.25,2.6 --depth 0.5 [--from 10] [--to 14] [--band 0.5,1.5] [--json out.json]

--from drops the start of the record (the ramp, the first wave front), --to its end; the
analysed record should hold a whole number of wave periods (regular waves: a Fourier bin then
falls on the wave's frequency) or be long (irregular ones). A run's gauges sample at the first
time step past each interval, so their times jitter by up to a time step: the records are
interpolated linearly onto a uniform grid over the same span first (the interpolation's error
is below (pi dt / T)^2 / 2 of the amplitude for a sample interval dt, 0.3% at 40 samples a
period).
--band limits the frequencies, Hz (default: where the incident spectrum holds energy, bins
above 1% of its peak). Prints Kr, the incident and reflected heights (Hm0 = 4 sqrt(m0)) and
the frequency of the incident peak.
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import sys

import numpy as np

G = 9.81


def wave_number(omega: float, depth: float, g: float = G) -> float:
    """The root k of omega^2 = g k tanh(k h) (Newton; netsph's waves/dispersion.cpp solves the
    same relation for the run)."""
    k = omega * omega / g / math.tanh((omega * omega / g * depth) ** 0.75) ** (2.0 / 3.0)
    for _ in range(50):
        t = math.tanh(k * depth)
        step = (g * k * t - omega * omega) / (g * (t + k * depth * (1 - t * t)))
        k -= step
        if abs(step) <= 1e-15 * k:
            break
    return k


def read_records(path: str, names: list[str]) -> tuple[np.ndarray, list[np.ndarray]]:
    """Time and the named columns of a CSV (headers `name` or `name [unit]`)."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        sys.exit(f"{path}: cannot read it: {e.strerror}")
    if len(rows) < 3:
        sys.exit(f"{path}: fewer than two rows of data")
    header = [h.split(" [")[0].strip() for h in rows[0]]
    cols = []
    for n in names:
        if n not in header:
            sys.exit(f"{path}: no column '{n}' (columns: {', '.join(header[1:])})")
        cols.append(header.index(n))
    values = []
    for line, r in enumerate(rows[1:], start=2):
        if not r:
            continue
        if len(r) != len(header):
            sys.exit(f"{path}:{line}: {len(r)} values, the header has {len(header)} columns")
        try:
            values.append([float(v) for v in r])
        except ValueError:
            sys.exit(f"{path}:{line}: a value that is not a number")
    data = np.array(values, dtype=float)
    return data[:, 0], [data[:, c] for c in cols]


def separate(t: np.ndarray, records: list[np.ndarray], x: list[float], depth: float,
             band: tuple[float, float] | None = None) -> dict:
    """Mansard & Funke's least squares at every Fourier frequency of the records (uniformly
    sampled, the same times for every gauge). Returns Kr and the spectra's summaries."""
    n = len(t)
    dt = (t[-1] - t[0]) / (n - 1)
    if np.max(np.abs(np.diff(t) - dt)) > 1e-6 * dt:
        if np.any(np.diff(t) <= 0):
            sys.exit("the record's times do not increase")
        uniform = np.linspace(t[0], t[-1], n)
        records = [np.interp(uniform, t, r) for r in records]
        t = uniform
    spectra = [np.fft.rfft(r - np.mean(r)) * 2 / n for r in records]  # amplitude spectra
    freqs = np.fft.rfftfreq(n, dt)
    zi = np.zeros(len(freqs), dtype=complex)
    zr = np.zeros(len(freqs), dtype=complex)
    cond = np.full(len(freqs), np.inf)
    for j in range(1, len(freqs)):
        k = wave_number(2 * math.pi * freqs[j], depth)
        a = np.array([[np.exp(-1j * k * xp), np.exp(1j * k * xp)] for xp in x])
        b = np.array([s[j] for s in spectra])
        sol, _, _, sv = np.linalg.lstsq(a, b, rcond=None)
        zi[j], zr[j] = sol
        cond[j] = sv[0] / sv[-1] if sv[-1] > 0 else np.inf
    ei, er = np.abs(zi) ** 2 / 2, np.abs(zr) ** 2 / 2  # variance per bin
    if band is None:
        use = ei > 0.01 * np.max(ei[1:])
    else:
        use = (freqs >= band[0]) & (freqs <= band[1])
    use[0] = False
    # Bins where the gauges cannot tell the waves apart (spacing a multiple of half a
    # wavelength for every pair) leave the fit singular: left out, and said.
    singular = use & (cond > 1e6)
    use &= ~singular
    if not np.any(use):
        sys.exit("no frequency in the band to analyse (empty band, or singular gauge spacing)")
    m0_i, m0_r = float(np.sum(ei[use])), float(np.sum(er[use]))
    return {
        "reflection_coefficient": math.sqrt(m0_r / m0_i),
        "incident_hm0_m": 4 * math.sqrt(m0_i),
        "reflected_hm0_m": 4 * math.sqrt(m0_r),
        "incident_peak_frequency_hz": float(freqs[use][np.argmax(ei[use])]),
        "frequencies_used": int(np.sum(use)),
        "frequencies_singular": int(np.sum(singular)),
        "band_hz": [float(freqs[use][0]), float(freqs[use][-1])],
    }


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("csv")
    p.add_argument("--gauges", required=True, help="three column names, comma-separated")
    p.add_argument("--x", required=True, help="the gauges' positions along the flume, m")
    p.add_argument("--depth", type=float, required=True, help="still-water depth, m")
    p.add_argument("--from", dest="t0", type=float, default=None, help="start time, s")
    p.add_argument("--to", dest="t1", type=float, default=None, help="end time, s")
    p.add_argument("--band", default=None, help="f_min,f_max in Hz")
    p.add_argument("--json", default=None, help="also write the results to this file")
    a = p.parse_args()
    names = a.gauges.split(",")
    xs = [float(v) for v in a.x.split(",")]
    if len(names) != 3 or len(xs) != 3:
        sys.exit("--gauges and --x need three entries each")
    if len(set(xs)) != 3:
        sys.exit("--x: the three gauges need three different positions")
    if not a.depth > 0:
        sys.exit("--depth must be positive")
    band = None
    if a.band:
        lo, hi = (float(v) for v in a.band.split(","))
        band = (lo, hi)
    t, recs = read_records(a.csv, names)
    if a.t0 is not None or a.t1 is not None:
        keep = (t >= (a.t0 if a.t0 is not None else -math.inf)) & (
            t <= (a.t1 if a.t1 is not None else math.inf))
        t, recs = t[keep], [r[keep] for r in recs]
    if len(t) < 16:
        sys.exit("fewer than 16 samples to analyse")
    r = separate(t, recs, xs, a.depth, band)
    print(f"Kr = {r['reflection_coefficient']:.4f}  incident Hm0 = {r['incident_hm0_m']:.5g} m  "
          f"reflected Hm0 = {r['reflected_hm0_m']:.5g} m  peak {r['incident_peak_frequency_hz']:.4g}"
          f" Hz  ({r['frequencies_used']} frequencies in {r['band_hz'][0]:.4g}-"
          f"{r['band_hz'][1]:.4g} Hz, {r['frequencies_singular']} singular left out)")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(r, f, indent=2)


if __name__ == "__main__":
    main()
