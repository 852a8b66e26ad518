#!/usr/bin/env bash
# `netsph run --restart DIR`: a run stopped after 31 steps (--max-steps) and continued from its
# checkpoint writes the same series, probe, body and net files and the same last snapshot as
# the run done in one go (tests/cases/good/plot_smoke.toml: inlet, outlet, a coupled net,
# probes). Only the wall-clock column of series.csv may differ. Then a finished run extended
# with --restart --set simulation.end_time (cases/floating_box2d.toml, the default averaging
# window: the run's second half) averages the body force over the new window, as the run done
# in one go does, not over the sums of the first run's window.
set -euo pipefail
netsph="$1"
case_file="$2"
box_case="$3"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$netsph" -q run "$case_file" --set simulation.end_time=0.12 -o "$tmp/whole" --no-plots
"$netsph" -q run "$case_file" --set simulation.end_time=0.12 -o "$tmp/split" --no-plots \
  --max-steps 31
[ -f "$tmp/split/checkpoint.h5" ] || { echo "no checkpoint after --max-steps"; exit 1; }
"$netsph" -q run --restart "$tmp/split" --no-plots
wall=$(head -1 "$tmp/whole/series.csv" | tr ',' '\n' | grep -n '^wall_time' | cut -d: -f1)
drop_wall() { cut -d, -f"1-$((wall - 1)),$((wall + 1))-" "$1"; }
diff <(drop_wall "$tmp/whole/series.csv") <(drop_wall "$tmp/split/series.csv")
for f in bodies.csv probes/line.csv probes/line_mean.csv probes/side_mean.csv tether.vtk.series tether.xdmf \
         net_tether_6.vtk particles.xdmf; do
  cmp "$tmp/whole/$f" "$tmp/split/$f" || { echo "$f differs"; exit 1; }
done
last=$(ls "$tmp/whole/snapshots" | tail -1)
[ "$last" = "$(ls "$tmp/split/snapshots" | tail -1)" ] || { echo "snapshot lists differ"; exit 1; }
h5diff "$tmp/whole/snapshots/$last" "$tmp/split/snapshots/$last"
# A restart without a checkpoint, or with a case as well, is a clear error.
if "$netsph" -q run --restart "$tmp/no-such-run" 2>/dev/null; then echo "restart without checkpoint ran"; exit 1; fi
if "$netsph" -q run "$case_file" --restart "$tmp/split" 2>/dev/null; then echo "case + restart ran"; exit 1; fi
# A restart may change the run's length, time stepping and outputs, not the model of its
# particles (a new dp would step them with another mass and kernel).
if "$netsph" -q run --restart "$tmp/split" --set simulation.dp=0.04 2>"$tmp/err"; then
  echo "restart with another dp ran"; exit 1
fi
grep -q "start a new run" "$tmp/err" || { cat "$tmp/err"; exit 1; }
# A restart whose end is not after the checkpoint has nothing to run: a clear error.
if "$netsph" -q run --restart "$tmp/whole" --no-plots 2>"$tmp/err"; then
  echo "restart of a finished run ran"; exit 1
fi
grep -q "nothing is left to run" "$tmp/err" || { cat "$tmp/err"; exit 1; }

# Without particle snapshots the net's shapes still go out at the snapshot times, and a restart
# numbers on from them.
"$netsph" -q run "$case_file" --set simulation.end_time=0.12 --set output.snapshots=false \
  -o "$tmp/nosnap" --no-plots --max-steps 31
"$netsph" -q run --restart "$tmp/nosnap" --no-plots
[ ! -d "$tmp/nosnap/snapshots" ] || { echo "particle snapshots written though off"; exit 1; }
for f in tether.xdmf tether.vtk.series; do
  cmp "$tmp/whole/$f" "$tmp/nosnap/$f" || { echo "$f differs without snapshots"; exit 1; }
done
[ "$(ls "$tmp/nosnap" | grep -c '^net_tether_.*\.vtk$')" = "$(ls "$tmp/whole" | grep -c '^net_tether_.*\.vtk$')" ] ||
  { echo "net shapes missing without snapshots"; exit 1; }

snap="--set output.snapshot_every=0.025"
"$netsph" -q run "$box_case" --set simulation.end_time=0.1 $snap -o "$tmp/box_whole" --no-plots
"$netsph" -q run "$box_case" --set simulation.end_time=0.05 $snap -o "$tmp/box_ext" --no-plots
"$netsph" -q run --restart "$tmp/box_ext" --set simulation.end_time=0.1 --no-plots 2>/dev/null
# Stopped off the series and snapshot schedules (--max-steps) and continued: the row and the
# snapshot the stop wrote are not kept, so the files are those of the run done in one go.
"$netsph" -q run "$box_case" --set simulation.end_time=0.1 $snap -o "$tmp/box_stop" --no-plots \
  --max-steps 137
"$netsph" -q run --restart "$tmp/box_stop" --no-plots
diff <(drop_wall "$tmp/box_whole/series.csv") <(drop_wall "$tmp/box_stop/series.csv")
cmp "$tmp/box_whole/bodies.csv" "$tmp/box_stop/bodies.csv" || { echo "bodies.csv differs"; exit 1; }
cmp "$tmp/box_whole/particles.xdmf" "$tmp/box_stop/particles.xdmf" ||
  { echo "snapshot lists differ after a stop off the schedules"; exit 1; }
/usr/bin/python3 - "$tmp/box_whole/summary.json" "$tmp/box_ext/summary.json" <<'PY'
import json, sys
whole, ext = (json.load(open(f))["bodies"][0] for f in sys.argv[1:3])
print("whole: window %s over %.5f s, Fz %.3f N/m; extended: window %s over %.5f s, Fz %.3f N/m"
      % (whole["window_s"], whole["averaged_over_s"], whole["force_N"][2], ext["window_s"],
         ext["averaged_over_s"], ext["force_N"][2]))
assert ext["window_s"] == whole["window_s"], "windows differ"
# The extension misses the one step that ended the first run (dt about 2e-4 s).
assert abs(ext["averaged_over_s"] - whole["averaged_over_s"]) < 1e-3, "averaged over another span"
assert abs(ext["force_N"][2] / whole["force_N"][2] - 1) < 1e-3, "another mean force"
PY
echo "ok: split run identical to the whole run; an extended run averages over its new window"
