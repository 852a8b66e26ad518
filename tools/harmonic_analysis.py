#!/usr/bin/python3
"""Bound and free second harmonics of a regular wave from a line of wave gauges.

A paddle moved to first order makes the Stokes wave's second harmonic, which is bound to the
first (wave number 2k, travelling at the wave's speed), and also a free second harmonic: a
wave of frequency 2 omega in its own right, with the wave number k2 of the dispersion relation
at 2 omega (k2 > 2k), travelling slower. Their sum beats along the flume over 2 pi / (k2 - 2k).
With gauges at several positions x_p along the flume, the complex amplitude of the second
harmonic at each,

    c2(x_p) = B exp(i 2k x_p) + F exp(i k2 x_p),

gives the bound (B) and free (F) amplitudes by least squares (the separation of Mansard & Funke
1980, applied to the two wave numbers at 2 omega instead of the incident and reflected waves at
one frequency; the bound-free split is that of, e.g., Schaffer 1996, Ocean Eng. 23(1):47-88).
The first harmonic's incident and reflected waves come the same way from
c1(x_p) = I exp(i k x_p) + R exp(-i k x_p). The measured wavelength is 2 pi over the slope of
the first harmonic's phase along the gauges (a straight-line fit to the unwrapped phases,
gauges closer than half a wavelength apart); on a current (--current U, m/s, along the waves'
travel: negative against them) it is compared with the Doppler-shifted dispersion relation
(omega - k U)^2 = g k tanh kh for the earth-frame period, which also gives the wave numbers
the separations use (the free second harmonic's at 2 omega on the same current).

Each gauge's record is fitted over [--from, --to] by least squares with a mean and the first
three harmonics of the given period (a whole number of periods in the window is best; the
records are first interpolated onto a uniform grid, since a run's gauges sample at the first
step past each interval). Wave numbers come from linear dispersion at the given depth. The
gauges should span at least one beat length (printed), or B and F cannot be told apart (the
fit's condition number says so).

Usage:
  /usr/bin/python3 tools/harmonic_analysis.py gauges.csv --period 1.946 --depth 0.5 \\
      [--current 0.2] [--gauges g1,g2,...] [--x 3.93,4.61,...] [--from 16] [--to 23.78] \\
      [--before T0,T1] [--json out.json] [--plot out.png]

--before T0,T1 gives a second window, before anything came back from the far end: the
incident wave there is the paddle's own, and the change of the incident wave between the two
windows, over the reflected wave of the main window, is the paddle's reflection coefficient
(1 for a paddle that re-reflects everything, 0 for one that absorbs it: active absorption).
--plot draws the first and second harmonics' amplitudes at the gauges with the fitted incident
plus reflected, and bound plus free, waves between them (matplotlib). --gauges defaults to
every column without "_target"; --x to the positions in the run's
summary.json beside the CSV (its "gauges" entries) when it has them. Positions are measured
from the paddle's rest position (the phase origin does not change the amplitudes).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reflection_analysis import G, read_records, wave_number  # noqa: E402


def wave_number_on_current(omega: float, depth: float, current: float, g: float = G,
                           blocked_ok: bool = False) -> float | None:
    """The root k of (omega - k U)^2 = g k tanh(k h) with omega - k U > 0 (the waves travel
    with U > 0 along them, against them for U < 0; netsph's waves/dispersion.cpp solves the
    same relation). Bisection: the left side minus the right falls through zero once on that
    branch below the blocking point. A blocked wave: None with blocked_ok, else an exit."""
    if current == 0:
        return wave_number(omega, depth, g)
    lo, hi = 0.0, 1.0
    f = lambda k: (omega - k * current) ** 2 - g * k * math.tanh(k * depth)  # noqa: E731
    while f(hi) > 0 and omega - hi * current > 0:
        hi *= 2
        if hi > 1e6:
            if blocked_ok:
                return None
            sys.exit(f"the waves are blocked by a current of {current} m/s: no wave number")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0 and omega - mid * current > 0:
            lo = mid
        else:
            hi = mid
    if f(lo) > 1e-9 * omega * omega or omega - lo * current <= 0:
        if blocked_ok:
            return None
        sys.exit(f"the waves are blocked by a current of {current} m/s: no wave number")
    return 0.5 * (lo + hi)


def harmonic_amplitudes(t: np.ndarray, eta: np.ndarray, omega: float,
                        harmonics: int = 3) -> tuple[list[complex], float]:
    """Complex amplitudes c_n with eta = mean + sum Re(c_n exp(-i n omega t)), and the fit's
    residual (rms) over the rms of the record about its mean."""
    cols = [np.ones_like(t)]
    for n in range(1, harmonics + 1):
        cols += [np.cos(n * omega * t), np.sin(n * omega * t)]
    a = np.stack(cols, axis=1)
    sol, *_ = np.linalg.lstsq(a, eta, rcond=None)
    # a cos + b sin = Re((a + i b) exp(-i n omega t))
    c = [complex(sol[2 * n - 1], sol[2 * n]) for n in range(1, harmonics + 1)]
    resid = eta - a @ sol
    spread = np.sqrt(np.mean((eta - np.mean(eta)) ** 2))
    return c, float(np.sqrt(np.mean(resid**2)) / spread) if spread > 0 else 0.0


def two_wave_fit(c: np.ndarray, x: np.ndarray, k_a: float, k_b: float) -> tuple[complex, complex,
                                                                                 float]:
    """Least squares c(x) = A exp(i k_a x) + B exp(i k_b x); returns A, B and the fit's
    condition number."""
    m = np.stack([np.exp(1j * k_a * x), np.exp(1j * k_b * x)], axis=1)
    sol, _, _, sv = np.linalg.lstsq(m, c, rcond=None)
    return complex(sol[0]), complex(sol[1]), float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf


def stokes_bound_amplitude(a: float, k: float, depth: float) -> float:
    """The Stokes second-order surface's amplitude for first-order amplitude a (Dean &
    Dalrymple 1991, sec. 11.2): k a^2 cosh kh (2 + cosh 2kh) / (4 sinh^3 kh)."""
    kh = k * depth
    return k * a * a * math.cosh(kh) * (2 + math.cosh(2 * kh)) / (4 * math.sinh(kh) ** 3)


def phase_wave_number(c: np.ndarray, x: np.ndarray) -> float:
    """The slope of the unwrapped phase of c along x (the gauges sorted by x), by least squares:
    the wave number for a wave exp(i k x), negative for one travelling in -x."""
    order = np.argsort(x)
    phase = np.unwrap(np.angle(c[order]))
    return float(np.polyfit(x[order], phase, 1)[0])


def analyse(t: np.ndarray, records: list[np.ndarray], x: list[float], period: float,
            depth: float, current: float = 0.0, direction: float | None = None) -> dict:
    n = len(t)
    if np.any(np.diff(t) <= 0):
        sys.exit("the record's times do not increase")
    uniform = np.linspace(t[0], t[-1], n)
    records = [np.interp(uniform, t, r) for r in records]
    omega = 2 * math.pi / period
    k = wave_number_on_current(omega, depth, current)
    # The free second harmonic is blocked by a weaker opposing current than the first: then
    # there is none to separate (None), and the first harmonic is still measured.
    k2 = wave_number_on_current(2 * omega, depth, current, blocked_ok=True)
    xs_sorted = np.sort(np.asarray(x, dtype=float))
    widest = float(np.max(np.diff(xs_sorted)))
    if widest >= 0.5 * (2 * math.pi / k):
        sys.exit(f"gauges {widest:.4g} m apart, at least half a wavelength ({math.pi / k:.4g} m): "
                 "the wave's phase along them is ambiguous; give gauges closer together")
    fits = [harmonic_amplitudes(uniform, r, omega) for r in records]
    xs = np.array(x, dtype=float)
    c1 = np.array([f[0][0] for f in fits])
    c2 = np.array([f[0][1] for f in fits])
    # A wave travelling in -x has its phase falling along x: the fits take the waves' direction
    # from the measured phase slope, unless it is given (a strong reflection, near a standing
    # wave, leaves the slope's sign to chance).
    k_measured = phase_wave_number(c1, xs)
    sign = direction if direction is not None else (1.0 if k_measured >= 0 else -1.0)
    inc, refl, cond1 = two_wave_fit(c1, xs, sign * k, -sign * k)
    if k2 is not None:
        bound, free, cond2 = two_wave_fit(c2, xs, sign * 2 * k, sign * k2)
    else:
        # Only the bound harmonic travels: its amplitude is the mean of the gauges' own.
        bound, free, cond2 = complex(np.mean(np.abs(c2))), 0j, 1.0
    a1 = abs(inc)
    separated = {"_inc": inc, "_refl": refl, "_bound": bound, "_free": free}  # for plot()
    return separated | {
        "direction": sign,
        "period_s": period,
        "current_m_per_s": current,
        "k_per_m": k,
        "wavelength_m": 2 * math.pi / k,
        "measured_wavelength_m": 2 * math.pi / abs(k_measured) if k_measured else math.inf,
        "wavelength_ratio": abs(k) / abs(k_measured) if k_measured else math.inf,
        "k2_free_per_m": k2,
        "beat_length_m": 2 * math.pi / (k2 - 2 * k) if k2 is not None else None,
        "gauge_span_m": float(xs.max() - xs.min()),
        "incident_height_m": 2 * a1,
        "reflection_coefficient": abs(refl) / a1 if a1 > 0 else math.nan,
        "bound_second_harmonic_m": abs(bound),
        "free_second_harmonic_m": abs(free) if k2 is not None else None,
        "free_over_bound": (abs(free) / abs(bound) if abs(bound) > 0 else math.inf)
        if k2 is not None else None,
        "stokes_bound_for_measured_height_m": stokes_bound_amplitude(a1, k, depth),
        "condition_first": cond1,
        "condition_second": cond2,
        "gauges": [{"x_m": float(xp), "first_harmonic_m": abs(f[0][0]),
                    "second_harmonic_m": abs(f[0][1]), "third_harmonic_m": abs(f[0][2]),
                    "fit_residual": f[1]} for xp, f in zip(xs, fits)],
    }


def plot(r: dict, path: str, title: str) -> None:
    """The harmonics' amplitudes at the gauges and the two-wave fits along the flume."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    xs = np.array([g["x_m"] for g in r["gauges"]])
    x = np.linspace(xs.min(), xs.max(), 400)
    sign = r["direction"]
    fit1 = np.abs(r["_inc"] * np.exp(1j * sign * r["k_per_m"] * x) +
                  r["_refl"] * np.exp(-1j * sign * r["k_per_m"] * x))
    k2 = r["k2_free_per_m"] if r["k2_free_per_m"] is not None else 0.0
    fit2 = np.abs(r["_bound"] * np.exp(1j * sign * 2 * r["k_per_m"] * x) +
                  r["_free"] * np.exp(1j * sign * k2 * x))
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    a1.plot(xs, [g["first_harmonic_m"] * 1e3 for g in r["gauges"]], "o", label="gauges")
    a1.plot(x, fit1 * 1e3, "-", label=f"incident + reflected (Kr = {r['reflection_coefficient']:.3f})")
    a1.set_ylabel("first harmonic, mm")
    a1.legend()
    a2.plot(xs, [g["second_harmonic_m"] * 1e3 for g in r["gauges"]], "o", label="gauges")
    free = r["free_second_harmonic_m"]
    a2.plot(x, fit2 * 1e3, "-", label=f"bound {r['bound_second_harmonic_m'] * 1e3:.2f} mm + free "
            + (f"{free * 1e3:.2f} mm" if free is not None else "(blocked)"))
    a2.axhline(r["stokes_bound_for_measured_height_m"] * 1e3, ls="--", c="gray",
               label="Stokes bound harmonic")
    a2.set_ylabel("second harmonic, mm")
    a2.set_xlabel("x, m")
    a2.set_ylim(bottom=0)
    a2.legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def positions_from_summary(csv_path: str, names: list[str]) -> list[float] | None:
    path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "summary.json")
    try:
        gauges = json.load(open(path)).get("gauges") or {}
    except (OSError, ValueError):
        return None
    entries = gauges.get("gauges", gauges) if isinstance(gauges, dict) else gauges
    where = {}
    if isinstance(entries, list):
        for g in entries:
            if isinstance(g, dict) and "name" in g and "x_m" in g:
                where[g["name"]] = g["x_m"]
    elif isinstance(entries, dict):
        for name, g in entries.items():
            if isinstance(g, dict) and "x_m" in g:
                where[name] = g["x_m"]
    if not all(n in where for n in names):
        return None
    return [float(where[n]) for n in names]


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("csv")
    p.add_argument("--period", type=float, required=True, help="the wave period, s")
    p.add_argument("--depth", type=float, required=True, help="still-water depth, m")
    p.add_argument("--current", type=float, default=0.0,
                   help="uniform current along the waves' travel, m/s (negative: opposing)")
    p.add_argument("--gauges", default=None, help="column names, comma-separated")
    p.add_argument("--x", default=None, help="the gauges' distances from the paddle, m")
    p.add_argument("--from", dest="t0", type=float, default=None, help="start time, s")
    p.add_argument("--to", dest="t1", type=float, default=None, help="end time, s")
    p.add_argument("--json", default=None, help="also write the results to this file")
    p.add_argument("--plot", default=None, help="also draw the harmonics along the flume (PNG)")
    p.add_argument("--direction", type=int, choices=(1, -1), default=None,
                   help="the incident waves travel in +x (1) or -x (-1); default: from the "
                   "phase along the gauges (or the --before window's)")
    p.add_argument("--before", default=None,
                   help="T0,T1 (write --before=T0,T1 if T0 is negative): a window before the "
                   "main one with the paddle's own wave only (paddle reflection)")
    a = p.parse_args()
    for name, v in (("--period", a.period), ("--depth", a.depth)):
        if not (math.isfinite(v) and 1e-6 < v < 1e6):
            sys.exit(f"{name} must be a positive number in (1e-6, 1e6), not {v}")
    if not (math.isfinite(a.current) and abs(a.current) < 1e3):
        sys.exit(f"--current must be a finite speed below 1000 m/s, not {a.current}")
    if a.gauges:
        names = a.gauges.split(",")
    else:
        try:
            with open(a.csv) as f:
                header = [h.split(" [")[0].strip() for h in f.readline().strip().split(",")]
        except OSError as e:
            sys.exit(f"{a.csv}: cannot read it: {e.strerror}")
        names = [h for h in header[1:] if not h.endswith("_target")]
    try:
        xs = [float(v) for v in a.x.split(",")] if a.x else positions_from_summary(a.csv, names)
    except ValueError:
        sys.exit(f"--x must be numbers separated by commas, not '{a.x}'")
    if xs is not None and not all(math.isfinite(v) for v in xs):
        sys.exit("--x: every position must be a finite number")
    if xs is None:
        sys.exit("give --x: the gauges' positions (summary.json beside the CSV does not list "
                 "them)")
    if len(xs) != len(names):
        sys.exit(f"--x has {len(xs)} positions for {len(names)} gauges")
    if len(set(xs)) < 3 or len(set(xs)) != len(xs):
        sys.exit("need at least three gauges at different positions")
    t_all, recs_all = read_records(a.csv, names)
    keep = (t_all >= (a.t0 if a.t0 is not None else -math.inf)) & (
        t_all <= (a.t1 if a.t1 is not None else math.inf))
    t, recs = t_all[keep], [r[keep] for r in recs_all]
    if len(t) < 16 or t[-1] - t[0] < a.period:  # the data actually in the window
        sys.exit("the window holds less than one period (or fewer than 16 samples)")
    for name, r in zip(names, recs):
        if np.any(np.isinf(r)):
            sys.exit(f"gauge {name} has an infinite value in the window")
        if not np.all(np.isfinite(r)):
            sys.exit(f"gauge {name} found no water somewhere in the window (nan)")
    direction = float(a.direction) if a.direction else None
    first = None
    if a.before:
        try:
            b0, b1 = (float(v) for v in a.before.split(","))
        except ValueError:
            sys.exit(f"--before must be T0,T1 in s, not '{a.before}'")
        if a.t0 is None or not b1 <= a.t0:
            sys.exit(f"--before {a.before}: the window must end at or before the main window's "
                     f"start (--from{'' if a.t0 is None else ' = ' + format(a.t0, 'g')}): it holds "
                     "the paddle's wave before anything came back")
        inside = (t_all >= b0) & (t_all <= b1)
        if np.count_nonzero(inside) < 16 or not t_all[inside][-1] - t_all[inside][0] >= a.period:
            sys.exit("--before: the record holds less than one period (or fewer than 16 samples) "
                     "in that window")
        early = [rec[inside] for rec in recs_all]
        if not all(np.all(np.isfinite(e)) for e in early):
            sys.exit("--before: a gauge found no water somewhere in the window (nan)")
        first = analyse(t_all[inside], early, xs, a.period, a.depth, a.current, direction)
        if direction is None:
            direction = first["direction"]  # the paddle's wave alone: its direction is clear
    r = analyse(t, recs, xs, a.period, a.depth, a.current, direction)
    if first is not None:
        # The fits' phases are those of absolute time (cos omega t): the two windows' complex
        # amplitudes compare directly.
        change = abs(r["_inc"] - first["_inc"])
        r["paddle_incident_height_before_m"] = first["incident_height_m"]
        r["paddle_reflection_coefficient"] = change / abs(r["_refl"]) if abs(r["_refl"]) > 0 \
            else math.inf
    print(f"first harmonic: incident H = {r['incident_height_m']:.5g} m, Kr = "
          f"{r['reflection_coefficient']:.4f} (condition {r['condition_first']:.3g})")
    if "paddle_reflection_coefficient" in r:
        print(f"paddle: incident H {r['paddle_incident_height_before_m']:.5g} m before, "
              f"{r['incident_height_m']:.5g} m after the far end's reflection came back; the "
              f"paddle's reflection coefficient = {r['paddle_reflection_coefficient']:.4f}")
    print(f"wavelength: measured {r['measured_wavelength_m']:.4g} m, dispersion relation "
          f"{r['wavelength_m']:.4g} m{' on the current' if a.current else ''} (measured / theory "
          f"= {r['wavelength_ratio']:.4f})")
    if r["k2_free_per_m"] is None:
        print(f"second harmonic: {r['bound_second_harmonic_m'] * 1e3:.4g} mm, all bound (a free "
              f"wave at twice the frequency is blocked by this current)")
    else:
        print(f"second harmonic: bound {r['bound_second_harmonic_m'] * 1e3:.4g} mm (Stokes, for "
              f"the measured height: {r['stokes_bound_for_measured_height_m'] * 1e3:.4g} mm), free "
              f"{r['free_second_harmonic_m'] * 1e3:.4g} mm, free / bound = "
              f"{r['free_over_bound']:.3f} (condition {r['condition_second']:.3g}; beat length "
              f"{r['beat_length_m']:.3g} m, gauges span {r['gauge_span_m']:.3g} m)")
    if a.plot:
        plot(r, a.plot, os.path.basename(os.path.dirname(os.path.abspath(a.csv))))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({k: v for k, v in r.items() if not k.startswith("_")}, f, indent=2)


if __name__ == "__main__":
    main()
