#!/usr/bin/env bash
# Command-line mistakes end in one clear line naming the option, before any work is done:
# a case after --set stays the case; an output folder that cannot be made (a file in the
# way) names -o and the reason, for run, net and validate; bench checks every size and its
# --json folder before the first run. Then what two hostile-input sweeps (2026-12-05) found:
# inputs that crashed or misreported, and short runs whose outputs said too little (a run
# into an earlier run's folder, a force window no sample reached, a probe in a wall).
set -euo pipefail
netsph="$1"
case_file="$2"   # cases/dambreak2d.toml
net_case="$3"    # cases/net_tethered_knot.toml
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

expect_error() {  # expect_error "message part" command...
  local want="$1"
  shift
  if "$@" >"$tmp/out" 2>&1; then
    echo "accepted: $*"; exit 1
  fi
  grep -qF -- "$want" "$tmp/out" || { echo "for: $*"; cat "$tmp/out"; exit 1; }
  grep -q "internal error" "$tmp/out" && { echo "internal error for: $*"; cat "$tmp/out"; exit 1; }
  return 0
}

# --set before the case: the case is still the case (one value per --set).
"$netsph" check --set simulation.dp=0.03 --set simulation.name='"moved"' "$case_file" >"$tmp/out" 2>&1
grep -q "case 'moved' from .*dambreak2d.toml: valid" "$tmp/out" || { cat "$tmp/out"; exit 1; }

touch "$tmp/afile"
expect_error "-o: cannot create the output folder $tmp/afile/run" \
  "$netsph" -q run "$case_file" -o "$tmp/afile/run" --max-steps 1 --no-plots
expect_error "-o: $tmp/afile is a file, not a folder" \
  "$netsph" -q net "$net_case" -o "$tmp/afile"
expect_error "-o: cannot create the output folder $tmp/afile/v" \
  "$netsph" -q validate --only table1 -o "$tmp/afile/v"

expect_error "--sizes: particle counts must be >= 1000" \
  "$netsph" -q bench --sizes 2000,-3 --steps 1
[ ! -s "$tmp/out" ] || ! grep -q "particle-steps" "$tmp/out" ||
  { echo "bench ran a size before checking the others"; cat "$tmp/out"; exit 1; }
expect_error "--json: the folder $tmp/nodir does not exist" \
  "$netsph" -q bench --sizes 2000 --steps 1 --json "$tmp/nodir/bench.json"
expect_error "--max-steps: must be >= 0" "$netsph" -q run "$case_file" --max-steps -1 -o "$tmp/neg"
[ ! -d "$tmp/neg" ] || { echo "--max-steps -1 made an output folder"; exit 1; }
expect_error "--sample-steps: must be >= 1" "$netsph" -q check "$case_file" --sample-steps 0
# Found by a hostile-input sweep (2026-12-05): each of these crashed, ran out of memory or
# misreported before.
expect_error "--threads: 100000 is more than 8 per core" \
  "$netsph" -q check "$case_file" --threads 100000
# A domain of 1e10 m overflowed the grid's int cell counts: every particle "left the domain".
# Coordinates are now bounded (1e5 m); a domain within them but of too many cells is refused
# by its cell count.
expect_error "domain.max = [10000000000.0, 0, 8]: x must be in [-100000, 100000] m" \
  "$netsph" -q run "$case_file" --set "domain.max=[1e10,0,8]" --max-steps 1 -o "$tmp/wide" --no-plots
expect_error "cells of the neighbour grid" \
  "$netsph" -q run "$case_file" --set "domain.max=[1e5,0,1e5]" --max-steps 1 -o "$tmp/wide" --no-plots
# A net of 10^5 m at 0.1 m meshes: refused by its mesh count, not by the machine's memory.
expect_error "numerical meshes of mesh_grouping x twine_length = 0.1 m, more than 10000 a side" \
  "$netsph" -q check "$net_case" --set net.0.width=1e5
# One mesh, one knot, no twine: `netsph net` reports it (it dereferenced the first twine).
"$netsph" -q net "$net_case" --set net.0.height=0.1 -o "$tmp/one_knot" >"$tmp/out" 2>&1 ||
  { echo "netsph net failed on a one-knot net"; cat "$tmp/out"; exit 1; }
grep -q "no twines: the outline holds a single knot" "$tmp/out" || { cat "$tmp/out"; exit 1; }
# 1.5e10 snapshots counted in an int came out negative, which silenced the disk-space warning.
"$netsph" check "$case_file" --set output.snapshot_every=1e-10 --sample-steps 1 >"$tmp/out" 2>&1 ||
  { cat "$tmp/out"; exit 1; }
grep -q "snapshots every 1e-10 s: 1.5e+10 snapshots of" "$tmp/out" || { cat "$tmp/out"; exit 1; }
expect_error "--sizes: particle counts must be finite" "$netsph" -q bench --sizes inf --steps 1
expect_error "--only: no validation entry 'nonsense'" "$netsph" -q validate --only nonsense --list
mkdir -p "$tmp/run_folder" && echo '{}' >"$tmp/run_folder/summary.json"
expect_error "--times: 'abc' is not a time" "$netsph" -q plot "$tmp/run_folder" --times 0.5,abc
# A second run into a run's folder keeps the earlier run: moved aside whole to <folder>.1 (a
# restart of the folder then continues the new run, never the old one).
"$netsph" -q run "$case_file" --max-steps 2 -o "$tmp/twice" --no-plots >"$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
"$netsph" run "$case_file" --max-steps 1 -o "$tmp/twice" --no-plots >"$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
grep -q "held an earlier run of case 'dambreak2d': moved to $tmp/twice.1" "$tmp/out" ||
  { echo "no word of the earlier run moved aside"; cat "$tmp/out"; exit 1; }
[ -f "$tmp/twice.1/checkpoint.h5" ] || { echo "the earlier run's checkpoint is gone"; exit 1; }
# A force window that no probe sample reaches: a warning (in summary.json too), not an empty
# mean found later by a script.
"$netsph" run "$case_file" -o "$tmp/window" --no-plots --set simulation.end_time=0.05 \
  --set output.snapshot_every=0.01 --set output.series_every=1.0 --set probe.0.type=point \
  --set 'probe.0.at=[0.5,0,0.5]' >"$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
grep -q "probe 'probe1': no sample in output.force_window" "$tmp/out" || { cat "$tmp/out"; exit 1; }
grep -q "probe 'probe1': no sample in output.force_window" "$tmp/window/summary.json" ||
  { echo "the warning is not in summary.json"; exit 1; }
# A point probe inside the tank's wall (coverage 0.01): its means come with a warning.
"$netsph" run "$case_file" -o "$tmp/in_wall" --no-plots --set simulation.end_time=0.05 \
  --set output.snapshot_every=0.01 --set probe.0.type=point --set 'probe.0.at=[-0.03,0,0.2]' \
  >"$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
grep -q "probe 'probe1': mean coverage 0.0.* the point lies mostly outside the fluid" "$tmp/out" ||
  { cat "$tmp/out"; exit 1; }
echo "ok: command-line mistakes are named before any work"
