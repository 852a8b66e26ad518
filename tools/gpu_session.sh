#!/usr/bin/env bash
# The checks a session lent a GPU machine should make for the CUDA issue, in order of
# importance, each under its own time limit so that the whole fits one device call (about 9
# minutes; on the H200 of 2026-12-04 the lot took 5):
#   1. the CUDA parity tests (tests/physics/device_parity_test.cpp, DeviceParity.Cuda*, the
#      rates kernel's variants and fast math among them); if one fails, it again with
#      NETSPH_CUDA_SYNC=1 (every kernel checked: the faulting launch is named) and under
#      compute-sanitizer's memcheck, and no whole runs at the end; then the suite again under
#      the settings a default may move to (fast math, other batches)
#   2. netsph bench --backend cuda at 1e6, 1e7 and 5e7 particles, with the step's phases, as
#      built and with NETSPH_CUDA_FAST_MATH=1
#   3. the rates kernel under Nsight Compute (ncu: occupancy, memory, stalls) at 1e6, then the
#      1e7 benchmark with the rates kernel's variants (docs/PERFORMANCE.md, "CUDA"): batches
#      (NETSPH_RATES_BATCH, 0: each pair summed where it is found), register caps
#      (NETSPH_RATES_MAX_REGISTERS=0 or 80: 2 or 3 blocks a multiprocessor instead of 4 at 64),
#      and some with fast math
#   4. the paper's flexible net at full resolution (1.35e8 particles): `netsph check` builds
#      it, steps it on the GPU and reports its memory and the time per simulated second, as
#      built and with fast math
#   5. whole runs with every output: the default case (`netsph run`, the reduced Bi 2014 net;
#      compare its summary.json with a CPU run's) and the 3D floating box at dp = 0.01 m
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
[ ! -f .gpu/bundle.tar.xz ] || tar -C .gpu -xJf .gpu/bundle.tar.xz
# The machine's own library path is kept after ours: it may be where the driver (libcuda) is.
export LD_LIBRARY_PATH=$PWD/.gpu/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} NETSPH_CASES_DIR=$PWD/cases OMP_NUM_THREADS=16
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv > "$work/r/gpu.txt" 2>&1
# The programs run as they are where the machine's C library is as new as this build's
# (Debian 12's); otherwise through the carried loader and C library (.gpu/sys, gpu_bundle.sh).
netsph=(.gpu/netsph)
parity=(.gpu/device_parity_test)
ldd --version 2>&1 | head -1 >> "$work/r/gpu.txt"
if ! .gpu/netsph --version >> "$work/r/gpu.txt" 2>&1; then
  loader=(.gpu/sys/ld-linux-x86-64.so.2 --library-path "$PWD/.gpu/sys:$PWD/.gpu/lib:${LD_LIBRARY_PATH:-}:/usr/local/nvidia/lib64:/usr/local/nvidia/lib")
  netsph=("${loader[@]}" .gpu/netsph)
  parity=("${loader[@]}" .gpu/device_parity_test)
  echo "through the carried loader: $("${netsph[@]}" --version 2>&1)" >> "$work/r/gpu.txt"
