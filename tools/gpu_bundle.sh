#!/usr/bin/env bash
# Collects what the GPU checks need into .gpu/ (git-ignored), so that a session lent a GPU
# machine (whose image has CUDA but not Debian's libraries) runs them from a build made here:
# the netsph binary, the device parity test, and every shared library they load except the C
# library's own (the CUDA runtime is linked statically; the driver is the machine's), packed
# into .gpu/bundle.tar.xz.
#
#   ./tools/gpu_bundle.sh [build-dir]        # default: build
#
# Then, through the device tool, with carry [".gpu"]: `bash tools/gpu_session.sh` (all the
# checks, docs/PERFORMANCE.md "CUDA"), or by hand:
#   tar -C .gpu -xJf .gpu/bundle.tar.xz
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
mkdir -p .gpu/lib .gpu/sys
cp "$build/src/netsph" "$build/tests/physics/device_parity_test" .gpu/
# Every library the two programs load, into .gpu/lib; the C library and its loader apart, into
# .gpu/sys: used only if the machine's own C library is older than the one this build needs
# (Debian 12's is 2.36; libstdc++ asks for it), by running the programs through the carried
# loader (tools/gpu_session.sh).
c_library='/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so'
for f in .gpu/netsph .gpu/device_parity_test; do ldd "$f"; done |
  grep -o -E '/[^ ]+\.so[.0-9]*' | sort -u |
  while read -r lib; do
    if [[ $lib =~ $c_library ]]; then cp -L "$lib" .gpu/sys/; else cp -L "$lib" .gpu/lib/; fi
  done
# Packed, so that what travels stays under the device tool's 64 MiB (two instantiations of the
# step, exact and fast math, make the programs about 10 MB each; the libraries are 30 MB):
# tools/gpu_session.sh unpacks it there.
tar -C .gpu -cf - netsph device_parity_test lib sys | xz -T2 -6 > .gpu.bundle.tar.xz
rm -rf .gpu && mkdir .gpu && mv .gpu.bundle.tar.xz .gpu/bundle.tar.xz
du -sh .gpu/bundle.tar.xz
