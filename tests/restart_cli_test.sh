#!/usr/bin/env bash
# `netsph run --restart DIR`: a run stopped after 31 steps (--max-steps) and continued from its
# checkpoint writes the same series, probe, body and net files and the same last snapshot as
# the run done in one go (tests/cases/good/plot_smoke.toml: inlet, outlet, a coupled net,
# probes). Only the wall-clock column of series.csv may differ.
set -euo pipefail
netsph="$1"
case_file="$2"
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
echo "ok: split run identical to the whole run"
