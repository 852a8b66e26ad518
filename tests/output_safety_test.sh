#!/usr/bin/env bash
# What a run does to the results already on disk and to a disk that fills (issue 46):
# - a run into a folder that holds an earlier run's results moves them aside to <folder>.1, .2,
#   ... (nothing deleted; the README's command works when typed again); --overwrite replaces
#   them; a folder that cannot be moved (the working folder) is refused with the way on;
# - a final checkpoint that cannot be written (a file size limit: the injected failure of
#   tests/unit/full_disk_test.cpp) ends the run with a non-zero exit and summary.json saying
#   "output failed", not "completed";
# - a restart with a new output.snapshot_every writes its first snapshot on the new schedule and
#   announces the snapshots it will write, not the whole run's;
# - netsph check warns when the outputs would not fit in the output folder's free space.
set -euo pipefail
netsph="$1"
case_file="$2"   # cases/dambreak2d.toml
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
base=(--set simulation.dp=0.04 --set output.series_every=0.005 --no-plots)
small=("${base[@]}" --set simulation.end_time=0.02 --set output.snapshot_every=0.01)

# Twice (and three times) into the default folder, as the README's command.
cd "$tmp"
"$netsph" -q run "$case_file" "${small[@]}"
[ -f out/dambreak2d/summary.json ] || { echo "no first run"; exit 1; }
echo "my notes" >out/dambreak2d/notes.txt
cp out/dambreak2d/series.csv "$tmp/first_series.csv"
"$netsph" run "$case_file" "${small[@]}" >"$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }
grep -q "out/dambreak2d held an earlier run of case 'dambreak2d': moved to out/dambreak2d.1" "$tmp/log" ||
  { echo "no word of the earlier run moved aside"; cat "$tmp/log"; exit 1; }
for f in summary.json checkpoint.h5 series.csv log.txt notes.txt particles.xdmf; do
  [ -e "out/dambreak2d.1/$f" ] || { echo "the earlier run's $f is gone"; exit 1; }
done
cmp out/dambreak2d.1/series.csv "$tmp/first_series.csv"
[ -f out/dambreak2d/summary.json ] && [ ! -e out/dambreak2d/notes.txt ] ||
  { echo "the new run is not in a fresh out/dambreak2d"; exit 1; }
"$netsph" -q run "$case_file" "${small[@]}"
[ -f out/dambreak2d.2/summary.json ] || { echo "the second run was not moved to .2"; exit 1; }
# --overwrite replaces the run in the folder: no new numbered folder.
"$netsph" run "$case_file" "${small[@]}" --overwrite >"$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }
grep -q "overwrite: this run replaces it" "$tmp/log" || { cat "$tmp/log"; exit 1; }
[ ! -e out/dambreak2d.3 ] || { echo "--overwrite moved the run aside"; exit 1; }
# The working folder itself cannot be moved aside: refused, nothing touched.
cd out/dambreak2d
if "$netsph" -q run "$case_file" "${small[@]}" -o . 2>"$tmp/err"; then
  echo "a run into the working folder with a run in it was accepted"; exit 1
fi
grep -q "holds an earlier run's results.*--overwrite" "$tmp/err" || { cat "$tmp/err"; exit 1; }
[ -f summary.json ] || { echo "the refused run touched the folder"; exit 1; }
cd "$tmp"
if "$netsph" -q run --restart out/dambreak2d --overwrite 2>"$tmp/err"; then
  echo "--overwrite with --restart was accepted"; exit 1
fi

# A final checkpoint that cannot be written: 64 KiB hold the series, log and summary but not
# the checkpoint (about 300 KB); no checkpoint falls due before the end.
rc=0
(ulimit -f 64; exec "$netsph" run "$case_file" "${small[@]}" --set output.snapshots=false \
   --set output.checkpoint_every=1 -o "$tmp/full") >"$tmp/log" 2>&1 || rc=$?
[ "$rc" -ne 0 ] || { echo "a run whose final checkpoint failed exited 0"; cat "$tmp/log"; exit 1; }
grep -q '"status": "output failed"' "$tmp/full/summary.json" ||
  { echo "summary.json does not say the output failed"; cat "$tmp/full/summary.json"; exit 1; }
grep -q "final output failed" "$tmp/log" || { cat "$tmp/log"; exit 1; }
[ ! -e "$tmp/full/checkpoint.h5" ] && [ ! -e "$tmp/full/checkpoint.h5.tmp" ] ||
  { echo "a partial checkpoint was left"; exit 1; }

# A restart with a new snapshot interval: snapshots at 0, 0.02, 0.04, then every 0.01 s.
"$netsph" -q run "$case_file" "${base[@]}" --set simulation.end_time=0.04 \
  --set output.snapshot_every=0.02 -o "$tmp/snap"
"$netsph" run --restart "$tmp/snap" --set simulation.end_time=0.08 \
  --set output.snapshot_every=0.01 --no-plots >"$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }
grep -q "snapshots every 0.01 s: 4 snapshots" "$tmp/log" ||
  { echo "the restart announced another snapshot count"; grep snapshots "$tmp/log"; exit 1; }
times=$(grep -o 'Time Value="[^"]*"' "$tmp/snap/particles.xdmf" | cut -d'"' -f2 | tr '\n' ' ')
/usr/bin/python3 - "$times" <<'PY' || exit 1
import sys
t = [float(x) for x in sys.argv[1].split()]
after = [x for x in t if x > 0.041]
ok = len(after) >= 4 and 0.05 <= after[0] < 0.055 and all(0.009 < b - a < 0.011 for a, b in zip(after, after[1:4]))
if not ok:
    sys.exit(f"snapshot times after the restart at 0.04 s: {after} (want 0.05, 0.06, 0.07, 0.08)")
PY

# netsph check: outputs far beyond any disk's free space (1e8 snapshots) are warned of.
"$netsph" check "$case_file" --set simulation.dp=0.04 --set simulation.end_time=100000 \
  --set output.snapshot_every=0.001 --sample-steps 2 -o "$tmp/check" >"$tmp/log" 2>&1 ||
  { cat "$tmp/log"; exit 1; }
grep -q "the run's outputs (snapshots and checkpoint) need about .* free" "$tmp/log" ||
  { echo "no free-space warning from netsph check"; cat "$tmp/log"; exit 1; }
echo "ok: earlier runs kept, failed outputs fail the run, restart schedule, free space"
