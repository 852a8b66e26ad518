#!/usr/bin/env bash
# `netsph run --restart DIR` refuses what it cannot continue, before it touches the folder:
# an empty folder name (which would otherwise start the default case), a checkpoint.h5 copied
# in from another run (another case, or the same case with other --set), and a checkpoint
# damaged inside (garbage bytes in an intact HDF5 file), which would otherwise be blamed on
# the run as an instability. The folder's own checkpoint still continues, and a restart warns
# of the snapshots that were deleted from the folder (particles.xdmf still lists them).
set -euo pipefail
netsph="$1"
dambreak="$2"
channel="$3"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
run() { "$netsph" -q run --threads 1 --no-plots "$@"; }
# $1: what the run that must fail is; $2: the text its message must hold; the rest: the run.
refused() {
  local what="$1" text="$2"
  shift 2
  if run "$@" 2>"$tmp/err"; then echo "$what: ran"; exit 1; fi
  grep -qF -- "$text" "$tmp/err" || { echo "$what: unexpected message:"; cat "$tmp/err"; exit 1; }
}

refused 'restart ""' "--restart: give a run folder" --restart "" --max-steps 1
[ ! -e out ] || { echo 'restart "" wrote outputs'; exit 1; }

run "$dambreak" -o a --max-steps 4
run "$channel" -o b --max-steps 4
run "$dambreak" -o c --max-steps 4 --set simulation.dp=0.04
cp a/checkpoint.h5 own.h5
cp a/series.csv series_before.csv

cp b/checkpoint.h5 a/checkpoint.h5
refused "another case's checkpoint" \
  "is not the checkpoint of the run in a: it continues case 'channel2d'" --restart a --max-steps 8
cp c/checkpoint.h5 a/checkpoint.h5
refused "a checkpoint with another dp" "--set simulation.dp=0.04)" --restart a --max-steps 8
cmp a/series.csv series_before.csv || { echo "a refused restart changed series.csv"; exit 1; }

# The folder's own checkpoint continues (also with the end of the run moved).
cp own.h5 a/checkpoint.h5
cp -r a d
run --restart a --max-steps 8
[ "$(tail -1 a/series.csv | cut -d, -f3)" = 8 ] || { echo "restart did not continue"; exit 1; }

# A checkpoint with garbage in its particle positions: the first 4 KiB of them overwritten.
h5dump -d /f64/particles.pos -b LE -o pos.bin d/checkpoint.h5 >/dev/null
/usr/bin/python3 - d/checkpoint.h5 pos.bin <<'PY'
import sys
data, pos = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read()
at = data.find(pos[:4096])
assert at > 0 and data.find(pos[:4096], at + 1) < 0, "positions not found once in the file"
with open(sys.argv[1], "r+b") as f:
    f.seek(at)
    f.write(b"\xff" * 4096)
PY
refused "a damaged checkpoint" "d/checkpoint.h5: the checkpoint is corrupt" \
  --restart d --max-steps 8
grep -q "particle id" "$tmp/err" || { cat "$tmp/err"; exit 1; }

# Snapshots deleted before a restart: a warning naming the first.
rm c/snapshots/particles_000000.h5
run --restart c --max-steps 8 2>"$tmp/err"
grep -qF "missing from c (the first: snapshots/particles_000000.h5)" "$tmp/err" ||
  { echo "no warning of the missing snapshot:"; cat "$tmp/err"; exit 1; }
echo "ok: empty, foreign and damaged restarts refused; own checkpoint continued"
