#!/usr/bin/env bash
# `netsph run --restart DIR` refuses what it cannot continue, before it touches the folder:
# an empty folder name (which would otherwise start the default case), a checkpoint.h5 copied
# in from another run (another case, or the same case with other --set), and a checkpoint
# damaged inside (garbage bytes, a zeroed page, a changed byte of the stored case), which would
# otherwise continue with other particles or other physics, or be blamed on the run as an
# instability. The folder's own checkpoint still continues, and a restart warns
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
  # One message of netsph's, none of HDF5's (its error stack, its complaints at exit).
  if grep -q "HDF5" "$tmp/err"; then echo "$what: HDF5 printed:"; cat "$tmp/err"; exit 1; fi
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

# Damaged checkpoints are refused by their checksums, naming the file and the dataset, before
# anything is written to the folder. Each damage on a fresh copy of d's checkpoint, found by
# content (h5dump's bytes of the dataset), $1: the dataset, $2: what to write over the first
# 4 KiB of it that are not zero already.
cp d/checkpoint.h5 intact.h5
damage() {
  cp intact.h5 d/checkpoint.h5
  h5dump -d "$1" -b LE -o data.bin intact.h5 >/dev/null
  /usr/bin/python3 - d/checkpoint.h5 data.bin "$2" <<'PY'
import sys
data, values, fill = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read(), sys.argv[3]
# A window of 4 KiB of the dataset (within its first chunk, which is stored contiguously) that
# is not all zeros (zeroing it would change nothing) and that is found once in the file.
for start in range(0, min(len(values), 65536) - 4096 + 1, 512):
    window = values[start:start + 4096]
    if any(window) and data.count(window) == 1:
        break
else:
    sys.exit("no unique 4 KiB window of the dataset in the file")
at = data.find(window)
with open(sys.argv[1], "r+b") as f:
    f.seek(at)
    f.write((b"\xff" if fill == "ff" else b"\0") * 4096)
PY
}
damage /f64/particles.pos ff
refused "garbage in the positions" "d/checkpoint.h5: cannot read /f64/particles.pos" \
  --restart d --max-steps 8
damage /u8/particles.kind 00
refused "a zeroed page of the particle kinds" "d/checkpoint.h5: cannot read /u8/particles.kind" \
  --restart d --max-steps 8
# The issue's example: the 9th page of the file zeroed, whatever lies there.
cp intact.h5 d/checkpoint.h5
dd if=/dev/zero of=d/checkpoint.h5 bs=4096 seek=8 count=1 conv=notrunc status=none
refused "a zeroed 9th page" "d/checkpoint.h5: cannot read" --restart d --max-steps 8
# One changed byte in the stored case: the density.
cp intact.h5 d/checkpoint.h5
/usr/bin/python3 - d/checkpoint.h5 <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
at = data.find(b"density = 1000.0")
assert at > 0 and data.find(b"density = 1000.0", at + 1) < 0, "the stored case not found once"
with open(sys.argv[1], "r+b") as f:
    f.seek(at + 11)
    f.write(b"8")
PY
refused "a changed byte in the stored case" "d/checkpoint.h5: cannot read /text/case.toml" \
  --restart d --max-steps 8
[ "$(tail -1 d/series.csv | cut -d, -f3)" = 4 ] || { echo "a refused restart wrote rows"; exit 1; }
cp intact.h5 d/checkpoint.h5

# Snapshots deleted before a restart: a warning naming the first.
rm c/snapshots/particles_000000.h5
run --restart c --max-steps 8 2>"$tmp/err"
grep -qF "missing from c (the first: snapshots/particles_000000.h5)" "$tmp/err" ||
  { echo "no warning of the missing snapshot:"; cat "$tmp/err"; exit 1; }
echo "ok: empty, foreign and damaged restarts refused; own checkpoint continued"
