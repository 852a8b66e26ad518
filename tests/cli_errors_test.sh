#!/usr/bin/env bash
# Command-line mistakes end in one clear line naming the option, before any work is done:
# a case after --set stays the case; an output folder that cannot be made (a file in the
# way) names -o and the reason, for run, net and validate; bench checks every size and its
# --json folder before the first run.
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
echo "ok: command-line mistakes are named before any work"
