#!/usr/bin/env bash
# Debian's ParaView opens netsph's output: tools/render_snapshot.py (pvbatch under xvfb-run)
# reads the last snapshot of a small coupled-net run (tests/cases/good/plot_smoke.toml) and
# the net's XDMF series, renders a PNG, and reports what it read; the point count and the speed
# and pressure ranges must equal those in the snapshot's HDF5 file (read with h5py), the net's
# knots, twines and tension those of its last VTK file. Skipped
# (exit 77, and said so) when pvbatch or xvfb-run is not installed:
#   apt-get install --no-install-recommends python3-paraview xvfb xauth
set -euo pipefail
netsph="$1"
case_file="$2"
script="$3"
for tool in pvbatch xvfb-run; do
  if ! command -v "$tool" > /dev/null; then
    echo "SKIP: $tool is not installed (python3-paraview xvfb xauth)"
    exit 77
  fi
done
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$netsph" -q run "$case_file" -o "$tmp/run" --no-plots
# Xvfb sometimes loses the race with its client on a loaded machine: try three times.
for attempt in 1 2 3; do
  if xvfb-run -a pvbatch "$script" "$tmp/run" --report "$tmp/report.json" > "$tmp/pv.log" 2>&1; then
    break
  fi
  [ "$attempt" = 3 ] && { tail -20 "$tmp/pv.log"; exit 1; }
done
/usr/bin/python3 - "$tmp/run" "$tmp/report.json" <<'PY'
import glob, json, sys
import h5py, numpy as np
run, report = sys.argv[1], json.load(open(sys.argv[2]))
last = sorted(glob.glob(run + "/snapshots/particles_*.h5"))[-1]
with h5py.File(last) as f:
    n = f["position"].shape[0]
    speed = np.linalg.norm(f["velocity"][:].astype(float), axis=1)
    pressure = f["pressure"][:]
assert report["points"] == n, (report["points"], n)
assert abs(report["speed_range"][1] - speed.max()) <= 1e-6 * speed.max(), (report, speed.max())
assert abs(report["pressure_range"][0] - pressure.min()) <= 1e-3, (report, pressure.min())
assert abs(report["pressure_range"][1] - pressure.max()) <= 1e-3, (report, pressure.max())
import os
# The net: ParaView's knots and twines are the generator's, its tensions the VTK file's.
nets = report["nets"]
assert list(nets) == ["tether"], nets
last_vtk = sorted(glob.glob(run + "/net_tether_*.vtk"), key=lambda p: int(p.split("_")[-1][:-4]))[-1]
tokens = open(last_vtk).read().split()
knots, twines = int(tokens[tokens.index("POINTS") + 1]), int(tokens[tokens.index("LINES") + 1])
tension = float(tokens[tokens.index("tension") + 5])  # SCALARS tension double 1 LOOKUP_TABLE default v
assert nets["tether"]["points"] == knots and nets["tether"]["cells"] == twines, (nets, knots, twines)
assert abs(nets["tether"]["tension_range"][1] - tension) <= 1e-6 * tension, (nets, tension)
size = os.path.getsize(report["image"])
assert size > 20000, f"the rendered image is only {size} bytes"
print(f"ok: ParaView read {n} points, speed up to {speed.max():.4g} m/s, image {size} bytes")
PY
