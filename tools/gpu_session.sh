#!/usr/bin/env bash
# The checks a session lent a GPU machine should make for the CUDA issue, in order of
# importance, each under its own time limit so that the whole fits one device call (about 9
# minutes):
#   1. the CUDA parity tests (tests/physics/device_parity_test.cpp, DeviceParity.Cuda*); if
#      one fails, it again with NETSPH_CUDA_SYNC=1 (every kernel checked: the faulting launch
#      is named), and no step 4
#   2. netsph bench --backend cuda at 1e6, 1e7 and 5e7 particles, with the step's phases
#   3. the paper's flexible net at full resolution (1.35e8 particles): `netsph check` builds
#      it, steps it on the GPU and reports its memory and the time per simulated second
#   4. if time is left, the 3D floating box at dp = 0.01 m, a whole run with every output
#      (its draft at this dp on the CPU: docs/VALIDATION.md)
# Prepare here with ./tools/gpu_bundle.sh, then call the device tool with carry [".gpu"] and
# the command `bash tools/gpu_session.sh`. Results come back in $OUT (summaries, logs,
# bench.json; one tar file).
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/gpu_out}
mkdir -p "$out/r"
export LD_LIBRARY_PATH=$PWD/.gpu/lib NETSPH_CASES_DIR=$PWD/cases OMP_NUM_THREADS=16
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv > "$out/r/gpu.txt" 2>&1
run() {  # run LIMIT NAME COMMAND...: the command's output in r/NAME.log, its status in $last_rc
  local limit=$1 name=$2
  shift 2
  echo "== $name" | tee -a "$out/r/index.txt"
  timeout "$limit" "$@" > "$out/r/$name.log" 2>&1
  last_rc=$?
  echo "   exit $last_rc" | tee -a "$out/r/index.txt"
}
run 90 parity .gpu/device_parity_test --gtest_filter='DeviceParity.Cuda*'
if [ "$last_rc" -ne 0 ]; then
  # The first failed test, or the one running when the process died, again with every kernel
  # waited for and checked: a fault is then named by the launch that caused it.
  log="$out/r/parity.log"
  failing=$(grep -o '^\[  FAILED  \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | head -1 | grep -o 'DeviceParity.*')
  [ -n "$failing" ] || failing=$(grep -o '^\[ RUN      \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | tail -1 | grep -o 'DeviceParity.*')
  run 60 parity_sync env NETSPH_CUDA_SYNC=1 .gpu/device_parity_test --gtest_filter="${failing:-DeviceParity.Cuda*}"
  skip_float3d=1
fi
run 150 bench .gpu/netsph bench --backend cuda --sizes 1e6,1e7,5e7 --steps 10 --profile \
  --json "$out/r/bench.json"
run 240 bi2014_full .gpu/netsph check builtin:paper/net_bi2014 --backend cuda --sample-steps 10
[ -n "${skip_float3d:-}" ] || run 80 float3d .gpu/netsph run builtin:floating_box3d --backend cuda --set simulation.dp=0.01 \
  --no-plots --plain-progress -o "$out/float3d"
for d in "$out"/float3d; do
  [ -d "$d" ] && cp "$d/summary.json" "$out/r/$(basename "$d")_summary.json" 2>/dev/null
  [ -f "$d/bodies.csv" ] && cp "$d/bodies.csv" "$out/r/$(basename "$d")_bodies.csv"
done
tar -C "$out" -czf "$out/results.tgz" r && rm -rf "$out/float3d"
cat "$out/r/index.txt"
