// The same device step as device_run_cuda.cu, compiled with nvcc's --use_fast_math
// (src/CMakeLists.txt): float division and square root approximated to about 2 units in the
// last place, denormal floats flushed to zero; doubles (the positions) unchanged. Picked by
// NETSPH_CUDA_FAST_MATH=1 (DeviceSetup::cuda_fast_math), to measure what the rates pass's
// divisions and square roots cost against what exact rounding buys.
//
// The step is instantiated on CudaFastExec, a type of its own, so that its kernels (the
// stepper's lambdas) are distinct from those of the exact build and each keeps its own flags;
// the executor's few shared helpers (CUB's sort and scans, integer kernels) are identical
// either way.
#include "netsph/backend/cuda/cuda_exec.cuh"
#include "netsph/backend/device/device_run_on.hpp"

namespace netsph {

struct CudaFastExec : CudaExec {};

std::unique_ptr<DeviceRun> make_cuda_fast_math_device_run(DeviceSetup setup, const ParticleSet& p) {
  return std::make_unique<DeviceRunOn<CudaFastExec>>(std::move(setup), p);
}

}  // namespace netsph
