#!/usr/bin/env bash
# `netsph run` writes PNG plots at its end, and `netsph plot DIR` redraws them: a coupled net
# with a line and a plane probe (tests/cases/good/plot_smoke.toml, a few seconds) must give the
# force, net, net-shape, probe and time-step plots, each a real PNG. Skipped (exit 77) when
# Debian's Python has no matplotlib, as netsph then only warns.
set -euo pipefail
netsph="$1"
case_file="$2"
out="$(mktemp -d)/run"
if ! /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then
  echo "SKIP: /usr/bin/python3 cannot import matplotlib and numpy"
  exit 77
fi
"$netsph" -q run "$case_file" -o "$out" --plain-progress
check() {
  local f="$out/plots/$1"
  [ -f "$f" ] || { echo "missing plot $f"; ls "$out/plots"; exit 1; }
  local size; size=$(stat -c %s "$f")
  [ "$size" -gt 5000 ] || { echo "$f is only $size bytes"; exit 1; }
  [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || { echo "$f is not a PNG"; exit 1; }
}
for f in forces_tether.png net_tether.png net_tether_shape.png probe_line.png probe_side.png time_step.png; do
  check "$f"
done
rm -r "$out/plots"
"$netsph" -q plot "$out" --times 0,0.04
check probe_side.png
if "$netsph" -q plot "$out/no-such-folder" 2>/dev/null; then
  echo "netsph plot accepted a folder without summary.json"; exit 1
fi
# A standalone net run (no fluid; its summary keys the nets by name) gets its force, net and
# shape plots too: `netsph plot` wrote none and said it had.
standalone="$(dirname "$out")/standalone"
"$netsph" -q run "$(dirname "$0")/../cases/net_bi2014_standalone.toml" -o "$standalone" \
  --set simulation.end_time=0.5 --set "output.force_window=[0.25,0.5]" --no-plots
"$netsph" -q plot "$standalone"
out="$standalone"
for f in forces_bi2014.png net_bi2014.png net_bi2014_shape.png; do
  check "$f"
done
echo "ok: $(ls "$out/plots" | wc -l) plots"
