#!/usr/bin/python3
"""The variance spectrum of an irregular sea at wave gauges, measured against the target.

For each gauge of gauges.csv (or those named with --gauges) the record over [--from, --to],
and its target column (<gauge>_target, the linear sum of the sea's components the run compares
with), is put on a uniform grid (a run's gauges sample at the first step past each interval),
its mean taken away, and its one-sided variance density S(f) estimated by Welch's method
(segments of --segment seconds, half overlapping, each with a Hann window; Welch 1967, IEEE
Trans. Audio Electroacoust. 15(2):70-73). From S(f) over [--fmin, --fmax]:

    m_n = integral f^n S(f) df,   Hm0 = 4 sqrt(m0),   Tm01 = m0 / m1,   Tp = 1 / f at the peak

(the spectral wave height and periods of IAHR/PIANC 1986). Measured and target go through the
same estimate, so the window, the segments and the grid affect both alike: their ratio is what
the run did to the sea. Prints a table; --json writes it, --plot draws both spectra.

Usage:
  /usr/bin/python3 tools/spectrum_analysis.py out/irregular_piston2d/gauges.csv --from 8 \\
      --to 30 [--gauges one_L,...] [--segment 8] [--fmin 0.2] [--fmax 3] [--json s.json] \\
      [--plot spectra.png]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ beside the tools
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reflection_analysis import read_records  # noqa: E402


def welch(x: np.ndarray, dt: float, segment: int) -> tuple[np.ndarray, np.ndarray]:
    """One-sided variance density of x (sampled every dt) by Welch's method: segments of
    `segment` samples, half overlapping, Hann windowed; the density integrates to x's
    variance (to the window's leakage)."""
    if segment > len(x):
        segment = len(x)
    step = max(segment // 2, 1)
    window = np.hanning(segment)
    scale = 1.0 / (np.sum(window**2) / dt)  # density normalisation: sum S df = variance
    spectra = []
    for start in range(0, len(x) - segment + 1, step):
        piece = x[start:start + segment]
        piece = (piece - piece.mean()) * window
        p = np.abs(np.fft.rfft(piece)) ** 2 * scale
        p[1:-1] *= 2  # one-sided (the Nyquist bin of an even segment, and 0 Hz, once)
        if segment % 2 == 1:
            p[-1] *= 2
        spectra.append(p)
    f = np.fft.rfftfreq(segment, dt)
    return f, np.mean(spectra, axis=0)


def moments(f: np.ndarray, s: np.ndarray, band: tuple[float, float]) -> dict:
    keep = (f >= band[0]) & (f <= band[1])
    fk, sk = f[keep], s[keep]
    if len(fk) < 3 or not np.any(sk > 0):
        return {"hm0_m": 0.0, "tm01_s": float("nan"), "tp_s": float("nan")}
    df = fk[1] - fk[0]
    m0, m1 = float(np.sum(sk) * df), float(np.sum(fk * sk) * df)
    return {"hm0_m": 4 * math.sqrt(m0), "tm01_s": m0 / m1, "tp_s": float(1 / fk[np.argmax(sk)])}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--gauges", help="comma-separated gauge names (default: every gauge)")
    ap.add_argument("--from", dest="t0", type=float, default=None, help="window start, s")
    ap.add_argument("--to", dest="t1", type=float, default=None, help="window end, s")
    ap.add_argument("--segment", type=float, default=8.0, help="Welch segment length, s")
    ap.add_argument("--fmin", type=float, default=0.0, help="lowest frequency of the moments, Hz")
    ap.add_argument("--fmax", type=float, default=float("inf"), help="highest, Hz")
    ap.add_argument("--json")
    ap.add_argument("--plot")
    a = ap.parse_args()

    with open(a.csv) as f:
        header = [h.split(" [")[0].strip() for h in f.readline().strip().split(",")]
    names = a.gauges.split(",") if a.gauges else [
        h for h in header[1:] if not h.endswith("_target") and h + "_target" in header]
    if not names:
        sys.exit(f"{a.csv}: no gauge with a target column (<name>_target)")
    columns = []
    for n in names:
        if n + "_target" not in header:
            sys.exit(f"{a.csv}: gauge '{n}' has no target column '{n}_target'")
        columns += [n, n + "_target"]
    t, recs = read_records(a.csv, columns)
    t0 = t[0] if a.t0 is None else a.t0
    t1 = t[-1] if a.t1 is None else a.t1
    inside = (t >= t0) & (t <= t1)
    if np.count_nonzero(inside) < 16:
        sys.exit(f"{a.csv}: fewer than 16 samples in [{t0:g}, {t1:g}] s")
    tw = t[inside]
    if np.any(np.diff(tw) <= 0):
        sys.exit(f"{a.csv}: the record's times do not increase")
    dt = float(np.median(np.diff(tw)))
    grid = np.arange(tw[0], tw[-1] + 0.5 * dt, dt)
    segment = int(round(a.segment / dt))
    if segment < 8:
        sys.exit(f"--segment {a.segment:g} s holds fewer than 8 samples (every {dt:g} s)")
    band = (a.fmin, a.fmax)
    results, curves = [], []
    for k, name in enumerate(names):
        row = {"gauge": name}
        pair = []
        for which, rec in (("measured", recs[2 * k]), ("target", recs[2 * k + 1])):
            f, s = welch(np.interp(grid, tw, rec[inside]), dt, segment)
            row[which] = moments(f, s, band)
            pair.append((f, s))
        m, tg = row["measured"], row["target"]
        row["hm0_ratio"] = m["hm0_m"] / tg["hm0_m"] if tg["hm0_m"] > 0 else float("nan")
        row["tm01_ratio"] = m["tm01_s"] / tg["tm01_s"]
        results.append(row)
        curves.append(pair)

    print(f"window {grid[0]:.3f}-{grid[-1]:.3f} s, Welch segments of {segment * dt:.3g} s "
          f"(resolution {1 / (segment * dt):.3g} Hz), band [{band[0]:g}, {band[1]:g}] Hz")
    print(f"{'gauge':16s} {'Hm0 meas':>9s} {'Hm0 tgt':>9s} {'ratio':>7s} {'Tm01 meas':>10s} "
          f"{'Tm01 tgt':>9s} {'ratio':>7s} {'Tp meas':>8s} {'Tp tgt':>8s}")
    for r in results:
        m, tg = r["measured"], r["target"]
        print(f"{r['gauge']:16s} {m['hm0_m']:9.4f} {tg['hm0_m']:9.4f} {r['hm0_ratio']:7.3f} "
              f"{m['tm01_s']:10.3f} {tg['tm01_s']:9.3f} {r['tm01_ratio']:7.3f} "
              f"{m['tp_s']:8.3f} {tg['tp_s']:8.3f}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"window_s": [float(grid[0]), float(grid[-1])], "segment_s": segment * dt,
                       "gauges": results}, f, indent=2)
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for r, ((fm, sm), (ft, st)) in zip(results, curves):
            line, = ax.plot(fm, sm, label=f"{r['gauge']} measured")
            ax.plot(ft, st, "--", color=line.get_color(), label=f"{r['gauge']} target")
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel("variance density [m$^2$/Hz]")
        ax.set_xlim(0, min(band[1], 3.5) if math.isfinite(band[1]) else 3.5)
        ax.legend(fontsize=8)
        ax.set_title("gauge spectra (Welch), measured and target")
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)


if __name__ == "__main__":
    main()
