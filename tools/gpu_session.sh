#!/usr/bin/env bash
# The checks a session lent a GPU machine should make for the CUDA issue, in order of
# importance, each under its own time limit so that the whole fits one device call (about 9
# minutes):
#   1. the CUDA parity tests (tests/physics/device_parity_test.cpp, DeviceParity.Cuda*); if
#      one fails, it again with NETSPH_CUDA_SYNC=1 (every kernel checked: the faulting launch
#      is named) and under compute-sanitizer's memcheck, and no step 4
#   2. netsph bench --backend cuda at 1e6, 1e7 and 5e7 particles, with the step's phases
#   3. the paper's flexible net at full resolution (1.35e8 particles): `netsph check` builds
#      it, steps it on the GPU and reports its memory and the time per simulated second;
#      then the 1e7 benchmark with the rates kernel's variants: every candidate cell scanned
#      (NETSPH_RATES_TRIM=0), each pair summed where it is found (NETSPH_RATES_BATCH=0),
#      registers not capped or capped at 64 (NETSPH_RATES_MAX_REGISTERS=0 or 64: 2 or 4 blocks
#      a multiprocessor instead of the default's 3 at 80), batches of 8 (the default 32); before
#      them, the rates kernel under Nsight Compute (ncu: occupancy, memory, stalls) at 1e6
#   4. if time is left, the 3D floating box at dp = 0.01 m, a whole run with every output
#      (its draft at this dp on the CPU: docs/VALIDATION.md)
# Prepare here with ./tools/gpu_bundle.sh, then call the device tool with carry [".gpu"] and
# the command `bash tools/gpu_session.sh`. Results come back in $OUT (summaries, logs,
# bench.json; one tar file).
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/gpu_out}
# Results gather in $work/r and travel back as one file, $OUT/results.tgz (the device tool
# returns at most 8 files from $OUT).
work=$(mktemp -d /tmp/gpu_session.XXXXXX)
mkdir -p "$out" "$work/r"
export LD_LIBRARY_PATH=$PWD/.gpu/lib NETSPH_CASES_DIR=$PWD/cases OMP_NUM_THREADS=16
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv > "$work/r/gpu.txt" 2>&1
# The device call is killed at its own limit (600 s): every step's limit is cut to what is
# left of $total, and the results are packed after each step, so a killed call still returns
# what had finished.
total=${GPU_SESSION_SECONDS:-570}
# Written aside and renamed, so that a call killed while packing still has the last archive.
pack() {
  tar -C "$work" -czf "$out/results.tgz.part" r && mv -f "$out/results.tgz.part" "$out/results.tgz"
}
run() {  # run LIMIT NAME COMMAND...: the command's output in r/NAME.log, its status in $last_rc
  local limit=$1 name=$2
  shift 2
  local left=$((total - SECONDS))
  [ "$limit" -le "$left" ] || limit=$left
  if [ "$limit" -lt 15 ]; then
    echo "== $name: skipped, ${left} s left of ${total}" | tee -a "$work/r/index.txt"
    last_rc=125
    return
  fi
  echo "== $name (limit ${limit} s, at ${SECONDS} s)" | tee -a "$work/r/index.txt"
  timeout "$limit" "$@" > "$work/r/$name.log" 2>&1
  last_rc=$?
  echo "   exit $last_rc after $((SECONDS)) s" | tee -a "$work/r/index.txt"
  pack
}
run 90 parity .gpu/device_parity_test --gtest_filter='DeviceParity.Cuda*'
if [ "$last_rc" -ne 0 ] && [ -f "$work/r/parity.log" ]; then
  # The first failed test, or the one running when the process died, again with every kernel
  # waited for and checked: a fault is then named by the launch that caused it.
  log="$work/r/parity.log"
  failing=$(grep -o '^\[  FAILED  \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | head -1 | grep -o 'DeviceParity.*')
  [ -n "$failing" ] || failing=$(grep -o '^\[ RUN      \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | tail -1 | grep -o 'DeviceParity.*')
  run 60 parity_sync env NETSPH_CUDA_SYNC=1 .gpu/device_parity_test --gtest_filter="${failing:-DeviceParity.Cuda*}"
  # And under compute-sanitizer's memcheck (it ran on the Firecracker machines: KINDS.md): an
  # out-of-bounds or misaligned access is named with its kernel and, from -lineinfo, its line.
  sanitizer=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
  [ ! -x "$sanitizer" ] || run 90 parity_memcheck "$sanitizer" --tool memcheck --print-limit 20 \
    .gpu/device_parity_test --gtest_filter="${failing:-DeviceParity.Cuda*}"
  skip_float3d=1
fi
run 150 bench .gpu/netsph bench --backend cuda --sizes 1e6,1e7,5e7 --steps 10 --profile \
  --json "$work/r/bench.json"
run 240 bi2014_full .gpu/netsph check builtin:paper/net_bi2014 --backend cuda --sample-steps 10
# The rates kernel (the step's only bounded launch) under Nsight Compute: occupancy reached,
# memory throughput, L1 hits, why warps stall. It read the counters on the Firecracker
# machines (KINDS.md); --clock-control none as METHOD.md asks. Two launches after the warm-up
# step: the first and the second pass of a step.
profiler=$(command -v ncu || echo /usr/local/cuda/bin/ncu)
[ ! -x "$profiler" ] || run 75 ncu_rates "$profiler" --clock-control none \
  --kernel-name regex:for_each_bounded_kernel --launch-skip 2 --launch-count 2 \
  --section SpeedOfLight --section Occupancy --section LaunchStats \
  --section MemoryWorkloadAnalysis --section WarpStateStats --section SchedulerStats \
  .gpu/netsph bench --backend cuda --sizes 1e6 --steps 2
for knob in NETSPH_RATES_TRIM=0 NETSPH_RATES_BATCH=0 NETSPH_RATES_MAX_REGISTERS=0 \
  NETSPH_RATES_MAX_REGISTERS=64 NETSPH_RATES_BATCH=8; do
  name=bench_$(echo "$knob" | sed 's/NETSPH_RATES_//; s/=//' | tr 'A-Z' 'a-z')
  run 45 "$name" env "$knob" .gpu/netsph bench --backend cuda --sizes 1e7 --steps 10 --profile \
    --json "$work/r/$name.json"
done
[ -n "${skip_float3d:-}" ] || run 80 float3d .gpu/netsph run builtin:floating_box3d --backend cuda --set simulation.dp=0.01 \
  --no-plots --plain-progress -o "$work/float3d"
for d in "$work"/float3d; do
  [ -d "$d" ] && cp "$d/summary.json" "$work/r/$(basename "$d")_summary.json" 2>/dev/null
  [ -f "$d/bodies.csv" ] && cp "$d/bodies.csv" "$work/r/$(basename "$d")_bodies.csv"
done
pack
rm -rf "$work"
