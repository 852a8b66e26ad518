#!/usr/bin/env bash
# Collects what the GPU checks need into .gpu/ (git-ignored), so that a session lent a GPU
# machine (whose image has CUDA but not Debian's libraries) runs them from a build made here:
# the netsph binary, the device parity test, and every shared library they load except the C
# library's own (the CUDA runtime is linked statically; the driver is the machine's).
#
#   ./tools/gpu_bundle.sh [build-dir]        # default: build
#
# Then, through the device tool, with carry [".gpu"]: `bash tools/gpu_session.sh` (all the
# checks, docs/PERFORMANCE.md "CUDA"), or by hand:
#   export LD_LIBRARY_PATH=$PWD/.gpu/lib NETSPH_CASES_DIR=$PWD/cases
#   .gpu/device_parity_test --gtest_filter='DeviceParity.Cuda*'
#   .gpu/netsph bench --backend cuda --sizes 1e6,1e7,5e7 --steps 10 --json $OUT/bench.json
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
for f in "$build/src/netsph" "$build/tests/physics/device_parity_test"; do
  [ -x "$f" ] || { echo "gpu_bundle: $f is missing; build first (cmake --build $build)" >&2; exit 1; }
done
if ! grep -q "NETSPH_HAVE_CUDA:INTERNAL=ON\|CMAKE_CUDA_COMPILER:.*nvcc" "$build/CMakeCache.txt"; then
  echo "gpu_bundle: $build was configured without CUDA (no nvcc): nothing to check on a GPU" >&2
  exit 1
fi
rm -rf .gpu
mkdir -p .gpu/lib
cp "$build/src/netsph" "$build/tests/physics/device_parity_test" .gpu/
for f in .gpu/netsph .gpu/device_parity_test; do ldd "$f"; done |
  awk '/=> \// {print $3}' | sort -u |
  grep -v -E '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" .gpu/lib/; done
du -sh .gpu