fi
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
# A result's name for a list of settings: "NETSPH_CUDA_FAST_MATH=1 NETSPH_RATES_BATCH=8" is
# cuda_fast_math1_batch8.
knob_name() { echo "$1" | sed 's/NETSPH_//g; s/RATES_//g; s/=//g; s/ /_/g' | tr 'A-Z' 'a-z'; }
run 90 parity "${parity[@]}" --gtest_filter='DeviceParity.Cuda*'
if [ "$last_rc" -ne 0 ] && [ -f "$work/r/parity.log" ]; then
  # The first failed test, or the one running when the process died, again with every kernel
  # waited for and checked: a fault is then named by the launch that caused it.
  log="$work/r/parity.log"
  failing=$(grep -o '^\[  FAILED  \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | head -1 | grep -o 'DeviceParity.*')
  [ -n "$failing" ] || failing=$(grep -o '^\[ RUN      \] DeviceParity\.Cuda[A-Za-z0-9]*' "$log" | tail -1 | grep -o 'DeviceParity.*')
  run 60 parity_sync env NETSPH_CUDA_SYNC=1 "${parity[@]}" --gtest_filter="${failing:-DeviceParity.Cuda*}"
  # And under compute-sanitizer's memcheck (it ran on the Firecracker machines: KINDS.md): an
  # out-of-bounds or misaligned access is named with its kernel and, from -lineinfo, its line.
  sanitizer=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
  [ ! -x "$sanitizer" ] || run 90 parity_memcheck "$sanitizer" --tool memcheck --print-limit 20 \
    "${parity[@]}" --gtest_filter="${failing:-DeviceParity.Cuda*}"
  skip_runs=1
fi
# The whole parity suite again under the settings a default may move to (a few seconds each).
for knobs in NETSPH_CUDA_FAST_MATH=1 NETSPH_RATES_BATCH=0 NETSPH_RATES_BATCH=8; do
  name=parity_$(knob_name "$knobs")
  # shellcheck disable=SC2086 # the list splits into its settings
  run 60 "$name" env $knobs "${parity[@]}" --gtest_filter='DeviceParity.Cuda*'
done
run 150 bench "${netsph[@]}" bench --backend cuda --sizes 1e6,1e7,5e7 --steps 10 --profile \
  --json "$work/r/bench.json"
run 150 bench_fast env NETSPH_CUDA_FAST_MATH=1 "${netsph[@]}" bench --backend cuda \
  --sizes 1e6,1e7,5e7 --steps 10 --profile --json "$work/r/bench_fast.json"
# The rates kernel (the step's only bounded launch) under Nsight Compute: occupancy reached,
# memory throughput, L1 hits, why warps stall. It read the counters on the Firecracker
# machines (KINDS.md); --clock-control none as METHOD.md asks. Two launches after the warm-up
# step: the first and the second pass of a step.
profiler=$(command -v ncu || echo /usr/local/cuda/bin/ncu)
[ ! -x "$profiler" ] || run 75 ncu_rates "$profiler" --clock-control none \
  --kernel-name regex:for_each_bounded_kernel --launch-skip 2 --launch-count 2 \
  --section SpeedOfLight --section Occupancy --section LaunchStats \
  --section MemoryWorkloadAnalysis --section WarpStateStats --section SchedulerStats \
  "${netsph[@]}" bench --backend cuda --sizes 1e6 --steps 2
# Each a space-separated list of settings.
for knobs in NETSPH_RATES_BATCH=0 NETSPH_RATES_BATCH=8 NETSPH_RATES_BATCH=16 \
  NETSPH_RATES_MAX_REGISTERS=80 NETSPH_RATES_MAX_REGISTERS=0 \
  "NETSPH_CUDA_FAST_MATH=1 NETSPH_RATES_BATCH=8" "NETSPH_CUDA_FAST_MATH=1 NETSPH_RATES_BATCH=16" \
  "NETSPH_CUDA_FAST_MATH=1 NETSPH_RATES_MAX_REGISTERS=80"; do
  name=bench_$(knob_name "$knobs")
  # shellcheck disable=SC2086 # the list splits into its settings
  run 45 "$name" env $knobs "${netsph[@]}" bench --backend cuda --sizes 1e7 --steps 10 --profile \
    --json "$work/r/$name.json"
done
run 120 bi2014_full "${netsph[@]}" check builtin:paper/net_bi2014 --backend cuda --sample-steps 10
run 120 bi2014_full_fast env NETSPH_CUDA_FAST_MATH=1 "${netsph[@]}" check builtin:paper/net_bi2014 \
  --backend cuda --sample-steps 10
if [ -z "${skip_runs:-}" ]; then
  run 120 default_run "${netsph[@]}" run --backend cuda --no-plots --plain-progress -o "$work/default_run"
  run 80 float3d "${netsph[@]}" run builtin:floating_box3d --backend cuda --set simulation.dp=0.01 \
    --no-plots --plain-progress -o "$work/float3d"
fi
for d in "$work"/default_run "$work"/float3d; do
  [ -d "$d" ] && cp "$d/summary.json" "$work/r/$(basename "$d")_summary.json" 2>/dev/null
  for f in bodies.csv nets.csv probes.csv series.csv; do
    [ -f "$d/$f" ] && cp "$d/$f" "$work/r/$(basename "$d")_$f"
  done
done
pack
rm -rf "$work"
